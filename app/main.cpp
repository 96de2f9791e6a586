// sdfwb: one binary for the workbench window and the headless batch commands. The window lives
// in libsdfwb_workbench.so, loaded only when it opens (core/Plugins.h), so a batch command starts
// without loading Qt Widgets.

#include "batch/CommandLine.h"

#ifdef SDFWB_WITH_GUI
#include <core/Plugins.h>
#endif

#include <cstdio>
#include <exception>

int main(int argc, char** argv) {
    try {
        if (auto exitCode = sdfwb::app::runCommandLine(argc, argv)) return *exitCode;
#ifdef SDFWB_WITH_GUI
        auto entry = sdfwb::plugins::symbol("libsdfwb_workbench.so", "sdfwb_workbench_main");
        if (!entry) {
            std::fprintf(stderr, "sdfwb: cannot open the workbench: %s\n", entry.error().message.c_str());
            return 2;
        }
        const auto runWorkbench = reinterpret_cast<int (*)(int, char**, const char*)>(*entry);
        return runWorkbench(argc, argv, argc > 1 ? argv[1] : nullptr);
#else
        std::fprintf(stderr, "sdfwb: built without the workbench (SDFWB_BUILD_GUI=OFF): only --batch commands run\n");
        return 2;
#endif
    } catch (const std::exception& error) {
        std::fprintf(stderr, "sdfwb: internal error: %s\n", error.what());
        return 1;
    }
}
