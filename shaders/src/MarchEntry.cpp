#include "MarchEntry.h"

#include <shaders/MarchAnalysis.h>
#include <shaders/ShaderComposer.h>

#include <core/Regex.h>

#include "MarchTree.h"
#include "Words.h"

#include <algorithm>
#include <cctype>
#include <cstring>
#include <regex>
#include <set>

// A whole shader's field chosen by its own march: the function it steps by, or the loop's inline
// field (SdfSource.cpp's prepareSdf calls these when the file names no entry).

namespace sdfwb::shaders::detail {
namespace {

// Makes `march` (one whose body the wrapper can run) the whole shader's field.
void useInlineMarch(PreparedSdf& prepared, const InlineMarch& march, const std::string& stripped) {
    SdfSignature& signature = prepared.signature;
    signature = SdfSignature{};
    signature.found = true;
    signature.entry = march.function;
    const std::string centre = mentions(stripped, "iResolution") ? "0.5 * iResolution.xy" : "vec2(0.0)";
    if (!march.coordinate.empty())
        signature.prelude = "vec2 " + march.coordinate + " = " + centre + "; vec4 " + march.colour + " = vec4(0.0);\n";
    signature.prelude += march.prelude;
    signature.traced = march.traced;
    signature.inlineBody = march.body;
    prepared.entrySource = EntrySource::March;
    prepared.marchThreshold = march.hitThreshold;
    prepared.marchThresholdLine = march.hitLine;
    // A march backwards (`t -= d`) has the step -(d): said as the shader writes it.
    const bool backwards = (march.field.empty() || !march.level.empty()) && march.step.size() > 3 &&
                           march.step.compare(0, 2, "-(") == 0 && march.step.back() == ')';
    std::string traced;
    for (const TracedValue& value : march.traced) traced += (traced.empty() ? "" : ", ") + value.name;
    const std::string stepText =
        march.counter + (backwards ? " -= " + march.step.substr(2, march.step.size() - 3) : " += " + march.step);
    prepared.entryReason = march.function + " (its march at line " + std::to_string(march.line) +
                           (march.level.empty() ? " writes the field inline: " + (march.field.empty() ? "" : march.field + ", ") +
                                                      "the step " + stepText
                                                : " steps " + stepText + " and stops where " + march.level + ": the field is " +
                                                      march.field + ", a level of the shader's values, not a distance") +
                           ")" + (traced.empty() ? "" : ", with " + traced + " as mainImage computes it");
    if (!march.level.empty())
        prepared.diagnostics.push_back({march.file, march.line, 1, Severity::Warning,
                                        "this march steps a fixed amount and stops where " + march.level + ": sdfwb's field is " +
                                            march.field +
                                            ", whose values are not distances; sphere tracing may step past "
                                            "thin parts of it (the audit gives a safe --step-factor)"});
}

// The inline marches of the user's code alone.
std::vector<InlineMarch> userInlineMarches(const PreparedSdf& prepared) {
    PreparedSdf userCode = prepared;
    userCode.signature.entry.clear(); // no entry: the user's code alone
    return inlineMarches(composeSdfShader(userCode, Stage::Fragment, std::vector<ShaderPiece>{}, FeatureDefines{}));
}

// The field's parameters after the point whose values mainImage computes from the pixel (its
// coordinate, or a name a statement of the prelude computes from one): the wrapper evaluates them
// at the frame's centre, so the field is that pixel's (a ray direction a field culls by, a uv).
std::vector<std::string> perPixelParameters(const MarchedFunction& m) {
    static const std::set<std::string> notNames = {
        "const", "highp", "mediump", "lowp",  "in",    "out",   "inout", "float", "int",   "uint",  "bool", "vec2", "vec3",
        "vec4",  "ivec2", "ivec3",   "ivec4", "uvec2", "uvec3", "uvec4", "bvec2", "bvec3", "bvec4", "mat2", "mat3", "mat4"};
    std::set<std::string> pixel = {m.coordinate.empty() ? std::string("fragCoord") : m.coordinate, "gl_FragCoord"};
    auto mentionsAny = [&pixel](const std::string& text) {
        return std::any_of(pixel.begin(), pixel.end(), [&](const std::string& name) { return mentions(text, name); });
    };
    const std::string prelude = stripComments(m.prelude);
    for (std::size_t start = 0; start < prelude.size();) {
        const std::size_t end = std::min(prelude.find(';', start), prelude.size());
        const std::string statement = prelude.substr(start, end - start);
        start = end + 1;
        if (!mentionsAny(statement)) continue;
        // What it assigns (`vec3 ro = ..., rd = ...;`, `uv.x *= ...;`), or what a call may write
        // (`camera(uv, ro, rd);`): names, not members after a `.`, types or called functions.
        bool assigns = false;
        for (std::size_t at = statement.find('='); at != std::string::npos; at = statement.find('=', at + 1)) {
            const char next = at + 1 < statement.size() ? statement[at + 1] : ' ';
            const char previous = at > 0 ? statement[at - 1] : ' ';
            if (next == '=' || previous == '=' || previous == '!' ||
                ((previous == '<' || previous == '>') && (at < 2 || statement[at - 2] != previous)))
                continue;
            assigns = true;
            std::size_t k = at; // back over the operator, then `[...]` and `.member` to the base name
            while (k > 0 && std::strchr("+-*/%&|^<> \t\r\n", statement[k - 1])) --k;
            for (;;) {
                if (k > 0 && statement[k - 1] == ']') {
                    int depth = 0;
                    while (k > 0 && !(statement[k - 1] == '[' && depth == 1))
                        depth += statement[--k] == ']' ? 1 : statement[k] == '[' ? -1 : 0;
                    if (k > 0) --k;
                    continue;
                }
                std::size_t wordStart = k;
                while (wordStart > 0 && isWordCharacter(statement[wordStart - 1])) --wordStart;
                if (wordStart == k) break;
                if (wordStart > 0 && statement[wordStart - 1] == '.') {
                    k = wordStart - 1;
                    continue;
                }
                pixel.insert(statement.substr(wordStart, k - wordStart));
                break;
            }
        }
        if (assigns) continue;
        detail::forEachIdentifier(statement, [&](std::size_t at, std::size_t wordEnd) {
            const std::string word = statement.substr(at, wordEnd - at);
            const std::size_t next = statement.find_first_not_of(" \t\r\n", wordEnd);
            const bool called = next != std::string::npos && statement[next] == '(';
            const bool member = at > 0 && statement[at - 1] == '.';
            if (!called && !member && !notNames.count(word) && !std::isdigit(static_cast<unsigned char>(word[0])))
                pixel.insert(word);
            return true;
        });
    }
    std::vector<std::string> out;
    for (const std::string& name : m.globals)
        if (pixel.count(name)) out.push_back(name);
    for (const TracedValue& traced : m.traced)
        if (mentionsAny(traced.value)) out.push_back(traced.name);
    return out;
}

// The user functions (not mainImage) that call every one of `names` themselves.
std::vector<std::string> functionsCallingAll(const PreparedSdf& prepared, const std::vector<std::string>& names) {
    PreparedSdf userCode = prepared;
    userCode.signature.entry.clear(); // no entry: the user's code alone
    Reached tree;
    if (!parseReached(composeSdfShader(userCode, Stage::Fragment, std::vector<ShaderPiece>{}, FeatureDefines{}), tree)) return {};
    std::vector<std::string> found;
    for (TIntermAggregate* function : tree.reached) {
        if (function == tree.mainImage) continue;
        std::set<std::string> called;
        for (TIntermAggregate* call : contentsOf(function).calls) called.insert(plainName(call->getName()));
        const std::string name = plainName(function->getName());
        if (std::all_of(names.begin(), names.end(), [&](const std::string& n) { return n != name && called.count(n); }))
            found.push_back(name);
    }
    return found;
}

// The name of the float after the point in `name`'s definition (`float map(vec3 p, float s)`: s).
// Tried only at each occurrence of the name, as detectSignature does: a search from every position
// of a long text is slow, and this runs at every prepare of an animated field.
std::string floatParameter(const std::string& stripped, const std::string& name) {
    static const std::regex definition(
        R"(\w+\s*\(\s*(?:(?:in|const|highp|mediump)\s+)*\w+\s+\w+\s*,\s*(?:(?:in|const|highp)\s+)*float\s+(\w+))", kLinearRegex);
    std::smatch match;
    for (std::size_t at : detail::wordOffsets(stripped, name))
        if (std::regex_search(stripped.begin() + std::ptrdiff_t(at), stripped.end(), match, definition,
                              std::regex_constants::match_continuous))
            return match[1].str();
    return {};
}

// Whether a parameter's name says it is the time (`time`, `iTime`, `fTime`, `t`, `tm`, `tt`).
bool namesTime(std::string name) {
    for (char& c : name) c = char(std::tolower(static_cast<unsigned char>(c)));
    return name.find("time") != std::string::npos || name == "t" || name == "tm" || name == "tt";
}

// Functions one loop steps by together (`d = min(torus(p), plane(p)); t += d;`): the field is what
// the loop steps by, its inline field, not either function. True when it chose one.
bool chooseLoopsUnion(PreparedSdf& prepared, const std::vector<std::pair<MarchedFunction, SdfSignature>>& valid,
                      const std::string& stripped) {
    const MarchedFunction& first = valid.front().first;
    if (valid.size() < 2 || !std::all_of(valid.begin(), valid.end(), [&](const auto& candidate) {
            return candidate.first.file == first.file && candidate.first.loopLine == first.loopLine;
        }))
        return false;
    std::string names;
    std::vector<std::string> tied;
    for (const auto& [marched, signature] : valid) {
        names += (names.empty() ? "" : " and ") + marched.name;
        tied.push_back(marched.name);
    }
    for (const InlineMarch& march : userInlineMarches(prepared))
        if (!march.body.empty() && march.file == first.file && march.line == first.loopLine) {
            useInlineMarch(prepared, march, stripped);
            prepared.entryReason += "; it steps by " + names + " together";
            return true;
        }
    // A loop whose text the wrapper cannot run (a reflection's branches): a function of a point that
    // calls each of them, the scene its normals are taken from (`df(p) { return min(sphere(p),
    // box(p)); }`), is their union.
    for (const std::string& name : functionsCallingAll(prepared, tied))
        if (SdfSignature signature = detectSignature(stripped, name); signature.found) {
            prepared.signature = std::move(signature);
            prepared.entrySource = EntrySource::March;
            prepared.entryReason = name + " (it calls " + names + ", which the march at line " + std::to_string(first.loopLine) +
                                   " steps by together)";
            return true;
        }
    return false;
}

} // namespace

std::string timeParameter(const SdfSignature& signature, const std::string& stripped) {
    return signature.animated ? floatParameter(stripped, signature.entry) : std::string();
}

bool floatIsNotTime(const SdfSignature& signature, const std::string& stripped) {
    return signature.animated && !namesTime(floatParameter(stripped, signature.entry));
}

// A whole shader whose march writes its field inline (shaders::InlineMarch), with no function the
// march steps by and no conventional name: the first such loop whose text the wrapper can run, one
// that steps by its field before one that stops at a level (a fixed-step shadow or fog loop).
void chooseInlineField(PreparedSdf& prepared, const std::string& stripped) {
    std::string unresolved;
    const std::vector<InlineMarch> marches = userInlineMarches(prepared);
    for (const bool levels : {false, true})
        for (const InlineMarch& march : marches) {
            if (march.level.empty() == levels) continue;
            if (march.body.empty()) {
                if (unresolved.empty())
                    unresolved =
                        "the march at line " + std::to_string(march.line) +
                        (levels ? " steps a fixed amount to a level of its point's values" : " writes its field inline") +
                        ", but " + march.unresolved;
                continue;
            }
            useInlineMarch(prepared, march, stripped);
            return;
        }
    if (!unresolved.empty() && prepared.entryReason.empty()) prepared.entryReason = unresolved;
}

// A whole shader without an `sdf`: the function its own march steps by (marchedFunctions), when
// it has an entry's form. The one most loops step by wins; functions one loop steps by together
// make that loop's inline field; a tie is broken by a conventional name, then by the fewest calls
// from mainImage, else it is an error naming the candidates (entryCandidates).
namespace {

// The definition the march calls: for FIELD(p) alone, of overloads, the one without a float after
// the point (a cloud layer's getDist(p, radius) beside the planet's getDist(p)).
SdfSignature marchedSignature(const std::string& stripped, const MarchedFunction& marched, const std::string& returns) {
    return marched.extraParameters == 0 ? detectSignatureOfForm(stripped, marched.name, returns, false)
                                        : detectSignature(stripped, marched.name, returns);
}

// A function's name in the user's text: the composer renames a word later GLSL took (sdfwb_sample).
std::string nameInUserText(const PreparedSdf& prepared, const std::string& name) {
    const auto& renamed = prepared.compat.renamed;
    const bool ours = name.rfind("sdfwb_", 0) == 0 && std::find(renamed.begin(), renamed.end(), name.substr(6)) != renamed.end();
    return ours ? name.substr(6) : name;
}

// How a marched function was found, for the reason.
std::string where(const MarchedFunction& m) {
    std::string globals;
    for (const std::string& name : m.globals) globals += (globals.empty() ? "" : ", ") + name;
    return m.name + " (called by the march at line " + std::to_string(m.line) + ")" +
           (m.arguments.empty() ? "" : ", with" + m.arguments.substr(1) + " as " + m.caller + " computes it") +
           (globals.empty()
                ? ""
                : ", after " + m.setter + (m.setter.find(" and ") == std::string::npos ? " sets " : " set ") + globals);
}

// Primary marches as often (keepPrimaryRays left them) of functions of a point alone: nothing after
// the point but the time, no out parameters, and the same statements of mainImage run first. The
// shader draws the nearer hit of each (dr2's cave and boats): the scene is their union. Leaves the
// first candidate holding the others (SdfSignature::unionWith) and returns the reason; leaves a tie
// it cannot unite as it was, and returns nothing.
std::string uniteTiedMarches(std::vector<std::pair<MarchedFunction, SdfSignature>>& valid) {
    if (valid.size() < 2) return "";
    const SdfSignature& first = valid.front().second;
    std::string prelude;
    for (const auto& [marched, signature] : valid) {
        if (!signature.arguments.empty() || !signature.traced.empty() || !signature.inlineBody.empty() ||
            !signature.outParameters.empty() || signature.pointOut || signature.animated != first.animated ||
            !signature.unionWith.empty())
            return "";
        if (marched.globals.empty()) continue;
        // The statements run first: one the other's beginning (mainImage's, then those of the
        // function that calls both marches, up to the later one), the longer run for both.
        auto open = [](std::string text) {
            if (text.size() >= 3 && text.compare(text.size() - 3, 3, "\n}\n") == 0) text.resize(text.size() - 3);
            return text;
        };
        const std::string mine = open(signature.prelude), theirs = open(prelude);
        if (mine.compare(0, theirs.size(), theirs) == 0)
            prelude = signature.prelude;
        else if (theirs.compare(0, mine.size(), mine) != 0)
            return "";
    }
    SdfSignature& united = valid.front().second;
    united.prelude = prelude;
    std::string reason = "the union of " + where(valid.front().first);
    for (std::size_t i = 1; i < valid.size(); ++i) {
        const SdfSignature& other = valid[i].second;
        united.unionWith.emplace_back(other.entry, !other.member.empty()         ? "." + other.member
                                                   : other.returnType == "float" ? std::string()
                                                                                 : std::string(".x"));
        reason += (i + 1 == valid.size() ? "; and " : "; ") + where(valid[i].first);
    }
    valid.resize(1);
    return reason + ": the primary ray marches each as often and the shader draws the nearer hit (--entry NAME opens one)";
}

// Among marches stepped by equally often, the primary ray's: the march nearest mainImage (a
// refraction's or a bounce's march is called from deeper down), else the one that runs whatever the
// others found (one that runs only where another's result lets it, a refraction inside
// `if (t.x > 0.)` or a second pass in an `else`, follows a primary ray). Marches as near as each
// other that run alike stay a tie (uniteTiedMarches may join them). Returns those left out, for the reason.
std::string keepPrimaryRays(std::vector<std::pair<MarchedFunction, SdfSignature>>& valid) {
    std::string deeper;
    if (valid.size() > 1) {
        int nearest = valid.front().first.depth;
        for (const auto& [marched, signature] : valid) nearest = std::min(nearest, marched.depth);
        for (const auto& [marched, signature] : valid)
            if (marched.depth > nearest)
                deeper += (deeper.empty() ? "" : ", ") + marched.name + " (line " + std::to_string(marched.line) + ")";
        std::erase_if(valid, [nearest](const auto& candidate) { return candidate.first.depth > nearest; });
    }
    if (valid.size() > 1) {
        std::set<std::string> names;
        for (const auto& [marched, signature] : valid) names.insert(marched.name);
        for (const auto& [marched, signature] : valid)
            if (names.count(marched.after))
                deeper += (deeper.empty() ? "" : ", ") + marched.name + " (line " + std::to_string(marched.line) + ", run only " +
                          marched.afterHow + ")";
        std::erase_if(valid, [&names](const auto& candidate) { return names.count(candidate.first.after) > 0; });
    }
    return deeper;
}

} // namespace

void chooseMarchedEntry(PreparedSdf& prepared, const std::string& stripped) {
    PreparedSdf userCode = prepared;
    userCode.signature.entry.clear(); // no entry: the user's code alone
    std::vector<std::pair<MarchedFunction, SdfSignature>> valid;
    std::string untraced; // why a marched field with parameters after the point could not be wrapped
    for (MarchedFunction& marched :
         marchedFunctions(composeSdfShader(userCode, Stage::Fragment, std::vector<ShaderPiece>{}, FeatureDefines{}))) {
        marched.name = nameInUserText(prepared, marched.name);
        // A struct's float member the march steps by (`Hit map(vec3 p)`, `t += h.d`) is the distance;
        // a vec3 is one when the march reads only its x (marchedFunctions).
        const std::string returns = !marched.member.empty()       ? marched.returnType
                                    : marched.valueType == "vec3" ? std::string("vec3")
                                                                  : std::string("float|vec2|vec4");
        SdfSignature signature = marchedSignature(stripped, marched, returns);
        if (!marched.member.empty()) signature.member = marched.member; // the one the march reads
        if (!marched.component.empty()) signature.member = marched.component;
        if (signature.found && !marched.globals.empty()) // what mainImage sets first, run first
            signature.prelude = "vec2 " + (marched.coordinate.empty() ? "fragCoord" : marched.coordinate) + " = " +
                                (mentions(stripped, "iResolution") ? "0.5 * iResolution.xy" : "vec2(0.0)") + "; vec4 " +
                                (marched.colour.empty() ? "fragColor" : marched.colour) + " = vec4(0.0);\n" + marched.prelude;
        // `float map(vec3 p, float s)` has the form of ENTRY(p, time), but a float not named as the
        // time is what the march passes: mainImage's values where they can be traced, else no field
        // (IQ's Apollonian's `s`, which mainImage hands to render and render to trace, read 0 at
        // time 0 and the field NaN everywhere).
        if (signature.found && signature.animated && marched.extraParameters > 0 &&
            !namesTime(floatParameter(stripped, marched.name)))
            signature.found = signature.animated = false;
        if (!signature.found && marched.extraParameters > 0 && !marched.arguments.empty() && !marched.valueType.empty()) {
            // Parameters after the point, computed by mainImage: the wrapper computes them the same way.
            signature.found = true;
            signature.entry = marched.name;
            signature.returnType = marched.valueType;
            signature.member = marched.member.empty() ? marched.component : marched.member;
            const std::string centre = mentions(stripped, "iResolution") ? "0.5 * iResolution.xy" : "vec2(0.0)";
            signature.prelude = "vec2 " + (marched.coordinate.empty() ? "fragCoord" : marched.coordinate) + " = " + centre +
                                "; vec4 " + (marched.colour.empty() ? "fragColor" : marched.colour) + " = vec4(0.0);\n" +
                                marched.prelude;
            signature.traced = marched.traced;
            signature.arguments = marched.arguments;
        }
        if (!signature.found && marched.extraParameters > 0 && untraced.empty() && !marched.unresolved.empty())
            untraced = "the march steps by " + marched.name + " (line " + std::to_string(marched.line) +
                       "), whose parameters after the point sdfwb cannot compute: " + marched.unresolved +
                       "; to open it with values of your choosing, add `float sdf(vec3 p) { return " + marched.name +
                       "(p, ...); }`";
        if (signature.found) valid.emplace_back(std::move(marched), std::move(signature));
    }
    if (valid.empty()) {
        if (!untraced.empty()) prepared.entryReason = untraced;
        return;
    }
    int most = 0;
    for (const auto& [marched, signature] : valid) most = std::max(most, marched.loops);
    std::erase_if(valid, [most](const auto& candidate) { return candidate.first.loops < most; });
    if (chooseLoopsUnion(prepared, valid, stripped)) return;
    if (valid.size() > 1) {
        const auto& names = conventionalEntries();
        auto conventional = [&names](const auto& candidate) {
            return std::find(names.begin(), names.end(), candidate.first.name) != names.end();
        };
        if (std::count_if(valid.begin(), valid.end(), conventional) == 1)
            std::erase_if(valid, [&](const auto& candidate) { return !conventional(candidate); });
    }
    const std::string deeper = keepPrimaryRays(valid);
    const std::string united = uniteTiedMarches(valid);
    if (valid.size() > 1) {
        std::string list;
        for (const auto& [marched, signature] : valid) {
            list += (list.empty() ? "" : ", ") + where(marched);
            prepared.entryCandidates.push_back(marched.name);
        }
        prepared.signature.entry = valid.front().first.name;
        prepared.diagnostics.push_back({valid.front().first.file, valid.front().first.line, 1, Severity::Error,
                                        "this shader marches " + std::to_string(valid.size()) + " functions equally often: " +
                                            list + "; choose the field with --entry NAME (or an `entry: NAME` metadata line)"});
        return;
    }
    // mainImage's own march of a field with parameters after the point: the loop's inline field
    // first, which holds what the loop adds to the field's distance (`d = min(d, ...)`), else the
    // field with mainImage's values (a point moved by `p = p + rd * d`, which no inline field reads).
    // So too where the loop steps by more than one call of it (two spheres by one sdSphere(p, centre,
    // radius)): the loop's field is what it steps by, not the first call's.
    if (const MarchedFunction& own = valid.front().first;
        (own.depth == 0 && !valid.front().second.arguments.empty()) || own.stepCalls > 1)
        for (const InlineMarch& march : userInlineMarches(prepared))
            if (!march.body.empty() && march.file == own.file && march.line == own.loopLine) {
                useInlineMarch(prepared, march, stripped);
                return;
            }
    prepared.signature = std::move(valid.front().second);
    prepared.entrySource = EntrySource::March;
    const MarchedFunction& chosen = valid.front().first;
    prepared.entryReason = united.empty() ? where(chosen) : united;
    if (!deeper.empty())
        prepared.entryReason +=
            "; " + deeper + " is marched as often, deeper in mainImage's calls or after the primary ray (a secondary ray)";
    prepared.marchThreshold = chosen.hitThreshold;
    prepared.marchThresholdLine = chosen.hitLine;
    if (const std::vector<std::string> pixel = perPixelParameters(chosen); !pixel.empty()) {
        std::string names;
        for (const std::string& name : pixel) names += (names.empty() ? "'" : ", '") + name + "'";
        prepared.diagnostics.push_back(
            {chosen.file, chosen.line, 1, Severity::Warning,
             chosen.name + " reads " + names + ", which mainImage computes for each pixel; sdfwb evaluates the field " +
                 "with the frame centre's value, so parts the shader draws for other pixels may be missing (to sample " +
                 "its whole scene, pass a function of the point alone with --entry)"});
    }
}

} // namespace sdfwb::shaders::detail
