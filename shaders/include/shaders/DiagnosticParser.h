#pragma once
// Turns a compiler info log into Diagnostic values that point at the user's file and line.
// Understands glslang ("ERROR: 2:14: 'x' : undeclared identifier"), Mesa ("2:14(7): error: ...")
// and NVIDIA ("2(14) : error C1008: ...") logs. Columns come from the log when it has them, else
// from the quoted token's position in that line. A "expecting ';'" error is moved back to the end
// of the statement that lacks it, where a person looks for it.

#include <shaders/Diagnostic.h>
#include <shaders/SourceMap.h>

#include <string_view>
#include <vector>

namespace sdfwb::shaders {

std::vector<Diagnostic> parseInfoLog(std::string_view log, const SourceMap& map);

} // namespace sdfwb::shaders
