// Calls and statements read from a shader's text (CallText.h).

#include "CallText.h"
#include "ParameterText.h"
#include "Words.h"

#include <algorithm>

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

} // namespace sdfwb::shaders::detail
