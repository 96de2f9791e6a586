// The parameter parser: a scan of the comment-stripped text at brace depth 0 for `uniform TYPE
// NAME = INIT;`, then the `//` comment after the `;` on that line of the original text.
#include <shaders/Parameters.h>

#include <shaders/SdfSource.h>

#include <core/Regex.h>
#include <core/TextFile.h>

#include "IsfHeader.h"
#include "ParameterText.h"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <map>
#include <regex>

namespace sdfwb::shaders {

const char* parameterTypeName(ParameterType type) {
    switch (type) {
    case ParameterType::Float:
        return "float";
    case ParameterType::Int:
        return "int";
    case ParameterType::Bool:
        return "bool";
    case ParameterType::Vec2:
        return "vec2";
    case ParameterType::Vec3:
        return "vec3";
    case ParameterType::Vec4:
        return "vec4";
    }
    return "float";
}

int componentCount(ParameterType type) {
    switch (type) {
    case ParameterType::Vec2:
        return 2;
    case ParameterType::Vec3:
        return 3;
    case ParameterType::Vec4:
        return 4;
    default:
        return 1;
    }
}

namespace {

bool isIdentifierStart(char c) { return std::isalpha(static_cast<unsigned char>(c)) || c == '_'; }
bool isIdentifierChar(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; }
bool isSpace(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\n' || c == '\f' || c == '\v'; }

std::optional<ParameterType> parseType(const std::string& word) {
    if (word == "float") return ParameterType::Float;
    if (word == "int") return ParameterType::Int;
    if (word == "bool") return ParameterType::Bool;
    if (word == "vec2") return ParameterType::Vec2;
    if (word == "vec3") return ParameterType::Vec3;
    if (word == "vec4") return ParameterType::Vec4;
    return std::nullopt;
}

} // namespace

std::string detail::trimmed(const std::string& text) {
    std::size_t begin = 0, end = text.size();
    while (begin < end && isSpace(text[begin])) ++begin;
    while (end > begin && isSpace(text[end - 1])) --end;
    return text.substr(begin, end - begin);
}

std::optional<float> detail::parseNumber(std::string text, bool integerOnly) {
    text = trimmed(text);
    if (text.empty() || text.size() > 64) return std::nullopt;
    if (!integerOnly && (text.back() == 'f' || text.back() == 'F') && text.find_first_of("xX") == std::string::npos)
        text.pop_back();
    const char* begin = text.c_str();
    char* end = nullptr;
    double value = 0.0;
    if (integerOnly) {
        for (std::size_t i = (text[0] == '-' || text[0] == '+') ? 1 : 0; i < text.size(); ++i)
            if (!std::isdigit(static_cast<unsigned char>(text[i]))) return std::nullopt;
        value = std::strtod(begin, &end);
        if (std::fabs(value) > 2147483647.0) return std::nullopt;
    } else {
        if (text.find_first_of("xXnN") != std::string::npos) return std::nullopt; // no hex floats, nan, inf
        value = std::strtod(begin, &end);
    }
    // The whole text, not up to a NUL inside it (strtod stops there).
    if (end != begin + text.size() || !std::isfinite(value) || !std::isfinite(float(value))) return std::nullopt;
    return float(value);
}

namespace {

using detail::parseList;
using detail::parseNumber;

struct Scanner {
    const std::string& original;
    const std::string& text; // comments blanked, same offsets
    const std::string& file;
    std::vector<std::size_t> lineStarts;
    ParameterScan result;

    std::pair<int, int> position(std::size_t offset) const {
        auto it = std::upper_bound(lineStarts.begin(), lineStarts.end(), offset);
        const std::size_t line = std::size_t(it - lineStarts.begin());
        return {int(line), int(offset - lineStarts[line - 1]) + 1};
    }

    void report(std::size_t offset, Severity severity, const std::string& message) {
        auto [line, column] = position(offset);
        result.diagnostics.push_back({file, line, column, severity, message});
    }

    std::size_t skipSpace(std::size_t i) const {
        while (i < text.size() && isSpace(text[i])) ++i;
        return i;
    }

    std::string identifierAt(std::size_t& i) const {
        std::size_t start = i;
        if (i < text.size() && isIdentifierStart(text[i]))
            while (i < text.size() && isIdentifierChar(text[i])) ++i;
        return text.substr(start, i - start);
    }

