#include <shaders/SdfSource.h>

#include <core/Regex.h>
#include <core/TextFile.h>
#include <shaders/SourceChecks.h>

#include <algorithm>
#include <iterator>
#include <regex>
#include <set>
#include <string_view>

namespace sdfwb::shaders {
namespace {

bool isWordCharacter(char c) {
    return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_';
}

// What `\s` matches.
bool isBlank(char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\v' || c == '\f' || c == '\r'; }

// A regex match that starts exactly at `at`, seeing the character before it for `\b`.
bool matchAt(const std::string& text, std::size_t at, const std::regex& pattern, std::smatch& match) {
    auto flags = std::regex_constants::match_continuous;
    if (at > 0) flags |= std::regex_constants::match_prev_avail;
    return std::regex_search(text.begin() + std::ptrdiff_t(at), text.end(), match, pattern, flags);
}

} // namespace

std::string stripComments(const std::string& text) {
    std::string out = text;
    enum class State { Code, Line, Block } state = State::Code;
    for (std::size_t i = 0; i < out.size(); ++i) {
        char c = out[i];
        char next = i + 1 < out.size() ? out[i + 1] : '\0';
        switch (state) {
        case State::Code:
            if (c == '/' && next == '/') { state = State::Line; out[i] = ' '; }
            else if (c == '/' && next == '*') { state = State::Block; out[i] = ' '; out[++i] = ' '; }
            break;
        case State::Line:
            if (c == '\n') state = State::Code;
            else out[i] = ' ';
            break;
        case State::Block:
            if (c == '*' && next == '/') { out[i] = ' '; out[++i] = ' '; state = State::Code; }
            else if (c != '\n') out[i] = ' ';
            break;
        }
    }
    return out;
}

SdfSignature detectSignature(const std::string& stripped) {
    // A definition (with a body), not a prototype. vec3 synonyms of the G3D dialect count.
    static const std::regex definition(
        R"(\bfloat\s+sdf\s*\(\s*((?:in\s+|const\s+|highp\s+|mediump\s+)*)(vec3|Point3|Vector3|float3)\s+\w+\s*)"
        R"((,\s*((?:in\s+|const\s+|highp\s+)*)float\s+\w+\s*)?\)\s*\{)", kLinearRegex);
    // Matched only where `float` + blanks + `sdf` starts: searching from every position of a long
    // text was the slow part of preparing one (1.8 s for 10 MB, 3.7 s with the linear executor).
    SdfSignature signature;
    std::smatch match;
    for (std::size_t at = stripped.find("float"); at != std::string::npos; at = stripped.find("float", at + 5)) {
        if (at > 0 && isWordCharacter(stripped[at - 1])) continue;
        std::size_t name = at + 5;
        while (name < stripped.size() && isBlank(stripped[name])) ++name;
        if (name == at + 5 || stripped.compare(name, 3, "sdf") != 0) continue;
        if (!matchAt(stripped, at, definition, match)) continue;
        signature.found = true;
        if (match[3].matched) signature.animated = true;
    }
    return signature;
}

std::vector<std::string> functionSignatures(const std::string& text) {
    static const std::regex definition(R"(\b(?:float|vec[234]|ivec[234]|int|uint|bool|mat[234]|void|Point3|Vector3|Color3|float[234])\s+(\w+)\s*\(([^)]*)\)\s*\{)", kLinearRegex);
    static const std::regex whitespace(R"(\s+)", kLinearRegex);
    std::string stripped = stripComments(text);
    std::vector<std::string> signatures;
    for (auto it = std::sregex_iterator(stripped.begin(), stripped.end(), definition); it != std::sregex_iterator(); ++it) {
        std::string parameters = std::regex_replace((*it)[2].str(), whitespace, " ");
        signatures.push_back((*it)[1].str() + "(" + parameters + ")");
    }
    return signatures;
}

bool CompatNeeds::usesSceneTime() const {
    return std::find(symbols.begin(), symbols.end(), "g3d_SceneTime") != symbols.end();
}

CompatNeeds detectCompatNeeds(const std::string& stripped) {
    static const char* const candidates[] = {
        "pi", "saturate", "lerp", "square", "frac", "lengthSquared", "Point3", "Vector3", "Color3",
        "Radiance3", "float2", "float3", "float4", "g3d_SceneTime", "g3d_uniformRandom"};
    // Declared by the file itself: a macro, a variable, a function or a struct of that name.
    // Compiled once: building 15 regexes per call cost more than the searches.
    static const std::vector<std::regex> declared = [] {
        std::vector<std::regex> patterns;
        for (const char* symbol : candidates) {
            const std::string name(symbol);
            patterns.emplace_back("(#\\s*define\\s+" + name + "\\b)|(\\b(const\\s+)?(float|int|vec[234]|bool|struct|uniform\\s+\\w+)\\s+" + name +
                                  "\\s*[=;(\\[{])", kLinearRegex);
        }
        return patterns;
    }();
    // The text's words (runs of [A-Za-z0-9_], what `\bNAME\b` matches), found in one pass:
    // a regex search per symbol took ~35 ms on a 12 KB SDF with its includes, on every edit.
    std::set<std::string_view> words;
    const std::string_view text(stripped);
    for (std::size_t i = 0; i < text.size();) {
        if (!isWordCharacter(text[i])) { ++i; continue; }
        std::size_t end = i;
        while (end < text.size() && isWordCharacter(text[end])) ++end;
        words.insert(text.substr(i, end - i));
        i = end;
    }
    CompatNeeds needs;
    for (std::size_t i = 0; i < std::size(candidates); ++i) {
        if (!words.count(candidates[i])) continue;
        if (std::regex_search(stripped, declared[i])) continue;
        needs.symbols.push_back(candidates[i]);
    }
    return needs;
}

namespace {

// Points at a function named sdf whose parameters are wrong, if any, else at line 1.
Diagnostic missingSdfDiagnostic(const ResolvedSource& source) {
    const std::string& root = source.map.files.front().text;
    std::string stripped = stripComments(root);
    static const std::regex anySdf(R"(\b\w+\s+sdf\s*\([^)]*\))", kLinearRegex);
    // The first match, tried only at the word before each blank-preceded `sdf` (see detectSignature).
    std::smatch match;
    for (std::size_t at = stripped.find("sdf"); at != std::string::npos; at = stripped.find("sdf", at + 3)) {
        std::size_t start = at;
        while (start > 0 && isBlank(stripped[start - 1])) --start;
        if (start == at || start == 0 || !isWordCharacter(stripped[start - 1])) continue;
        while (start > 0 && isWordCharacter(stripped[start - 1])) --start;
        if (!matchAt(stripped, start, anySdf, match)) continue;
        int line = 1 + int(std::count(stripped.begin(), stripped.begin() + std::ptrdiff_t(start), '\n'));
        std::size_t lineStart = stripped.rfind('\n', start);
        int column = int(start - (lineStart == std::string::npos ? 0 : lineStart + 1)) + 1;
        return {source.map.files.front().name, line, column, Severity::Error,
                "sdf() must be declared as `float sdf(vec3 p)` or `float sdf(vec3 p, float time)`; found `" + match.str(0) + "`"};
    }
    return {source.map.files.front().name, 1, 1, Severity::Error,
            "no SDF here: define `float sdf(vec3 p)` or `float sdf(vec3 p, float time)`"};
}

} // namespace

PreparedSdf prepareSdf(const std::string& text, const std::string& name, const std::filesystem::path& path,
                       const IncludeOptions& options) {
    PreparedSdf prepared;
    prepared.source = resolveIncludes(text, name, path, options);
    prepared.diagnostics = prepared.source.diagnostics;
    for (Diagnostic& d : checkSourceFiles(prepared.source)) prepared.diagnostics.push_back(std::move(d));
    std::string stripped = stripComments(prepared.source.text);
    prepared.signature = detectSignature(stripped);
    prepared.compat = detectCompatNeeds(stripped);
    if (!prepared.signature.found) prepared.diagnostics.push_back(missingSdfDiagnostic(prepared.source));
    return prepared;
}

PreparedSdf prepareSdfFile(const std::filesystem::path& path, const IncludeOptions& options) {
    auto text = readTextFile(path);
    if (!text) {
        PreparedSdf failed;
        failed.source.map.files.push_back({path.string(), ""});
        failed.diagnostics.push_back({path.string(), 0, 0, Severity::Error, text.error().message});
        return failed;
    }
    return prepareSdf(*text, path.string(), path, options);
}

} // namespace sdfwb::shaders
