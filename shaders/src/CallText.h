#pragma once
// Reading calls and statements from a shader's text (comments blanked) at the lines glslang reports:
// what the march analysis hands a wrapper (MarchAnalysis.cpp). Private to shaders/.

#include <cstddef>
#include <string>
#include <vector>

namespace sdfwb::shaders::detail {

// The offset of the first character of 1-based `line`, or npos.
std::size_t lineStart(const std::string& text, int line);

// The arguments of the first call of `name` on `line`, split at the call's own commas and trimmed;
// `before` receives the line's text before the name. glslang places a call at the line its
// argument list ends on, so the name is looked for up to 16 lines above too (arguments written one
// to a line); `nameLine` receives the line it was found on. Empty when none is found.
std::vector<std::string> callArguments(const std::string& text, int line, const std::string& name, std::string* before,
                                       int* nameLine = nullptr);

// Whether `code` is whole statements a wrapper can run before its own: balanced, ending with a
// statement, and neither returning nor discarding.
bool wholeStatements(const std::string& code);

// The code before a loop nested in others (an anti-aliasing loop around the march, a loop over
// cameras), entered as one pass of each: every block still open at its end keeps its brace, a
// `for (INIT; ...; ...)` before one becomes `INIT;` (its first pass), and a while, if, else or do
// header is dropped. `opened` receives how many blocks are left open (-1: the code cannot be read).
std::string enteredBlocks(std::string code, int& opened);

} // namespace sdfwb::shaders::detail