    // The initializer `text` into the parameter's default; false after reporting why.
    bool readInitializer(Parameter& p, const std::string& initializer, std::size_t offset) {
        const std::string value = detail::trimmed(initializer);
        const int n = componentCount(p.type);
        if (p.type == ParameterType::Bool) {
            if (value == "true" || value == "false") {
                p.defaultValue[0] = value == "true" ? 1.0f : 0.0f;
                return true;
            }
            report(offset, Severity::Error,
                   "parameter '" + p.name + "': a bool's default must be true or false, not '" + value + "'");
            return false;
        }
        if (n == 1) {
            auto number = parseNumber(value, p.type == ParameterType::Int);
            if (!number) {
                report(offset, Severity::Error,
                       "parameter '" + p.name + "': the default must be a " +
                           (p.type == ParameterType::Int ? std::string("whole number") : std::string("number")) + ", not '" +
                           value + "' (parameters take literal defaults)");
                return false;
            }
            p.defaultValue[0] = *number;
            return true;
        }
        const std::string constructor = parameterTypeName(p.type);
        std::size_t open = value.find('(');
        if (value.rfind(constructor, 0) != 0 || open == std::string::npos ||
            detail::trimmed(value.substr(constructor.size(), open - constructor.size())) != "" || value.back() != ')') {
            report(offset, Severity::Error,
                   "parameter '" + p.name + "': the default must be " + constructor + "(...) of numbers, not '" + value + "'");
            return false;
        }
        std::vector<float> numbers;
        std::string inner = value.substr(open + 1, value.size() - open - 2);
        std::size_t start = 0;
        while (true) {
            std::size_t comma = inner.find(',', start);
            auto number = parseNumber(inner.substr(start, comma == std::string::npos ? std::string::npos : comma - start), false);
            if (!number) {
                report(offset, Severity::Error,
                       "parameter '" + p.name + "': " + constructor + "(...) must hold numbers, not '" + value + "'");
                return false;
            }
            numbers.push_back(*number);
            if (comma == std::string::npos) break;
            start = comma + 1;
        }
        if (numbers.size() != 1 && int(numbers.size()) != n) {
            report(offset, Severity::Error,
                   "parameter '" + p.name + "': " + constructor + "(...) takes 1 or " + std::to_string(n) + " numbers, not " +
                       std::to_string(numbers.size()));
            return false;
        }
        for (int k = 0; k < n; ++k) p.defaultValue[std::size_t(k)] = numbers.size() == 1 ? numbers[0] : numbers[std::size_t(k)];
        return true;
    }

