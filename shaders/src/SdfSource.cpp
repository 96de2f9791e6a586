#include <shaders/SdfSource.h>

#include <shaders/GlslChecker.h>
#include <shaders/MarchAnalysis.h>
#include <shaders/ShaderComposer.h>

#include <core/Regex.h>
#include <core/TextFile.h>
#include <shaders/SourceChecks.h>

#include "ForeignHosts.h"
#include "MarchEntry.h"
#include "Words.h"

#include <algorithm>
#include <cctype>
#include <cstring>
#include <iterator>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <regex>
#include <set>
#include <string_view>

namespace sdfwb::shaders {
namespace {

// The regex for `pattern`, compiled the first time it is asked for and kept for the process (the
// patterns are made from names: preparing an SDF asks for some on every job and mesh call, and
// compiling them each time cost more than the searches). The cache grows by one per new name.
const std::regex& compiledOnce(const std::string& pattern) {
    static std::mutex mutex;
    static std::map<std::string, std::unique_ptr<const std::regex>> compiled;
    std::lock_guard lock(mutex);
    std::unique_ptr<const std::regex>& slot = compiled[pattern];
    if (!slot) slot = std::make_unique<const std::regex>(pattern, kLinearRegex);
    return *slot;
}

// What `\s` matches.
bool isBlank(char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\v' || c == '\f' || c == '\r'; }

// A regex match that starts exactly at `at`, seeing the character before it for `\b`.
bool matchAt(const std::string& text, std::size_t at, const std::regex& pattern, std::smatch& match) {
    auto flags = std::regex_constants::match_continuous;
    if (at > 0) flags |= std::regex_constants::match_prev_avail;
    return std::regex_search(text.begin() + std::ptrdiff_t(at), text.end(), match, pattern, flags);
}

// Shrunk and golfed code names its types through macros (GLSL Shader Shrinker's `#define v3 vec3`,
// `#define _f float`). The text analyses that read a definition's types (the entry's signature, the
// march's field, mainImage's form) read `stripped` with those names expanded. Directive lines are
// kept as they are; every line keeps its number (only its columns move).
std::string expandTypeAliases(const std::string& stripped) {
    static const std::regex builtinType(R"((?:float|double|int|uint|bool|[biud]?vec[234]|d?mat[234](?:x[234])?))", kLinearRegex);
    std::map<std::string, std::string, std::less<>> aliases;
    for (const MacroDirective& d : macroDirectives(stripped)) {
        if (d.undefine) continue;
        const std::size_t nameEnd = d.offset + d.name.size();
        const std::size_t lineEnd = std::min(stripped.find('\n', nameEnd), stripped.size());
        if (nameEnd < lineEnd && stripped[nameEnd] == '(') continue; // a function-like macro
        const std::size_t body = stripped.find_first_not_of(" \t", nameEnd);
        if (body >= lineEnd) continue;
        std::size_t bodyEnd = stripped.find_last_not_of(" \t\r", lineEnd - 1) + 1;
        const std::string type = stripped.substr(body, bodyEnd - body);
        if (std::regex_match(type, builtinType)) aliases.emplace(d.name, type);
    }
    if (aliases.empty()) return stripped;
    std::string out;
    out.reserve(stripped.size() + stripped.size() / 8);
    std::size_t copied = 0;
    for (std::size_t lineStart = 0; lineStart < stripped.size();) {
        const std::size_t lineEnd = std::min(stripped.find('\n', lineStart), stripped.size());
        const std::size_t first = stripped.find_first_not_of(" \t", lineStart);
        for (std::size_t at = lineStart; at < lineEnd && !(first < lineEnd && stripped[first] == '#');) {
            std::size_t end = at;
            while (end < lineEnd && isWordCharacter(stripped[end])) ++end;
            if (end == at) {
                ++at;
                continue;
            }
            if (auto alias = aliases.find(std::string_view(stripped).substr(at, end - at)); alias != aliases.end()) {
                out.append(stripped, copied, at - copied);
                out += alias->second;
                copied = end;
            }
            at = end;
        }
        lineStart = lineEnd + 1;
    }
    out.append(stripped, copied, std::string::npos);
    return out;
}

} // namespace

bool isWordCharacter(char c) { return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_'; }

bool mentions(const std::string& text, const std::string& name) {
    bool found = false;
    detail::forEachOccurrence(text, name, [&](std::size_t) { return !(found = true); });
    return found;
}

std::string stripComments(const std::string& text) {
    std::string out = text;
    enum class State { Code, Line, Block } state = State::Code;
    for (std::size_t i = 0; i < out.size(); ++i) {
        char c = out[i];
        char next = i + 1 < out.size() ? out[i + 1] : '\0';
        switch (state) {
        case State::Code:
            if (c == '/' && next == '/') {
                state = State::Line;
                out[i] = ' ';
            } else if (c == '/' && next == '*') {
                state = State::Block;
                out[i] = ' ';
                out[++i] = ' ';
            }
            break;
        case State::Line:
            if (c == '\n')
                state = State::Code;
            else
                out[i] = ' ';
            break;
        case State::Block:
            if (c == '*' && next == '/') {
                out[i] = ' ';
                out[++i] = ' ';
                state = State::Code;
            } else if (c != '\n')
                out[i] = ' ';
            break;
        }
    }
    return out;
}

namespace {

bool isIdentifier(const std::string& name) {
    if (name.empty() || (name[0] >= '0' && name[0] <= '9')) return false;
    return std::all_of(name.begin(), name.end(), isWordCharacter);
}

// Start of the word that ends right before the blanks in front of `at`, or npos.
std::size_t previousWord(const std::string& text, std::size_t at) {
    std::size_t end = at;
    while (end > 0 && isBlank(text[end - 1])) --end;
    if (end == at || end == 0 || !isWordCharacter(text[end - 1])) return std::string::npos;
    std::size_t start = end;
    while (start > 0 && isWordCharacter(text[start - 1])) --start;
    return start;
}

// The first `float` member of `struct NAME { ... }` in the text: a struct an entry returns holds
// its distance there (`struct Hit { float d; int id; }`). Empty when there is none.
std::string firstFloatMember(const std::string& stripped, const std::string& name) {
    if (!isIdentifier(name)) return {};
    const std::regex& definition = compiledOnce(R"(\bstruct\s+)" + name + R"(\s*\{([^}]*)\})");
    std::smatch match;
    if (!std::regex_search(stripped, match, definition)) return {};
    static const std::regex member(R"((?:^|[;{\s])(?:highp\s+|mediump\s+|lowp\s+)?float\s+(\w+)\s*[;,])", kLinearRegex);
    const std::string body = match[1].str();
    std::smatch found;
    return std::regex_search(body, found, member) ? found[1].str() : std::string();
}

} // namespace

namespace {

SdfSignature detectSignatureOf(const std::string& stripped, const std::string& entry, const std::string& returnTypes,
                               std::optional<bool> form) {
    SdfSignature signature;
    signature.entry = entry;
    if (!isIdentifier(entry)) return signature;
    // A definition (with a body), not a prototype. vec3 synonyms of the G3D dialect count.
    const std::regex& definition =
        compiledOnce(R"(\b()" + returnTypes + R"()\s+)" + entry +
                     R"(\s*\(\s*((?:in\s+|out\s+|inout\s+|const\s+|highp\s+|mediump\s+)*)(vec3|Point3|Vector3|float3)\s+\w+\s*)"
                     R"((,\s*((?:in\s+|const\s+|highp\s+)*)float\s+\w+\s*)?)"
                     R"(((?:,\s*(?:out|inout)\s+(?:highp\s+|mediump\s+|lowp\s+)?\w+\s+\w+\s*)*)\)\s*\{)");
    // Tried only at the word before each occurrence of the name: searching from every position of
    // a long text was the slow part of preparing one (1.8 s for 10 MB).
    std::smatch match;
    for (std::size_t at : detail::wordOffsets(stripped, entry)) {
        std::size_t type = previousWord(stripped, at);
        if (type == std::string::npos || !matchAt(stripped, type, definition, match)) continue;
        if (form && *form != match[4].matched) continue; // the other overload
        const std::string returned = match[1].str();
        std::string member;
        if (returned != "float" && returned != "vec2" && returned != "vec3" && returned != "vec4") {
            member = firstFloatMember(stripped, returned); // a struct: its distance member
            if (member.empty()) continue;
        }
        signature.found = true;
        signature.returnType = returned;
        signature.member = member;
        if (match[4].matched) signature.animated = true;
        static const std::regex outPoint(R"(\bout\b)", kLinearRegex);
        signature.pointOut = std::regex_search(match[2].str(), outPoint);
        // Out parameters after the point (`out float id`, `out Material m`): the wrapper passes
        // locals of their types and drops what they receive.
        signature.outParameters.clear();
        static const std::regex outParameter(R"(,\s*(?:out|inout)\s+(?:highp\s+|mediump\s+|lowp\s+)?(\w+)\s+\w+)", kLinearRegex);
        const std::string outs = match[6].str();
        for (auto it = std::sregex_iterator(outs.begin(), outs.end(), outParameter); it != std::sregex_iterator(); ++it)
            signature.outParameters.push_back((*it)[1].str());
    }
    return signature;
}

} // namespace

SdfSignature detectSignature(const std::string& stripped, const std::string& entry, const std::string& returnTypes) {
    return detectSignatureOf(stripped, entry, returnTypes, std::nullopt);
}

SdfSignature detail::detectSignatureOfForm(const std::string& stripped, const std::string& entry, const std::string& returnTypes,
                                           bool animated) {
    return detectSignatureOf(stripped, entry, returnTypes, animated);
}

std::string metadataEntry(const std::string& text) {
    std::size_t start = text.find_first_not_of(" \t\r\n");
    if (start == std::string::npos || text.compare(start, 8, "/* sdfwb") != 0) return {};
    std::size_t end = text.find("*/", start);
    if (end == std::string::npos) return {};
    static const std::regex line(R"((?:^|\n)[ \t]*entry[ \t]*:[ \t]*(\w+)[ \t]*\r?(?=\n|$))", kLinearRegex);
    const std::string block = text.substr(start, end - start);
    std::smatch match;
    return std::regex_search(block, match, line) ? match[1].str() : std::string();
}

const std::vector<std::string>& conventionalEntries() {
    static const std::vector<std::string> names = {"map", "scene", "sceneSDF", "sdScene", "de", "DE"};
    return names;
}

std::vector<MacroDirective> macroDirectives(const std::string& stripped) {
    std::vector<MacroDirective> found;
    for (std::size_t lineStart = 0; lineStart < stripped.size();) {
        std::size_t lineEnd = stripped.find('\n', lineStart);
        if (lineEnd == std::string::npos) lineEnd = stripped.size();
        std::size_t i = lineStart;
        while (i < lineEnd && (stripped[i] == ' ' || stripped[i] == '\t')) ++i;
        if (i < lineEnd && stripped[i] == '#') {
            ++i;
            while (i < lineEnd && (stripped[i] == ' ' || stripped[i] == '\t')) ++i;
            std::size_t wordEnd = i;
            while (wordEnd < lineEnd && isWordCharacter(stripped[wordEnd])) ++wordEnd;
            const std::string_view directive(stripped.data() + i, wordEnd - i);
            if (directive == "define" || directive == "undef") {
                std::size_t name = wordEnd;
                while (name < lineEnd && (stripped[name] == ' ' || stripped[name] == '\t')) ++name;
                std::size_t nameEnd = name;
                while (nameEnd < lineEnd && isWordCharacter(stripped[nameEnd])) ++nameEnd;
                std::string word = stripped.substr(name, nameEnd - name);
                if (name > wordEnd && isIdentifier(word)) found.push_back({std::move(word), name, directive == "undef"});
            }
        }
        lineStart = lineEnd + 1;
    }
    return found;
}

std::vector<std::string> definedMacros(const std::string& stripped) {
    std::vector<std::string> names;
    std::set<std::string, std::less<>> seen;
    for (MacroDirective& d : macroDirectives(stripped))
        if (!d.undefine && seen.insert(d.name).second) names.push_back(std::move(d.name));
    return names;
}

std::vector<std::string> functionSignatures(const std::string& text) {
    static const std::regex definition(
        R"(\b(?:float|vec[234]|ivec[234]|int|uint|bool|mat[234]|void|Point3|Vector3|Color3|float[234])\s+(\w+)\s*\(([^)]*)\)\s*\{)",
        kLinearRegex);
    static const std::regex whitespace(R"(\s+)", kLinearRegex);
    std::string stripped = stripComments(text);
    std::vector<std::string> signatures;
    for (auto it = std::sregex_iterator(stripped.begin(), stripped.end(), definition); it != std::sregex_iterator(); ++it) {
        std::string parameters = std::regex_replace((*it)[2].str(), whitespace, " ");
        signatures.push_back((*it)[1].str() + "(" + parameters + ")");
    }
    return signatures;
}

bool CompatNeeds::usesTimeSymbol() const {
    return std::find_if(symbols.begin(), symbols.end(),
                        [](const std::string& s) { return s == "g3d_SceneTime" || s == "iTime"; }) != symbols.end();
}

bool CompatNeeds::usesShadertoyChannel() const {
    return std::find_if(symbols.begin(), symbols.end(), [](const std::string& s) { return s.rfind("iChannel", 0) == 0; }) !=
           symbols.end();
}

const std::vector<std::string>& compatCandidates() {
    static const std::vector<std::string> names = {
        // The original sdf-explorer's G3D dialect.
        "pi", "saturate", "lerp", "square", "frac", "lengthSquared", "Point3", "Vector3", "Color3", "Radiance3", "float2",
        "float3", "float4", "g3d_SceneTime", "g3d_uniformRandom",
        // Shadertoy's inputs, which its code uses without declaring them.
        "iTime", "iResolution", "iTimeDelta", "iFrame", "iFrameRate", "iMouse", "iDate", "iSampleRate", "iChannel0", "iChannel1",
        "iChannel2", "iChannel3", "iChannelTime", "iChannelResolution", "HW_PERFORMANCE",
        // GLSL ES 1.0 idioms that core GLSL lacks.
        "texture2D", "texture2DLod", "textureCube", "textureCubeLod",
        // Derivatives exist in fragment shaders only; elsewhere (the sampler's compute stage) the
        // composer maps them onto zero (a Shadertoy's mainImage uses them, and it is never called).
        "dFdx", "dFdy", "fwidth",
        // Fragment-only too, in the helpers mainImage calls: the pixel's position (a dither's or a
        // jitter's seed; zero elsewhere), texture()'s bias form (the level-0 lookup elsewhere) and
        // discard (mainImage's own, `if (t > tmax) discard;`: nothing elsewhere).
        "gl_FragCoord", "texture", "discard"};
    return names;
}

namespace {

// The rest of a #define's logical line from `at` (backslash continuations joined).
std::string macroBody(const std::string& text, std::size_t at) {
    std::string body;
    for (std::size_t i = at; i < text.size() && text[i] != '\n'; ++i) {
        if (text[i] == '\\' && i + 1 < text.size() && text[i + 1] == '\n') {
            ++i;
            continue;
        }
        body += text[i];
    }
    return body;
}

// Whether `name` is a later declarator of a file-scope declaration's comma list
// (`float det = .005, maxdist = 50., pi = 3.1416;`): after a comma outside parentheses, followed by
// `=`, `;`, `,` or `[`, in a statement that starts with a type or a qualifier.
template <class Depth> bool declaredInList(const std::string& text, const std::string& name, Depth&& depthAt) {
    static const std::regex declarationStart(
        R"(^\s*(?:(?:const|uniform|highp|mediump|lowp|precise)\s+)*(?:float|int|uint|bool|double|[iud]?vec[234]|mat[234](?:x[234])?|Point3|Vector3|Color3|float[234])\b)",
        kLinearRegex);
    for (std::size_t at : detail::wordOffsets(text, name)) {
        const std::size_t end = at + name.size();
        if (depthAt(at) != 0) continue;
        std::size_t before = at;
        while (before > 0 && std::isspace(static_cast<unsigned char>(text[before - 1]))) --before;
        if (before == 0 || text[before - 1] != ',') continue;
        std::size_t after = end;
        while (after < text.size() && std::isspace(static_cast<unsigned char>(text[after]))) ++after;
        if (after >= text.size() || std::string_view("=;,[").find(text[after]) == std::string_view::npos) continue;
        std::size_t lineStart = text.rfind('\n', before - 1);
        lineStart = lineStart == std::string::npos ? 0 : lineStart + 1;
        const std::size_t lineText = text.find_first_not_of(" \t", lineStart);
        if (lineText != std::string::npos && text[lineText] == '#') continue; // a directive (#define A a, b)
        const std::size_t start = text.find_last_of(";{}", before - 1);
        const std::size_t from = start == std::string::npos ? 0 : start + 1;
        // The statement, without the directive lines before it.
        std::string statement;
        for (std::size_t line = from; line < before;) {
            std::size_t next = std::min(text.find('\n', line), before);
            const std::size_t first = text.find_first_not_of(" \t", line);
            if (first >= next || text[first] != '#') statement.append(text, line, next - line);
            line = next + 1;
        }
        int parentheses = 0;
        for (char c : statement) parentheses += c == '(' ? 1 : c == ')' ? -1 : 0;
        if (parentheses != 0) continue;
        std::smatch match;
        if (std::regex_search(statement, match, declarationStart)) return true;
    }
    return false;
}

} // namespace

CompatNeeds detectCompatNeeds(const std::string& stripped) {
    const std::vector<std::string>& candidates = compatCandidates();
    // Declared by the file itself at file scope: a macro, a global variable or constant, a
    // uniform, a function or a struct of that name. A local variable or a parameter of the same
    // name (`vec3 pi = ...` inside one function) does not count: it hides the built-in only in
    // its own scope, and other functions still use the built-in.
    // Each compiled the first time a text uses its name (all ~60 at once cost every process ~10 ms).
    auto declared = [&candidates](std::size_t i) -> const std::regex& {
        const std::string& name = candidates[i];
        return compiledOnce(
            "(#\\s*define\\s+" + name +
            "\\b)|(\\b(const\\s+)?(float|int|uint|bool|[iu]?vec[234]|mat[234]|sampler2D|struct|uniform\\s+\\w+)\\s+" + name +
            "\\s*[=;(\\[{])");
    };
    // The text's words (runs of [A-Za-z0-9_], what `\bNAME\b` matches), found in one pass:
    // a regex search per symbol took ~35 ms on a 12 KB SDF with its includes, on every edit.
    std::set<std::string_view> words;
    const std::string_view text(stripped);
    detail::forEachIdentifier(text,
                              [&](std::size_t at, std::size_t end) { return words.insert(text.substr(at, end - at)), true; });
    // Brace depth at each byte, made only when some used name has a declaration to place.
    std::vector<std::uint8_t> depth;
    auto depthAt = [&](std::size_t at) {
        if (depth.empty()) {
            depth.resize(stripped.size() + 1);
            int level = 0;
            for (std::size_t i = 0; i < stripped.size(); ++i) {
                depth[i] = std::uint8_t(std::min(level, 255));
                if (stripped[i] == '{') ++level;
                if (stripped[i] == '}' && level > 0) --level;
            }
            depth[stripped.size()] = std::uint8_t(std::min(level, 255));
        }
        return int(depth[at]);
    };
    CompatNeeds needs;
    for (const char* noise : {"noise1", "noise2", "noise3", "noise4"}) {
        if (!words.count(noise)) continue;
        const std::regex& definition = compiledOnce(R"(\b\w+\s+)" + std::string(noise) + R"(\s*\([^)]*\)\s*\{)");
        for (auto it = std::sregex_iterator(stripped.begin(), stripped.end(), definition); it != std::sregex_iterator(); ++it)
            if (depthAt(std::size_t(it->position(0))) == 0) {
                needs.renamed.push_back(noise);
                break;
            }
    }
    // Words later GLSL made keywords that GLSL 1.10 and WebGL 1 code (GLSL Sandbox, three.js,
    // Processing, glslCanvas) uses as names (`float smooth`, `vec3 sample(...)`): renamed like the
    // noise functions where the file never uses one as a qualifier, which a word follows (`smooth in`).
    for (const char* keyword :
         {"smooth", "sample", "buffer", "shared", "patch", "centroid", "precise", "coherent", "restrict", "readonly", "writeonly",
          "resource", "common", "partition", "active", "filter", "noperspective"}) {
        if (!words.count(keyword)) continue;
        bool qualifier = false;
        detail::forEachOccurrence(stripped, keyword, [&](std::size_t at) {
            std::size_t k = at + std::strlen(keyword);
            while (k < stripped.size() && std::isspace(static_cast<unsigned char>(stripped[k]))) ++k;
            qualifier = k < stripped.size() && (std::isalpha(static_cast<unsigned char>(stripped[k])) || stripped[k] == '_');
            return !qualifier;
        });
        if (!qualifier) needs.renamed.push_back(keyword);
    }
    for (std::size_t i = 0; i < candidates.size(); ++i) {
        if (!words.count(candidates[i])) continue;
        bool declaredHere = false, wraps = false;
        for (auto it = std::sregex_iterator(stripped.begin(), stripped.end(), declared(i)); it != std::sregex_iterator(); ++it) {
            // A macro whose body names itself wraps the input (`#define iTime (iTime - 25.)`): the
            // preprocessor leaves the inner name alone, so it still needs the input.
            if ((*it)[1].matched && mentions(macroBody(stripped, std::size_t(it->position(0) + it->length(0))), candidates[i])) {
                wraps = true;
                continue;
            }
            // A macro is defined wherever it stands; anything else counts at file scope only.
            if ((*it)[1].matched || depthAt(std::size_t(it->position(0))) == 0) {
                declaredHere = true;
                break;
            }
        }
        if (declaredHere || declaredInList(stripped, candidates[i], depthAt)) continue;
        needs.symbols.push_back(candidates[i]);
        if (wraps) needs.wrapped.push_back(candidates[i]);
    }
    return needs;
}

namespace {

// Whether `d` is the reserved-name check's error for a name a host's adaptation wrote (ISF's
// sdfwb_isfThisPixel, TouchDesigner's sdfwb_sTD2DInputs), which the user's `text` does not hold.
bool adapterName(const Diagnostic& d, const std::string& host, const std::string& text) {
    static constexpr std::string_view reserved = "': names beginning with sdfwb_";
    const std::size_t end = d.message.find(reserved);
    if (host.empty() || d.message.empty() || d.message[0] != '\'' || end == std::string::npos) return false;
    return detail::wordOffsets(text, d.message.substr(1, end - 1)).empty();
}

// Points at a function named `entry` whose parameters are wrong, if any, else at line 1.
Diagnostic missingEntryDiagnostic(const ResolvedSource& source, const std::string& entry, bool requested) {
    const std::string& root = source.map.files.front().text;
    const std::string form = "`float " + entry + "(vec3 p)` or `float " + entry +
                             "(vec3 p, float time)` (vec2/vec3/vec4 returns give the distance in .x)";
    std::string stripped = stripComments(root);
    const std::regex anyDefinition(R"(\b\w+\s+)" + entry + R"(\s*\([^)]*\))", kLinearRegex);
    std::smatch match;
    for (std::size_t at : isIdentifier(entry) ? detail::wordOffsets(stripped, entry) : std::vector<std::size_t>()) {
        std::size_t start = previousWord(stripped, at);
        if (start == std::string::npos || !matchAt(stripped, start, anyDefinition, match)) continue;
        int line = 1 + int(std::count(stripped.begin(), stripped.begin() + std::ptrdiff_t(start), '\n'));
        std::size_t lineStart = stripped.rfind('\n', start);
        int column = int(start - (lineStart == std::string::npos ? 0 : lineStart + 1)) + 1;
        return {source.map.files.front().name, line, column, Severity::Error,
                entry + "() must be declared as " + form + "; found `" + match.str(0) + "`"};
    }
    if (requested)
        return {source.map.files.front().name, 1, 1, Severity::Error,
                "entry point '" + entry + "' not found: define " + form + " (or name another function)"};
    std::string conventional;
    for (const std::string& name : conventionalEntries()) conventional += (conventional.empty() ? "" : ", ") + name;
    return {source.map.files.front().name, 1, 1, Severity::Error,
            "no SDF here: define `float sdf(vec3 p)` or `float sdf(vec3 p, float time)`, one of " + conventional +
                " with that form, or name your function with --entry NAME or an `entry: NAME` metadata line"};
}

// Shadertoy's cube-map channels: a channel the code reads with a direction (`texture(iChannel0,
// rd)`, `textureCube(iChannel1, n)`) does not compile as a sampler2D. Each channel the code uses is
// tried as a samplerCube, and kept as one where that leaves fewer errors; code that compiles as it
// is is parsed once.
void chooseCubeChannels(PreparedSdf& prepared) {
    if (!prepared.compat.usesShadertoyChannel()) return;
    auto errors = [&prepared] {
        PreparedSdf userCode = prepared;
        userCode.signature.entry.clear(); // the user's code alone
        const std::vector<Diagnostic> found =
            checkWithGlslang(composeSdfShader(userCode, Stage::Fragment, std::vector<ShaderPiece>{}, FeatureDefines{}));
        return std::count_if(found.begin(), found.end(), [](const Diagnostic& d) { return d.severity == Severity::Error; });
    };
    auto least = errors();
    for (const std::string& symbol : prepared.compat.symbols) {
        if (least == 0) return;
        if (symbol.rfind("iChannel", 0) != 0 || symbol.size() != 9) continue; // not iChannelTime/Resolution
        prepared.compat.cubeChannels.push_back(symbol);
        const auto now = errors();
        if (now < least)
            least = now;
        else
            prepared.compat.cubeChannels.pop_back();
    }
}

} // namespace

std::string hostDescription(const std::string& host) {
    if (host.empty()) return "";
    if (host == "Fragmentarium")
        return "a Fragmentarium fragment: sliders and presets as parameters, its includes' names provided, init() run first";
    if (host == "a Shadertoy port") return "a Shadertoy port: its main() wrapper left out";
    if (host == "an old Shadertoy shader") return "an old Shadertoy shader: its iGlobalTime is iTime";
    if (host == "ISF")
        return "an ISF shader (VDMX, Resolume, editor.isf.video): its INPUTS as parameters, TIME and RENDERSIZE as "
               "Shadertoy's inputs, main() as Shadertoy's mainImage";
    if (host == "twigl")
        return "a twigl shader (geeker/geekest mode): its text as the body of mainImage, FC its pixel, r the resolution, "
               "t the time, o its colour";
    if (host == "Synesthesia")
        return "a Synesthesia scene: renderMain() as Shadertoy's mainImage, its controls from the scene.json beside it, "
               "its audio silent (its audio clocks run as the time)";
    if (host == "MadMapper")
        return "a MadMapper material: materialColorForPixel as Shadertoy's mainImage, its INPUTS as parameters, a "
               "time_base generator the time";
    if (host == "the VS Code Shader Toy extension")
        return "a VS Code Shader Toy extension shader: its #iUniform lines as parameters, its #iChannel, #iKeyboard and "
               "#iFirstPersonControls lines left out (no key is down, iViewMatrix is the identity)";
    return (host.compare(0, 2, "a ") == 0 || host.compare(0, 3, "an ") == 0 ? host + "'s" : "a " + host) +
           " shader: main() as Shadertoy's mainImage, its inputs as Shadertoy's";
}

PreparedSdf prepareSdf(const std::string& text, const std::string& name, const std::filesystem::path& path,
                       const IncludeOptions& options, const std::string& entry) {
    PreparedSdf prepared;
    ParameterScan parameters = parseParameters(text, name);
    // Another host's whole shader (a `void main()`, a Fragmentarium fragment): read in sdfwb's terms.
    detail::HostAdaptation host = detail::adaptForeignHost(text, parameters.parameters);
    prepared.host = std::move(host.host);
    prepared.source = resolveIncludes(prepared.host.empty() ? text : host.text, name, path, options);
    prepared.diagnostics = prepared.source.diagnostics;
    for (Diagnostic& d : checkSourceFiles(prepared.source))
        if (!adapterName(d, prepared.host, text)) prepared.diagnostics.push_back(std::move(d));
    if (prepared.host == "Synesthesia" && std::none_of(parameters.parameters.begin(), parameters.parameters.end(),
                                                       [](const Parameter& p) { return p.syntax == Parameter::Syntax::Isf; }))
        prepared.diagnostics.push_back(
            {name, 1, 1, Severity::Warning,
             "a Synesthesia scene's controls are declared by the scene.json beside its main.glsl, and none was read (" +
                 (path.empty() ? std::string("the text is no file's")
                               : (path.parent_path() / "scene.json").string() + ": missing or no CONTROLS") +
                 "): a control the code reads is an undeclared identifier"});
    prepared.parameters = std::move(parameters.parameters);
    for (Diagnostic& d : parameters.diagnostics) prepared.diagnostics.push_back(std::move(d));
    std::string stripped = expandTypeAliases(stripComments(prepared.source.text));
    prepared.compat = detectCompatNeeds(stripped);
    prepared.macros = definedMacros(stripped);
    chooseCubeChannels(prepared);
    static const std::regex mainImage(
        R"(\bvoid\s+mainImage\s*\(\s*out\s+vec4\s+\w+\s*,\s*(?:in\s+|const\s+)*vec2\s+\w+\s*\)\s*\{)", kLinearRegex);
    prepared.shadertoyMainImage = stripped.find("mainImage") != std::string::npos && std::regex_search(stripped, mainImage);
    std::string chosen = entry;
    prepared.entrySource = EntrySource::Requested;
    if (chosen.empty()) {
        chosen = metadataEntry(text);
        prepared.entrySource = EntrySource::Metadata;
    }
    if (chosen.empty()) {
        chosen = "sdf";
        prepared.entrySource = EntrySource::Default;
    }
    auto refuse = [&](const std::string& why) {
        prepared.signature.entry = chosen;
        prepared.diagnostics.push_back({prepared.source.map.files.front().name, 1, 1, Severity::Error, why});
    };
    if (!isIdentifier(chosen)) {
        refuse("entry point '" + chosen + "' is not a GLSL identifier");
        return prepared;
    }
    if (chosen == "main" || chosen.rfind("gl_", 0) == 0 || (chosen.size() >= 6 && [&] {
            std::string head = chosen.substr(0, 6);
            for (char& c : head) c = char(std::tolower(static_cast<unsigned char>(c)));
            return head == "sdfwb_";
        }())) {
        refuse("entry point '" + chosen + "' is reserved (main, gl_*, sdfwb_*): name your own function");
        return prepared;
    }
    prepared.signature = detectSignature(stripped, chosen);
    if (!prepared.signature.found && prepared.entrySource == EntrySource::Default && prepared.shadertoyMainImage) {
        detail::chooseMarchedEntry(prepared, stripped);
        if (!prepared.entryCandidates.empty()) return prepared;
    }
    if (!prepared.signature.found && prepared.entrySource == EntrySource::Default) {
        for (const std::string& conventional : conventionalEntries()) {
            SdfSignature candidate = detectSignature(stripped, conventional);
            if (!candidate.found || (prepared.shadertoyMainImage && detail::floatIsNotTime(candidate, stripped))) continue;
            prepared.signature = candidate;
            prepared.entrySource = EntrySource::Convention;
            break;
        }
    }
    // Also where the march calls a field whose parameters cannot be traced (mainImage marches
    // `capsule(p, a, b, r)` itself): the loop's body run once makes that call as the march does.
    if (!prepared.signature.found && prepared.entrySource == EntrySource::Default && prepared.shadertoyMainImage)
        detail::chooseInlineField(prepared, stripped);
    // `float sdSphere(vec3 p, float r)` named as the entry: its float gets the time, which its name
    // does not say it is (a radius 0 at --time 0). Said at the definition, with what to do instead.
    if (prepared.signature.found && prepared.signature.inlineBody.empty() &&
        detail::floatIsNotTime(prepared.signature, stripped)) {
        const std::string& root = prepared.source.map.files.front().text;
        const std::string entry = prepared.signature.entry, name = detail::timeParameter(prepared.signature, stripped);
        const std::string rootStripped = stripComments(root);
        std::smatch definition;
        const int line = std::regex_search(rootStripped, definition, std::regex(R"(\b\w+\s+)" + entry + R"(\s*\()", kLinearRegex))
                             ? 1 + int(std::count(rootStripped.begin(), definition[0].first, '\n'))
                             : 1;
        prepared.diagnostics.push_back({prepared.source.map.files.front().name, line, 1, Severity::Warning,
                                        entry + "'s '" + name + "' after the point is given the scene time (0 at --time 0), " +
                                            "as a float after the point is read; to give it a value, open a file holding " +
                                            "`float sdf(vec3 p) { return " + entry + "(p, VALUE); }`"});
    }
    // Fragmentarium's init(), which its raytracer calls before the field: the wrapper calls it.
    if (prepared.signature.found && !host.entryPrelude.empty() && prepared.signature.prelude.empty())
        prepared.signature.prelude = host.entryPrelude;
    if (!prepared.signature.found) {
        Diagnostic missing = missingEntryDiagnostic(prepared.source, chosen, prepared.entrySource != EntrySource::Default);
        // The march's field, where its parameters after the point could not be traced: why.
        if (prepared.entrySource == EntrySource::Default && !prepared.entryReason.empty())
            missing.message += " (" + prepared.entryReason + ")";
        // A whole shader whose march was not read because its code does not compile: the
        // compiler's errors say why, at the user's lines.
        if (prepared.entrySource == EntrySource::Default && prepared.shadertoyMainImage && prepared.entryReason.empty() &&
            prepared.ok()) {
            PreparedSdf userCode = prepared;
            userCode.signature.entry.clear(); // the user's code alone
            int shown = 0;
            const std::vector<ShaderPiece> stage{{"<sdfwb main>", "void main() {}\n"}}; // the stage needs one to link
            for (Diagnostic& d : checkWithGlslang(composeSdfShader(userCode, Stage::Fragment, stage, FeatureDefines{})))
                if (d.severity == Severity::Error && shown++ < 3) prepared.diagnostics.push_back(std::move(d));
            if (shown > 0)
                missing.message +=
                    " (the shader does not compile, so its march could not be read: see the errors before this one)";
        }
        prepared.diagnostics.push_back(std::move(missing));
    }
    return prepared;
}

PreparedSdf prepareMeshSdf(std::shared_ptr<const meshfield::MeshField> mesh, const std::filesystem::path& path,
                           const std::string& text, const std::string& entry) {
    const std::string generated = mesh->glslSource();
    PreparedSdf prepared = prepareSdf(text.empty() ? generated : text, path.string(), path, IncludeOptions{}, entry);
    prepared.meshIsTheField = (text.empty() || text == generated) && entry.empty();
    prepared.mesh = std::move(mesh);
    return prepared;
}

PreparedSdf prepareMeshFile(const std::filesystem::path& path, const meshfield::MeshFieldOptions& options,
                            const std::string& text, const std::string& entry) {
    auto mesh = meshfield::loadMeshField(path, options);
    if (mesh) return prepareMeshSdf(std::move(*mesh), path, text, entry);
    PreparedSdf failed;
    failed.source.map.files.push_back({path.string(), ""});
    failed.diagnostics.push_back({path.string(), 0, 0, Severity::Error, mesh.error().message});
    return failed;
}

PreparedSdf prepareSdfFile(const std::filesystem::path& path, const IncludeOptions& options, const std::string& entry) {
    if (meshfield::isMeshPath(path)) return prepareMeshFile(path, {}, {}, entry); // the default sign: winding numbers
    auto text = readTextFile(path);
    if (!text) {
        PreparedSdf failed;
        failed.source.map.files.push_back({path.string(), ""});
        failed.diagnostics.push_back({path.string(), 0, 0, Severity::Error, text.error().message});
        return failed;
    }
    return prepareSdf(*text, path.string(), path, options, entry);
}

} // namespace sdfwb::shaders
