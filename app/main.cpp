// sdfwb: one binary for the workbench window and the headless batch commands.

#include "batch/CommandLine.h"
#include "gui/GuiMain.h"

#include <cstdio>
#include <exception>

int main(int argc, char** argv) {
    try {
        if (auto exitCode = sdfwb::app::runCommandLine(argc, argv)) return *exitCode;
        return sdfwb::app::runGui(argc, argv, argc > 1 ? argv[1] : nullptr);
    } catch (const std::exception& error) {
        std::fprintf(stderr, "sdfwb: internal error: %s\n", error.what());
        return 1;
    }
}