    // The annotations of the `//` comment starting at `offset` in the original text.
    void readAnnotations(Parameter& p, std::size_t offset, std::size_t end) {
        const std::string comment = original.substr(offset, end - offset);
        std::size_t i = 0;
        auto word = [&]() {
            while (i < comment.size() && isSpace(comment[i])) ++i;
            std::size_t start = i;
            while (i < comment.size() && !isSpace(comment[i])) ++i;
            return comment.substr(start, i - start);
        };
        while ((i = comment.find('@', i)) != std::string::npos) {
            const std::size_t at = offset + i;
            ++i;
            std::size_t start = i;
            while (i < comment.size() && isIdentifierChar(comment[i])) ++i;
            const std::string name = comment.substr(start, i - start);
            const bool integer = p.type == ParameterType::Int;
            if (name == "range") {
                const std::string a = word(), b = word();
                auto lo = parseNumber(a, integer), hi = parseNumber(b, integer);
                if (p.type == ParameterType::Bool) {
                    report(at, Severity::Error, "parameter '" + p.name + "': a bool takes no @range");
                } else if (!lo || !hi) {
                    report(at, Severity::Error,
                           "parameter '" + p.name + "': @range takes two " + (integer ? "whole numbers" : "numbers") +
                               " (@range MIN MAX), got '" + detail::trimmed(a + " " + b) + "'");
                } else if (!(*lo < *hi)) {
                    report(at, Severity::Error,
                           "parameter '" + p.name + "': @range " + a + " " + b + " is empty (MIN must be below MAX)");
                } else {
                    p.minimum = *lo;
                    p.maximum = *hi;
                }
            } else if (name == "step") {
                const std::string a = word();
                auto step = parseNumber(a, false);
                if (!step || !(*step > 0.0f))
                    report(at, Severity::Error, "parameter '" + p.name + "': @step takes a positive number, got '" + a + "'");
                else
                    p.step = *step;
            } else if (name == "log") {
                p.logarithmic = true;
            } else if (name == "color") {
                if (p.type != ParameterType::Vec3 && p.type != ParameterType::Vec4)
                    report(at, Severity::Error,
                           "parameter '" + p.name + "': @color needs a vec3 or vec4, not a " + parameterTypeName(p.type));
                else
                    p.color = true;
            } else if (name == "label") {
                while (i < comment.size() && isSpace(comment[i])) ++i;
                if (i < comment.size() && comment[i] == '"') {
                    std::size_t close = comment.find('"', i + 1);
                    if (close == std::string::npos) {
                        report(at, Severity::Error, "parameter '" + p.name + "': @label's text has no closing quote");
                        i = comment.size();
                    } else {
                        p.label = comment.substr(i + 1, close - i - 1);
                        i = close + 1;
                    }
                } else {
                    p.label = word();
                    if (p.label.empty())
                        report(at, Severity::Error, "parameter '" + p.name + "': @label takes a text (@label \"Radius\")");
                }
            } else {
                report(at, Severity::Warning,
                       "parameter '" + p.name + "': unknown annotation '@" + name +
                           "' (known: @range, @step, @log, @label, @color)");
            }
        }
        if (p.logarithmic && (!p.minimum || !(*p.minimum > 0.0f))) {
            report(offset, Severity::Error, "parameter '" + p.name + "': @log needs a @range with a positive minimum");
            p.logarithmic = false;
        }
        if (p.minimum && p.maximum)
            for (int k = 0; k < componentCount(p.type); ++k) {
                const float v = p.defaultValue[std::size_t(k)];
                if (v < *p.minimum || v > *p.maximum) {
                    report(offset, Severity::Warning, "parameter '" + p.name + "': the default lies outside its @range");
                    break;
                }
            }
    }

    void scan() {
        lineStarts.push_back(0);
        for (std::size_t i = 0; i < original.size(); ++i)
            if (original[i] == '\n') lineStarts.push_back(i + 1);
        int depth = 0;
        for (std::size_t i = 0; i < text.size();) {
            const char c = text[i];
            if (c == '{') ++depth;
            if (c == '}') depth = std::max(0, depth - 1);
            if (c == '#') { // a preprocessor line: skip it (with its continuations)
                while (i < text.size() && text[i] != '\n') i += (text[i] == '\\' && i + 1 < text.size()) ? 2 : 1;
                continue;
            }
            if (!isIdentifierStart(c) || (i > 0 && isIdentifierChar(text[i - 1]))) {
                ++i;
                continue;
            }
            const std::size_t start = i;
            const std::string word = identifierAt(i);
            if (word != "uniform" || depth != 0) continue;
            declaration(start, i);
        }
    }

