#pragma once
// Whole words of GLSL text: the one place the shader readers (SdfSource, MarchAnalysis,
// InlineField, ShaderComposer, ForeignHosts) find an identifier without matching it inside a
// longer one. Private to shaders/.

#include <shaders/SdfSource.h>

#include <algorithm>
#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

namespace sdfwb::shaders::detail {

// Whether text[at, at + length) is a whole word: no identifier character right before or after.
inline bool isWholeWord(const std::string& text, std::size_t at, std::size_t length) {
    return (at == 0 || !isWordCharacter(text[at - 1])) && (at + length >= text.size() || !isWordCharacter(text[at + length]));
}

// Whether `word` starts at `at` as a whole word.
inline bool isWordAt(const std::string& text, std::size_t at, std::string_view word) {
    return text.compare(at, word.size(), word) == 0 && isWholeWord(text, at, word.size());
}

// Calls `visit(at)` for each whole-word `word` starting in text[from, to), in order, until it
// returns false.
template <class Visit>
void forEachOccurrence(const std::string& text, const std::string& word, Visit visit, std::size_t from = 0,
                       std::size_t to = std::string::npos) {
    if (word.empty()) return;
    for (std::size_t at = text.find(word, from); at != std::string::npos && at < to; at = text.find(word, at + 1))
        if (isWholeWord(text, at, word.size()) && !visit(at)) return;
}

// The offsets of every whole-word `word` starting in text[from, to).
inline std::vector<std::size_t> wordOffsets(const std::string& text, const std::string& word, std::size_t from = 0,
                                            std::size_t to = std::string::npos) {
    std::vector<std::size_t> out;
    forEachOccurrence(
        text, word, [&](std::size_t at) { return out.push_back(at), true; }, from, to);
    return out;
}

// Calls `visit(at, end)` for each identifier-like word of `text` (a run of letters, digits and
// _) in order, until it returns false.
template <class Text, class Visit> void forEachIdentifier(const Text& text, Visit visit) {
    for (std::size_t at = 0; at < text.size();) {
        if (!isWordCharacter(text[at])) {
            ++at;
            continue;
        }
        std::size_t end = at;
        while (end < text.size() && isWordCharacter(text[end])) ++end;
        if (!visit(at, end)) return;
        at = end;
    }
}

// Whether `stripped` (comments blanked) defines a function `name`: `TYPE name(...) {`, not only
// declares or calls it. The hosts' adapters (ForeignHosts, Synesthesia, TouchDesigner) provide a
// helper only where the file has none of its own.
inline bool definesFunction(const std::string& stripped, const std::string& name) {
    auto space = [](char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r'; };
    auto skipSpace = [&](std::size_t k) {
        while (k < stripped.size() && space(stripped[k])) ++k;
        return k;
    };
    bool found = false;
    forEachOccurrence(stripped, name, [&](std::size_t at) {
        std::size_t type = at;
        while (type > 0 && space(stripped[type - 1])) --type;
        if (type == at || type == 0 || !isWordCharacter(stripped[type - 1])) return true;
        std::size_t open = skipSpace(at + name.size());
        if (open >= stripped.size() || stripped[open] != '(') return true;
        std::size_t close = stripped.find(')', open);
        if (close == std::string::npos) return true;
        std::size_t body = skipSpace(close + 1);
        found = body < stripped.size() && stripped[body] == '{';
        return !found;
    });
    return found;
}

// `const float PI = ...; ` where `stripped` (comments blanked) uses PI and defines none of its own
// (`#define PI ...`, `float PI = ...`), else empty: what a host's own includes give (Fragmentarium's
// MathUtils.frag, MadMapper's MadCommon.glsl, Synesthesia's built-ins).
inline std::string piWhereUsed(const std::string& stripped) {
    const std::vector<std::size_t> uses = wordOffsets(stripped, "PI");
    auto defines = [&](std::size_t at) {
        std::size_t before = at;
        while (before > 0 && (stripped[before - 1] == ' ' || stripped[before - 1] == '\t')) --before;
        std::size_t after = at + 2;
        while (after < stripped.size() && (stripped[after] == ' ' || stripped[after] == '\t')) ++after;
        return (before >= 6 && stripped.compare(before - 6, 6, "define") == 0) ||
               (after < stripped.size() && stripped[after] == '=' &&
                (after + 1 >= stripped.size() || stripped[after + 1] != '='));
    };
    return uses.empty() || std::any_of(uses.begin(), uses.end(), defines) ? std::string() : "const float PI = 3.14159265358979; ";
}

} // namespace sdfwb::shaders::detail
