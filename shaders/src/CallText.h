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

} // namespace sdfwb::shaders::detail
