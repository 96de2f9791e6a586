// Calls and statements read from a shader's text (CallText.h).

#include "CallText.h"
#include "ParameterText.h"
#include "Words.h"

#include <algorithm>
#include <cctype>

namespace sdfwb::shaders::detail {

std::size_t lineStart(const std::string& text, int line) {
    std::size_t at = 0;
    for (int i = 1; i < line; ++i) {
        at = text.find('\n', at);
        if (at == std::string::npos) return std::string::npos;
        ++at;
    }
    return at;
}

namespace {

// callArguments on `line` alone.
std::vector<std::string> callArgumentsOnLine(const std::string& text, int line, const std::string& name, std::string* before) {
    const std::size_t start = lineStart(text, line);
    if (start == std::string::npos) return {};
    const std::size_t end = std::min(text.find('\n', start), text.size());
    for (std::size_t at : wordOffsets(text, name, start, end)) {
        std::size_t open = text.find_first_not_of(" \t\r\n", at + name.size());
        if (open == std::string::npos || text[open] != '(') continue;
        std::vector<std::string> arguments;
        std::string current;
        int depth = 0;
        for (std::size_t i = open; i < text.size(); ++i) {
            const char c = text[i];
            if (c == '(' || c == '[' || c == '{') {
                if (depth++ == 0) continue;
            } else if (c == ')' || c == ']' || c == '}') {
                if (--depth == 0) {
                    arguments.push_back(trimmed(current));
                    if (before) *before = text.substr(start, at - start);
                    return arguments;
                }
            } else if (c == ',' && depth == 1) {
                arguments.push_back(trimmed(current));
                current.clear();
                continue;
            }
            current += c;
        }
        return {};
    }
    return {};
}

} // namespace

std::vector<std::string> callArguments(const std::string& text, int line, const std::string& name, std::string* before,
                                       int* nameLine) {
    for (int at = line; at >= std::max(1, line - 16); --at) {
        std::vector<std::string> arguments = callArgumentsOnLine(text, at, name, before);
        if (arguments.empty()) continue;
        if (nameLine) *nameLine = at;
        return arguments;
    }
    return {};
}

bool wholeStatements(const std::string& code) {
    const std::string end = trimmed(code);
    int braces = 0, parentheses = 0;
    for (char c : code) {
        braces += c == '{' ? 1 : c == '}' ? -1 : 0;
        parentheses += c == '(' ? 1 : c == ')' ? -1 : 0;
    }
    return braces == 0 && parentheses == 0 && (end.empty() || end.back() == ';' || end.back() == '}') &&
           !mentions(code, "return") && !mentions(code, "discard");
}

std::string enteredBlocks(std::string code, int& opened) {
    std::vector<std::size_t> open;
    for (std::size_t i = 0; i < code.size(); ++i) {
        if (code[i] == '{') open.push_back(i);
        if (code[i] == '}') {
            if (open.empty()) {
                opened = -1;
                return code;
            }
            open.pop_back();
        }
    }
    opened = int(open.size());
    auto spaceBefore = [&code](std::size_t at) {
        while (at > 0 && std::isspace(static_cast<unsigned char>(code[at - 1]))) --at;
        return at;
    };
    for (auto brace = open.rbegin(); brace != open.rend(); ++brace) {
        // The headers before the brace, innermost first: `for (...) for (...) {`, `else if (...) {`.
        std::size_t spanStart = spaceBefore(*brace);
        const std::size_t spanEnd = spanStart;
        std::string inits;
        for (;;) {
            const std::size_t at = spaceBefore(spanStart);
            if (at > 0 && code[at - 1] == ')') {
                int depth = 0;
                std::size_t paren = at - 1;
                for (;; --paren) {
                    depth += code[paren] == ')' ? 1 : code[paren] == '(' ? -1 : 0;
                    if (depth == 0 || paren == 0) break;
                }
                const std::size_t word = spaceBefore(paren);
                std::size_t wordStart = word;
                while (wordStart > 0 && isWordCharacter(code[wordStart - 1])) --wordStart;
                const std::string keyword = code.substr(wordStart, word - wordStart);
                if (depth != 0 || (keyword != "for" && keyword != "while" && keyword != "if")) break;
                if (keyword == "for") {
                    const std::string clauses = code.substr(paren + 1, at - 2 - paren);
                    int inner = 0;
                    std::size_t semicolon = 0;
                    while (semicolon < clauses.size() && !(clauses[semicolon] == ';' && inner == 0)) {
                        inner += clauses[semicolon] == '(' ? 1 : clauses[semicolon] == ')' ? -1 : 0;
                        ++semicolon;
                    }
                    const std::string init = trimmed(clauses.substr(0, semicolon));
                    if (!init.empty()) inits = init + "; " + inits;
                }
                spanStart = wordStart;
                continue;
            }
            std::size_t wordStart = at;
            while (wordStart > 0 && isWordCharacter(code[wordStart - 1])) --wordStart;
            const std::string keyword = code.substr(wordStart, at - wordStart);
            if (keyword == "else" || keyword == "do") {
                spanStart = wordStart;
                continue;
            }
            break;
        }
        code.replace(spanStart, spanEnd - spanStart, inits);
    }
    return code;
}

} // namespace sdfwb::shaders::detail