    // After `uniform` at `start` (ending at `i`).
    void declaration(std::size_t start, std::size_t& i) {
        std::size_t j = skipSpace(i);
        std::string typeWord = identifierAt(j);
        for (const char* precision : {"lowp", "mediump", "highp"})
            if (typeWord == precision) {
                j = skipSpace(j);
                typeWord = identifierAt(j);
            }
        auto type = parseType(typeWord);
        if (!type) return; // samplers, other types, blocks: not parameters
        j = skipSpace(j);
        const std::size_t nameOffset = j;
        const std::string name = identifierAt(j);
        if (name.empty()) return;
        j = skipSpace(j);
        if (j < text.size() && (text[j] == '[' || text[j] == ',')) return; // arrays and lists are not parameters
        std::string initializer;
        bool hasInitializer = false;
        std::size_t initializerOffset = j;
        std::size_t initializerEnd = j;
        if (j < text.size() && text[j] == '=') {
            hasInitializer = true;
            initializerOffset = skipSpace(j + 1);
            std::size_t k = j + 1;
            int parens = 0;
            // A directive line ends it: what follows is no initializer we read (a `#iUniform` line,
            // then another uniform's `;`, would take that uniform with it).
            auto directiveLine = [&](std::size_t at) {
                return text[at] == '\n' && text.find_first_not_of(" \t\r", at + 1) < text.size() &&
                       text[text.find_first_not_of(" \t\r", at + 1)] == '#';
            };
            while (k < text.size() && !(text[k] == ';' && parens == 0) && text[k] != '{' && text[k] != '}' && !directiveLine(k)) {
                if (text[k] == '(') ++parens;
                if (text[k] == ')') --parens;
                ++k;
            }
            initializer = text.substr(j + 1, k - j - 1);
            initializerEnd = k;
            while (initializerEnd > initializerOffset && isSpace(text[initializerEnd - 1])) --initializerEnd;
            j = k;
        }
        if (j >= text.size() || text[j] != ';') return; // not a declaration we understand: leave it to the compiler
        i = j + 1;
        // The comment on the line of the `;`, in the original text.
        const std::size_t lineEnd = std::min(original.find('\n', j), original.size());
        const std::size_t commentStart = original.find("//", j);
        const bool annotated = commentStart < lineEnd && original.find('@', commentStart) < lineEnd;
        Parameter p;
        p.name = name;
        p.type = *type;
        auto [line, column] = position(start);
        p.line = line;
        p.column = column;
        if (!hasInitializer) {
            if (fragmentariumAnnotation(p, j + 1, lineEnd)) {
                add(std::move(p), nameOffset);
                return;
            }
            if (annotated)
                report(nameOffset, Severity::Error,
                       "parameter '" + name + "': annotated uniforms need a default (uniform " + typeWord + " " + name +
                           " = ...;)");
            return;
        }
        p.initializerOffset = initializerOffset;
        p.initializerLength = initializerEnd - initializerOffset;
        if (!readInitializer(p, initializer, initializerOffset)) return;
        if (annotated) readAnnotations(p, commentStart + 2, lineEnd);
        add(std::move(p), nameOffset);
    }

    void add(Parameter p, std::size_t nameOffset) {
        for (const Parameter& other : result.parameters)
            if (other.name == p.name) {
                report(nameOffset, Severity::Error,
                       "parameter '" + p.name + "' is declared twice (first at line " + std::to_string(other.line) + ")");
                return;
            }
        result.parameters.push_back(std::move(p));
    }

    // Splits `inner` at the commas outside parentheses: (offset, length) of each item, trimmed.
    std::vector<std::pair<std::size_t, std::size_t>> items(std::size_t from, std::size_t to) const {
        std::vector<std::pair<std::size_t, std::size_t>> out;
        int parens = 0;
        std::size_t start = from;
        for (std::size_t k = from; k <= to; ++k) {
            if (k < to && text[k] == '(') ++parens;
            if (k < to && text[k] == ')') --parens;
            if (k == to || (text[k] == ',' && parens == 0)) {
                std::size_t a = start, b = k;
                while (a < b && isSpace(text[a])) ++a;
                while (b > a && isSpace(text[b - 1])) --b;
                out.emplace_back(a, b - a);
                start = k + 1;
            }
        }
        return out;
    }

    // One value of a Fragmentarium annotation: a number, true/false, or `(x,y,z)` for a vector.
    std::optional<std::array<float, 4>> fragmentariumValue(const Parameter& p, std::string value) const {
        value = detail::trimmed(value);
        const int n = componentCount(p.type);
        std::array<float, 4> out{};
        if (p.type == ParameterType::Bool) {
            if (value != "true" && value != "false") return std::nullopt;
            out[0] = value == "true" ? 1.0f : 0.0f;
            return out;
        }
        if (n > 1) {
            if (value.size() >= 2 && value.front() == '(' && value.back() == ')') value = value.substr(1, value.size() - 2);
            auto list = parseList(value);
            if (!list || (list->size() != 1 && int(list->size()) != n)) return std::nullopt;
            for (int k = 0; k < n; ++k) out[std::size_t(k)] = list->size() == 1 ? (*list)[0] : (*list)[std::size_t(k)];
            return out;
        }
        auto number = parseNumber(value, p.type == ParameterType::Int);
        if (!number) return std::nullopt;
        out[0] = *number;
        return out;
    }

