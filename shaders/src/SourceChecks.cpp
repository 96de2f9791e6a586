#include <shaders/SourceChecks.h>

#include <shaders/SdfSource.h>

#include <core/Regex.h>

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <regex>
#include <set>
#include <string>
#include <string_view>
#include <vector>

namespace sdfwb::shaders {
namespace {

bool isWord(char c) { return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_'; }

struct Token {
    std::string text;   // an identifier, or one punctuation character
    std::size_t offset; // in the scanned text
};

// Identifiers and single punctuation characters; numbers count as identifiers, whitespace and
// preprocessor lines are skipped. Linear, no recursion: safe on any input.
std::vector<Token> tokenize(const std::string& text) {
    std::vector<Token> tokens;
    bool lineStart = true;
    for (std::size_t i = 0; i < text.size();) {
        const char c = text[i];
        if (c == '\n') {
            lineStart = true;
            ++i;
            continue;
        }
        if (c == ' ' || c == '\t' || c == '\r') {
            ++i;
            continue;
        }
        if (c == '#' && lineStart) { // a directive: skip to the end of the line
            while (i < text.size() && text[i] != '\n') ++i;
            continue;
        }
        lineStart = false;
        if (isWord(c)) {
            std::size_t end = i;
            while (end < text.size() && isWord(text[end])) ++end;
            tokens.push_back({text.substr(i, end - i), i});
            i = end;
        } else {
            tokens.push_back({std::string(1, c), i});
            ++i;
        }
    }
    return tokens;
}

struct Found {
    std::string name;
    std::string key;    // functions: "name(type,type)"; declarations: the name
    std::size_t offset; // of the name
    bool function;
};

// Top-level (brace depth 0) function definitions "TYPE NAME ( ... ) {", uniforms
// "uniform TYPE NAME" and structs "struct NAME".
std::vector<Found> topLevelDeclarations(const std::vector<Token>& tokens) {
    std::vector<Found> found;
    int depth = 0;
    auto isIdentifier = [](const std::string& t) { return !t.empty() && isWord(t[0]) && !(t[0] >= '0' && t[0] <= '9'); };
    for (std::size_t i = 0; i < tokens.size(); ++i) {
        const std::string& t = tokens[i].text;
        if (t == "{") {
            ++depth;
            continue;
        }
        if (t == "}") {
            depth = depth > 0 ? depth - 1 : 0;
            continue;
        }
        if (depth != 0) continue;
        if (t == "struct" && i + 1 < tokens.size() && isIdentifier(tokens[i + 1].text)) {
            found.push_back({tokens[i + 1].text, tokens[i + 1].text, tokens[i + 1].offset, false});
        } else if (t == "uniform" && i + 2 < tokens.size() && isIdentifier(tokens[i + 2].text)) {
            found.push_back({tokens[i + 2].text, tokens[i + 2].text, tokens[i + 2].offset, false});
        } else if (isIdentifier(t) && i + 2 < tokens.size() && isIdentifier(tokens[i + 1].text) && tokens[i + 2].text == "(") {
            // Parameter types: in each comma-separated group, the last identifier before the
            // parameter's name (or the only one), qualifiers skipped.
            std::vector<std::string> group;
            std::string types;
            std::size_t j = i + 3;
            bool closed = false;
            auto flush = [&] {
                static const std::set<std::string> qualifiers = {"in",    "out",     "inout", "const",
                                                                 "highp", "mediump", "lowp",  "precise"};
                std::vector<std::string> words;
                for (const std::string& w : group)
                    if (!qualifiers.count(w)) words.push_back(w);
                if (!words.empty() && words.front() != "void") types += (types.empty() ? "" : ",") + words.front();
                group.clear();
            };
            for (; j < tokens.size(); ++j) {
                const std::string& p = tokens[j].text;
                if (p == ")") {
                    closed = true;
                    break;
                }
                if (p == "(" || p == "{" || p == "}" || p == ";") break;
                if (p == ",")
                    flush();
                else if (isIdentifier(p))
                    group.push_back(p);
            }
            if (!closed || j + 1 >= tokens.size() || tokens[j + 1].text != "{") continue;
            flush();
            found.push_back({tokens[i + 1].text, tokens[i + 1].text + "(" + types + ")", tokens[i + 1].offset, true});
            i = j; // the body's "{" comes next
        }
    }
    return found;
}

// The reserved prefix, in any letter case ("sdfwb_", "SDFWB_", "Sdfwb_", ...).
bool hasReservedPrefix(std::string_view word) {
    static constexpr std::string_view prefix = "sdfwb_";
    if (word.size() < prefix.size()) return false;
    for (std::size_t i = 0; i < prefix.size(); ++i)
        if (char(std::tolower(static_cast<unsigned char>(word[i]))) != prefix[i]) return false;
    return true;
}

// Words that may stand before a name without declaring it ("return sdfwb_x", "else sdfwb_x").
bool isStatementKeyword(const std::string& word) {
    static const std::set<std::string> keywords = {"return", "else", "case", "do", "discard", "break", "continue"};
    return keywords.count(word) != 0;
}

// Offsets of every name with the reserved prefix that `stripped` defines: after a type, a
// qualifier, `struct` or `]` (a declaration), or as the name of a #define / #undef.
std::vector<std::size_t> reservedDefinitions(const std::string& stripped, const std::vector<Token>& tokens) {
    std::vector<std::size_t> found;
    for (const MacroDirective& d : macroDirectives(stripped))
        if (hasReservedPrefix(d.name)) found.push_back(d.offset);
    for (std::size_t i = 1; i < tokens.size(); ++i) {
        if (!hasReservedPrefix(tokens[i].text)) continue;
        const std::string& before = tokens[i - 1].text;
        const bool afterName = isWord(before[0]) && !(before[0] >= '0' && before[0] <= '9') && !isStatementKeyword(before);
        if (afterName || before == "]") found.push_back(tokens[i].offset);
    }
    std::sort(found.begin(), found.end());
    return found;
}

// 1-based line and column of byte `offset` in `text`.
std::pair<int, int> position(const std::string& text, std::size_t offset) {
    int line = 1;
    std::size_t lineStart = 0;
    for (std::size_t i = 0; i < offset && i < text.size(); ++i)
        if (text[i] == '\n') {
            ++line;
            lineStart = i + 1;
        }
    return {line, int(offset - lineStart) + 1};
}

} // namespace

std::size_t maximumCodeBytes() {
    if (const char* text = std::getenv("SDFWB_MAX_SOURCE_BYTES"); text && *text) {
        char* end = nullptr;
        unsigned long long value = std::strtoull(text, &end, 10);
        if (end && *end == '\0' && value > 0) return std::size_t(value);
    }
    return std::size_t(4) << 20;
}

std::vector<Diagnostic> checkSourceFiles(const ResolvedSource& source) {
    std::vector<Diagnostic> out;
    // Code (not comments or blanks) beyond a few MB takes the GLSL compilers minutes (1 MB of
    // small functions: 2.4 s in Mesa; 10 MB did not finish in 2 minutes) and would hold the
    // viewport that long: refuse it up front, with the figure.
    // Each file stripped once (line numbers kept); the code size counts them all.
    std::vector<std::string> strippedFiles;
    std::size_t code = 0;
    for (const SourceFile& file : source.map.files) {
        strippedFiles.push_back(stripComments(file.text));
        for (char c : strippedFiles.back()) code += !(c == ' ' || c == '\n' || c == '\t' || c == '\r');
    }
    if (code > maximumCodeBytes()) {
        char text[256];
        std::snprintf(
            text, sizeof text,
            "the SDF with its includes holds %.1f MB of code (comments and blanks not counted); sdfwb compiles at most %.1f MB "
            "(set SDFWB_MAX_SOURCE_BYTES to raise the limit; expect minutes of compile time)",
            double(code) / 1048576.0, double(maximumCodeBytes()) / 1048576.0);
        out.push_back({source.map.files.front().name, 1, 1, Severity::Error, text});
        return out;
    }
    for (std::size_t index = 0; index < source.map.files.size(); ++index) {
        const SourceFile& file = source.map.files[index];
        const std::string& stripped = strippedFiles[index];
        auto report = [&](std::size_t offset, std::string message) {
            auto [line, column] = position(stripped, offset);
            out.push_back({file.name, line, column, Severity::Error, std::move(message)});
        };
        // GLSL source is ASCII; comments may hold anything.
        for (std::size_t i = 0; i < stripped.size(); ++i) {
            const auto byte = static_cast<unsigned char>(stripped[i]);
            if (byte >= 0x80 || (byte < 0x20 && byte != '\n' && byte != '\r' && byte != '\t' && byte != '\f' && byte != '\v')) {
                char text[160];
                std::snprintf(text, sizeof text,
                              "byte 0x%02X is not GLSL: outside comments a shader must be ASCII (an accented letter, a "
                              "non-UTF-8 file or binary data?)",
                              unsigned(byte));
                report(i, text);
                break; // one per file: the rest is usually more of the same
            }
        }
        const std::vector<Token> tokens = tokenize(stripped); // once, for both checks
        for (const Found& f : topLevelDeclarations(tokens))
            if (f.function && f.name == "main")
                report(f.offset, "main() is written by the workbench (the tracer's and the samplers' own); an SDF file defines "
                                 "float sdf(vec3 p) and its helpers: remove this main()");
        // glslify's imports (three.js and stack.gl code): its bundler resolves them, not a compiler.
        static const std::regex glslify(R"((?:^|\n)[ \t]*#[ \t]*pragma[ \t]+glslify[ \t]*:[ \t]*(\w+)[ \t]*=[ \t]*require\b)",
                                        kLinearRegex);
        for (auto it = std::sregex_iterator(stripped.begin(), stripped.end(), glslify); it != std::sregex_iterator(); ++it) {
            const std::string name = (*it)[1].str();
            out.push_back({file.name, position(stripped, std::size_t(it->position(1))).first, 1, Severity::Warning,
                           "glslify's import of '" + name + "': the glslify bundler resolves `#pragma glslify: ... require`, " +
                               "sdfwb does not, so '" + name + "' is not defined here (bundle the file first, `npx glslify " +
                               "FILE > bundled.glsl`, and open the result)"});
        }
        for (std::size_t offset : reservedDefinitions(stripped, tokens)) {
            std::size_t end = offset;
            while (end < stripped.size() && isWord(stripped[end])) ++end;
            report(offset, "'" + stripped.substr(offset, end - offset) +
                               "': names beginning with sdfwb_ (in any letter case) are "
                               "reserved for the workbench's own shader code; every other name is yours: rename this one");
        }
    }
    return out;
}

} // namespace sdfwb::shaders
