// The parameter parser: a scan of the comment-stripped text at brace depth 0 for `uniform TYPE
// NAME = INIT;`, then the `//` comment after the `;` on that line of the original text.
#include <shaders/Parameters.h>

#include <shaders/SdfSource.h>

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdlib>
#include <cstring>

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

std::string trim(const std::string& text) {
    std::size_t begin = 0, end = text.size();
    while (begin < end && isSpace(text[begin])) ++begin;
    while (end > begin && isSpace(text[end - 1])) --end;
    return text.substr(begin, end - begin);
}

// A whole number or floating literal, as GLSL writes them (a trailing f/F allowed), finite.
std::optional<float> parseNumber(std::string text, bool integerOnly) {
    text = trim(text);
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
    if (end == begin || *end != '\0' || !std::isfinite(value) || !std::isfinite(float(value))) return std::nullopt;
    return float(value);
}

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
        const std::string value = trim(initializer);
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
            trim(value.substr(constructor.size(), open - constructor.size())) != "" || value.back() != ')') {
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
                               " (@range MIN MAX), got '" + trim(a + " " + b) + "'");
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
            while (k < text.size() && !(text[k] == ';' && parens == 0) && text[k] != '{' && text[k] != '}') {
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
        if (!hasInitializer) {
            if (annotated)
                report(nameOffset, Severity::Error,
                       "parameter '" + name + "': annotated uniforms need a default (uniform " + typeWord + " " + name +
                           " = ...;)");
            return;
        }
        Parameter p;
        p.name = name;
        p.type = *type;
        auto [line, column] = position(start);
        p.line = line;
        p.column = column;
        p.initializerOffset = initializerOffset;
        p.initializerLength = initializerEnd - initializerOffset;
        if (!readInitializer(p, initializer, initializerOffset)) return;
        if (annotated) readAnnotations(p, commentStart + 2, lineEnd);
        for (const Parameter& other : result.parameters)
            if (other.name == p.name) {
                report(nameOffset, Severity::Error,
                       "parameter '" + p.name + "' is declared twice (first at line " + std::to_string(other.line) + ")");
                return;
            }
        result.parameters.push_back(std::move(p));
    }
};

} // namespace

ParameterScan parseParameters(const std::string& text, const std::string& file) {
    const std::string stripped = stripComments(text);
    Scanner scanner{text, stripped, file, {}, {}};
    scanner.scan();
    return std::move(scanner.result);
}

namespace {

std::string shortest(float value) {
    char text[32];
    auto end = std::to_chars(text, text + sizeof text, value).ptr;
    return std::string(text, end);
}

// "a,b,c" of numbers (true/false as 1/0); nullopt when any item is not one.
std::optional<std::vector<float>> parseList(const std::string& text) {
    std::vector<float> values;
    std::size_t start = 0;
    while (true) {
        const std::size_t comma = text.find(',', start);
        const std::string item = trim(text.substr(start, comma == std::string::npos ? std::string::npos : comma - start));
        if (item == "true") {
            values.push_back(1.0f);
        } else if (item == "false") {
            values.push_back(0.0f);
        } else {
            auto number = parseNumber(item, false);
            if (!number) return std::nullopt;
            values.push_back(*number);
        }
        if (comma == std::string::npos) break;
        start = comma + 1;
    }
    if (values.empty() || values.size() > 4) return std::nullopt;
    return values;
}

bool isIdentifier(const std::string& name) {
    if (name.empty() || !isIdentifierStart(name[0])) return false;
    return std::all_of(name.begin(), name.end(), isIdentifierChar);
}

std::string listOf(const std::vector<float>& values) {
    std::string text;
    for (float v : values) text += (text.empty() ? "" : ",") + shortest(v);
    return text;
}

const Parameter* findDeclared(const std::vector<Parameter>& declared, const std::string& name) {
    for (const Parameter& p : declared)
        if (p.name == name) return &p;
    return nullptr;
}

std::string declaredNames(const std::vector<Parameter>& declared) {
    if (declared.empty()) return "the SDF declares no parameters";
    std::string names;
    for (const Parameter& p : declared) names += (names.empty() ? "" : ", ") + p.name;
    return "declared: " + names;
}

// splitmix64: a small, portable, well-mixed generator (the same draws on every machine).
std::uint64_t mix(std::uint64_t& state) {
    std::uint64_t z = (state += 0x9e3779b97f4a7c15ull);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
    return z ^ (z >> 31);
}
double uniform01(std::uint64_t& state) { return double(mix(state) >> 11) * (1.0 / 9007199254740992.0); }

} // namespace

