#pragma once
// The first error among a piece of GLSL's diagnostics, for the test files that check them.

#include <shaders/Diagnostic.h>

#include <string>
#include <vector>

namespace sdfwb::testing {

// The first error among `diagnostics`, or an empty diagnostic (no message) when there is none.
inline shaders::Diagnostic firstError(const std::vector<shaders::Diagnostic>& diagnostics) {
    for (const shaders::Diagnostic& d : diagnostics)
        if (d.severity == shaders::Severity::Error) return d;
    return {};
}

// The same as a compiler would print it ("file:line:column: error: ..."), or "" when there is none.
inline std::string firstErrorText(const std::vector<shaders::Diagnostic>& diagnostics) {
    const shaders::Diagnostic d = firstError(diagnostics);
    return d.message.empty() ? std::string() : shaders::formatDiagnostic(d);
}

} // namespace sdfwb::testing
