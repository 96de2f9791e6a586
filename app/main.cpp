// sdfwb: one binary for the workbench window and the headless batch commands.

#include "batch/CommandLine.h"
#ifdef SDFWB_WITH_GUI
#include "gui/GuiMain.h"
#endif

#include <cstdio>
#include <exception>

int main(int argc, char** argv) {
    try {
        if (auto exitCode = sdfwb::app::runCommandLine(argc, argv)) return *exitCode;
#ifdef SDFWB_WITH_GUI
        return sdfwb::app::runGui(argc, argv, argc > 1 ? argv[1] : nullptr);
#else
        std::fprintf(stderr, "sdfwb: built without the workbench (SDFWB_BUILD_GUI=OFF): only --batch commands run\n");
        return 2;
#endif
    } catch (const std::exception& error) {
        std::fprintf(stderr, "sdfwb: internal error: %s\n", error.what());
        return 1;
    }
}
