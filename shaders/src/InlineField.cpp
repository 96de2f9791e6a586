#include "InlineField.h"
#include "Words.h"

#include <core/Regex.h>
#include <shaders/SdfSource.h>

#include <algorithm>
#include <map>
#include <optional>
#include <regex>
#include <set>

namespace sdfwb::shaders {
namespace {

using detail::isWordAt;

std::size_t skipSpace(const std::string& text, std::size_t at) {
    while (at < text.size() && std::isspace(static_cast<unsigned char>(text[at]))) ++at;
    return at;
}

// Just past the bracket that closes the one at `open` ((, [ or {), or npos.
std::size_t pastMatching(const std::string& text, std::size_t open) {
    int depth = 0;
    for (std::size_t i = open; i < text.size(); ++i) {
        const char c = text[i];
        if (c == '(' || c == '[' || c == '{') ++depth;
        if ((c == ')' || c == ']' || c == '}') && --depth == 0) return i + 1;
    }
    return std::string::npos;
}

// Just past the `( ... )` after `at` (spaces allowed before it), or npos.
std::size_t pastParentheses(const std::string& text, std::size_t at) {
    at = skipSpace(text, at);
    return at < text.size() && text[at] == '(' ? pastMatching(text, at) : std::string::npos;
}

bool isLoopKeyword(const std::string& text, std::size_t at) {
    return isWordAt(text, at, "for") || isWordAt(text, at, "while") || isWordAt(text, at, "do") || isWordAt(text, at, "switch");
}

std::string trimmedText(const std::string& text) {
    const std::size_t first = text.find_first_not_of(" \t\r\n");
    if (first == std::string::npos) return {};
    return text.substr(first, text.find_last_not_of(" \t\r\n") - first + 1);
}

} // namespace

std::size_t statementEnd(const std::string& text, std::size_t at) {
    at = skipSpace(text, at);
    if (at >= text.size()) return std::string::npos;
    if (text[at] == '{') return pastMatching(text, at);
    if (isWordAt(text, at, "if")) {
        std::size_t end = statementEnd(text, pastParentheses(text, at + 2));
        if (end == std::string::npos) return end;
        const std::size_t next = skipSpace(text, end);
        return isWordAt(text, next, "else") ? statementEnd(text, next + 4) : end;
    }
    if (isWordAt(text, at, "for") || isWordAt(text, at, "while"))
        return statementEnd(text, pastParentheses(text, at + (text[at] == 'f' ? 3 : 5)));
    if (isWordAt(text, at, "switch")) {
        const std::size_t header = skipSpace(text, pastParentheses(text, at + 6));
        return header < text.size() && text[header] == '{' ? pastMatching(text, header) : std::string::npos;
    }
    if (isWordAt(text, at, "do")) {
        const std::size_t body = statementEnd(text, at + 2);
        const std::size_t keyword = skipSpace(text, body);
        if (body == std::string::npos || !isWordAt(text, keyword, "while")) return std::string::npos;
        const std::size_t semicolon = skipSpace(text, pastParentheses(text, keyword + 5));
        return semicolon < text.size() && text[semicolon] == ';' ? semicolon + 1 : std::string::npos;
    }
    int depth = 0;
    for (std::size_t i = at; i < text.size(); ++i) {
        const char c = text[i];
        if (c == '(' || c == '[' || c == '{') ++depth;
        if (c == ')' || c == ']' || c == '}') {
            if (--depth < 0) return std::string::npos;
        }
        if (c == ';' && depth == 0) return i + 1;
    }
    return std::string::npos;
}

std::vector<std::string> splitStatements(const std::string& text) {
    std::vector<std::string> statements;
    for (std::size_t at = skipSpace(text, 0); at < text.size(); at = skipSpace(text, at)) {
        const std::size_t end = statementEnd(text, at);
        if (end == std::string::npos) return {};
        statements.push_back(text.substr(at, end - at));
        at = end;
    }
    return statements;
}

std::string withoutLoopExits(const std::string& text) {
    std::string out = text;
    for (std::size_t i = 0; i < out.size(); ++i) {
        if (i > 0 && isWordCharacter(out[i - 1])) continue;
        if (isLoopKeyword(out, i)) { // a nested loop keeps its own break and continue, not a return
            const std::size_t end = statementEnd(out, i);
            if (end == std::string::npos) return out;
            for (std::size_t k = i; k < end; ++k)
                for (const char* exit : {"return", "discard"})
                    if ((k == 0 || !isWordCharacter(out[k - 1])) && isWordAt(out, k, exit))
                        out.replace(k, std::char_traits<char>::length(exit), std::char_traits<char>::length(exit), ' ');
            i = end - 1;
            continue;
        }
        for (const char* exit : {"break", "continue", "return", "discard"})
            if (isWordAt(out, i, exit)) {
                out.replace(i, std::char_traits<char>::length(exit), std::char_traits<char>::length(exit), ' ');
                break;
            }
    }
    return out;
}

namespace {

// Object-like macros (`#define NAME body`, continuation lines joined) by name.
std::map<std::string, std::string> objectMacros(const std::string& text) {
    std::map<std::string, std::string> macros;
    for (std::size_t at = 0; at < text.size();) {
        std::size_t end = text.find('\n', at);
        while (end != std::string::npos && end > at && text[end - 1] == '\\') end = text.find('\n', end + 1);
        if (end == std::string::npos) end = text.size();
        std::string line = text.substr(at, end - at);
        at = end + 1;
        std::size_t i = skipSpace(line, 0);
        if (i >= line.size() || line[i] != '#') continue;
        i = skipSpace(line, i + 1);
        if (!isWordAt(line, i, "define")) continue;
        i = skipSpace(line, i + 6);
        std::size_t nameEnd = i;
        while (nameEnd < line.size() && isWordCharacter(line[nameEnd])) ++nameEnd;
        if (nameEnd == i || (nameEnd < line.size() && line[nameEnd] == '(')) continue; // function-like
        std::string body = line.substr(nameEnd);
        for (char& c : body)
            if (c == '\\' || c == '\n' || c == '\r') c = ' ';
        macros[line.substr(i, nameEnd - i)] = trimmedText(body);
    }
    return macros;
}

// `code` with each object-like macro replaced by its expansion, `depth` levels deep; a macro does
// not expand inside its own expansion, as the preprocessor's rule is.
std::string expandedMacros(const std::string& code, const std::map<std::string, std::string>& macros,
                           const std::set<std::string>& expanding, int depth) {
    std::string out;
    for (std::size_t i = 0; i < code.size();) {
        if (!isWordCharacter(code[i]) || (i > 0 && isWordCharacter(code[i - 1]))) {
            out += code[i++];
            continue;
        }
        std::size_t end = i;
        while (end < code.size() && isWordCharacter(code[end])) ++end;
        const std::string word = code.substr(i, end - i);
        auto macro = macros.find(word);
        if (macro == macros.end() || expanding.count(word) || depth <= 0 || std::isdigit(static_cast<unsigned char>(word[0]))) {
            out += word;
        } else {
            std::set<std::string> inner = expanding;
            inner.insert(word);
            out += " " + expandedMacros(macro->second, macros, inner, depth - 1) + " ";
        }
        i = end;
    }
    return out;
}

bool holdsLoopKeyword(const std::string& code) {
    for (std::size_t i = 0; i < code.size(); ++i)
        if (isWordAt(code, i, "for") || isWordAt(code, i, "while")) return true;
    return false;
}

} // namespace

std::string withLoopMacroExpanded(const std::string& text, std::size_t line) {
    const std::size_t lineEnd = std::min(text.find('\n', line), text.size());
    const std::string code = text.substr(line, lineEnd - line);
    if (holdsLoopKeyword(code) || code.find('#') != std::string::npos) return text;
    const std::map<std::string, std::string> macros = objectMacros(text);
    for (std::size_t i = 0; i < code.size(); ++i) {
        if (!isWordCharacter(code[i]) || (i > 0 && isWordCharacter(code[i - 1]))) continue;
        const std::size_t start = i;
        while (i + 1 < code.size() && isWordCharacter(code[i + 1])) ++i;
        const std::string word = code.substr(start, i + 1 - start);
        if (!macros.count(word)) continue;
        const std::string expansion = expandedMacros(word, macros, {}, 16);
        if (!holdsLoopKeyword(expansion)) continue;
        std::string out = text;
        out.replace(line + start, word.size(), expansion);
        return out;
    }
    return text;
}

namespace {

// `text` split at each `separator` outside parentheses and brackets (a for header's clauses, an
// increment's comma-separated parts).
std::vector<std::string> splitOutside(const std::string& text, char separator) {
    std::vector<std::string> parts(1);
    int depth = 0;
    for (char c : text) {
        depth += (c == '(' || c == '[') ? 1 : (c == ')' || c == ']') ? -1 : 0;
        if (c == separator && depth == 0)
            parts.emplace_back();
        else
            parts.back() += c;
    }
    return parts;
}

// `e += I, c += e * .35;`: an expression statement whose top-level commas sequence assignments,
// as separate statements (the comma operator's order). Declarations and calls stay whole.
std::vector<std::string> expandedCommas(const std::vector<std::string>& statements) {
    static const std::regex assignment(
        R"(^\s*(?:(?:--|\+\+)\s*)?[A-Za-z_]\w*\s*(?:\.\s*\w+\s*|\[[^\]]*\]\s*)*(?:[-+*/%&|^]?=[^=]|\+\+|--))", kLinearRegex);
    std::vector<std::string> out;
    for (const std::string& statement : statements) {
        const std::string text = trimmedText(statement);
        const std::vector<std::string> parts = !text.empty() && text.back() == ';' && std::regex_search(text, assignment)
                                                   ? splitOutside(text.substr(0, text.size() - 1), ',')
                                                   : std::vector<std::string>{};
        if (parts.size() < 2) {
            out.push_back(statement);
            continue;
        }
        for (const std::string& part : parts) out.push_back(trimmedText(part) + ";");
    }
    return out;
}

// A loop's initialisation, increment and body statements (and its test, when asked), from its
// keyword at `keyword`; false, with `why`, when they cannot be read.
bool readLoop(const std::string& text, std::size_t keyword, std::string& init, std::string& increment,
              std::vector<std::string>& statements, std::string& why, std::string* test = nullptr) {
    std::size_t bodyAt = std::string::npos;
    if (isWordAt(text, keyword, "for")) {
        const std::size_t open = skipSpace(text, keyword + 3);
        const std::size_t close = pastParentheses(text, keyword + 3);
        if (close == std::string::npos) {
            why = "its loop's header could not be read";
            return false;
        }
        const std::vector<std::string> clauses = splitOutside(text.substr(open + 1, close - open - 2), ';');
        if (clauses.size() != 3) {
            why = "its loop's header could not be read";
            return false;
        }
        init = trimmedText(clauses[0]);
        increment = clauses[2];
        if (test) *test = trimmedText(clauses[1]);
        bodyAt = close;
    } else if (isWordAt(text, keyword, "while")) {
        const std::size_t open = skipSpace(text, keyword + 5);
        bodyAt = pastParentheses(text, keyword + 5);
        if (test && bodyAt != std::string::npos) *test = trimmedText(text.substr(open + 1, bodyAt - open - 2));
    } else {
        why = "its loop is not a for or while loop";
        return false;
    }
    const std::size_t bodyEnd = bodyAt == std::string::npos ? bodyAt : statementEnd(text, bodyAt);
    if (bodyEnd == std::string::npos) {
        why = "its loop's body could not be read";
        return false;
    }
    std::string body = trimmedText(text.substr(bodyAt, bodyEnd - bodyAt));
    if (!body.empty() && body.front() == '{') body = body.substr(1, body.size() - 2);
    statements = expandedCommas(splitStatements(body));
    if (statements.empty()) {
        why = "its loop's body could not be split into statements";
        return false;
    }
    return true;
}

// The statement that sets the point (`vec3 A = p + q * k, b = A;`) with the point's own value the
// point given, so that what the statement copies from the point after it (b) sees the point given;
// nothing where it does not set the whole point with a plain `=`.
std::optional<std::string> pointGivenInPlace(const std::string& statement, const std::string& point) {
    const std::regex sets(R"((^|[^\w.])()" + point + R"()\s*=)", kLinearRegex);
    std::smatch match;
    if (!std::regex_search(statement, match, sets)) return std::nullopt;
    const std::size_t from = std::size_t(match.position(0) + match.length(0));
    if (from < statement.size() && statement[from] == '=') return std::nullopt; // `==`
    int depth = 0;
    for (std::size_t k = from; k < statement.size(); ++k) {
        const char c = statement[k];
        if (c == '(' || c == '[' || c == '{') ++depth;
        if ((c == ')' || c == ']' || c == '}') && --depth < 0) return std::nullopt;
        if (depth == 0 && (c == ',' || c == ';')) return statement.substr(0, from) + " sdfwb_point" + statement.substr(k);
    }
    return std::nullopt;
}

// `t += STEP`, or backwards `t -= STEP`: matched whole.
std::regex stepPattern(const std::string& counter) {
    return std::regex(R"(^\s*)" + counter + R"(\s*([-+])=\s*([\s\S]*);\s*$)", kLinearRegex);
}

// What a match of stepPattern steps by: STEP, or -(STEP) backwards.
std::string stepOf(const std::smatch& m) {
    const std::string by = trimmedText(m[2].str());
    return m[1].str() == "-" ? "-(" + by + ")" : by;
}

// The step in a for loop's increment (`i++, t += d`), or empty.
std::string stepInIncrement(const std::string& increment, const std::regex& steps) {
    std::string step;
    std::smatch match;
    for (const std::string& part : splitOutside(increment, ',')) {
        const std::string statement = part + ";";
        if (std::regex_match(statement, match, steps)) step = stepOf(match);
    }
    return step;
}

// Where a loop's statements compute its point from the counter: the first statement that assigns
// it from the counter (`vec3 p = ro + rd * t;`; statements.size() when none does), and the last of
// the statements right after it that only move or turn the point (`p.z -= 3.;`, `p.xz *=
// rot(iTime)`: +=, -= or *= by what reads neither the point nor the counter). Those place the
// camera: the given point is set after them, so that the scene sits where the shader's camera
// looks, not at the camera's distance from the origin.
struct PointPlacement {
    std::size_t pointAt, setAt;
};
PointPlacement placePoint(const std::vector<std::string>& statements, const std::string& counter, const std::string& point) {
    const std::regex assigns(R"((^|[^\w.])()" + point + R"()\s*(\.\s*\w+|\[[^\]]*\])?\s*[-+*/]?=[^=])", kLinearRegex);
    std::size_t pointAt = statements.size();
    for (std::size_t i = 0; i < statements.size() && pointAt == statements.size(); ++i)
        if (mentions(statements[i], counter) && std::regex_search(statements[i], assigns)) pointAt = i;
    const std::regex moves(R"(^\s*)" + point + R"(\s*(\.\s*[xyzrgbstpq]+)?\s*[-+*]=([\s\S]*);\s*$)", kLinearRegex);
    const std::regex unitMove(R"(^\s*(?:(?:--|\+\+)\s*)" + point + R"(|)" + point + R"(\s*(?:--|\+\+))\s*;\s*$)", kLinearRegex);
    std::size_t setAt = pointAt;
    for (std::size_t i = pointAt + 1; i < statements.size(); ++i) {
        if (std::regex_match(statements[i], unitMove)) { // `--p;`: a move by one
            setAt = i;
            continue;
        }
        std::smatch moved;
        if (!std::regex_match(statements[i], moved, moves) || mentions(moved[2].str(), point) ||
            mentions(moved[2].str(), counter))
            break;
        setAt = i;
    }
    return {pointAt, setAt};
}

// The statements before `end` but `skip`, their loop exits blanked, with the point the point given
// where `placed` says.
std::string givenStatements(const std::vector<std::string>& statements, const PointPlacement& placed, const std::string& point,
                            std::size_t skip, std::size_t end, int pointSize = 3) {
    const std::optional<std::string> inPlace =
        placed.setAt == placed.pointAt && placed.pointAt < statements.size() && pointSize == 3
            ? pointGivenInPlace(statements[placed.pointAt], point)
            : std::nullopt;
    std::string out;
    for (std::size_t i = 0; i < std::min(end, statements.size()); ++i) {
        if (i == skip) continue;
        out += withoutLoopExits(i == placed.pointAt && inPlace ? *inPlace : statements[i]) + "\n";
        if (i == placed.setAt && !inPlace) out += point + (pointSize == 4 ? ".xyz" : "") + " = sdfwb_point;\n";
    }
    return out;
}

} // namespace

std::string inlineFieldBody(const std::string& text, std::size_t keyword, const std::string& counter, const std::string& point,
                            std::string& step, std::string& why, int pointSize) {
    std::string init, increment;
    std::vector<std::string> statements;
    if (!readLoop(text, keyword, init, increment, statements, why)) return {};
    const std::regex steps = stepPattern(counter);
    // What the for header does after the step (golfed: `z += d, q = vec4(dir * z, .2), ..., d =
    // ...`) runs before the next pass's body: it comes first.
    const std::vector<std::string> parts = splitOutside(increment, ',');
    for (std::size_t k = 0; k + 1 < parts.size(); ++k)
        if (std::regex_match(parts[k] + ";", steps)) {
            std::vector<std::string> after;
            for (std::size_t j = k + 1; j < parts.size(); ++j) after.push_back(trimmedText(parts[j]) + ";");
            statements.insert(statements.begin(), after.begin(), after.end());
            break;
        }
    const PointPlacement placed = placePoint(statements, counter, point);
    if (placed.pointAt == statements.size()) {
        why = "the statement that computes '" + point + "' from '" + counter + "' was not found";
        return {};
    }
    std::size_t stepAt = statements.size();
    std::smatch match;
    for (std::size_t i = placed.pointAt + 1; i < statements.size(); ++i)
        if (std::regex_match(statements[i], match, steps)) {
            step = stepOf(match);
            stepAt = i;
            break;
        }
    if (stepAt == statements.size()) step = stepInIncrement(increment, steps); // `for (...; ...; i++, t += d)`
    if (step.empty()) {
        why = "the statement that advances '" + counter + "' is not one of its loop's own statements";
        return {};
    }
    return "{\n" + (init.empty() ? "" : init + ";\n") +
           givenStatements(statements, placed, point, statements.size(), stepAt, pointSize) + "return float(" + step + ");\n}\n";
}

std::string pointMarchBody(const std::string& text, std::size_t keyword, const std::string& point, std::string& field, int factor,
                           std::string& step, std::string& why) {
    std::string init, increment;
    std::vector<std::string> statements;
    if (!readLoop(text, keyword, init, increment, statements, why)) return {};
    // The step: `p += rd * d;`, or `q = p += ...;` that also copies the point.
    const std::regex steps(R"(^\s*((?:\w+\s*=\s*)?)()" + point + R"()\s*[-+]=\s*([\s\S]*);\s*$)", kLinearRegex);
    std::smatch match;
    std::size_t stepAt = statements.size();
    std::string copy;
    for (std::size_t i = 0; i < statements.size(); ++i)
        if (std::regex_match(statements[i], match, steps)) {
            copy = match[1].str();
            step = trimmedText(match[3].str());
            stepAt = i;
            break;
        }
    if (stepAt == statements.size()) {
        // `for (...; ...; p += D * d)`: the step follows the whole body.
        for (const std::string& part : splitOutside(increment, ',')) {
            const std::string statement = part + ";";
            if (step.empty() && std::regex_match(statement, match, steps) && trimmedText(match[1].str()).empty())
                step = trimmedText(match[3].str());
        }
    }
    if (stepAt == statements.size() && step.empty()) {
        why = "the statement that advances '" + point + "' is not one of its loop's own statements";
        return {};
    }
    // The field computed before the step (`d = ...; p += rd * d;`), or in it: the body up to the
    // step. Else (`p += rd * d; ... d = ...;`) the whole body, the step replaced by the point given.
    bool before = factor >= 0;
    if (before) {
        // `a * b * c` is `(a * b) * c`: the right factor is the last, the left all before it.
        const std::vector<std::string> factors = splitOutside(step, '*');
        if (factors.size() < 2) {
            why = "the step of '" + point + "' is not a product of the field and a direction: " + step;
            return {};
        }
        std::string left;
        for (std::size_t i = 0; i + 1 < factors.size(); ++i) left += (i ? "*" : "") + factors[i];
        field = trimmedText(factor == 1 ? factors.back() : "(" + trimmedText(left) + ")");
    } else {
        const std::regex assigns(R"((^|[^\w.])()" + field + R"()\s*[-+*/]?=[^=])", kLinearRegex);
        for (std::size_t i = 0; i < stepAt; ++i) before = before || std::regex_search(statements[i], assigns);
    }
    std::string out = "{\n";
    if (!init.empty()) out += init + ";\n";
    out += point + " = sdfwb_point;\n";
    for (std::size_t i = 0; i < (before ? stepAt : statements.size()); ++i) {
        if (i == stepAt) {
            if (!trimmedText(copy).empty()) out += copy + point + ";\n";
            continue;
        }
        out += withoutLoopExits(statements[i]) + "\n";
    }
    out += "return float(" + field + ");\n}\n";
    return out;
}

namespace {

// `text` without the parentheses that enclose all of it.
std::string withoutOuterParentheses(std::string text) {
    for (text = trimmedText(text); text.size() > 1 && text.front() == '(' && pastMatching(text, 0) == text.size();)
        text = trimmedText(text.substr(1, text.size() - 2));
    return text;
}

// A comparison `left op right`, op one of <, <=, > and >=.
struct Comparison {
    std::string left, op, right;
    std::string text() const { return left + " " + op + " " + right; }
};

// The parts of a condition that && and || join outside parentheses, each read as a comparison at
// its top level (parts that are none left out).
std::vector<Comparison> comparisonsOf(const std::string& condition) {
    std::vector<std::string> parts(1);
    int depth = 0;
    for (std::size_t i = 0; i < condition.size(); ++i) {
        const char c = condition[i];
        depth += (c == '(' || c == '[') ? 1 : (c == ')' || c == ']') ? -1 : 0;
        if (depth == 0 && (c == '&' || c == '|') && i + 1 < condition.size() && condition[i + 1] == c) {
            parts.emplace_back();
            ++i;
            continue;
        }
        parts.back() += c;
    }
    std::vector<Comparison> out;
    for (const std::string& part : parts) {
        const std::string text = withoutOuterParentheses(part);
        depth = 0;
        for (std::size_t i = 0; i < text.size(); ++i) {
            const char c = text[i];
            depth += (c == '(' || c == '[') ? 1 : (c == ')' || c == ']') ? -1 : 0;
            if (depth != 0 || (c != '<' && c != '>')) continue;
            if (i + 1 < text.size() && text[i + 1] == c) break; // a shift, not a comparison
            const std::size_t width = i + 1 < text.size() && text[i + 1] == '=' ? 2 : 1;
            out.push_back({trimmedText(text.substr(0, i)), text.substr(i, width), trimmedText(text.substr(i + width))});
            break;
        }
    }
    return out;
}

// An operand of a difference: as written where it is one name, member, number or call, else in
// parentheses.
std::string operand(const std::string& text) {
    static const std::regex simple(R"(^[\w.]+(\s*\([^()]*\))?$)", kLinearRegex);
    return std::regex_match(text, simple) ? text : "(" + text + ")";
}

// Whether `text` mentions one of `names`.
bool mentionsAny(const std::string& text, const std::set<std::string>& names) {
    return std::any_of(names.begin(), names.end(), [&](const std::string& name) { return mentions(text, name); });
}

// The first comparison of `condition` that `levels` makes a level (LevelNames), as the difference
// that is negative where the march stops: left - right when it stops where left is below right
// (`stops` and < or <=, or going on while left is above it). False when none does.
bool levelOf(const std::string& condition, bool stops, const LevelNames& levels, std::string& field, std::string& level) {
    for (const Comparison& comparison : comparisonsOf(condition))
        if (mentionsAny(comparison.left, levels.values) || mentionsAny(comparison.right, levels.values) ||
            (mentionsAny(comparison.left, levels.sides) && mentionsAny(comparison.right, levels.sides))) {
            const bool leftBelow = (comparison.op[0] == '<') == stops;
            field = leftBelow ? operand(comparison.left) + " - " + operand(comparison.right)
                              : operand(comparison.right) + " - " + operand(comparison.left);
            level = comparison.text();
            return true;
        }
    return false;
}

// An `if (C) { ... }` statement (with no else unless `orElse`): its condition and the block C runs;
// false when it is none.
bool readIf(const std::string& statement, std::string& condition, std::string& block, bool orElse = false) {
    const std::size_t at = skipSpace(statement, 0);
    if (!isWordAt(statement, at, "if")) return false;
    const std::size_t open = skipSpace(statement, at + 2), close = pastParentheses(statement, at + 2);
    if (close == std::string::npos) return false;
    const std::size_t end = statementEnd(statement, close);
    if (end == std::string::npos || (!orElse && skipSpace(statement, end) != statement.size())) return false;
    condition = statement.substr(open + 1, close - open - 2);
    block = trimmedText(statement.substr(close, end - close));
    if (!block.empty() && block.front() == '{') block = block.substr(1, block.size() - 2);
    return true;
}

} // namespace

std::string levelFieldBody(const std::string& text, std::size_t keyword, const std::string& counter, const std::string& point,
                           const LevelNames& levels, std::string& field, std::string& level, std::string& step,
                           std::string& why) {
    std::string init, increment, test;
    std::vector<std::string> statements;
    if (!readLoop(text, keyword, init, increment, statements, why, &test)) return {};
    const std::regex steps = stepPattern(counter);
    std::smatch match;
    std::size_t stepAt = statements.size();
    for (std::size_t i = 0; i < statements.size() && stepAt == statements.size(); ++i)
        if (std::regex_match(statements[i], match, steps)) step = stepOf(match), stepAt = i;
    // What keeps the march going: the loop's test, or an if that holds the step (`if (h < p.y) { t
    // += dt; p = ro + rd * t; h = f(p.xz); }`), whose block is then the loop's body.
    std::vector<std::string> going{test};
    if (stepAt == statements.size()) step = stepInIncrement(increment, steps);
    for (std::size_t i = 0; i < statements.size() && step.empty(); ++i) {
        std::string condition, block;
        if (!readIf(statements[i], condition, block)) continue;
        const std::vector<std::string> inner = expandedCommas(splitStatements(block));
        for (std::size_t k = 0; k < inner.size() && step.empty(); ++k)
            if (std::regex_match(inner[k], match, steps)) {
                step = stepOf(match), stepAt = k;
                going.push_back(condition);
                statements = inner;
            }
    }
    if (step.empty()) {
        why = "the statement that advances '" + counter + "' is not one of its loop's own statements";
        return {};
    }
    // The point: given at the start where the loop steps it itself (`p += rd * .05`), else where
    // the loop computes it from the counter.
    const bool marchesPoint = counter == point;
    const PointPlacement placed =
        marchesPoint ? PointPlacement{statements.size(), statements.size()} : placePoint(statements, counter, point);
    if (!marchesPoint && placed.pointAt == statements.size()) {
        why = "the statement that computes '" + point + "' from '" + counter + "' was not found";
        return {};
    }
    const std::string start = "{\n" + (init.empty() ? "" : init + ";\n") + (marchesPoint ? point + " = sdfwb_point;\n" : "");
    // A test after the point that stops the march (`if (p.y < h) break;`): the field is computed by
    // the statements before it. One before the point reads the last pass's values: all of them.
    for (std::size_t i = 0; i < statements.size(); ++i) {
        std::string condition, then;
        if (!readIf(statements[i], condition, then, true) || withoutLoopExits(then) == then || mentions(then, "continue") ||
            !levelOf(condition, true, levels, field, level))
            continue;
        const std::size_t end = marchesPoint || i > placed.pointAt ? i : statements.size();
        return start + givenStatements(statements, placed, point, stepAt, end) + "return float(" + field + ");\n}\n";
    }
    for (const std::string& condition : going)
        if (levelOf(condition, false, levels, field, level))
            return start + givenStatements(statements, placed, point, stepAt, statements.size()) + "return float(" + field +
                   ");\n}\n";
    why = "no test of its loop compares a value of '" + point + "' with a level";
    return {};
}

} // namespace sdfwb::shaders
