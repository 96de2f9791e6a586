#include "Synesthesia.h"

#include <shaders/SdfSource.h>

#include <core/Regex.h>

#include "ForeignHosts.h"
#include "TextEdits.h"
#include "Words.h"

#include <algorithm>
#include <array>
#include <map>
#include <regex>

namespace sdfwb::shaders::detail {
namespace {

// Synesthesia's built-in functions (its documented forms), written here: each is declared only
// where the text calls it and defines no function of that name.
const std::array<std::pair<const char*, const char*>, 21> kFunctions{{
    {"_rotate",
     "vec2 _rotate(vec2 v, float a) { float c = cos(a), s = sin(a); return vec2(c * v.x - s * v.y, s * v.x + c * v.y); }"},
    {"_scale", "float _scale(float v, float lo, float hi) { return lo + v * (hi - lo); }"},
    {"_map", "float _map(float v, float a, float b, float c, float d) { return c + (v - a) * (d - c) / (b - a); }"},
    {"_smin", "float _smin(float a, float b, float k) { float h = clamp(0.5 + 0.5 * (b - a) / k, 0.0, 1.0); "
              "return mix(b, a, h) - k * h * (1.0 - h); }"},
    {"_nsin", "float _nsin(float x) { return 0.5 + 0.5 * sin(x); }"},
    {"_ncos", "float _ncos(float x) { return 0.5 + 0.5 * cos(x); }"},
    {"_nclamp", "float _nclamp(float x) { return clamp(x, 0.0, 1.0); }"},
    {"_rand", "float _rand(float s) { return fract(sin(s * 12.9898) * 43758.5453); } "
              "float _rand(vec2 s) { return fract(sin(dot(s, vec2(12.9898, 78.233))) * 43758.5453); }"},
    {"_pulse", "float _pulse(float x, float c, float w) { return smoothstep(c - w, c, x) - smoothstep(c, c + w, x); }"},
    {"_sqPulse", "float _sqPulse(float x, float c, float w) { return step(c - w, x) - step(c + w, x); }"},
    {"_toPolar", "vec2 _toPolar(vec2 p) { return vec2(length(p), atan(p.y, p.x)); }"},
    {"_toRect", "vec2 _toRect(vec2 p) { return p.x * vec2(cos(p.y), sin(p.y)); }"},
    {"_luminance", "float _luminance(vec3 c) { return dot(c, vec3(0.2126, 0.7152, 0.0722)); }"},
    {"_grayscale", "vec3 _grayscale(vec3 c) { return vec3(dot(c, vec3(0.2126, 0.7152, 0.0722))); }"},
    {"_palette", "vec3 _palette(float t, vec3 a, vec3 b, vec3 c, vec3 d) { return a + b * cos(6.28318530718 * (c * t + d)); }"},
    {"_hsv2rgb", "vec3 _hsv2rgb(vec3 c) { vec3 k = clamp(abs(mod(c.x * 6.0 + vec3(0.0, 4.0, 2.0), 6.0) - 3.0) - 1.0, 0.0, 1.0); "
                 "return c.z * mix(vec3(1.0), k, c.y); }"},
    {"_rgb2hsv", "vec3 _rgb2hsv(vec3 c) { float hi = max(c.r, max(c.g, c.b)), lo = min(c.r, min(c.g, c.b)), d = hi - lo; "
                 "float h = d == 0.0 ? 0.0 : hi == c.r ? mod((c.g - c.b) / d, 6.0) : hi == c.g ? (c.b - c.r) / d + 2.0 "
                 ": (c.r - c.g) / d + 4.0; return vec3(h / 6.0, hi == 0.0 ? 0.0 : d / hi, hi); }"},
    // Its media (a video or image the user drops in, and the user image): none loaded, black.
    {"_loadMedia", "vec4 _loadMedia() { return vec4(0.0); } vec4 _loadMedia(vec2 offset) { return vec4(0.0); }"},
    {"_textureMedia", "vec4 _textureMedia(vec2 uv) { return vec4(0.0); }"},
    {"_loadUserImage", "vec4 _loadUserImage() { return vec4(0.0); }"},
    {"_textureUserImage", "vec4 _textureUserImage(vec2 uv) { return vec4(0.0); }"},
}};

// Its inputs in Shadertoy's terms.
const std::array<std::pair<const char*, const char*>, 11> kInputs{{
    {"TIME", "iTime"},
    {"RENDERSIZE", "iResolution.xy"},
    {"FRAMECOUNT", "float(iFrame)"},
    {"PASSINDEX", "0"},
    {"_xy", "gl_FragCoord.xy"},
    {"_uv", "(gl_FragCoord.xy / iResolution.xy)"},
    {"_uvc", "((gl_FragCoord.xy - 0.5 * iResolution.xy) / iResolution.y)"},
    {"_mouse", "iMouse"},
    {"_muv", "(iMouse.xy / iResolution.xy)"},
    {"_muvc", "((iMouse.xy - 0.5 * iResolution.xy) / iResolution.y)"},
    {"_click", "vec3(0.0)"},
}};

// Its audio textures (read from the empty unit, ForeignHosts.h's emptyUnit("sampler2D")).
const std::array<const char*, 5> kTextures{"syn_Spectrum", "syn_LevelTrail", "syn_Media", "syn_FinalPass", "syn_UserImage"};

bool defines(const std::string& stripped, const std::string& name) {
    return definesFunction(stripped, name) ||
           std::regex_search(stripped, std::regex(R"(#\s*define\s+)" + name + R"(\b)", kLinearRegex)) ||
           std::regex_search(stripped, std::regex(R"(\b(?:float|const\s+float)\s+)" + name + R"(\s*=)", kLinearRegex));
}

// A variable of that name declared by the text (`vec2 _uv = ...`): the text's own, kept.
bool declares(const std::string& stripped, const std::string& name) {
    return std::regex_search(stripped,
                             std::regex(R"(\b(?:float|int|vec[234]|mat[234])\s+)" + name + R"(\s*[=;,)])", kLinearRegex));
}

} // namespace

std::optional<std::string> adaptSynesthesia(const std::string& text, const std::vector<Parameter>& controls) {
    const std::string stripped = stripComments(text);
    static const std::regex renderMain(R"(\bvec4\s+renderMain\s*\(\s*\)\s*\{)", kLinearRegex);
    static const std::regex hostMain(R"(\bvoid\s+(?:main|mainImage)\s*\()", kLinearRegex);
    if (stripped.find("renderMain") == std::string::npos || !std::regex_search(stripped, renderMain) ||
        std::regex_search(stripped, hostMain))
        return std::nullopt;
    std::vector<Edit> edits;
    auto notMember = [&](std::size_t at) { return at == 0 || stripped[at - 1] != '.'; };
    for (const auto& [name, value] : kInputs)
        for (std::size_t at : declares(stripped, name) ? std::vector<std::size_t>{} : wordOffsets(stripped, name))
            if (notMember(at)) edits.push_back({at, std::char_traits<char>::length(name), value});
    // Audio: its clocks run as the time, its BPM is 120, its levels and hits are silent.
    std::string declared;
    for (const char* texture : kTextures)
        if (!wordOffsets(stripped, texture).empty())
            declared += "layout(binding = " + std::to_string(emptyUnit("sampler2D")) + ") uniform sampler2D " +
                        std::string(texture) + "; ";
    forEachIdentifier(stripped, [&](std::size_t at, std::size_t end) {
        const std::string word = stripped.substr(at, end - at);
        if (word.rfind("syn_", 0) != 0 || !notMember(at) ||
            std::find(kTextures.begin(), kTextures.end(), word) != kTextures.end())
            return true;
        const bool clock = word.size() > 8 && word.compare(word.size() - 4, 4, "Time") == 0;
        edits.push_back({at, word.size(), clock ? "iTime" : word == "syn_BPM" ? "120.0" : "0.0"});
        return true;
    });
    declared += piWhereUsed(stripped);
    for (const auto& [name, definition] : kFunctions)
        if (!wordOffsets(stripped, name).empty() && !defines(stripped, name)) declared += std::string(definition) + " ";
    for (const Parameter& p : controls)
        if (p.syntax == Parameter::Syntax::Isf)
            declared += "uniform " + std::string(parameterTypeName(p.type)) + " " + p.name + "; ";
    // Before the first line of code (not a directive, not blank once comments are gone).
    const std::size_t found = firstCodeOffset(stripped), first = found < stripped.size() ? found : 0;
    // mainImage returns renderMain (declared ahead, defined where the text has it), on that line too.
    declared += "vec4 renderMain(); void mainImage(out vec4 synesthesiaColour, in vec2 synesthesiaPixel) { "
                "synesthesiaColour = renderMain(); } ";
    // An insertion before any replacement at that offset (applyEdits keeps the given order there).
    edits.insert(edits.begin(), {first, 0, declared});
    return applyEdits(text, std::move(edits));
}

} // namespace sdfwb::shaders::detail