Expected<ParameterValue> parseParameterValue(const std::string& text) {
    const std::size_t equals = text.find('=');
    if (equals == std::string::npos) return makeError("'" + text + "': expected NAME=VALUE (vectors as NAME=x,y,z)");
    ParameterValue value;
    value.name = trim(text.substr(0, equals));
    if (!isIdentifier(value.name)) return makeError("'" + text + "': '" + value.name + "' is not a parameter name");
    auto list = parseList(text.substr(equals + 1));
    if (!list) return makeError("'" + text + "': the value must be 1 to 4 finite numbers separated by commas (or true/false)");
    value.value = std::move(*list);
    return value;
}

std::string formatParameterValue(const ParameterValue& value) { return value.name + "=" + listOf(value.value); }

Expected<ResolvedParameters> resolveParameters(const std::vector<Parameter>& declared, const std::vector<ParameterValue>& given) {
    ResolvedParameters resolved;
    for (const Parameter& p : declared) resolved.settings.push_back({p.name, p.type, p.defaultValue});
    for (const ParameterValue& g : given) {
        const Parameter* p = findDeclared(declared, g.name);
        if (!p) return makeError("parameter '" + g.name + "' is not declared (" + declaredNames(declared) + ")");
        const int n = componentCount(p->type);
        if (g.value.size() != 1 && int(g.value.size()) != n)
            return makeError("parameter '" + g.name + "' is a " + parameterTypeName(p->type) + ": give " +
                             (n == 1 ? std::string("one number") : "1 or " + std::to_string(n) + " numbers") + ", not " +
                             std::to_string(g.value.size()));
        std::array<float, 4> value{};
        for (int k = 0; k < n; ++k) value[std::size_t(k)] = g.value.size() == 1 ? g.value[0] : g.value[std::size_t(k)];
        if (p->type == ParameterType::Int && (value[0] != std::floor(value[0]) || std::fabs(value[0]) > 2147483647.0f))
            return makeError("parameter '" + g.name + "' is an int: " + shortest(value[0]) + " is not a whole number");
        if (p->type == ParameterType::Bool && value[0] != 0.0f && value[0] != 1.0f)
            return makeError("parameter '" + g.name + "' is a bool: give true, false, 1 or 0");
        if (p->minimum && p->maximum)
            for (int k = 0; k < n; ++k)
                if (value[std::size_t(k)] < *p->minimum || value[std::size_t(k)] > *p->maximum) {
                    resolved.warnings.push_back("parameter '" + g.name + "' = " + listOf(g.value) + " lies outside its @range " +
                                                shortest(*p->minimum) + " " + shortest(*p->maximum));
                    break;
                }
        for (ParameterSetting& s : resolved.settings)
            if (s.name == g.name) s.value = value;
    }
    return resolved;
}

std::vector<ParameterValue> valuesOf(const std::vector<ParameterSetting>& settings) {
    std::vector<ParameterValue> values;
    for (const ParameterSetting& s : settings)
        values.push_back({s.name, std::vector<float>(s.value.begin(), s.value.begin() + componentCount(s.type))});
    return values;
}

std::string parametersJson(const std::vector<ParameterSetting>& settings) {
    if (settings.empty()) return "";
    std::string out = "{";
    for (const ParameterSetting& s : settings) {
        out += (out.size() > 1 ? "," : "") + ("\"" + s.name + "\":");
        const int n = componentCount(s.type);
        if (s.type == ParameterType::Bool) {
            out += s.value[0] != 0.0f ? "true" : "false";
        } else if (n == 1) {
            out += shortest(s.value[0]);
        } else {
            out += "[";
            for (int k = 0; k < n; ++k) out += (k ? "," : "") + shortest(s.value[std::size_t(k)]);
            out += "]";
        }
    }
    return out + "}";
}

