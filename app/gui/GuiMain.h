#pragma once

namespace sdfwb::app {

// The OpenGL format of the workbench's windows (4.3 core, no depth buffer: the tracer writes
// every pixel and tests nothing); call before the QApplication exists. The GUI tests and
// benchmarks use it too, so they measure the window users get.
void setDefaultSurfaceFormat();

// Runs the workbench window; `file` may be null (then the default dataset SDF opens).
int runGui(int argc, char** argv, const char* file);

} // namespace sdfwb::app
