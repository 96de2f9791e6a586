// Parameter values: given on the command line or in a request, resolved against the declared
// parameters, written back as defaults, swept and drawn for shape families.
#include <shaders/Parameters.h>

#include "ParameterText.h"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdlib>
#include <cstring>

namespace sdfwb::shaders {

namespace {

using detail::parseNumber;
using detail::shortest;
bool isIdentifierStart(char c) { return std::isalpha(static_cast<unsigned char>(c)) || c == '_'; }
bool isIdentifierChar(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; }

} // namespace

std::string detail::shortest(float value) {
    char text[32];
    auto end = std::to_chars(text, text + sizeof text, value).ptr;
    return std::string(text, end);
}

std::optional<std::vector<float>> detail::parseList(const std::string& text) {
    std::vector<float> values;
    std::size_t start = 0;
    while (true) {
        const std::size_t comma = text.find(',', start);
        const std::string item =
            detail::trimmed(text.substr(start, comma == std::string::npos ? std::string::npos : comma - start));
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

namespace {

using detail::parseList;

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
    value.name = detail::trimmed(text.substr(0, equals));
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

// A default as Fragmentarium writes it: a slider's `(x,y,z)` or a preset line's `x,y,z`.
std::string fragmentariumLiteral(const Parameter& p, const std::array<float, 4>& value) {
    if (p.type == ParameterType::Bool) return value[0] != 0.0f ? "true" : "false";
    if (p.type == ParameterType::Int) return std::to_string(static_cast<long long>(value[0]));
    // A colour annotation holds the colour alone (a vec4's alpha has its own slider there); a preset line every component.
    const int n = p.color && p.syntax == Parameter::Syntax::FragmentariumSlider ? 3 : componentCount(p.type);
    std::string text;
    for (int k = 0; k < n; ++k) text += (k ? "," : "") + shortest(value[std::size_t(k)]);
    return n > 1 && p.syntax == Parameter::Syntax::FragmentariumSlider && !p.color ? "(" + text + ")" : text;
}

// A default as an ISF header writes it: JSON (`0.5`, `true`, `[0.5, 0.5, 0.8, 1]`).
std::string isfLiteral(const Parameter& p, const std::array<float, 4>& value) {
    if (p.type == ParameterType::Bool) return value[0] != 0.0f ? "true" : "false";
    if (p.type == ParameterType::Int) return std::to_string(static_cast<long long>(value[0]));
    if (p.type == ParameterType::Float) return shortest(value[0]);
    std::string text = "[";
    for (int k = 0; k < componentCount(p.type); ++k) text += (k ? ", " : "") + shortest(value[std::size_t(k)]);
    return text + "]";
}

std::string withDefaults(const std::string& text, const std::vector<Parameter>& declared,
                         const std::vector<ParameterSetting>& values) {
    std::vector<std::pair<const Parameter*, std::string>> edits;
    for (const ParameterSetting& s : values)
        if (const Parameter* p = findDeclared(declared, s.name);
            p && p->initializerOffset + p->initializerLength <= text.size() &&
            !(p->syntax == Parameter::Syntax::Isf && p->initializerLength == 0))
            edits.emplace_back(p, p->syntax == Parameter::Syntax::Glsl  ? glslLiteral(p->type, s.value)
                                  : p->syntax == Parameter::Syntax::Isf ? isfLiteral(*p, s.value)
                                                                        : fragmentariumLiteral(*p, s.value));
    std::sort(edits.begin(), edits.end(),
              [](const auto& a, const auto& b) { return a.first->initializerOffset > b.first->initializerOffset; });
    std::string out = text;
    for (const auto& [p, literal] : edits) {
        // An initializer written over lines (`vec3(\n 1, 0.5, 0.2)`) keeps its line breaks after the
        // new one: every other line keeps its number (and a Fragmentarium annotation its line).
        const auto breaks = std::count(text.begin() + std::ptrdiff_t(p->initializerOffset),
                                       text.begin() + std::ptrdiff_t(p->initializerOffset + p->initializerLength), '\n');
        out.replace(p->initializerOffset, p->initializerLength, literal + std::string(std::size_t(breaks), '\n'));
    }
    return out;
}

Expected<ParameterSweep> parseParameterSweep(const std::string& text) {
    const std::size_t equals = text.find('=');
    const std::string form = "expected NAME=FROM:TO:COUNT (vectors as x,y,z at FROM and TO)";
    if (equals == std::string::npos) return makeError("'" + text + "': " + form);
    ParameterSweep sweep;
    sweep.name = detail::trimmed(text.substr(0, equals));
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