std::string glslLiteral(ParameterType type, const std::array<float, 4>& value) {
    auto number = [](float v) {
        std::string text = shortest(v);
        if (text.find_first_of(".e") == std::string::npos) text += ".0";
        return text;
    };
    switch (type) {
    case ParameterType::Bool:
        return value[0] != 0.0f ? "true" : "false";
    case ParameterType::Int:
        return std::to_string(static_cast<long long>(value[0]));
    case ParameterType::Float:
        return number(value[0]);
    default: {
        std::string text = std::string(parameterTypeName(type)) + "(";
        for (int k = 0; k < componentCount(type); ++k) text += (k ? ", " : "") + number(value[std::size_t(k)]);
        return text + ")";
    }
    }
}

std::string withDefaults(const std::string& text, const std::vector<Parameter>& declared,
                         const std::vector<ParameterSetting>& values) {
    std::vector<std::pair<const Parameter*, std::string>> edits;
    for (const ParameterSetting& s : values)
        if (const Parameter* p = findDeclared(declared, s.name); p && p->initializerOffset + p->initializerLength <= text.size())
            edits.emplace_back(p, glslLiteral(p->type, s.value));
    std::sort(edits.begin(), edits.end(),
              [](const auto& a, const auto& b) { return a.first->initializerOffset > b.first->initializerOffset; });
    std::string out = text;
    for (const auto& [p, literal] : edits) out.replace(p->initializerOffset, p->initializerLength, literal);
    return out;
}

Expected<ParameterSweep> parseParameterSweep(const std::string& text) {
    const std::size_t equals = text.find('=');
    const std::string form = "expected NAME=FROM:TO:COUNT (vectors as x,y,z at FROM and TO)";
    if (equals == std::string::npos) return makeError("'" + text + "': " + form);
    ParameterSweep sweep;
    sweep.name = trim(text.substr(0, equals));
    if (!isIdentifier(sweep.name)) return makeError("'" + text + "': '" + sweep.name + "' is not a parameter name");
    const std::string rest = text.substr(equals + 1);
    const std::size_t first = rest.find(':'), second = rest.find(':', first == std::string::npos ? 0 : first + 1);
    if (first == std::string::npos || second == std::string::npos || rest.find(':', second + 1) != std::string::npos)
        return makeError("'" + text + "': " + form);
    auto from = parseList(rest.substr(0, first));
    auto to = parseList(rest.substr(first + 1, second - first - 1));
    auto count = parseNumber(rest.substr(second + 1), true);
    if (!from || !to) return makeError("'" + text + "': FROM and TO must be 1 to 4 finite numbers separated by commas");
    if (from->size() != to->size()) return makeError("'" + text + "': FROM and TO must have as many components");
    if (!count || *count < 1 || *count > 100000) return makeError("'" + text + "': COUNT must be a whole number in 1..100000");
    sweep.from = std::move(*from);
    sweep.to = std::move(*to);
    sweep.count = int(*count);
    return sweep;
}

std::string formatParameterSweep(const ParameterSweep& sweep) {
    return sweep.name + "=" + listOf(sweep.from) + ":" + listOf(sweep.to) + ":" + std::to_string(sweep.count);
}

