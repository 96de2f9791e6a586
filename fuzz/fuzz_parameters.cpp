// Fuzzes the parameter parsers (shaders/src/Parameters.cpp: annotated uniforms and their
// defaults; `--param NAME=VALUE` and `--sweep NAME=FROM:TO:COUNT` texts). Contract: no crash;
// every diagnostic points inside the text; every parameter it accepts has a finite default, a
// non-empty range when it has one, and a name; writing the defaults back into the initializers
// ("Save values as defaults") reads back the same parameters; every value or sweep text it
// accepts survives formatting and parsing again unchanged.

#include <shaders/Parameters.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

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
        require(p.initializerOffset + p.initializerLength <= text.size(), "an initializer outside the text");
    }
    std::vector<sdfwb::shaders::ParameterSetting> defaults;
    for (const auto& p : scan.parameters) defaults.push_back({p.name, p.type, p.defaultValue});
    const auto again =
        sdfwb::shaders::parseParameters(sdfwb::shaders::withDefaults(text, scan.parameters, defaults), "fuzz.glsl");
    require(again.parameters.size() == scan.parameters.size(), "saving the defaults changed the parameters");
    for (std::size_t i = 0; i < again.parameters.size(); ++i) {
        require(again.parameters[i].name == scan.parameters[i].name, "saving the defaults changed a name");
        require(again.parameters[i].defaultValue == scan.parameters[i].defaultValue, "saving the defaults changed a value");
    }
    if (auto value = sdfwb::shaders::parseParameterValue(text)) {
        auto back = sdfwb::shaders::parseParameterValue(sdfwb::shaders::formatParameterValue(*value));
        require(back && *back == *value, "a --param value changed in a round trip");
    }
    if (auto sweep = sdfwb::shaders::parseParameterSweep(text)) {
        auto back = sdfwb::shaders::parseParameterSweep(sdfwb::shaders::formatParameterSweep(*sweep));
        require(back && *back == *sweep, "a --sweep changed in a round trip");
    }
    return 0;
}
