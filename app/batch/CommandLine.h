#pragma once
// Parses sdfwb's command line for the headless paths (`--batch ...`, `--help`, `--version`) and
// runs them. The GUI path (`sdfwb [FILE]`) is decided here too but run by the caller.

#include <optional>
#include <string>
#include <vector>

namespace sdfwb::app {

// The exit code when the command line asks for headless work or help; nullopt when it asks for
// the workbench window (no arguments, or one file to open).
std::optional<int> runCommandLine(int argc, char** argv);

// Parse-only twins of runCommandLine and of `--batch JOBFILE`, for tests and fuzzing: the same
// parsing and validation, with the same messages and exit codes, stopping where the work would
// start. They run no command: no GL, no dataset scan, no file written (a `--batch JOBFILE`
// argument is still read). kExitOk means the real run would go on to the run*() functions of
// BatchCommands.h, whose own checks are not made: whether the SDF and the output folder exist,
// the sample count against the format's limit. (Value ranges such as --fps, --samples, --time
// and the steps and tolerances are checked while parsing.) Not thread-safe: the messages go to
// stdout/stderr as in the real run.
// `arguments` are argv[1..], without the program name.
std::optional<int> checkCommandLine(const std::vector<std::string>& arguments);
// `text` is a job file's content; `name` labels the messages as its path would.
int checkJobFile(const std::string& text, const std::string& name);

} // namespace sdfwb::app