Expected<std::vector<std::vector<ParameterValue>>> familyInstances(const std::vector<Parameter>& declared,
                                                                   const std::vector<ParameterValue>& base,
                                                                   const std::vector<ParameterSweep>& sweeps,
                                                                   std::uint32_t randomize, std::uint64_t seed) {
    constexpr std::uint64_t kMaxInstances = 100000;
    auto withBase = [&](std::vector<ParameterValue> set) {
        for (const ParameterValue& b : base) {
            bool overridden = false;
            for (const ParameterValue& v : set) overridden = overridden || v.name == b.name;
            if (!overridden) set.insert(set.begin(), b);
        }
        std::stable_sort(set.begin(), set.end(), [&](const ParameterValue& a, const ParameterValue& b) {
            auto index = [&](const std::string& name) {
                for (std::size_t i = 0; i < declared.size(); ++i)
                    if (declared[i].name == name) return i;
                return declared.size();
            };
            return index(a.name) < index(b.name);
        });
        return set;
    };
    std::vector<std::vector<ParameterValue>> instances;
    if (randomize > 0) {
        if (!sweeps.empty()) return makeError(key("sweep") + " and " + key("randomize") + " cannot be combined");
        if (randomize > kMaxInstances) return makeError("at most 100000 instances");
        std::vector<const Parameter*> drawn;
        for (const Parameter& p : declared) {
            bool fixed = false;
            for (const ParameterValue& b : base) fixed = fixed || b.name == p.name;
            if (fixed) continue;
            if (p.type == ParameterType::Bool || (p.minimum && p.maximum)) drawn.push_back(&p);
        }
        if (drawn.empty()) return makeError("no parameter has a @range to draw from (" + declaredNames(declared) + ")");
        std::uint64_t state = seed;
        for (std::uint32_t i = 0; i < randomize; ++i) {
            std::vector<ParameterValue> set;
            for (const Parameter* p : drawn) {
                ParameterValue v{p->name, {}};
                for (int k = 0; k < componentCount(p->type); ++k) {
                    const double u = uniform01(state);
                    float x = 0.0f;
                    if (p->type == ParameterType::Bool) {
                        x = u < 0.5 ? 0.0f : 1.0f;
                    } else if (p->type == ParameterType::Int) {
                        const double lo = std::ceil(*p->minimum), hi = std::floor(*p->maximum);
                        x = float(std::min(hi, lo + std::floor(u * (hi - lo + 1.0))));
                    } else if (p->logarithmic) {
                        x = float(std::exp(std::log(double(*p->minimum)) +
                                           u * (std::log(double(*p->maximum)) - std::log(double(*p->minimum)))));
                    } else {
                        x = float(double(*p->minimum) + u * (double(*p->maximum) - double(*p->minimum)));
                    }
                    v.value.push_back(std::clamp(x, p->type == ParameterType::Bool ? 0.0f : *p->minimum,
                                                 p->type == ParameterType::Bool ? 1.0f : *p->maximum));
                }
                set.push_back(std::move(v));
            }
            instances.push_back(withBase(std::move(set)));
        }
        return instances;
    }
    std::uint64_t total = 1;
    for (const ParameterSweep& s : sweeps) {
        const Parameter* p = findDeclared(declared, s.name);
        if (!p) return makeError("parameter '" + s.name + "' is not declared (" + declaredNames(declared) + ")");
        const int n = componentCount(p->type);
        if (s.from.size() != 1 && int(s.from.size()) != n)
            return makeError("'" + s.name + "' is a " + parameterTypeName(p->type) + ": give 1 or " + std::to_string(n) +
                             " numbers at each end");
        for (const ParameterSweep& other : sweeps)
            if (&other != &s && other.name == s.name) return makeError("'" + s.name + "' is swept twice");
        total *= std::uint64_t(s.count);
        if (total > kMaxInstances) return makeError("more than 100000 instances in the grid");
    }
    for (std::uint64_t i = 0; i < total; ++i) {
        std::vector<ParameterValue> set;
        std::uint64_t rest = i;
        for (std::size_t k = sweeps.size(); k-- > 0;) {
            const ParameterSweep& s = sweeps[k];
            const std::uint64_t step = rest % std::uint64_t(s.count);
            rest /= std::uint64_t(s.count);
            const double t = s.count == 1 ? 0.0 : double(step) / double(s.count - 1);
            ParameterValue v{s.name, {}};
            for (std::size_t c = 0; c < s.from.size(); ++c)
                v.value.push_back(step + 1 == std::uint64_t(s.count) && s.count > 1
                                      ? s.to[c]
                                      : float(double(s.from[c]) + t * (double(s.to[c]) - double(s.from[c]))));
            if (findDeclared(declared, s.name)->type == ParameterType::Int)
                for (float& x : v.value) x = std::round(x);
            set.insert(set.begin(), std::move(v));
        }
        instances.push_back(withBase(std::move(set)));
    }
    return instances;
}

} // namespace sdfwb::shaders
