// Fuzzes the parameter parser (shaders/src/Parameters.cpp: annotated uniforms and their
// defaults). Contract: no crash; every diagnostic points inside the text; every parameter it
// accepts has a finite default, a non-empty range when it has one, and a name.

#include <shaders/Parameters.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>

namespace {

void require(bool condition, const char* what) {
    if (!condition) {
        std::fprintf(stderr, "fuzz_parameters: contract broken: %s\n", what);
        std::abort();
    }
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string text(reinterpret_cast<const char*>(data), size);
    const auto scan = sdfwb::shaders::parseParameters(text, "fuzz.glsl");
    const int lines = int(std::count(text.begin(), text.end(), '\n')) + 1;
    for (const auto& d : scan.diagnostics) {
        require(d.file == "fuzz.glsl", "a diagnostic names another file");
        require(d.line >= 1 && d.line <= lines, "a diagnostic's line is outside the text");
        require(d.column >= 1, "a diagnostic without a column");
        require(!d.message.empty(), "a diagnostic without a message");
    }
    for (const auto& p : scan.parameters) {
        require(!p.name.empty(), "a parameter without a name");
        require(p.line >= 1 && p.line <= lines, "a parameter's line is outside the text");
        for (float v : p.defaultValue) require(std::isfinite(v), "a default that is not finite");
        require(p.minimum.has_value() == p.maximum.has_value(), "half a range");
        if (p.minimum) require(*p.minimum < *p.maximum, "an empty range");
        if (p.logarithmic) require(p.minimum && *p.minimum > 0.0f, "@log without a positive minimum");
    }
    return 0;
}