    // Fragmentarium's annotation after a declaration's `;` on its line (`slider[MIN,DEFAULT,MAX]`,
    // vectors as `(x,y,z)`; `checkbox[true]`; `color[R,G,B]`), optionally followed by Locked or
    // NotLocked: the parameter's default and range. False when there is none.
    bool fragmentariumAnnotation(Parameter& p, std::size_t from, std::size_t lineEnd) {
        std::size_t k = skipSpace(from);
        if (k >= lineEnd) return false;
        const std::size_t at = k;
        const std::string kind = identifierAt(k);
        if (kind != "slider" && kind != "checkbox" && kind != "color") return false;
        k = skipSpace(k);
        const std::size_t close = text.find(']', k);
        if (k >= lineEnd || text[k] != '[' || close == std::string::npos || close > lineEnd) {
            report(at, Severity::Error, "parameter '" + p.name + "': " + kind + "[...] has no closing ]");
            return false;
        }
        // `slider[uniform float B; slider[0,1,2]`: the ] closes another annotation, whose numbers are not this one's.
        if (const std::size_t open = text.find('[', k + 1); open < close) {
            report(open, Severity::Error, "parameter '" + p.name + "': " + kind + "[...] has no closing ] before this [");
            return false;
        }
        const auto parts = items(k + 1, close);
        const std::string form = kind == "slider"     ? "slider[MIN,DEFAULT,MAX]"
                                 : kind == "checkbox" ? "checkbox[true|false]"
                                                      : "color[R,G,B]";
        const bool typeFits = kind == "slider"     ? p.type != ParameterType::Bool
                              : kind == "checkbox" ? p.type == ParameterType::Bool
                                                   : p.type == ParameterType::Vec3 || p.type == ParameterType::Vec4;
        if (!typeFits) {
            report(at, Severity::Error,
                   "parameter '" + p.name + "': " + kind + "[...] does not fit a " + parameterTypeName(p.type));
            return false;
        }
        if (kind == "color") {
            // Three numbers, the colour (a vec4's alpha 1); or, for a vec4, Fragmentarium's six:
            // the alpha's slider (MIN, DEFAULT, MAX), then the colour. New defaults rewrite the colour.
            const bool withAlpha = p.type == ParameterType::Vec4 && parts.size() == 6;
            const std::size_t first = withAlpha ? 3 : 0;
            std::string list;
            for (std::size_t k = first; k < parts.size(); ++k)
                list += (list.empty() ? "" : ",") + text.substr(parts[k].first, parts[k].second);
            auto value = parts.size() - first == 3 ? parseList(list) : std::nullopt;
            auto alpha =
                withAlpha ? parseNumber(text.substr(parts[1].first, parts[1].second), false) : std::optional<float>(1.0f);
            if (!value || value->size() != 3 || !alpha) {
                report(at, Severity::Error,
                       "parameter '" + p.name + "': expected " +
                           (p.type == ParameterType::Vec4 ? "color[R,G,B] or color[MIN,ALPHA,MAX,R,G,B]" : form));
                return false;
            }
            p.defaultValue = std::array<float, 4>{(*value)[0], (*value)[1], (*value)[2], *alpha};
            p.color = true;
            p.initializerOffset = parts[first].first;
            p.initializerLength = parts.back().first + parts.back().second - parts[first].first;
        } else {
            const std::size_t index = kind == "slider" ? 1 : 0;
            if (parts.size() != (kind == "slider" ? 3u : 1u)) {
                report(at, Severity::Error, "parameter '" + p.name + "': expected " + form);
                return false;
            }
            auto value = fragmentariumValue(p, text.substr(parts[index].first, parts[index].second));
            if (!value) {
                report(parts[index].first, Severity::Error,
                       "parameter '" + p.name + "': '" + text.substr(parts[index].first, parts[index].second) +
                           "' is not a default for a " + parameterTypeName(p.type) + " (" + form + ")");
                return false;
            }
            p.defaultValue = *value;
            p.initializerOffset = parts[index].first;
            p.initializerLength = parts[index].second;
            if (kind == "slider") { // one range for every component: the widest the slider gives
                auto lo = fragmentariumValue(p, text.substr(parts[0].first, parts[0].second));
                auto hi = fragmentariumValue(p, text.substr(parts[2].first, parts[2].second));
                if (lo && hi) {
                    const int n = componentCount(p.type);
                    p.minimum = *std::min_element(lo->begin(), lo->begin() + n);
                    p.maximum = *std::max_element(hi->begin(), hi->begin() + n);
                    if (!(*p.minimum < *p.maximum)) p.minimum = p.maximum = std::nullopt;
                }
            }
        }
        p.syntax = Parameter::Syntax::FragmentariumSlider;
        return true;
    }

