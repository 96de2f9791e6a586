#pragma once
// Reading and writing the numbers of parameter declarations and values (Parameters.cpp,
// ParameterValues.cpp), and Fragmentarium's presets (ForeignHosts.cpp too).

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

namespace sdfwb::shaders::detail {

// `text` without leading and trailing white space.
std::string trimmed(const std::string& text);
// A whole number or floating literal, as GLSL writes them (a trailing f/F allowed), finite.
std::optional<float> parseNumber(std::string text, bool integerOnly);
// "a,b,c" of 1 to 4 numbers (true/false as 1/0); nullopt when any item is not one.
std::optional<std::vector<float>> parseList(const std::string& text);
// The shortest decimal that reads back as `value`.
std::string shortest(float value);

// A `Name = value` line of Fragmentarium's `#preset Default` block (else of its first preset): the
// value's place in the text, without a trailing Locked or NotLocked.
struct PresetLine {
    std::string name;
    std::size_t valueOffset = 0, valueLength = 0;
};
std::vector<PresetLine> defaultPresetLines(const std::string& text);

} // namespace sdfwb::shaders::detail
