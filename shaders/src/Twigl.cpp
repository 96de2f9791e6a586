#include "Twigl.h"

#include <shaders/SdfSource.h>

#include <core/Regex.h>

#include "Words.h"

#include <array>
#include <regex>

namespace sdfwb::shaders::detail {

std::optional<std::string> adaptTwigl(const std::string& text) {
    const std::string stripped = stripComments(text);
    static const std::regex function(R"(\b\w+\s+\w+\s*\([^()]*\)\s*\{)", kLinearRegex);
    static const std::regex control(R"(^(?:if|for|while|switch|return|else)$)", kLinearRegex);
    if (wordOffsets(stripped, "FC").empty() || wordOffsets(stripped, "o").empty()) return std::nullopt;
    // A definition `TYPE NAME(...) {`, not a loop's header (`for (...) {`, `else if (...) {`).
    for (auto it = std::sregex_iterator(stripped.begin(), stripped.end(), function); it != std::sregex_iterator(); ++it) {
        static const std::regex words(R"(\b(\w+)\s+(\w+)\s*\()", kLinearRegex);
        std::smatch parts;
        const std::string head = it->str();
        if (std::regex_search(head, parts, words) && !std::regex_match(parts[1].str(), control) &&
            !std::regex_match(parts[2].str(), control))
            return std::nullopt;
    }
    // twigl's helpers (geekest mode), written here; each declared only where the text calls it.
    static const std::array<std::pair<const char*, const char*>, 3> helpers{{
        {"rotate2D", "mat2 rotate2D(float a) { float c = cos(a), s = sin(a); return mat2(c, s, -s, c); } "},
        {"rotate3D",
         "mat3 rotate3D(float a, vec3 axis) { vec3 k = normalize(axis); float c = cos(a), s = sin(a); "
         "return mat3(c) + (1.0 - c) * outerProduct(k, k) + s * mat3(0.0, k.z, -k.y, -k.z, 0.0, k.x, k.y, -k.x, 0.0); } "},
        {"hsv", "vec3 hsv(float h, float s, float v) { vec3 k = clamp(abs(mod(h * 6.0 + vec3(0.0, 4.0, 2.0), 6.0) - 3.0) - 1.0, "
                "0.0, 1.0); return v * mix(vec3(1.0), k, s); } "},
    }};
    std::string prefix;
    for (const auto& [name, definition] : helpers)
        if (!wordOffsets(stripped, name).empty()) prefix += definition;
    prefix += "void mainImage(out vec4 o, in vec2 twiglPixel) { vec2 r = iResolution.xy; float t = iTime; "
              "vec4 FC = gl_FragCoord; o = vec4(0.0); ";
    if (!wordOffsets(stripped, "m").empty()) prefix += "vec2 m = iMouse.xy / iResolution.xy; ";
    // The closing brace after the last code on the last line of code (its comment after it), so
    // every line keeps its number; a text ending in a directive (`#endif`) is left as it is.
    const std::size_t last = stripped.find_last_not_of(" \t\r\n\f\v");
    if (last == std::string::npos) return std::nullopt;
    const std::size_t lineStart = stripped.rfind('\n', last) == std::string::npos ? 0 : stripped.rfind('\n', last) + 1;
    if (stripped[stripped.find_first_not_of(" \t", lineStart)] == '#') return std::nullopt;
    return prefix + text.substr(0, last + 1) + " }" + text.substr(last + 1);
}

} // namespace sdfwb::shaders::detail
