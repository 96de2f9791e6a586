// Other hosts' whole shaders in sdfwb's terms (ForeignHosts.h). Every edit stays on its line: a
// replacement may be longer or shorter than what it replaces, but no newline is added or removed.

#include "ForeignHosts.h"
#include "GlslDialects.h"
#include "IsfHeader.h"
#include "MadMapper.h"
#include "ParameterText.h"
#include "Synesthesia.h"
#include "TextEdits.h"
#include "TouchDesigner.h"
#include "Twigl.h"
#include "Words.h"

#include <core/Regex.h>
#include <shaders/SdfSource.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <map>
#include <optional>
#include <regex>
#include <set>

namespace sdfwb::shaders::detail {
namespace {

bool isSpaceChar(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\f' || c == '\v' || c == '\n'; }

// Spaces for text[offset, offset + length), newlines kept.
Edit blank(const std::string& text, std::size_t offset, std::size_t length) {
    std::string spaces = text.substr(offset, length);
    for (char& c : spaces)
        if (c != '\n') c = ' ';
    return {offset, length, std::move(spaces)};
}

// The comment-stripped text with the brace depth at each offset and its words.
struct Code {
    const std::string& original;
    std::string stripped;
    std::vector<int> depth; // brace depth before each character

    explicit Code(const std::string& text) : original(text), stripped(stripComments(text)), depth(stripped.size() + 1, 0) {
        int d = 0;
        for (std::size_t i = 0; i < stripped.size(); ++i) {
            depth[i] = d;
            if (stripped[i] == '{') ++d;
            if (stripped[i] == '}') d = std::max(0, d - 1);
        }
        depth[stripped.size()] = d;
    }

    std::size_t skipSpace(std::size_t i) const {
        while (i < stripped.size() && isSpaceChar(stripped[i])) ++i;
        return i;
    }
    std::string wordAt(std::size_t& i) const {
        const std::size_t start = i;
        while (i < stripped.size() && isWordCharacter(stripped[i])) ++i;
        return stripped.substr(start, i - start);
    }
    // Offsets of every whole-word `word` outside comments, optionally within [from, to).
    std::vector<std::size_t> occurrences(const std::string& word, std::size_t from = 0,
                                         std::size_t to = std::string::npos) const {
        return wordOffsets(stripped, word, from, to);
    }
    // The offset of the `}` closing the `{` at `open`, or npos.
    std::size_t closing(std::size_t open) const {
        for (std::size_t k = open + 1; k < stripped.size(); ++k)
            if (stripped[k] == '}' && depth[k] == depth[open] + 1) return k;
        return std::string::npos;
    }
    // Whether a preprocessor line starts at or before `at` on its line.
    bool inDirective(std::size_t at) const {
        std::size_t start = stripped.rfind('\n', at);
        start = start == std::string::npos ? 0 : start + 1;
        return stripped.find_first_not_of(" \t", start) < at && stripped[stripped.find_first_not_of(" \t", start)] == '#';
    }
};

// A file-scope declaration `[layout(...)] QUALIFIER [precision] TYPE NAME;` (one name, no
// initializer): where it starts and ends (after the `;`), its type and name.
struct Declaration {
    std::size_t begin = 0, end = 0;
    std::string qualifier, type, name;
    bool layout = false;
};

std::vector<Declaration> fileScopeDeclarations(const Code& code, const std::vector<std::string>& qualifiers) {
    std::vector<Declaration> out;
    for (const std::string& qualifier : qualifiers)
        for (std::size_t at : code.occurrences(qualifier)) {
            if (code.depth[at] != 0 || code.inDirective(at)) continue;
            Declaration d;
            d.qualifier = qualifier;
            d.begin = at;
            // A layout(...) before the qualifier belongs to the declaration.
            std::size_t before = at;
            while (before > 0 && isSpaceChar(code.stripped[before - 1])) --before;
            if (before > 0 && code.stripped[before - 1] == ')') {
                const std::size_t open = code.stripped.rfind('(', before - 1);
                if (open != std::string::npos && open >= 6) {
                    std::size_t word = open;
                    while (word > 0 && isSpaceChar(code.stripped[word - 1])) --word;
                    if (word >= 6 && code.stripped.compare(word - 6, 6, "layout") == 0 &&
                        (word == 6 || !isWordCharacter(code.stripped[word - 7]))) {
                        d.begin = word - 6;
                        d.layout = true;
                    }
                }
            }
            std::size_t k = code.skipSpace(at + qualifier.size());
            std::string type = code.wordAt(k);
            if (type == "lowp" || type == "mediump" || type == "highp") {
                k = code.skipSpace(k);
                type = code.wordAt(k);
            }
            k = code.skipSpace(k);
            const std::string name = code.wordAt(k);
            k = code.skipSpace(k);
            if (type.empty() || name.empty() || k >= code.stripped.size() || code.stripped[k] != ';') continue;
            d.type = type;
            d.name = name;
            d.end = k + 1;
            out.push_back(d);
        }
    std::sort(out.begin(), out.end(), [](const Declaration& a, const Declaration& b) { return a.begin < b.begin; });
    return out;
}

// A top-level definition `void NAME ( [void] ) {`: the offsets of NAME, of the parameter list's
// `(` and `)`, and of the body's braces; nullopt when there is none.
struct Definition {
    std::size_t name = 0, open = 0, close = 0, bodyOpen = 0, bodyClose = 0;
};
std::optional<Definition> voidFunction(const Code& code, const std::string& name, bool noParameters) {
    for (std::size_t at : code.occurrences(name)) {
        if (code.depth[at] != 0 || code.inDirective(at)) continue;
        std::size_t before = at;
        while (before > 0 && isSpaceChar(code.stripped[before - 1])) --before;
        if (before < 4 || code.stripped.compare(before - 4, 4, "void") != 0) continue;
        Definition d;
        d.name = at;
        d.open = code.skipSpace(at + name.size());
        if (d.open >= code.stripped.size() || code.stripped[d.open] != '(') continue;
        d.close = code.stripped.find(')', d.open);
        if (d.close == std::string::npos) continue;
        if (noParameters) {
            std::string inside = code.stripped.substr(d.open + 1, d.close - d.open - 1);
            inside.erase(std::remove_if(inside.begin(), inside.end(), isSpaceChar), inside.end());
            if (!inside.empty() && inside != "void") continue;
        }
        d.bodyOpen = code.skipSpace(d.close + 1);
        if (d.bodyOpen >= code.stripped.size() || code.stripped[d.bodyOpen] != '{') continue;
        d.bodyClose = code.closing(d.bodyOpen);
        if (d.bodyClose == std::string::npos) continue;
        return d;
    }
    return std::nullopt;
}

// A name not in the text, from `wanted` (then wanted_, wanted_2, ...).
std::string freshName(const Code& code, const std::string& wanted) {
    if (code.occurrences(wanted).empty()) return wanted;
    for (int n = 1;; ++n) {
        std::string name = wanted + "_" + (n == 1 ? std::string() : std::to_string(n));
        if (code.occurrences(name).empty()) return name;
    }
}

// Another host's inputs, declared by the file as uniforms: what sdfwb gives them (Shadertoy's).
struct HostInput {
    const char* name;
    const char* type;
    const char* value; // an expression of Shadertoy's inputs
    const char* host;
};
constexpr std::array<HostInput, 20> kHostInputs{{
    {"u_time", "float", "iTime", "glslViewer"},
    {"u_resolution", "vec2", "iResolution.xy", "glslViewer"},
    {"u_mouse", "vec2", "iMouse.xy", "glslViewer"},
    {"u_delta", "float", "iTimeDelta", "glslViewer"},
    {"u_date", "vec4", "iDate", "glslViewer"},
    {"u_frame", "int", "iFrame", "glslViewer"},
    {"fGlobalTime", "float", "iTime", "Bonzomatic"},
    {"v2Resolution", "vec2", "iResolution.xy", "Bonzomatic"},
    {"fFrameTime", "float", "iTimeDelta", "Bonzomatic"},
    {"time", "float", "iTime", "GLSL Sandbox"},
    {"resolution", "vec2", "iResolution.xy", "GLSL Sandbox"},
    {"mouse", "vec2", "(iMouse.xy / iResolution.xy)", "GLSL Sandbox"}, // normalised there
    {"frame", "int", "iFrame", "GLSL Sandbox"},
    {"iGlobalTime", "float", "iTime", "an old Shadertoy port"},
    {"surfacePosition", "vec2", "vec2(0.0)", "GLSL Sandbox"},
    {"surfaceSize", "vec2", "vec2(1.0)", "GLSL Sandbox"},
    {"uTime", "float", "iTime", "three.js"},
    {"uResolution", "vec2", "iResolution.xy", "three.js"},
    {"uMouse", "vec2", "iMouse.xy", "three.js"},
    {"iResolution", "vec2", "iResolution.xy", "a WebGL page"}, // Max/Jitter's, sokol's
}};

// Shadertoy's own inputs: a file's declaration of one goes, so sdfwb's (which it sets) is used.
bool shadertoyInput(const Declaration& d) {
    static const std::array<std::pair<const char*, const char*>, 8> inputs{{{"iTime", "float"},
                                                                            {"iResolution", "vec3"},
                                                                            {"iMouse", "vec4"},
                                                                            {"iFrame", "int"},
                                                                            {"iTimeDelta", "float"},
                                                                            {"iFrameRate", "float"},
                                                                            {"iDate", "vec4"},
                                                                            {"iSampleRate", "float"}}};
    for (const auto& [name, type] : inputs)
        if (d.name == name && d.type == type) return true;
    return d.name.size() == 9 && d.name.rfind("iChannel", 0) == 0 && d.name[8] >= '0' && d.name[8] <= '3' &&
           (d.type == "sampler2D" || d.type == "samplerCube");
}

// Fragmentarium's system includes, which come with the program and are not on disk here (named
// with or without their folder: "include/DE-Raytracer.frag").
bool fragmentariumSystemInclude(std::string name) {
    if (const std::size_t slash = name.find_last_of("/\\"); slash != std::string::npos) name = name.substr(slash + 1);
    static const std::array<const char*, 24> names{"DE-Raytracer.frag",
                                                   "DE-Raytracer-v0.9.1.frag",
                                                   "DE-Raytracer-v0.9.10.frag",
                                                   "Fast-Raytracer.frag",
                                                   "Fast-Raytracer-with-Textures.frag",
                                                   "DE-Kn2.frag",
                                                   "DE-Kn2cr11.frag",
                                                   "DE-Kn8.frag",
                                                   "Soft-Raytracer.frag",
                                                   "Brute-Raytracer.frag",
                                                   "IBL-Raytracer.frag",
                                                   "Path-Raytracer.frag",
                                                   "Sky-Pathtracer.frag",
                                                   "Classic-Raytracer.frag",
                                                   "Subblue-Raytracer.frag",
                                                   "DE-Raytracer-Slicer.frag",
                                                   "3D.frag",
                                                   "MathUtils.frag",
                                                   "matrix.frag",
                                                   "Progressive3D.frag",
                                                   "ZBuffer3D.frag",
                                                   "common-camera-3d.frag", // FragmentariumWeb's own three
                                                   "common-primitives.frag",
                                                   "common-fractal-utils.frag"};
    return std::find(names.begin(), names.end(), name) != names.end();
}

// What Fragmentarium's MathUtils.frag gives that fractal code calls: rotations by an angle in
// degrees, in its convention (its matrices turn by -angle about v, as they multiply row vectors).
constexpr std::array<std::pair<const char*, const char*>, 5> kMathUtils{{
    {"rotationMatrix3",
     "mat3 rotationMatrix3(vec3 v, float angle) { float c = cos(radians(angle)), s = sin(radians(angle)); return c * "
     "mat3(1.0) + (1.0 - c) * outerProduct(v, v) - s * mat3(0.0, v.z, -v.y, -v.z, 0.0, v.x, v.y, -v.x, 0.0); } "},
    {"rotationMatrixXYZ",
     "mat3 rotationMatrixXYZ(vec3 v) { return rotationMatrix3(vec3(1.0, 0.0, 0.0), v.x) * rotationMatrix3(vec3(0.0, "
     "1.0, 0.0), v.y) * rotationMatrix3(vec3(0.0, 0.0, 1.0), v.z); } "},
    {"rotationMatrix", "mat4 rotationMatrix(vec3 v, float angle) { return mat4(rotationMatrix3(v, angle)); } "},
    {"translate", "mat4 translate(vec3 v) { mat4 m = mat4(1.0); m[3] = vec4(v, 1.0); return m; } "},
    {"scale4", "mat4 scale4(float s) { return mat4(vec4(s, 0.0, 0.0, 0.0), vec4(0.0, s, 0.0, 0.0), vec4(0.0, 0.0, s, 0.0), "
               "vec4(0.0, 0.0, 0.0, 1.0)); } "},
}};

// What FragmentariumWeb's common-primitives.frag and common-fractal-utils.frag give: its
// rotationMatrix takes radians and an axis of any length and returns a mat3 (the turn of
// MathUtils.frag's, by -angle), and powN1 is a Mandelbulb step with its running derivative.
constexpr std::array<std::pair<const char*, const char*>, 5> kWebIncludes{{
    {"sdSphere", "float sdSphere(vec3 p, float r) { return length(p) - r; } "},
    {"sdBox",
     "float sdBox(vec3 p, vec3 b) { vec3 q = abs(p) - b; return length(max(q, 0.0)) + min(max(q.x, max(q.y, q.z)), 0.0); } "},
    {"sdRoundBox", "float sdRoundBox(vec3 p, vec3 b, float r) { vec3 q = abs(p) - b; "
                   "return length(max(q, 0.0)) + min(max(q.x, max(q.y, q.z)), 0.0) - r; } "},
    {"rotationMatrix",
     "mat3 rotationMatrix(vec3 axis, float angle) { vec3 v = normalize(axis); float c = cos(angle), s = sin(angle); "
     "return c * mat3(1.0) + (1.0 - c) * outerProduct(v, v) - s * mat3(0.0, v.z, -v.y, -v.z, 0.0, v.x, v.y, -v.x, 0.0); } "},
    {"powN1", "vec3 powN1(vec3 z, float power, inout float dr) { float r = length(z); float theta = acos(z.z / max(r, 1.0e-6)) "
              "* power, phi = atan(z.y, z.x) * power; dr = pow(r, power - 1.0) * power * dr + 1.0; "
              "return pow(r, power) * vec3(sin(theta) * cos(phi), sin(phi) * sin(theta), cos(theta)); } "},
}};

// DE-Raytracer.frag's colouring sliders, with its defaults (a vec4's alpha last).
struct RaytracerInput {
    const char* name;
    ParameterType type;
    std::array<float, 4> value;
};
const std::array<RaytracerInput, 9> kRaytracerInputs{{
    {"BaseColor", ParameterType::Vec3, {1.0f, 1.0f, 1.0f, 0.0f}},
    {"OrbitStrength", ParameterType::Float, {0.8f, 0.0f, 0.0f, 0.0f}},
    {"X", ParameterType::Vec4, {0.5f, 0.6f, 0.6f, 0.7f}},
    {"Y", ParameterType::Vec4, {1.0f, 0.6f, 0.0f, 0.4f}},
    {"Z", ParameterType::Vec4, {0.8f, 0.78f, 1.0f, 0.5f}},
    {"R", ParameterType::Vec4, {0.4f, 0.7f, 1.0f, 0.12f}},
    {"BackgroundColor", ParameterType::Vec3, {0.6f, 0.6f, 0.45f, 0.0f}},
    {"CycleColors", ParameterType::Bool, {0.0f, 0.0f, 0.0f, 0.0f}},
    {"Cycles", ParameterType::Float, {1.1f, 0.0f, 0.0f, 0.0f}},
}};

// The raytracer's colouring sliders that a fragment's own code reads (a DE mixing OrbitStrength
// in, a baseColor()), declared at the Default preset's value, else at the raytracer's default.
// `blocks`: the #preset and #vertex blocks, whose lines are not the file's declarations.
std::string raytracerInputs(const Code& code, const std::vector<std::pair<std::size_t, std::size_t>>& blocks) {
    const std::string& text = code.original;
    std::string provided;
    const std::vector<std::string> macros = definedMacros(code.stripped);
    const std::vector<detail::PresetLine> preset = detail::defaultPresetLines(text);
    for (const RaytracerInput& input : kRaytracerInputs) {
        const std::vector<std::size_t> uses = code.occurrences(input.name);
        if (uses.empty() || std::find(macros.begin(), macros.end(), input.name) != macros.end() ||
            std::any_of(uses.begin(), uses.end(), [&](std::size_t at) {
                return code.depth[at] == 0 && std::none_of(blocks.begin(), blocks.end(), [at](const auto& block) {
                           return at >= block.first && at < block.second;
                       });
            }))
            continue; // unused, a macro, or the file's own
        std::array<float, 4> value = input.value;
        const int n = componentCount(input.type);
        for (const detail::PresetLine& line : preset)
            if (line.name == input.name)
                if (auto given = detail::parseList(text.substr(line.valueOffset, line.valueLength));
                    given && int(given->size()) == n)
                    std::copy(given->begin(), given->end(), value.begin());
        provided += std::string("uniform ") + parameterTypeName(input.type) + " " + input.name + " = " +
                    glslLiteral(input.type, value) + "; ";
    }
    return provided;
}

// Orbit traps older system includes declared (`minDist2 = min(minDist2, r*r);` in a DE, with no
// declaration in the fragment): floats starting far away, declared once each.
std::string trapAccumulators(const Code& code) {
    static const std::regex smallest(R"(\b([A-Za-z_]\w*)\s*=\s*min\s*\(\s*([A-Za-z_]\w*)\s*,)", kLinearRegex);
    std::set<std::string> names;
    for (auto it = std::sregex_iterator(code.stripped.begin(), code.stripped.end(), smallest); it != std::sregex_iterator(); ++it)
        if ((*it)[1].str() == (*it)[2].str() && (*it)[1].str() != "orbitTrap") names.insert((*it)[1].str()); // a vec4, above
    std::string provided;
    for (const std::string& name : names) {
        // Declared by the fragment: a type, then the name before any ; { } ( or ) (`float r, minDist2;`).
        const std::regex declared(R"(\b(float|double|int|vec[234]|dvec[234])\b[^;{}()]*\b)" + name + R"(\b)", kLinearRegex);
        if (!std::regex_search(code.stripped, declared)) provided += "float " + name + " = 10000.0; ";
    }
    return provided;
}

// Fragmentarium: directives, annotations, system includes, init().
void adaptFragmentarium(const Code& code, const std::vector<Parameter>& parameters, std::vector<Edit>& edits,
                        HostAdaptation& out) {
    const std::string& text = code.original;
    bool fragmentarium = false;
    // Directive lines; #preset ... #endpreset and #vertex ... #endvertex blocks whole.
    static const std::array<const char*, 9> lineDirectives{
        "info", "group", "camera", "donotrun", "buffer", "buffershader", "TexParameter", "replace", "FragmentariumUpdate"};
    std::size_t blockStart = std::string::npos;
    std::string blockEnd;
    std::size_t firstInclude = std::string::npos;            // the edit blanking the first system include
    bool webIncludes = false;                                // FragmentariumWeb's primitives or fractal utilities
    std::vector<std::pair<std::size_t, std::size_t>> blocks; // #preset and #vertex blocks: not GLSL
    for (std::size_t start = 0; start < text.size();) {
        std::size_t stop = text.find('\n', start);
        if (stop == std::string::npos) stop = text.size();
        const std::size_t hash = code.stripped.find_first_not_of(" \t", start);
        if (hash < stop && code.stripped[hash] == '#') {
            std::size_t k = hash + 1;
            k = code.skipSpace(k) > stop ? stop : code.skipSpace(k);
            const std::string word = code.wordAt(k);
            if (blockStart == std::string::npos && (word == "preset" || word == "vertex")) {
                blockStart = start;
                blockEnd = "end" + word;
            } else if (blockStart != std::string::npos && word == blockEnd) {
                blocks.emplace_back(blockStart, stop);
                edits.push_back(blank(text, blockStart, stop - blockStart));
                blockStart = std::string::npos;
                fragmentarium = true;
            } else if (blockStart == std::string::npos &&
                       std::find(lineDirectives.begin(), lineDirectives.end(), word) != lineDirectives.end()) {
                edits.push_back(blank(text, hash, stop - hash));
                fragmentarium = true;
            } else if (blockStart == std::string::npos && word == "include") {
                const std::size_t open = text.find('"', k);
                const std::size_t close = open < stop ? text.find('"', open + 1) : std::string::npos;
                const std::string name = close < stop ? text.substr(open + 1, close - open - 1) : std::string();
                if (close < stop && fragmentariumSystemInclude(name)) {
                    webIncludes |= name.find("common-primitives") != std::string::npos ||
                                   name.find("common-fractal-utils") != std::string::npos;
                    if (firstInclude == std::string::npos) firstInclude = edits.size();
                    edits.push_back(blank(text, hash, stop - hash));
                    fragmentarium = true;
                }
            }
        }
        start = stop + 1;
    }
    if (blockStart != std::string::npos) edits.push_back(blank(text, blockStart, text.size() - blockStart)); // unclosed
    // Annotations after uniforms: blanked, the default written as the initializer.
    for (const Parameter& p : parameters) {
        if (p.syntax == Parameter::Syntax::Glsl || p.syntax == Parameter::Syntax::Isf) continue; // not its own
        fragmentarium = true;
        for (const Declaration& d : fileScopeDeclarations(code, {"uniform"})) {
            if (d.name != p.name) continue;
            const std::size_t lineEnd = std::min(text.find('\n', d.end), text.size());
            std::size_t k = code.skipSpace(d.end);
            const std::size_t close = text.find(']', k);
            if (close == std::string::npos || close > lineEnd) break;
            std::size_t after = close + 1;
            std::size_t word = code.skipSpace(after);
            std::size_t wordEnd = word;
            const std::string lock = word < lineEnd ? code.wordAt(wordEnd) : std::string();
            if (lock == "Locked" || lock == "NotLocked" || lock == "NotLockable") after = wordEnd;
            // `color[1,1,1];`: a semicolon after the annotation too.
            if (const std::size_t next = code.skipSpace(after); next < lineEnd && code.stripped[next] == ';') after = next + 1;
            edits.push_back({d.end - 1, 1, " = " + glslLiteral(p.type, p.defaultValue) + ";"});
            edits.push_back(blank(text, d.end, after - d.end));
            break;
        }
    }
    if (!fragmentarium) return;
    out.host = "Fragmentarium";
    // Fragmentarium calls init() once before tracing, where code computes globals from uniforms.
    if (voidFunction(code, "init", true)) out.entryPrelude = "init();";
    // What the system includes declare that the code uses, on the first include's line.
    if (firstInclude == std::string::npos) return;
    std::string provided;
    const std::vector<std::size_t> traps = code.occurrences("orbitTrap");
    if (!traps.empty() && std::none_of(traps.begin(), traps.end(), [&](std::size_t at) { return code.depth[at] == 0; }))
        provided += "vec4 orbitTrap = vec4(10000.0); ";
    provided += trapAccumulators(code);
    // Those the code calls and does not define, and rotationMatrix3, which the other rotations call.
    if (webIncludes)
        for (const auto& [name, definition] : kWebIncludes)
            if (!code.occurrences(name).empty() && !definesFunction(code.stripped, name)) provided += definition;
    for (const auto& [name, definition] : kMathUtils) {
        const std::string helper = name;
        if (webIncludes && helper == "rotationMatrix") continue; // the web one above
        const bool called = !code.occurrences(helper).empty() ||
                            (helper == "rotationMatrix3" &&
                             (!code.occurrences("rotationMatrixXYZ").empty() || !code.occurrences("rotationMatrix").empty()));
        if (called && !definesFunction(code.stripped, helper)) provided += definition;
    }
    // The historical matrix.frag's rotationMatrix returned a mat3 in some versions: where the code
    // keeps it in a mat3, that one.
    static const std::regex intoMat3(R"(\bmat3\s+\w+\s*=\s*rotationMatrix\s*\()", kLinearRegex);
    if (std::regex_search(code.stripped, intoMat3)) {
        const std::size_t at = provided.find("mat4 rotationMatrix(");
        if (at != std::string::npos)
            provided.replace(at, provided.find("} ", at) + 2 - at,
                             "mat3 rotationMatrix(vec3 v, float angle) { return rotationMatrix3(v, angle); } ");
    }
    provided += piWhereUsed(code.stripped); // MathUtils.frag's `#define PI`
    provided += raytracerInputs(code, blocks);
    // The system includes declare `uniform float time`: sdfwb's scene time.
    bool timeDeclared = false;
    for (const Declaration& d : fileScopeDeclarations(code, {"uniform"})) timeDeclared |= d.name == "time";
    if (!timeDeclared)
        for (std::size_t at : code.occurrences("time"))
            if (at == 0 || code.stripped[at - 1] != '.') edits.push_back({at, 4, "iTime"});
    edits[firstInclude].replacement = provided + edits[firstInclude].replacement;
}

// The depth a host's main writes (raylib's hybrid example writes gl_FragDepth): a global of its
// own, declared before the `void` of the main whose name is at `mainName`, as a compute stage has none.
void writtenDepth(const Code& code, std::size_t mainName, std::vector<Edit>& edits) {
    const std::vector<std::size_t> depths = code.occurrences("gl_FragDepth");
    if (depths.empty()) return;
    const std::string depth = freshName(code, "fragDepth");
    std::size_t start = mainName;
    while (start > 0 && isSpaceChar(code.stripped[start - 1])) --start;
    edits.push_back({start >= 4 ? start - 4 : 0, 0, "float " + depth + "; "});
    for (std::size_t at : depths) edits.push_back({at, 12, depth});
}

// A host's `void main()`: Shadertoy's mainImage.
void adaptMain(const Code& code, std::vector<Edit>& edits, HostAdaptation& out) {
    const std::string& text = code.original;
    auto main = voidFunction(code, "main", true);
    if (!main) return;
    const bool hasMainImage = !code.occurrences("mainImage").empty() && voidFunction(code, "mainImage", false).has_value();
    // A fragment shader's main writes a colour: gl_FragColor, or the file's `out vec4`. Any other
    // main() is not a host's (SourceChecks says the workbench writes main).
    // Through a macro too (`#define O gl_FragColor`, golfed and preview-extension code).
    const std::vector<std::size_t> colourWrites = code.occurrences("gl_FragColor");
    bool writesColour = std::any_of(colourWrites.begin(), colourWrites.end(), [&](std::size_t at) {
        return (at > main->bodyOpen && at < main->bodyClose) || code.inDirective(at);
    });
    for (const Declaration& d : fileScopeDeclarations(code, {"out"})) writesColour |= d.type == "vec4";
    if (!writesColour) return;
    // three.js's shader chunks (`#include <common>`, `#include <tonemapping_fragment>`), which its
    // renderer splices in: colour management and helpers, nothing a field needs.
    bool threeChunks = false;
    for (std::size_t start = 0; start < text.size();) {
        std::size_t stop = std::min(text.find('\n', start), text.size());
        const std::size_t hash = code.stripped.find_first_not_of(" \t", start);
        if (hash < stop && code.stripped[hash] == '#') {
            std::size_t k = code.stripped.find_first_not_of(" \t", hash + 1);
            if (k < stop && code.wordAt(k) == "include") {
                k = code.stripped.find_first_not_of(" \t", k);
                if (k < stop && code.stripped[k] == '<') {
                    edits.push_back(blank(text, hash, stop - hash));
                    threeChunks = true;
                }
            }
        }
        start = stop + 1;
    }
    std::string host = "a WebGL page";
    if (threeChunks) host = "three.js";
    const std::vector<Declaration> uniforms = fileScopeDeclarations(code, {"uniform"});
    // Inputs: the host's become Shadertoy's; the file's own Shadertoy inputs go.
    std::vector<std::pair<std::string, std::string>> renames;
    for (const Declaration& d : uniforms) {
        if (shadertoyInput(d)) {
            edits.push_back(blank(text, d.begin, d.end - d.begin));
            continue;
        }
        for (const HostInput& input : kHostInputs)
            if (d.name == input.name && d.type == input.type) {
                edits.push_back(blank(text, d.begin, d.end - d.begin));
                renames.emplace_back(input.name, input.value);
                if (host == "a WebGL page") host = input.host;
            }
        const int unit = emptyUnit(d.type);
        if (unit >= 0 && !d.layout && !shadertoyInput(d))
            edits.push_back({d.begin, 0, "layout(binding = " + std::to_string(unit) + ") "});
    }
    // A layer that copies the host's inputs into Shadertoy's names at file scope (Processing's
    // `vec3 iResolution = vec3(resolution, 0.0);`): sdfwb declares and sets those.
    // A vec2 frame size (RetroArch's `vec2 iResolution = OutputSize.xy;`) is sdfwb's `.xy`.
    static const std::regex layer(R"(\b(?:vec([23])\s+iResolution|vec4\s+iMouse|float\s+iTime)\s*=[^;{}]*;)", kLinearRegex);
    for (auto it = std::sregex_iterator(code.stripped.begin(), code.stripped.end(), layer); it != std::sregex_iterator(); ++it)
        if (const std::size_t at = std::size_t(it->position(0)); code.depth[at] == 0) {
            edits.push_back(blank(text, at, std::size_t(it->length(0))));
            if ((*it)[1].str() == "2") renames.emplace_back("iResolution", "iResolution.xy");
        }
    for (const auto& [name, value] : renames)
        for (std::size_t at : code.occurrences(name)) // macros' bodies too
            if (at == 0 || code.stripped[at - 1] != '.') edits.push_back({at, name.size(), value});
    // Varyings and inputs: plain globals (zero), as a compute stage has none; an input block
    // (KodeLife's `in VertexData { ... } inData;`) a struct and a global of it.
    for (std::size_t at : code.occurrences("in")) {
        if (code.depth[at] != 0 || code.inDirective(at)) continue;
        std::size_t k = code.skipSpace(at + 2);
        if (code.wordAt(k).empty()) continue;
        k = code.skipSpace(k);
        if (k < code.stripped.size() && code.stripped[k] == '{') {
            edits.push_back({at, 2, "struct"});
            host = "KodeLife"; // its template's VertexData block
        }
    }
    // A full-screen quad's texture coordinate (three.js's vUv, glslViewer's v_texcoord, ...) is the
    // pixel's position over the frame: in main, mainImage's coordinate over iResolution.
    const std::string coordinate = freshName(code, "fragCoord");
    static const std::array<const char*, 6> quadCoordinates{"vUv", "v_texcoord", "vTexCoord", "v_uv", "vUV", "out_texcoord"};
    std::string colour;
    for (const Declaration& d : fileScopeDeclarations(code, {"varying", "in", "out"})) {
        if (d.qualifier == "out" && d.type == "vec4" && colour.empty()) {
            colour = d.name;
            edits.push_back(blank(text, d.begin, d.end - d.begin));
        } else if (d.qualifier != "out" && d.type == "vec2" &&
                   std::find(quadCoordinates.begin(), quadCoordinates.end(), d.name) != quadCoordinates.end()) {
            edits.push_back(blank(text, d.begin, d.end - d.begin));
            for (std::size_t at : code.occurrences(d.name))
                if (at != code.stripped.find(d.name, d.begin))
                    edits.push_back({at, d.name.size(),
                                     at > main->bodyOpen && at < main->bodyClose ? "(" + coordinate + " / iResolution.xy)"
                                                                                 : "(gl_FragCoord.xy / iResolution.xy)"});
        } else if (d.qualifier != "out") {
            edits.push_back(blank(text, d.begin, d.qualifier.size() + (code.stripped.find(d.qualifier, d.begin) - d.begin)));
        }
    }
    if (hasMainImage) { // a port's wrapper: mainImage is the shader
        std::size_t start = main->name;
        while (start > 0 && isSpaceChar(code.stripped[start - 1])) --start;
        edits.push_back(blank(text, start - 4, main->bodyClose + 1 - (start - 4))); // from its `void`
        out.host = host == "a WebGL page" ? "a Shadertoy port" : host;
        return;
    }
    writtenDepth(code, main->name, edits);
    if (colour.empty()) colour = freshName(code, "fragColor");
    edits.push_back({main->name, main->close + 1 - main->name, "mainImage(out vec4 " + colour + ", in vec2 " + coordinate + ")"});
    for (std::size_t at : code.occurrences("gl_FragColor")) edits.push_back({at, 12, colour});
    for (std::size_t at : code.occurrences("gl_FragCoord"))
        if ((at > main->bodyOpen && at < main->bodyClose) || code.inDirective(at)) // `#define U gl_FragCoord.xy`
            edits.push_back({at, 12, "vec4(" + coordinate + ", 0.0, 1.0)"});
    out.host = host;
}

// An ISF shader (VDMX, Resolume, Millumin, editor.isf.video), after adaptMain has made its main()
// mainImage: its header's INPUTS declared as uniforms after the header, on its last line (values
// are parameters, Parameters.cpp; images and audio samplers on the empty unit), and its built-ins in
// Shadertoy's terms.
void adaptIsf(const Code& code, std::vector<Edit>& edits, HostAdaptation& out) {
    const IsfHeader header = readIsfHeader(code.original);
    if (!header.found || out.host.empty()) return;
    static const std::map<std::string, std::string> types{
        {"float", "float"}, {"long", "int"},     {"int", "int"},         {"bool", "bool"},       {"event", "bool"},
        {"color", "vec4"},  {"point2D", "vec2"}, {"image", "sampler2D"}, {"audio", "sampler2D"}, {"audioFFT", "sampler2D"}};
    std::string declared;
    for (const IsfInput& input : header.inputs)
        if (auto type = types.find(input.type); type != types.end())
            declared += (type->second == "sampler2D" ? "layout(binding = " + std::to_string(emptyUnit("sampler2D")) + ") " : "") +
                        "uniform " + type->second + " " + input.name + "; ";
    static const std::array<std::pair<const char*, const char*>, 12> builtins{{
        {"TIME", "iTime"},
        {"TIMEDELTA", "iTimeDelta"},
        {"RENDERSIZE", "iResolution.xy"},
        {"FRAMEINDEX", "iFrame"},
        {"DATE", "iDate"},
        {"PASSINDEX", "0"},
        {"isf_FragNormCoord", "(gl_FragCoord.xy / iResolution.xy)"},
        {"IMG_NORM_PIXEL", "texture"},
        {"IMG_THIS_NORM_PIXEL", "sdfwb_isfThisPixel"},
        {"IMG_THIS_PIXEL", "sdfwb_isfThisPixel"},
        {"IMG_PIXEL", "sdfwb_isfPixel"},
        {"IMG_SIZE", "sdfwb_isfSize"},
    }};
    bool images = false;
    for (const auto& [name, value] : builtins)
        for (std::size_t at : code.occurrences(name))
            if (at == 0 || code.stripped[at - 1] != '.') {
                edits.push_back({at, std::char_traits<char>::length(name), value});
                images = images || std::string(value).rfind("sdfwb_isf", 0) == 0;
            }
    if (images)
        declared += "vec4 sdfwb_isfPixel(sampler2D s, vec2 c) { return texture(s, c / vec2(textureSize(s, 0))); } "
                    "vec4 sdfwb_isfThisPixel(sampler2D s) { return texture(s, gl_FragCoord.xy / iResolution.xy); } "
                    "vec2 sdfwb_isfSize(sampler2D s) { return vec2(textureSize(s, 0)); } ";
    if (!declared.empty()) edits.push_back({header.end, 0, " " + declared});
    if (out.host != "MadMapper") out.host = "ISF";
}

// Shadertoy named its time iGlobalTime until 2017: shaders downloaded then (and sites that mirror
// them) use it undeclared, or declare it as the ports of then did. It is iTime.
void adaptOldShadertoy(const Code& code, std::vector<Edit>& edits, HostAdaptation& out) {
    if (!out.host.empty() || code.occurrences("mainImage").empty()) return;
    bool renamed = false;
    for (const Declaration& d : fileScopeDeclarations(code, {"uniform"}))
        if (d.name == "iGlobalTime") edits.push_back(blank(code.original, d.begin, d.end - d.begin));
    for (std::size_t at : code.occurrences("iGlobalTime"))
        if (at == 0 || code.stripped[at - 1] != '.') {
            edits.push_back({at, 11, "iTime"});
            renamed = true;
        }
    if (renamed) out.host = "an old Shadertoy shader";
}

// Where declarations for a directive inside a function at `at` go (the VS Code extension hoists its
// uniforms): before that function, after the `;` or `}` that ends what comes before it at file
// scope, else at the first line that is not a directive.
std::size_t fileScopeBefore(const Code& code, std::size_t at) {
    for (std::size_t p = at; p-- > 0;)
        if ((code.stripped[p] == ';' || code.stripped[p] == '}') && code.depth[p + 1] == 0 && !code.inDirective(p)) return p + 1;
    for (std::size_t start = 0; start < at;) {
        const std::size_t first = code.stripped.find_first_not_of(" \t\r\n", start);
        if (first >= at || code.stripped[first] != '#') return first >= at ? at : first;
        start = std::min(code.stripped.find('\n', first), code.stripped.size());
    }
    return at;
}

// The VS Code Shader Toy extension (stevensona.shader-toy): its directives blanked (`#iChannel0
// "file://..."` and its `::` settings, iChannel4-9 declared on the empty unit, #iKeyboard,
// #iFirstPersonControls, #StrictCompatibility, #iVertex) and its `#iUniform TYPE NAME = VALUE in {MIN, MAX}` declared as uniforms
// (parameters, Parameters.cpp); #iKeyboard's functions answer no key, iViewMatrix (its fly camera) is the identity it starts as,
// and its iGlobalTime is iTime.
void adaptVscodeShaderToy(const Code& code, std::vector<Edit>& edits, HostAdaptation& out) {
    const std::string& text = code.original;
    std::map<std::size_t, std::string> declared; // at an offset, declarations
    std::size_t firstPlace = std::string::npos;
    bool keyboard = false;
    std::set<std::string> extraChannels;
    for (std::size_t start = 0; start < code.stripped.size();) {
        const std::size_t stop = std::min(code.stripped.find('\n', start), code.stripped.size());
        const std::size_t hash = code.stripped.find_first_not_of(" \t", start);
        if (hash < stop && code.stripped[hash] == '#') {
            std::size_t k = code.skipSpace(hash + 1);
            const std::string word = code.wordAt(k);
            const bool channel = word.rfind("iChannel", 0) == 0 && word.size() > 8 &&
                                 std::all_of(word.begin() + 8, word.end(), [](char c) { return c >= '0' && c <= '9'; });
            if (channel && word.size() == 9 && word[8] >= '4') extraChannels.insert(word);
            if (channel || word == "iKeyboard" || word == "iFirstPersonControls" || word == "StrictCompatibility" ||
                word == "iVertex" || word == "iUniform") {
                // After the blanked line at file scope (an insertion at its start would be dropped).
                const std::size_t place = code.depth[hash] == 0 ? stop : fileScopeBefore(code, hash);
                firstPlace = std::min(firstPlace, place);
                edits.push_back(blank(text, hash, stop - hash));
                keyboard = keyboard || word == "iKeyboard";
                k = code.skipSpace(k);
                std::string type = code.wordAt(k);
                k = code.skipSpace(k);
                const std::string name = code.wordAt(k);
                if (type == "color3") type = "vec3";
                if (type == "color4") type = "vec4";
                if (word == "iUniform" && !name.empty() && !type.empty())
                    declared[place] += "uniform " + type + " " + name + "; ";
            }
        }
        start = stop + 1;
    }
    if (firstPlace == std::string::npos) return;
    std::string provided;
    if (keyboard) {
        provided += "bool isKeyPressed(int k) { return false; } bool isKeyReleased(int k) { return false; } "
                    "bool isKeyDown(int k) { return false; } bool isKeyToggled(int k) { return false; } ";
        std::set<std::string> keys;
        forEachIdentifier(code.stripped, [&](std::size_t at, std::size_t end) {
            const std::string word = code.stripped.substr(at, end - at);
            if (word.rfind("Key_", 0) == 0 && word.size() > 4 && keys.insert(word).second) {
                static const std::map<std::string, int> named{
                    {"Backspace", 8}, {"Tab", 9},    {"Enter", 13},     {"Shift", 16},   {"Ctrl", 17},       {"Alt", 18},
                    {"Escape", 27},   {"Space", 32}, {"LeftArrow", 37}, {"UpArrow", 38}, {"RightArrow", 39}, {"DownArrow", 40}};
                const std::string key = word.substr(4);
                const int value = key.size() == 1 ? int(std::toupper(static_cast<unsigned char>(key[0])))
                                                  : (named.count(key) ? named.at(key) : 0);
                provided += "const int " + word + " = " + std::to_string(value) + "; ";
            }
            return true;
        });
    }
    // Channels past Shadertoy's four (the extension has iChannel0-9): a unit nothing is bound to.
    for (const Declaration& d : fileScopeDeclarations(code, {"uniform"})) extraChannels.erase(d.name);
    for (const std::string& channel : extraChannels)
        provided += "layout(binding = " + std::to_string(emptyUnit("sampler2D")) + ") uniform sampler2D " + channel + "; ";
    bool viewMatrixDeclared = false;
    for (const Declaration& d : fileScopeDeclarations(code, {"uniform"})) viewMatrixDeclared |= d.name == "iViewMatrix";
    if (!viewMatrixDeclared && !code.occurrences("iViewMatrix").empty()) provided += "const mat4 iViewMatrix = mat4(1.0); ";
    if (!code.occurrences("iMouseButton").empty()) provided += "const vec2 iMouseButton = vec2(0.0); ";
    if (!provided.empty()) declared[firstPlace] += provided;
    for (const auto& [at, text] : declared) edits.push_back({at, 0, text});
    for (std::size_t at : code.occurrences("iGlobalTime"))
        if (at == 0 || code.stripped[at - 1] != '.') edits.push_back({at, 11, "iTime"});
    out.host = "the VS Code Shader Toy extension";
}

} // namespace

HostAdaptation adaptForeignHost(const std::string& original, const std::vector<Parameter>& parameters) {
    HostAdaptation out;
    const DialectText dialect = readGlslDialect(original);
    const std::string& text = dialect.text.empty() ? original : dialect.text;
    const Code code(text);
    std::vector<Edit> edits;
    adaptFragmentarium(code, parameters, edits, out);
    adaptMain(code, edits, out);
    if (out.host.empty())
        if (std::vector<Edit> material = madMapperEdits(text, code.stripped); !material.empty()) {
            edits.insert(edits.end(), material.begin(), material.end());
            out.host = "MadMapper";
        }
    if (!out.host.empty())
        if (std::vector<Edit> touch = touchDesignerEdits(code.stripped); !touch.empty()) {
            edits.insert(edits.begin(), touch.begin(), touch.end()); // its insertion before a blanked uniform there
            out.host = "TouchDesigner";
        }
    adaptIsf(code, edits, out);
    adaptVscodeShaderToy(code, edits, out);
    adaptOldShadertoy(code, edits, out);
    if (out.host.empty() && edits.empty())
        if (std::optional<std::string> synesthesia = adaptSynesthesia(text, parameters)) {
            out.text = std::move(*synesthesia);
            out.host = "Synesthesia";
            return out;
        }
    if (out.host.empty() && edits.empty())
        if (std::optional<std::string> twigl = adaptTwigl(text)) {
            out.text = std::move(*twigl);
            out.host = "twigl";
            return out;
        }
    out.text = edits.empty() ? text : applyEdits(text, std::move(edits));
    if (!out.host.empty() && !dialect.dialect.empty()) out.host = dialect.dialect;
    return out;
}

} // namespace sdfwb::shaders::detail
