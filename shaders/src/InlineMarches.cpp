#include <shaders/MarchAnalysis.h>

#include "CallText.h"
#include "InlineField.h"
#include "MarchThreshold.h"
#include "MarchTree.h"
#include "Words.h"

#include <shaders/SdfSource.h>

#include <algorithm>
#include <cctype>
#include <map>
#include <optional>
#include <set>

// Marches that write their field inline (InlineMarch): the loops mainImage's functions run that
// grow a point, or a distance along a ray, by a float the loop computes from it.

namespace sdfwb::shaders {
namespace {

using namespace detail;

// The parameters of `function`, which holds an inline march, with the values mainImage passes at
// the top of its body (`t = raymarch(ro, rd, torusParams, angle)`): its statements before that
// call become the march's prelude, run once, as for a marched function's parameters
// (MarchedFunction::traced). False, with nothing set, where mainImage makes no such call or a
// parameter's type cannot be declared: the caller then gives the parameters zeros.
bool traceParameters(InlineMarch& march, TIntermAggregate* function, const std::vector<TIntermSymbol*>& parameters,
                     const Reached& tree, const std::string& text) {
    const MarcherCall found = findMarcherCall(function, tree);
    if (!found.call || !found.fromMainImage || found.call->getLoc().string != function->getLoc().string ||
        tree.mainImage->getLoc().string != function->getLoc().string)
        return false;
    std::string before;
    int callLineNumber = found.call->getLoc().line;
    const std::vector<std::string> values =
        callArguments(text, callLineNumber, plainName(function->getName()), &before, &callLineNumber);
    if (values.size() != parameters.size() || before.find_first_of(";{}") != std::string::npos) return false;
    const std::size_t open = bodyOpen(text, tree.mainImage), callLine = lineStart(text, callLineNumber);
    if (open == std::string::npos || callLine == std::string::npos || open >= callLine ||
        !wholeStatements(text.substr(open + 1, callLine - open - 1)))
        return false;
    std::vector<TracedValue> traced;
    for (std::size_t k = 0; k < parameters.size(); ++k) {
        const std::string type = glslTypeName(parameters[k]->getType());
        if (type.empty() || !isInParameter(parameters[k])) return false;
        traced.push_back({type, parameters[k]->getName().c_str(), values[k]});
    }
    march.prelude = text.substr(open + 1, callLine - open - 1);
    march.traced = std::move(traced);
    const std::vector<TIntermSymbol*> mainParameters = parametersOf(tree.mainImage);
    if (mainParameters.size() == 2) {
        march.colour = mainParameters[0]->getName().c_str();
        march.coordinate = mainParameters[1]->getName().c_str();
    }
    return true;
}

// `code` with its preprocessor lines blanked: what is left of it must be whole statements.
std::string withoutDirectives(std::string code) {
    for (std::size_t at = 0; at < code.size();) {
        const std::size_t stop = std::min(code.find('\n', at), code.size());
        if (const std::size_t k = code.find_first_not_of(" \t", at); k < stop && code[k] == '#')
            std::fill(code.begin() + std::ptrdiff_t(at), code.begin() + std::ptrdiff_t(stop), ' ');
        at = stop + 1;
    }
    return code;
}

// The code before a loop with the branches of preprocessor conditionals still open at the loop
// blanked up to the branch that holds it (`#if NAIVE ... #else` before the march, whose `#endif`
// follows it): the loop is in the active branch, so the ones before it are not. Conditionals
// closed before the loop are left to the preprocessor.
std::string withoutInactiveBranches(std::string code) {
    std::vector<std::size_t> open, branchEnd; // where each conditional still open began, its last #else's end
    auto directive = [&](std::size_t at, std::size_t stop) {
        std::size_t k = code.find_first_not_of(" \t", at);
        if (k >= stop || code[k] != '#') return std::string();
        k = code.find_first_not_of(" \t", k + 1);
        std::size_t end = k;
        while (end < stop && std::isalpha(static_cast<unsigned char>(code[end]))) ++end;
        return k < stop ? code.substr(k, end - k) : std::string();
    };
    for (std::size_t at = 0; at < code.size();) {
        const std::size_t stop = std::min(code.find('\n', at), code.size());
        const std::string word = directive(at, stop);
        if (word == "if" || word == "ifdef" || word == "ifndef") {
            open.push_back(at);
            branchEnd.push_back(std::string::npos);
        } else if ((word == "else" || word == "elif") && !open.empty()) {
            branchEnd.back() = stop;
        } else if (word == "endif" && !open.empty()) {
            open.pop_back();
            branchEnd.pop_back();
        }
        at = stop + 1;
    }
    for (std::size_t i = 0; i < open.size(); ++i) {
        // Unclosed without an #else before the loop: only its #if line goes.
        const std::size_t end =
            branchEnd[i] != std::string::npos ? branchEnd[i] : std::min(code.find('\n', open[i]), code.size());
        for (std::size_t k = open[i]; k < end; ++k)
            if (code[k] != '\n') code[k] = ' ';
    }
    return code;
}

// Fills an inline march's prelude and body from its loop's text (InlineField.h), or its unresolved.
void readInlineMarch(InlineMarch& march, TIntermLoop* loop, TIntermAggregate* function, const Reached& tree,
                     const ComposedShader& composed, const LevelNames* levels = nullptr) {
    const bool isMainImage = function == tree.mainImage;
    const int file = loop->getLoc().string;
    if (file < 0 || file >= int(composed.map.files.size()) || function->getLoc().string != file) {
        march.unresolved = "the loop and its function are in different files";
        return;
    }
    const std::string stripped = stripComments(composed.map.files[std::size_t(file)].text);
    const std::size_t line = lineStart(stripped, loop->getLoc().line);
    if (line == std::string::npos) {
        march.unresolved = "the loop's line could not be read";
        return;
    }
    // A loop a macro writes (golfed `#define c F{...}`): read from the macro's expansion.
    const std::string text = withLoopMacroExpanded(stripped, line);
    // The loop's keyword: at glslang's column, else the line's first loop keyword.
    const std::size_t lineEnd = std::min(text.find('\n', line), text.size());
    auto isKeyword = [&](std::size_t at) {
        return at < lineEnd && (detail::isWordAt(text, at, "for") || detail::isWordAt(text, at, "while"));
    };
    std::size_t keyword = std::string::npos;
    const std::size_t column = line + std::size_t(std::max(1, loop->getLoc().column));
    if (isKeyword(column - 1))
        keyword = column - 1;
    else
        for (std::size_t at = line; at < lineEnd && keyword == std::string::npos; ++at)
            if (isKeyword(at)) keyword = at;
    const std::size_t open = bodyOpen(text, function);
    int enclosing = 0;
    const std::string before = open == std::string::npos || keyword == std::string::npos || open >= keyword
                                   ? std::string()
                                   : enteredBlocks(withoutInactiveBranches(text.substr(open + 1, keyword - open - 1)), enclosing);
    if (keyword == std::string::npos || open == std::string::npos || open >= keyword ||
        !wholeStatements(withoutDirectives(before) + std::string(std::size_t(std::max(0, enclosing)), '}'))) {
        march.unresolved = march.function + "'s code before the loop is not whole statements";
        return;
    }
    std::string why;
    march.body =
        levels ? levelFieldBody(text, keyword, march.counter, march.point, *levels, march.field, march.level, march.step, why)
        : march.field.empty() && march.fieldFactor < 0
            ? inlineFieldBody(text, keyword, march.counter, march.point, march.step, why, march.pointSize)
            : pointMarchBody(text, keyword, march.point, march.field, march.fieldFactor, march.step, why);
    if (march.body.empty()) {
        march.unresolved = why;
        return;
    }
    const std::vector<TIntermSymbol*> parameters = parametersOf(function);
    std::string declarations;
    if (isMainImage && parameters.size() == 2) {
        march.colour = parameters[0]->getName().c_str();
        march.coordinate = parameters[1]->getName().c_str();
    } else if (traceParameters(march, function, parameters, tree, text)) {
        march.body = before + march.body + std::string(std::size_t(enclosing), '}');
        return;
    } else {
        // Another function's parameters (the ray's origin and direction): zero, since the point is given.
        for (TIntermSymbol* parameter : parameters) {
            const std::string type = glslTypeName(parameter->getType()), zero = zeroValue(parameter->getType());
            if (type.empty() || zero.empty()) {
                march.body.clear();
                march.unresolved =
                    "parameter '" + std::string(parameter->getName().c_str()) + "' has a type the wrapper cannot declare";
                return;
            }
            declarations += type + " " + parameter->getName().c_str() + " = " + zero + ";\n";
        }
    }
    march.prelude = declarations + before;
    march.body += std::string(std::size_t(enclosing), '}'); // the blocks the prelude entered
}

void setHitThreshold(InlineMarch& march, TIntermLoop* loop, std::set<long long> distances) {
    const detail::HitThreshold hit = detail::hitThreshold(loop, nullptr, std::move(distances));
    march.hitThreshold = hit.value, march.hitLine = hit.line;
}

// `from` with every symbol the loop's assignments to its members read, through each other (but
// `except`'s).
std::set<long long> readThrough(std::set<long long> from, const std::vector<Assignment>& assignments,
                                const Assignment* except = nullptr) {
    for (bool grew = true; grew;) {
        grew = false;
        for (const Assignment& a : assignments)
            if (&a != except && a.target >= 0 && from.count(a.target))
                for (long long r : a.reads) grew |= from.insert(r).second;
    }
    return from;
}

// What leaves a loop from a branch of an if in it (break, return, discard; not in a loop nested in
// it), or holds the loop's step.
struct LeavesOrSteps : glslang::TIntermTraverser {
    TIntermBinary* step = nullptr;
    bool found = false;
    bool visitBranch(glslang::TVisit, glslang::TIntermBranch* node) override {
        const glslang::TOperator op = node->getFlowOp();
        found |= op == glslang::EOpBreak || op == glslang::EOpReturn || op == glslang::EOpKill;
        return true;
    }
    bool visitBinary(glslang::TVisit, TIntermBinary* node) override {
        found |= node == step;
        return true;
    }
    bool visitLoop(glslang::TVisit, TIntermLoop*) override { return false; }
    bool visitSwitch(glslang::TVisit, glslang::TIntermSwitch*) override { return false; }
};

// The comparisons (<, <=, >, >=) a loop's test holds, and those of its ifs whose branch leaves
// the loop or holds `step`: where a march that steps a fixed amount stops.
struct StopTests : glslang::TIntermTraverser {
    TIntermBinary* step = nullptr;
    std::vector<TIntermBinary*> comparisons;
    bool inTest = false;
    bool visitSelection(glslang::TVisit, glslang::TIntermSelection* node) override {
        LeavesOrSteps branch;
        branch.step = step;
        if (node->getTrueBlock()) node->getTrueBlock()->traverse(&branch);
        if (branch.found && node->getCondition()) {
            inTest = true;
            node->getCondition()->traverse(this);
            inTest = false;
        }
        return true;
    }
    bool visitBinary(glslang::TVisit, TIntermBinary* node) override {
        const glslang::TOperator op = node->getOp();
        if (inTest && (op == glslang::EOpLessThan || op == glslang::EOpLessThanEqual || op == glslang::EOpGreaterThan ||
                       op == glslang::EOpGreaterThanEqual))
            comparisons.push_back(node);
        return true;
    }
    bool visitLoop(glslang::TVisit, TIntermLoop*) override { return false; }
};

// A march that steps a fixed amount and stops where a value of the point crosses a level
// (InlineMarch::level): `counter` (a float, or the vec3 point itself) grows by what reads no value
// of the point, and a stop test compares a value the loop computes from the point through the
// shader's functions (`h = terrain(p.xz)`, not accumulated) or such a call itself, or both its
// sides read the point (a height written inline: `cos(p.z) - abs(sin(p.x)) < p.y`). The names
// go to `levels` (LevelNames); the point's symbol is returned, or -1.
long long levelMarchPoint(TIntermLoop* loop, const Assignment& stepping, TIntermBinary* stepNode,
                          const std::vector<Assignment>& assignments, const std::map<long long, TIntermSymbol*>& byId,
                          LevelNames& levels) {
    auto typeOf = [&](long long id) -> const glslang::TType* {
        auto it = byId.find(id);
        return it == byId.end() ? nullptr : &it->second->getType();
    };
    const glslang::TType* counterType = typeOf(stepping.target);
    if (!counterType ||
        (!isFloatVec3(*counterType) && (!counterType->isScalar() || counterType->getBasicType() != glslang::EbtFloat)))
        return -1;
    long long point = isFloatVec3(*counterType) ? stepping.target : -1;
    for (const Assignment& a : assignments)
        if (point < 0 && a.target >= 0 && a.target != stepping.target && a.reads.count(stepping.target) && typeOf(a.target) &&
            isFloatVec3(*typeOf(a.target)))
            point = a.target;
    if (point < 0) return -1;
    auto readsPoint = [&](const std::set<long long>& symbols) {
        return symbols.count(point) || readThrough(symbols, assignments, &stepping).count(point);
    };
    std::set<long long> values; // computed from the point through a call, not added up
    for (const Assignment& a : assignments)
        if (a.target >= 0 && a.target != point && a.target != stepping.target && !a.calls.empty() && a.op == glslang::EOpAssign &&
            !a.reads.count(a.target) && readsPoint(a.reads))
            values.insert(a.target);
    for (const Assignment& a : assignments) // a value added up is no level
        if (a.op != glslang::EOpAssign || a.reads.count(a.target)) values.erase(a.target);
    if (readThrough(stepping.reads, assignments, &stepping).count(point) && stepping.target != point) return -1;
    StopTests tests;
    tests.step = stepNode;
    if (loop->getBody()) loop->getBody()->traverse(&tests);
    if (loop->getTest()) {
        tests.inTest = true;
        loop->getTest()->traverse(&tests);
    }
    std::set<long long> derived{point}; // the point and what the loop computes from it, not added up
    for (const Assignment& a : assignments)
        if (a.target >= 0 && a.target != stepping.target && a.op == glslang::EOpAssign && readsPoint(a.reads))
            derived.insert(a.target);
    for (const Assignment& a : assignments)
        if (a.target != point && (a.op != glslang::EOpAssign || a.reads.count(a.target))) derived.erase(a.target);
    auto name = [&](long long symbol) { return std::string(byId.at(symbol)->getName().c_str()); };
    for (TIntermBinary* comparison : tests.comparisons) {
        const Contents read = contentsOf(comparison);
        for (long long symbol : read.symbols)
            if (values.count(symbol)) levels.values.insert(name(symbol));
        for (TIntermAggregate* call : read.calls)
            if (readsPoint(contentsOf(call).symbols)) levels.values.insert(plainName(call->getName()));
        auto sideReads = [&](TIntermTyped* side, bool keep) {
            bool found = false;
            for (long long symbol : contentsOf(side).symbols)
                if (derived.count(symbol)) {
                    found = true;
                    if (keep) levels.sides.insert(name(symbol));
                }
            return found;
        };
        if (sideReads(comparison->getLeft(), false) && sideReads(comparison->getRight(), false))
            sideReads(comparison->getLeft(), true), sideReads(comparison->getRight(), true);
    }
    return levels.values.empty() && levels.sides.empty() ? -1 : point;
}

InlineMarch marchAt(TIntermAggregate* function, TIntermLoop* loop, const ComposedShader& composed) {
    InlineMarch march;
    march.function = plainName(function->getName());
    march.file = composed.map.fileName(loop->getLoc().string);
    march.line = loop->getLoc().line;
    return march;
}

// The symbols a subtree reads or writes, by id.
struct SymbolsById : glslang::TIntermTraverser {
    std::map<long long, TIntermSymbol*> byId;
    void visitSymbol(TIntermSymbol* node) override { byId.emplace(node->getId(), node); }
};

// The march of `loop` that steps a fixed amount and stops at a level (levelMarchPoint), read.
std::optional<InlineMarch> levelMarch(TIntermAggregate* function, TIntermLoop* loop, const Contents& inside,
                                      const std::vector<Assignment>& assignments, const std::set<TIntermBinary*>& nested,
                                      const std::map<long long, TIntermSymbol*>& byId, const Reached& tree,
                                      const ComposedShader& composed) {
    std::optional<InlineMarch> first; // the first such march, if none can be read
    for (std::size_t s = 0; s < inside.assignments.size(); ++s) {
        const Assignment& stepping = assignments[s];
        if ((stepping.op != glslang::EOpAddAssign && stepping.op != glslang::EOpSubAssign) || stepping.target < 0 ||
            nested.count(inside.assignments[s]) || !inside.assignments[s]->getLeft()->getAsSymbolNode())
            continue;
        LevelNames levels;
        const long long point = levelMarchPoint(loop, stepping, inside.assignments[s], assignments, byId, levels);
        if (point < 0) continue;
        InlineMarch march = marchAt(function, loop, composed);
        march.counter = byId.at(stepping.target)->getName().c_str();
        march.point = byId.at(point)->getName().c_str();
        readInlineMarch(march, loop, function, tree, composed, &levels);
        if (!march.body.empty()) return march;
        if (!first) first = std::move(march);
    }
    return first;
}

// The point of a march that steps `counter` by what `from` holds: a vec3 in it that the loop
// computes from the counter, else such a vec4 whose xyz is the point (golfed: `p = vec4(z *
// normalize(...), .1 * iTime)`); -1 when none. `size` receives 3 or 4.
long long marchedPoint(const std::vector<Assignment>& assignments, const std::set<long long>& from, long long counter,
                       const std::map<long long, TIntermSymbol*>& byId, int& size) {
    for (const int wanted : {3, 4})
        for (const Assignment& a : assignments) {
            auto symbol = byId.find(a.target);
            if (symbol == byId.end() || !from.count(a.target) || !a.reads.count(counter)) continue;
            const glslang::TType& type = symbol->second->getType();
            if (type.getBasicType() == glslang::EbtFloat && type.isVector() && !type.isArray() &&
                type.getVectorSize() == wanted) {
                size = wanted;
                return a.target;
            }
        }
    return -1;
}

} // namespace

std::vector<InlineMarch> inlineMarches(const ComposedShader& composed) {
    Reached tree;
    if (!parseReached(composed, tree)) return {};
    std::vector<InlineMarch> found;
    for (TIntermAggregate* function : tree.reached) {
        for (TIntermLoop* loop : contentsOf(function).loops) {
            Contents inside;
            inside.everyMove = true; // `d /= o` carries the point into the step as `d = d / o` does
            loop->traverse(&inside);
            // A loop nested in this one advances its own march: found when that loop's turn comes.
            std::set<TIntermBinary*> nested;
            for (TIntermLoop* inner : inside.loops) {
                if (inner == loop) continue;
                Contents innerContents;
                innerContents.everyMove = true;
                inner->traverse(&innerContents);
                nested.insert(innerContents.assignments.begin(), innerContents.assignments.end());
            }
            std::vector<Assignment> assignments;
            for (TIntermBinary* node : inside.assignments) {
                Contents right = contentsOf(node->getRight());
                Assignment a{assignedSymbol(node->getLeft()), node->getOp(), right.symbols,
                             std::set<TIntermAggregate*>(right.calls.begin(), right.calls.end())};
                if (a.op != glslang::EOpAssign && a.target >= 0) a.reads.insert(a.target);
                assignments.push_back(std::move(a));
            }
            SymbolsById symbols; // names and types of the loop's symbols
            loop->traverse(&symbols);
            auto typeOf = [&](long long id) -> const glslang::TType* {
                auto it = symbols.byId.find(id);
                return it == symbols.byId.end() ? nullptr : &it->second->getType();
            };
            bool marched = false;
            // A point that grows itself (`p += rd * d`) by a float the loop computes from it.
            for (std::size_t s = 0; s < inside.assignments.size() && !marched; ++s) {
                const Assignment& stepping = assignments[s];
                TIntermSymbol* point = inside.assignments[s]->getLeft()->getAsSymbolNode();
                if ((stepping.op != glslang::EOpAddAssign && stepping.op != glslang::EOpSubAssign) || !point ||
                    !isFloatVec3(point->getType()) || nested.count(inside.assignments[s]))
                    continue;
                for (long long read : stepping.reads) {
                    const glslang::TType* type = typeOf(read);
                    if (read == stepping.target || !type || !type->isScalar() || type->getBasicType() != glslang::EbtFloat)
                        continue;
                    if (!readThrough({read}, assignments, &stepping).count(stepping.target)) continue;
                    InlineMarch march = marchAt(function, loop, composed);
                    march.counter = march.point = point->getName().c_str();
                    march.field = symbols.byId[read]->getName().c_str();
                    readInlineMarch(march, loop, function, tree, composed);
                    setHitThreshold(march, loop, {read});
                    found.push_back(std::move(march));
                    marched = true;
                    break;
                }
                // Or by a float expression of itself in the step (`p += (.1 - length(o.xy)) * d`).
                TIntermBinary* product = inside.assignments[s]->getRight()->getAsBinaryNode();
                if (marched || !product ||
                    (product->getOp() != glslang::EOpVectorTimesScalar && product->getOp() != glslang::EOpMul))
                    continue;
                for (int factor = 0; factor < 2 && !marched; ++factor) {
                    TIntermTyped* operand = factor == 0 ? product->getLeft() : product->getRight();
                    if (!operand->getType().isScalar() || operand->getType().getBasicType() != glslang::EbtFloat) continue;
                    if (!readThrough(contentsOf(operand).symbols, assignments, &stepping).count(stepping.target)) continue;
                    InlineMarch march = marchAt(function, loop, composed);
                    march.counter = march.point = point->getName().c_str();
                    march.fieldFactor = factor;
                    readInlineMarch(march, loop, function, tree, composed);
                    found.push_back(std::move(march));
                    marched = true;
                }
            }
            for (std::size_t s = 0; s < inside.assignments.size() && !marched; ++s) {
                const Assignment& stepping = assignments[s];
                TIntermSymbol* counter = inside.assignments[s]->getLeft()->getAsSymbolNode();
                // `t += d`, or a march backwards (`t -= d`: the field is -d).
                if ((stepping.op != glslang::EOpAddAssign && stepping.op != glslang::EOpSubAssign) || !counter ||
                    !counter->getType().isScalar() || counter->getType().getBasicType() != glslang::EbtFloat ||
                    nested.count(inside.assignments[s]))
                    continue;
                // What the step is computed from, through the loop's assignments.
                std::set<long long> from = stepping.reads;
                for (bool grew = true; grew;) {
                    grew = false;
                    for (const Assignment& a : assignments)
                        if (a.target >= 0 && a.target != stepping.target && from.count(a.target))
                            for (long long read : a.reads) grew |= read != stepping.target && from.insert(read).second;
                }
                int pointSize = 3;
                const long long point = marchedPoint(assignments, from, stepping.target, symbols.byId, pointSize);
                if (point < 0) continue;
                InlineMarch march = marchAt(function, loop, composed);
                march.counter = counter->getName().c_str();
                march.point = symbols.byId[point]->getName().c_str();
                march.pointSize = pointSize;
                readInlineMarch(march, loop, function, tree, composed);
                std::set<long long> floats; // the step's floats (`t += d`, `t += d * .5`)
                for (long long read : stepping.reads)
                    if (const glslang::TType* type = typeOf(read);
                        read != stepping.target && type && type->isScalar() && type->getBasicType() == glslang::EbtFloat)
                        floats.insert(read);
                setHitThreshold(march, loop, std::move(floats));
                found.push_back(std::move(march));
                marched = true;
                break;
            }
            // A march that steps a fixed amount and stops at a level of the point's value.
            if (std::optional<InlineMarch> march;
                !marched && (march = levelMarch(function, loop, inside, assignments, nested, symbols.byId, tree, composed)))
                found.push_back(std::move(*march));
        }
    }
    return found;
}

} // namespace sdfwb::shaders
