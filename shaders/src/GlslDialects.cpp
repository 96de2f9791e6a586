#include "GlslDialects.h"

#include <shaders/SdfSource.h>

#include <core/Regex.h>

#include "TextEdits.h"
#include "Words.h"

#include <regex>
#include <vector>

namespace sdfwb::shaders::detail {
namespace {

// text[at, at + length) as spaces, its line breaks kept.
Edit blanked(const std::string& text, std::size_t at, std::size_t length) {
    std::string spaces = text.substr(at, length);
    for (char& c : spaces)
        if (c != '\n' && c != '\r') c = ' ';
    return {at, length, spaces};
}

// sokol-shdc: the annotation lines blanked, and the vertex stages and every fragment stage after
// the first with them.
bool sokolEdits(const std::string& text, std::vector<Edit>& edits) {
    bool annotated = false, dropping = false, fragment = false;
    for (std::size_t start = 0; start < text.size();) {
        const std::size_t stop = std::min(text.find('\n', start), text.size());
        const std::size_t k = text.find_first_not_of(" \t", start);
        std::string word;
        if (k < stop && text[k] == '@') {
            std::size_t end = k + 1;
            while (end < stop && (std::isalnum(static_cast<unsigned char>(text[end])) || text[end] == '_')) ++end;
            word = text.substr(k + 1, end - k - 1);
        }
        static const std::regex known("vs|fs|end|block|program|ctype|module|include_block|header|glsl_options|"
                                      "hlsl_options|msl_options|image_sample_type|sampler_type|cs",
                                      kLinearRegex);
        if (!word.empty() && std::regex_match(word, known)) {
            annotated = true;
            if (word == "vs" || word == "cs" || (word == "fs" && fragment)) dropping = true;
            if (word == "fs") fragment = true;
            edits.push_back(blanked(text, start, stop - start));
            if (word == "end") dropping = false;
        } else if (dropping) {
            edits.push_back(blanked(text, start, stop - start));
        }
        start = stop + 1;
    }
    if (!annotated) edits.clear();
    return annotated;
}

// A Max/Jitter shader file (`<jittershader>` XML): the text of its first fragment program's CDATA
// kept, everything else blanked.
bool jitterEdits(const std::string& text, std::vector<Edit>& edits) {
    if (text.find("<jittershader") == std::string::npos) return false;
    static const std::regex fragment(R"(<program\b[^>]*\btype\s*=\s*"fragment"[^>]*>\s*<!\[CDATA\[)", kLinearRegex);
    std::smatch program;
    if (!std::regex_search(text, program, fragment)) return false;
    const std::size_t begin = std::size_t(program.position(0) + program.length(0));
    const std::size_t end = std::min(text.find("]]>", begin), text.size());
    edits.push_back(blanked(text, 0, begin));
    edits.push_back(blanked(text, end, text.size() - end));
    return true;
}

// RetroArch's GLSL shaders hold both stages in one file (`#if defined(VERTEX) ... #elif
// defined(FRAGMENT) ... #endif`): the vertex part and the three directive lines blanked.
bool retroArchEdits(const std::string& text, const std::string& stripped, std::vector<Edit>& edits) {
    static const std::regex vertex(R"(^[ \t]*#[ \t]*if[ \t]+defined[ \t]*\([ \t]*VERTEX[ \t]*\))", kLinearRegex);
    static const std::regex fragment(R"(^[ \t]*#[ \t]*elif[ \t]+defined[ \t]*\([ \t]*FRAGMENT[ \t]*\))", kLinearRegex);
    static const std::regex opens(R"(^[ \t]*#[ \t]*if)", kLinearRegex), closes(R"(^[ \t]*#[ \t]*endif\b)", kLinearRegex);
    if (stripped.find("VERTEX") == std::string::npos) return false; // (a line-by-line search is slow on MBs)
    std::size_t start = std::string::npos, middle = std::string::npos;
    int depth = 0;
    for (std::size_t line = 0; line < stripped.size();) {
        const std::size_t stop = std::min(stripped.find('\n', line), stripped.size());
        const std::string text1 = stripped.substr(line, stop - line);
        if (start == std::string::npos) {
            if (std::regex_search(text1, vertex)) start = line;
        } else if (depth == 0 && middle == std::string::npos && std::regex_search(text1, fragment)) {
            middle = stop;
        } else if (std::regex_search(text1, opens)) {
            ++depth;
        } else if (std::regex_search(text1, closes) && depth-- == 0) {
            if (middle == std::string::npos) return false;
            edits.push_back(blanked(text, start, middle - start));
            edits.push_back(blanked(text, line, stop - line));
            // Its inputs declared through its macro (`COMPAT_VARYING vec4 TEX0;`, `in` in a fragment
            // stage): plain globals, as a compute stage has no inputs.
            static const std::regex varying(R"((?:^|\n)[ \t]*(COMPAT_VARYING)[ \t]+\w+[ \t]+\w+[ \t]*;)", kLinearRegex);
            const std::string part = stripped.substr(middle, line - middle);
            for (auto it = std::sregex_iterator(part.begin(), part.end(), varying); it != std::sregex_iterator(); ++it)
                edits.push_back(blanked(text, middle + std::size_t(it->position(1)), std::size_t(it->length(1))));
            return true;
        }
        line = stop + 1;
    }
    return false;
}

// Vulkan's push constants (a struct and a global) and descriptor sets (gone from the layout).
bool vulkanEdits(const std::string& text, const std::string& stripped, std::vector<Edit>& edits) {
    static const std::regex layout(R"(\blayout\s*\(([^()]*)\))", kLinearRegex);
    static const std::regex set(R"(\bset\s*=\s*\d+\s*,?\s*)", kLinearRegex);
    static const std::regex pushed(R"(^\s*uniform\b)", kLinearRegex);
    bool vulkan = false;
    if (stripped.find("layout") == std::string::npos) return false;
    for (auto it = std::sregex_iterator(stripped.begin(), stripped.end(), layout); it != std::sregex_iterator(); ++it) {
        const std::size_t at = std::size_t(it->position(0)), length = std::size_t(it->length(0));
        const std::string inside = (*it)[1].str();
        std::smatch uniform;
        const std::string after = stripped.substr(at + length, 40);
        if (inside.find("push_constant") != std::string::npos && std::regex_search(after, uniform, pushed)) {
            edits.push_back(blanked(text, at, length));
            edits.push_back({at + length + std::size_t(uniform.position(0) + uniform.length(0)) - 7, 7, "struct"});
            vulkan = true;
        } else if (std::regex_search(inside, set)) {
            const std::string kept = std::regex_replace(inside, set, "");
            const bool empty = kept.find_first_not_of(" \t,") == std::string::npos;
            edits.push_back({at, length, empty ? std::string(length, ' ') : "layout(" + kept + ")"});
            vulkan = true;
        }
    }
    return vulkan;
}

// A uniform block without an instance name: its members plain uniforms. Each `uniform` word is
// tried where it stands (a regex search over MBs of code takes seconds).
void namelessBlockEdits(const std::string& text, const std::string& stripped, std::vector<Edit>& edits) {
    static const std::regex block(R"(\buniform\s+\w+\s*\{([^{}]*)\}\s*;)", kLinearRegex);
    static const std::regex layout(R"(\blayout\s*\([^()]*\)\s*$)", kLinearRegex);
    for (std::size_t word = stripped.find("uniform"), next = 0; word != std::string::npos;
         word = stripped.find("uniform", next)) {
        next = word + 7;
        const std::size_t closing = stripped.find('}', word);
        if (closing == std::string::npos) break;
        const std::size_t semicolon = stripped.find_first_not_of(" \t\r\n", closing + 1);
        const std::string candidate =
            stripped.substr(word, (semicolon == std::string::npos ? stripped.size() : semicolon + 1) - word);
        std::smatch match;
        if (!std::regex_search(candidate, match, block, std::regex_constants::match_continuous)) continue;
        if (word > 0 && isWordCharacter(stripped[word - 1])) continue;
        // `layout(std140) uniform Params { ... };`: the layout goes with it.
        std::size_t at = word;
        const std::size_t lookBack = std::min<std::size_t>(word, 200);
        const std::string before = stripped.substr(word - lookBack, lookBack);
        std::smatch qualifier;
        if (std::regex_search(before, qualifier, layout)) at = word - lookBack + std::size_t(qualifier.position(0));
        const std::size_t open = stripped.find('{', word);
        const std::size_t close = word + std::size_t(match.length(0)) - 1; // the ';'
        const std::size_t brace = closing;
        edits.push_back(blanked(text, at, open + 1 - at));
        for (std::size_t member = open + 1; member < brace;) {
            const std::size_t k = stripped.find_first_not_of(" \t\r\n", member);
            if (k >= brace) break;
            edits.push_back({k, 0, "uniform "});
            member = std::min(stripped.find(';', k), brace) + 1;
        }
        edits.push_back(blanked(text, brace, close + 1 - brace));
        next = close + 1;
    }
}

} // namespace

DialectText readGlslDialect(const std::string& text) {
    DialectText out;
    std::vector<Edit> edits;
    if (jitterEdits(text, edits))
        out.dialect = "Max/Jitter";
    else if (sokolEdits(text, edits))
        out.dialect = "sokol-shdc";
    const std::string sokol = applyEdits(text, std::move(edits));
    edits = {};
    const std::string stripped = stripComments(sokol);
    if (vulkanEdits(sokol, stripped, edits) && out.dialect.empty()) out.dialect = "Vulkan GLSL";
    if (retroArchEdits(sokol, stripped, edits) && out.dialect.empty()) out.dialect = "RetroArch";
    namelessBlockEdits(sokol, stripped, edits);
    if (out.dialect.empty() && edits.empty()) return out;
    out.text = applyEdits(sokol, std::move(edits));
    return out;
}

} // namespace sdfwb::shaders::detail
