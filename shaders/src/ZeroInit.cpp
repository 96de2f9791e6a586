#include "ZeroInit.h"
#include "TextEdits.h"

#include <shaders/SdfSource.h>

#include <core/Regex.h>

#include <algorithm>
#include <cctype>
#include <regex>
#include <vector>

namespace sdfwb::shaders::detail {
namespace {

bool isWord(char c) { return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_'; }

bool isValueType(const std::string& word) {
    static const std::regex types(R"((?:float|int|uint|bool|[biu]?vec[234]|mat[234](?:x[234])?))", kLinearRegex);
    return std::regex_match(word, types);
}

} // namespace

std::string zeroInitialised(const std::string& text) {
    const std::string s = stripComments(text); // same offsets, comments blanked
    // Directive lines are no code.
    std::vector<bool> directive(s.size() + 1, false);
    bool continued = false; // the line before was a directive ending in a backslash
    for (std::size_t start = 0; start < s.size();) {
        std::size_t stop = s.find('\n', start);
        if (stop == std::string::npos) stop = s.size();
        const std::size_t first = s.find_first_not_of(" \t\r", start);
        const bool isDirective = continued || (first < stop && s[first] == '#');
        for (std::size_t k = start; k < stop && isDirective; ++k) directive[k] = true;
        const std::size_t last = stop > start ? s.find_last_not_of(" \t\r", stop - 1) : std::string::npos;
        continued = isDirective && last != std::string::npos && last >= start && s[last] == '\\';
        start = stop + 1;
    }
    std::vector<Edit> inserts;
    // Per open brace: data rather than code (a struct's or an interface block's members, an
    // initializer list: no values written). At file scope only a function's body, after its `)`, is code.
    std::vector<bool> dataBody;
    int parens = 0;
    char previous = ';'; // the last character of code before this one
    bool statementStart = true, afterFor = false;
    for (std::size_t i = 0; i < s.size();) {
        const char c = s[i];
        if (directive[i] || c == ' ' || c == '\t' || c == '\r' || c == '\n' || c == '\f' || c == '\v') {
            ++i;
            continue;
        }
        if (!isWord(c)) {
            if (c == '(') {
                ++parens;
                statementStart = afterFor; // a for loop's init clause declares
            } else {
                if (c == ')') parens = std::max(0, parens - 1);
                if (c == '{') dataBody.push_back(dataBody.empty() ? previous != ')' : dataBody.back());
                if (c == '}' && !dataBody.empty()) dataBody.pop_back();
                statementStart = parens == 0 && (c == ';' || c == '{' || c == '}');
            }
            afterFor = false;
            previous = c;
            ++i;
            continue;
        }
        std::size_t end = i;
        while (end < s.size() && isWord(s[end])) ++end;
        const std::string word = s.substr(i, end - i);
        // Locals only: a global is zero already, and one mainImage sets before the march (dr2's
        // `float dstFar;`) must stay a plain global for the march analysis to see it set.
        const bool declares = statementStart && isValueType(word) && !dataBody.empty() && !dataBody.back();
        afterFor = word == "for";
        previous = 'w';
        statementStart = false;
        i = end;
        if (!declares) continue;
        // TYPE NAME [= VALUE] [, NAME [= VALUE]]... ; (or the for clause's `;`). Not `TYPE NAME(`
        // (a function), `TYPE[N] NAME` or an array among other names, `TYPE(...)` (an expression).
        std::size_t k = i;
        while (k < s.size() && (s[k] == ' ' || s[k] == '\t' || s[k] == '\n' || s[k] == '\r')) ++k;
        if (k >= s.size() || !isWord(s[k]) || std::isdigit(static_cast<unsigned char>(s[k]))) continue;
        std::vector<Edit> mine;
        bool ok = true;
        while (ok) {
            std::size_t nameEnd = k;
            while (nameEnd < s.size() && isWord(s[nameEnd])) ++nameEnd;
            std::size_t after = nameEnd;
            while (after < s.size() && (s[after] == ' ' || s[after] == '\t' || s[after] == '\n' || s[after] == '\r')) ++after;
            // An array alone in its declaration, in a body (`vec4 acc[N];`, not a for clause's):
            // zeroed by a loop after it, on its line, whatever N is (a macro, a constant).
            if (mine.empty() && parens == 0 && after < s.size() && s[after] == '[' && !directive[after]) {
                std::size_t close = s.find(']', after), semicolon = close;
                if (close != std::string::npos) semicolon = s.find_first_not_of(" \t\r\n", close + 1);
                if (semicolon != std::string::npos && s[semicolon] == ';' && s.find('[', after + 1) > close) {
                    const std::string name = s.substr(k, nameEnd - k);
                    mine.push_back({semicolon + 1, 0,
                                    " for (int sdfwb_zero = 0; sdfwb_zero < " + name + ".length(); ++sdfwb_zero) " + name +
                                        "[sdfwb_zero] = " + word + "(0);"});
                    break;
                }
            }
            if (nameEnd == k || after >= s.size() || s[after] == '(' || s[after] == '[' || directive[after]) {
                ok = false;
                break;
            }
            if (s[after] != '=') mine.push_back({nameEnd, 0, " = " + word + "(0)"});
            // To the declarator's end: a `,` or `;` outside parentheses and brackets.
            int depth = 0;
            std::size_t j = after;
            for (; j < s.size(); ++j) {
                if (s[j] == '(' || s[j] == '[') ++depth;
                if (s[j] == ')' || s[j] == ']') --depth;
                if (depth < 0 || (depth == 0 && (s[j] == ',' || s[j] == ';')) || s[j] == '{' || s[j] == '}') break;
            }
            if (j >= s.size() || depth < 0 || s[j] == '{' || s[j] == '}') {
                ok = false;
                break;
            }
            if (s[j] == ';') break;
            k = j + 1;
            while (k < s.size() && (s[k] == ' ' || s[k] == '\t' || s[k] == '\n' || s[k] == '\r')) ++k;
            if (k >= s.size() || !isWord(s[k])) ok = false;
        }
        if (ok) inserts.insert(inserts.end(), mine.begin(), mine.end());
    }
    return inserts.empty() ? text : applyEdits(text, std::move(inserts));
}

} // namespace sdfwb::shaders::detail
