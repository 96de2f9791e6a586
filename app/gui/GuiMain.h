#pragma once

namespace sdfwb::app {

// Runs the workbench window; `file` may be null (then the default dataset SDF opens).
int runGui(int argc, char** argv, const char* file);

} // namespace sdfwb::app
