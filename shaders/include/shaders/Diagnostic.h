#pragma once
// A compiler or resolver message pinned to a user's file and line. Produced by the include
// resolver, the glslang checker and the driver's info log parser; drawn by the editor.

#include <string>
#include <vector>

namespace sdfwb::shaders {

enum class Severity { Error, Warning, Note };

struct Diagnostic {
    std::string file; // path as the user knows it ("<editor>" for unsaved text)
    int line = 0;     // 1-based; 0 when the message has no line
    int column = 0;   // 1-based; 0 when unknown
    Severity severity = Severity::Error;
    std::string message; // without file/line prefix
};

const char* severityName(Severity severity);

// "file:line:column: error: message" (column omitted when unknown), as compilers print.
std::string formatDiagnostic(const Diagnostic& diagnostic);

bool hasErrors(const std::vector<Diagnostic>& diagnostics);

} // namespace sdfwb::shaders
