#pragma once
// Parses sdfwb's command line for the headless paths (`--batch ...`, `--help`, `--version`) and
// runs them. The GUI path (`sdfwb [FILE]`) is decided here too but run by the caller.

#include <optional>

namespace sdfwb::app {

// The exit code when the command line asks for headless work or help; nullopt when it asks for
// the workbench window (no arguments, or one file to open).
std::optional<int> runCommandLine(int argc, char** argv);

} // namespace sdfwb::app
