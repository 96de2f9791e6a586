#include "TouchDesigner.h"

#include "ForeignHosts.h"
#include "Words.h"

#include <core/Regex.h>

#include <array>
#include <cctype>
#include <cstring>
#include <regex>

namespace sdfwb::shaders::detail {
namespace {

// TouchDesigner's functions, written here from their documented meaning.
const std::array<std::pair<const char*, const char*>, 4> kFunctions{{
    {"TDOutputSwizzle", "vec4 TDOutputSwizzle(vec4 c) { return c; } uvec4 TDOutputSwizzle(uvec4 c) { return c; } "},
    {"TDDither", "vec4 TDDither(vec4 c) { return c; } "},
    {"TDHSVToRGB", "vec3 TDHSVToRGB(vec3 c) { vec3 k = clamp(abs(mod(c.x * 6.0 + vec3(0.0, 4.0, 2.0), 6.0) - 3.0) - 1.0, 0.0, "
                   "1.0); return c.z * mix(vec3(1.0), k, c.y); } "},
    {"TDRGBToHSV", "vec3 TDRGBToHSV(vec3 c) { float hi = max(c.r, max(c.g, c.b)), lo = min(c.r, min(c.g, c.b)), d = hi - lo; "
                   "float h = d == 0.0 ? 0.0 : hi == c.r ? mod((c.g - c.b) / d, 6.0) : hi == c.g ? (c.b - c.r) / d + 2.0 : "
                   "(c.r - c.g) / d + 4.0; return vec3(h / 6.0, hi == 0.0 ? 0.0 : d / hi, hi); } "},
}};

// The samplers of the TOP's inputs, arrays TouchDesigner declares, and their types.
const std::array<std::pair<const char*, const char*>, 3> kInputs{{
    {"sTD2DInputs", "sampler2D"},
    {"sTD3DInputs", "sampler3D"},
    {"sTDCubeInputs", "samplerCube"},
}};

} // namespace

std::vector<Edit> touchDesignerEdits(const std::string& stripped) {
    static const std::regex ownUv(R"(\b(?:in|varying)\s+vec[234]\s+vUV\b)", kLinearRegex);
    const bool swizzle = !wordOffsets(stripped, "TDOutputSwizzle").empty(),
               info = !wordOffsets(stripped, "uTDOutputInfo").empty();
    bool inputs = false;
    for (const auto& [name, type] : kInputs) inputs |= !wordOffsets(stripped, name).empty();
    if ((!swizzle && !info && !inputs) || std::regex_search(stripped, ownUv)) return {};
    std::vector<Edit> edits;
    // The TOP's inputs, `sTD2DInputs[0]`: none is connected here, so each array element is the one
    // sampler of its type on the empty unit (an array would run over the next type's unit).
    for (const auto& [name, type] : kInputs)
        for (std::size_t at : wordOffsets(stripped, name)) {
            std::size_t open = at + std::strlen(name);
            while (open < stripped.size() && std::isspace(static_cast<unsigned char>(stripped[open]))) ++open;
            const std::size_t close =
                open < stripped.size() && stripped[open] == '[' ? stripped.find(']', open) : std::string::npos;
            if (close != std::string::npos) edits.push_back({at, close + 1 - at, std::string("sdfwb_") + name});
        }
    std::string declared;
    for (const auto& [name, definition] : kFunctions)
        if (!wordOffsets(stripped, name).empty() && !definesFunction(stripped, name)) declared += definition;
    for (const auto& [name, type] : kInputs)
        if (!wordOffsets(stripped, name).empty())
            declared += "layout(binding = " + std::to_string(emptyUnit(type)) + ") uniform " + type + " sdfwb_" + name + "; ";
    const std::size_t first = firstCodeOffset(stripped);
    if (!declared.empty()) edits.push_back({first < stripped.size() ? first : 0, 0, declared});
    for (std::size_t at : wordOffsets(stripped, "vUV"))
        if (at == 0 || stripped[at - 1] != '.') edits.push_back({at, 3, "vec3(gl_FragCoord.xy / iResolution.xy, 0.0)"});
    for (std::size_t at : wordOffsets(stripped, "uTDOutputInfo")) {
        static const std::regex res(R"(^uTDOutputInfo\s*\.\s*res\b)", kLinearRegex);
        std::smatch match;
        const std::string rest = stripped.substr(at, 40);
        if (std::regex_search(rest, match, res))
            edits.push_back({at, std::size_t(match.length(0)), "vec4(1.0 / iResolution.xy, iResolution.xy)"});
    }
    return edits;
}

} // namespace sdfwb::shaders::detail