    // Fragmentarium's `#preset Default` block (else its first preset), whose `Name = value` lines
    // set the defaults it loads with: they override the sliders' (and are where new defaults go).
    void applyPreset() {
        for (const detail::PresetLine& line : detail::defaultPresetLines(original)) {
            auto it = std::find_if(result.parameters.begin(), result.parameters.end(),
                                   [&](const Parameter& p) { return p.name == line.name; });
            if (it == result.parameters.end()) continue;
            const std::string text = original.substr(line.valueOffset, line.valueLength);
            auto value = fragmentariumValue(*it, text);
            if (!value) {
                report(line.valueOffset, Severity::Warning,
                       "preset value '" + text + "' for '" + line.name + "' is not a " + parameterTypeName(it->type) +
                           ": the slider's default is kept");
                continue;
            }
            it->defaultValue = *value;
            it->initializerOffset = line.valueOffset;
            it->initializerLength = line.valueLength;
            it->syntax = Parameter::Syntax::FragmentariumPreset;
        }
    }
};

} // namespace

std::vector<detail::PresetLine> detail::defaultPresetLines(const std::string& text) {
    std::vector<PresetLine> lines;
    std::size_t begin = std::string::npos;
    for (std::size_t at = 0; (at = text.find("#preset", at)) != std::string::npos; at += 7) {
        if (at > 0 && text[at - 1] != '\n' && !isSpace(text[at - 1])) continue;
        const std::size_t k = at + 7;
        const std::string name = trimmed(text.substr(k, std::min(text.find('\n', k), text.size()) - k));
        if (begin == std::string::npos || name == "Default") begin = at;
        if (name == "Default") break;
    }
    if (begin == std::string::npos) return lines;
    const std::size_t end = std::min(text.find("#endpreset", begin), text.size());
    for (std::size_t line = text.find('\n', begin); line != std::string::npos && line < end; line = text.find('\n', line + 1)) {
        const std::size_t start = line + 1;
        const std::size_t stop = std::min(text.find('\n', start), end);
        const std::size_t equals = text.find('=', start);
        if (equals == std::string::npos || equals >= stop) continue;
        std::size_t a = equals + 1, b = stop;
        while (a < b && isSpace(text[a])) ++a;
        while (b > a && isSpace(text[b - 1])) --b;
        for (const std::string word : {"NotLocked", "Locked"}) { // `Scale = 2.5 Locked`
            if (b - a > word.size() && text.compare(b - word.size(), word.size(), word) == 0 &&
                isSpace(text[b - word.size() - 1])) {
                b -= word.size();
                while (b > a && isSpace(text[b - 1])) --b;
                break;
            }
        }
        lines.push_back({trimmed(text.substr(start, equals - start)), a, b - a});
    }
    return lines;
}

namespace {

// An ISF input's (or a scene control's) DEFAULT on p's components (one number fills them all, a
// shorter list leaves the rest, such as a colour's alpha), a non-finite one 0; its MIN and MAX as p's
// range (a vector's widest), none for a bool or a colour or where they are empty or not finite.
void setDefaultAndRange(Parameter& p, const detail::IsfInput& input) {
    for (int k = 0; k < componentCount(p.type) && !input.value.empty(); ++k)
        if (input.value.size() == 1 || std::size_t(k) < input.value.size())
            p.defaultValue[std::size_t(k)] = float(input.value[input.value.size() == 1 ? 0 : std::size_t(k)]);
    for (float& v : p.defaultValue)
        if (!std::isfinite(v)) v = 0.0f; // a double beyond a float's range
    if (!input.low.empty() && !input.high.empty() && p.type != ParameterType::Bool && !p.color) {
        p.minimum = float(*std::min_element(input.low.begin(), input.low.end()));
        p.maximum = float(*std::max_element(input.high.begin(), input.high.end()));
        if (!(*p.minimum < *p.maximum) || !std::isfinite(*p.minimum) || !std::isfinite(*p.maximum))
            p.minimum.reset(), p.maximum.reset();
    }
}

// An ISF header's INPUTS that are values (not images or audio), as parameters: the host declares
// them as uniforms (ForeignHosts.cpp declares them in sdfwb's text). Ranges from MIN and MAX (a
// point2D's widest), a colour's alpha 1 where its DEFAULT leaves it out.
std::vector<Parameter> isfParameters(const std::string& text) {
    std::vector<Parameter> out;
    for (const detail::IsfInput& input : detail::readIsfHeader(text).inputs) {
        Parameter p;
        p.name = input.name;
        p.label = input.label;
        if (input.type == "float")
            p.type = ParameterType::Float;
        else if (input.type == "long" || input.type == "int") // int: MadMapper's materials
            p.type = ParameterType::Int;
        else if (input.type == "bool" || input.type == "event")
            p.type = ParameterType::Bool;
        else if (input.type == "color")
            p.type = ParameterType::Vec4, p.color = true, p.defaultValue[3] = 1.0f;
        else if (input.type == "point2D")
            p.type = ParameterType::Vec2;
        else
            continue;
        setDefaultAndRange(p, input);
        // As saving writes them back: a long's default a whole number, a bool's true or false.
        if (p.type == ParameterType::Int)
            p.defaultValue[0] = std::abs(p.defaultValue[0]) < 1e9f ? std::trunc(p.defaultValue[0]) : 0.0f;
        if (p.type == ParameterType::Bool) p.defaultValue[0] = p.defaultValue[0] != 0.0f ? 1.0f : 0.0f;
        p.line = 1 + int(std::count(text.begin(), text.begin() + std::ptrdiff_t(input.nameOffset), '\n'));
        p.column = 1 + int(input.nameOffset - (text.rfind('\n', input.nameOffset) + 1));
        p.initializerOffset = input.valueLength ? input.valueOffset : 0;
        p.initializerLength = input.valueLength;
        p.syntax = Parameter::Syntax::Isf;
        out.push_back(std::move(p));
    }
    return out;
}

// The VS Code Shader Toy extension's `#iUniform TYPE NAME = VALUE [in { MIN, MAX }] [step S]` lines
// (ForeignHosts.cpp declares the uniforms): float, int, vec2-4 and its colours color3/color4. VALUE
// is a number or a constructor, one argument filling every component; saving rewrites it as GLSL.
std::vector<Parameter> vscodeParameters(const std::string& text) {
    static const std::regex directive(R"(^[ \t]*#[ \t]*iUniform[ \t]+(\w+)[ \t]+(\w+)[ \t]*=[ \t]*)", kLinearRegex);
    static const std::regex range(R"([ \t]in[ \t]*\{([^}]*)\})", kLinearRegex);
    static const std::regex step(R"([ \t]step[ \t]+([^ \t;\r]+))", kLinearRegex);
    static const std::map<std::string, std::pair<ParameterType, bool>, std::less<>> types{
        {"float", {ParameterType::Float, false}}, {"int", {ParameterType::Int, false}},   {"vec2", {ParameterType::Vec2, false}},
        {"vec3", {ParameterType::Vec3, false}},   {"vec4", {ParameterType::Vec4, false}}, {"color3", {ParameterType::Vec3, true}},
        {"color4", {ParameterType::Vec4, true}}};
    auto numbers = [](std::string list) {
        std::vector<float> out;
        for (std::size_t start = 0; start <= list.size();) {
            std::size_t stop = std::min(list.find(',', start), list.size());
            std::string piece = list.substr(start, stop - start);
            piece.erase(0, piece.find_first_not_of(" \t"));
            piece.erase(piece.find_last_not_of(" \t") + 1);
            char* end = nullptr;
            const float v = std::strtof(piece.c_str(), &end);
            if (piece.empty() || end != piece.c_str() + piece.size() || !std::isfinite(v)) return std::vector<float>{};
            out.push_back(v);
            start = stop + 1;
        }
        return out;
    };
    const std::string stripped = stripComments(text);
    std::vector<Parameter> out;
    for (std::size_t lineStart = 0, lineNumber = 1; lineStart < stripped.size(); ++lineNumber) {
        const std::size_t lineEnd = std::min(stripped.find('\n', lineStart), stripped.size());
        const std::string line = stripped.substr(lineStart, lineEnd - lineStart);
        std::smatch match;
        auto type = types.end();
        if (line.find("iUniform") != std::string::npos && std::regex_search(line, match, directive) &&
            (type = types.find(match[1].str())) != types.end()) {
            Parameter p;
            p.name = match[2].str();
            p.type = type->second.first;
            p.color = type->second.second;
            p.line = int(lineNumber);
            p.column = 1 + int(match.position(2));
            // VALUE runs to ` in {`, ` step` or the line's end (a `;` and spaces left out).
            const std::string rest = match.suffix().str();
            std::smatch inRange, inStep;
            const bool hasRange = std::regex_search(rest, inRange, range), hasStep = std::regex_search(rest, inStep, step);
            std::size_t valueEnd = std::min(hasRange ? std::size_t(inRange.position(0)) : rest.size(),
                                            hasStep ? std::size_t(inStep.position(0)) : rest.size());
            while (valueEnd > 0 && std::strchr(" \t;\r", rest[valueEnd - 1])) --valueEnd;
            std::string value = rest.substr(0, valueEnd);
            p.initializerOffset = lineStart + std::size_t(match.length(0));
            p.initializerLength = valueEnd;
            const std::size_t open = value.find('('), close = value.rfind(')');
            if (open != std::string::npos && close == value.size() - 1) value = value.substr(open + 1, close - open - 1);
            const std::vector<float> given = numbers(value);
            for (int k = 0; k < componentCount(p.type) && !given.empty(); ++k)
                p.defaultValue[std::size_t(k)] = given[std::min(std::size_t(k), given.size() - 1)];
            if (p.type == ParameterType::Int) p.defaultValue[0] = std::trunc(p.defaultValue[0]);
            if (const std::vector<float> bounds = numbers(hasRange ? inRange[1].str() : "");
                bounds.size() == 2 && bounds[0] < bounds[1])
                p.minimum = bounds[0], p.maximum = bounds[1];
            if (const std::vector<float> by = numbers(hasStep ? inStep[1].str() : ""); by.size() == 1 && by[0] > 0.0f)
                p.step = by[0];
            out.push_back(std::move(p));
        }
        lineStart = lineEnd + 1;
    }
    return out;
}

// A Synesthesia scene's controls: its main.glsl (a `vec4 renderMain()`) reads them, its scene.json
// beside it declares them (CONTROLS: sliders, knobs, toggles and bangs are floats, an xy pad a
// vec2, a colour a vec3). ForeignHosts.cpp declares them as uniforms. scene.json is another file:
// its defaults are read, not rewritten (saving leaves them out, as an ISF input without DEFAULT).
std::vector<Parameter> synesthesiaParameters(const std::string& text, const std::string& file) {
    static const std::regex renderMain(R"(\bvec4\s+renderMain\s*\(\s*\)\s*\{)", kLinearRegex);
    if (file.empty() || file.front() == '<' || text.find("renderMain") == std::string::npos ||
        !std::regex_search(stripComments(text), renderMain))
        return {};
    std::error_code error;
    const std::filesystem::path scene = std::filesystem::path(file).parent_path() / "scene.json";
    if (!std::filesystem::is_regular_file(scene, error)) return {};
    const auto json = readTextFile(scene);
    if (!json) return {};
    std::vector<Parameter> out;
    for (const detail::IsfInput& input : detail::readSceneControls(*json)) {
        Parameter p;
        p.name = input.name;
        const std::string kind = input.type.substr(0, input.type.find(' '));
        if (kind == "slider" || kind == "knob" || kind == "toggle" || kind == "bang" || kind == "dropdown")
            p.type = ParameterType::Float;
        else if (kind == "xy")
            p.type = ParameterType::Vec2;
        else if (kind == "color")
            p.type = ParameterType::Vec3, p.color = true;
        else
            continue;
        setDefaultAndRange(p, input);
        p.label = input.name + " (scene.json)";
        p.syntax = Parameter::Syntax::Isf; // initializerLength 0: saving leaves it out
        out.push_back(std::move(p));
    }
    return out;
}

} // namespace

ParameterScan parseParameters(const std::string& text, const std::string& file) {
    const std::string stripped = stripComments(text);
    Scanner scanner{text, stripped, file, {}, {}};
    scanner.scan();
    scanner.applyPreset();
    std::vector<Parameter> hosts = isfParameters(text);
    for (Parameter& p : vscodeParameters(text)) hosts.push_back(std::move(p));
    for (Parameter& p : synesthesiaParameters(text, file)) hosts.push_back(std::move(p));
    for (Parameter& p : hosts)
        if (std::none_of(scanner.result.parameters.begin(), scanner.result.parameters.end(),
                         [&](const Parameter& other) { return other.name == p.name; }))
            scanner.result.parameters.push_back(std::move(p));
    return std::move(scanner.result);
}

} // namespace sdfwb::shaders
