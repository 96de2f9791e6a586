// The one symbol libsdfwb_workbench.so exports: the workbench window's entry point. The sdfwb
// binary loads this module only when it opens the window (app/main.cpp), so `sdfwb --batch`
// never loads Qt Widgets, QScintilla or the GUI's OpenGL.

#include "GuiMain.h"

extern "C" __attribute__((visibility("default"))) int sdfwb_workbench_main(int argc, char** argv, const char* file) {
    return sdfwb::app::runGui(argc, argv, file);
}
