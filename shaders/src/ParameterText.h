#pragma once
// Reading and writing the numbers of parameter declarations and values (Parameters.cpp,
// ParameterValues.cpp).

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

} // namespace sdfwb::shaders::detail
