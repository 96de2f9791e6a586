#include <shaders/MarchAnalysis.h>

#include "CallText.h"
#include "InlineField.h"
#include "MarchOrder.h"
#include "MarchThreshold.h"
#include "MarchTree.h"
#include "ParameterText.h"
#include "Words.h"

#include <shaders/GlslChecker.h>
#include <shaders/SdfSource.h>

#include <glslang/Include/intermediate.h>
#include <glslang/MachineIndependent/localintermediate.h>
#include <glslang/Public/ResourceLimits.h>
#include <glslang/Public/ShaderLang.h>

#include <algorithm>
#include <deque>
#include <map>
#include <set>

namespace sdfwb::shaders {
namespace {

using namespace detail;

using detail::callArguments;
using detail::enteredBlocks;
using detail::lineStart;
using detail::wholeStatements;

using glslang::TIntermAggregate;
using glslang::TIntermBinary;
using glslang::TIntermLoop;
using glslang::TIntermSymbol;
using glslang::TIntermTyped;

// A distance's return: float, vec2 or vec4 (a value and a material id or colour). Not vec3: what a
// march loop calls and returns a vec3 is a normal or a colour (a reflection loop's `ro += nor * eps`
// grows the point by calcNormal's result), unless the loop reads only its x
// (readsFirstComponentOnly).
bool returnsFloats(const glslang::TType& type) {
    return type.getBasicType() == glslang::EbtFloat && !type.isArray() &&
           (type.isScalar() || (type.isVector() && type.getVectorSize() != 3));
}

bool returnsStruct(const glslang::TType& type) { return type.getBasicType() == glslang::EbtStruct && !type.isArray(); }

// What holds a call's result in a loop: the call itself, or a variable assigned it
// (`Hit h = map(p);`, `vec4 ds = sdScene(p);`).
struct CallResult {
    TIntermAggregate* call = nullptr;
    std::set<long long> holders;
    bool holds(TIntermTyped* node) const {
        TIntermSymbol* symbol = node->getAsSymbolNode();
        return node == call || (symbol && holders.count(symbol->getId()));
    }
};

CallResult resultOf(TIntermAggregate* call, const std::vector<TIntermBinary*>& assignments) {
    CallResult result{call, {}};
    for (TIntermBinary* a : assignments)
        if (a->getOp() == glslang::EOpAssign && a->getRight() == call) result.holders.insert(assignedSymbol(a->getLeft()));
    return result;
}

// The float member of the struct `call` returns that the loop reads first, from the call itself
// or from a variable assigned the call (`Hit h = map(p); ... t += h.d;`); empty when none.
std::string distanceMember(TIntermNode* loop, const CallResult& result) {
    struct Members : glslang::TIntermTraverser {
        const CallResult* result = nullptr;
        std::string found;
        bool visitBinary(glslang::TVisit, TIntermBinary* node) override {
            if (!found.empty() || node->getOp() != glslang::EOpIndexDirectStruct) return true;
            TIntermTyped* base = node->getLeft();
            if (!result->holds(base)) return true;
            const glslang::TTypeList* members = base->getType().getStruct();
            const glslang::TIntermConstantUnion* index = node->getRight()->getAsConstantUnion();
            if (!members || !index) return true;
            const int i = index->getConstArray()[0].getIConst();
            if (i < 0 || i >= int(members->size())) return true;
            const glslang::TType& member = *(*members)[std::size_t(i)].type;
            if (member.getBasicType() == glslang::EbtFloat && member.isScalar()) found = member.getFieldName().c_str();
            return true;
        }
    } members;
    members.result = &result;
    loop->traverse(&members);
    return members.found;
}

// How a subtree reads the components of a call's result: one component at a time (`.x`, `.w`,
// `[1]`), counted per component, or otherwise (`.xyz`, an index not constant).
struct ComponentReads : glslang::TIntermTraverser {
    const CallResult* result = nullptr;
    int single[4] = {0, 0, 0, 0};
    int other = 0;
    bool visitBinary(glslang::TVisit, TIntermBinary* node) override {
        const glslang::TOperator op = node->getOp();
        if (op != glslang::EOpVectorSwizzle && op != glslang::EOpIndexDirect) return true;
        if (!result->holds(node->getLeft())) return true;
        const glslang::TIntermConstantUnion* index = node->getRight()->getAsConstantUnion();
        const TIntermAggregate* swizzle = node->getRight()->getAsAggregate();
        if (op == glslang::EOpVectorSwizzle && swizzle && swizzle->getSequence().size() == 1)
            index = swizzle->getSequence().front()->getAsConstantUnion();
        else if (op == glslang::EOpVectorSwizzle)
            index = nullptr;
        const int i = index ? index->getConstArray()[0].getIConst() : -1;
        ++(i >= 0 && i < 4 ? single[i] : other);
        return true;
    }
};

ComponentReads componentReads(TIntermNode* node, const CallResult& result) {
    ComponentReads reads;
    reads.result = &result;
    if (node) node->traverse(&reads);
    return reads;
}

// Whether the loop reads only the first component (`.x`, `.r`, `[0]`) of what `call` returns, from
// the call itself or from a variable assigned the call (`vec3 h = f(p); t += h.x;`): a vec3 field
// that carries its distance in x and a material or orbit trap in y and z. A normal or a colour is
// read whole or in all its components.
bool readsFirstComponentOnly(TIntermNode* loop, const CallResult& result) {
    const ComponentReads reads = componentReads(loop, result);
    return reads.single[0] > 0 && reads.single[1] + reads.single[2] + reads.single[3] + reads.other == 0;
}

// Assignments a loop's body makes under a condition or in a loop nested in it.
std::set<TIntermBinary*> conditionalAssignments(TIntermLoop* loop) {
    struct Walk : glslang::TIntermTraverser {
        std::set<TIntermBinary*> found;
        int nesting = 0;
        bool visitSelection(glslang::TVisit, glslang::TIntermSelection* node) override {
            ++nesting;
            if (node->getTrueBlock()) node->getTrueBlock()->traverse(this);
            if (node->getFalseBlock()) node->getFalseBlock()->traverse(this);
            --nesting;
            return false;
        }
        bool visitLoop(glslang::TVisit, TIntermLoop* node) override {
            ++nesting;
            if (node->getBody()) node->getBody()->traverse(this);
            --nesting;
            return false;
        }
        bool visitBinary(glslang::TVisit, TIntermBinary* node) override {
            if (nesting > 0) found.insert(node);
            return true;
        }
    } walk;
    if (loop->getBody()) loop->getBody()->traverse(&walk);
    return walk.found;
}

// Whether the value `call` gives a variable after the step is overwritten before the step reads it
// again: `h = Map(p); ... t += clamp(.5 * h, ...); h = MapClouds(p);` (a terrain that reuses h for
// its clouds) steps by Map alone.
bool overwrittenBeforeTheStep(const std::vector<Assignment>& assignments, TIntermAggregate* call, const Assignment& step,
                              const std::set<TIntermBinary*>& conditional) {
    auto before = [](const glslang::TSourceLoc& a, const glslang::TSourceLoc& b) {
        return a.line < b.line || (a.line == b.line && a.column < b.column);
    };
    for (const Assignment& given : assignments) {
        if (!given.calls.count(call) || given.op != glslang::EOpAssign || given.target < 0 ||
            !before(step.node->getLoc(), given.node->getLoc()))
            continue;
        for (const Assignment& other : assignments)
            if (&other != &given && other.target == given.target && other.op == glslang::EOpAssign &&
                !other.reads.count(other.target) && !conditional.count(other.node) &&
                before(other.node->getLoc(), step.node->getLoc()))
                return true;
    }
    return false;
}

// Whether two calls pass the same arguments: the same variables, the same constants (`scene(p)`
// twice, once to step and once for the sign of the next steps, is one field).
bool sameArguments(TIntermAggregate* a, TIntermAggregate* b) {
    auto same = [](TIntermNode* x, TIntermNode* y) {
        if (TIntermSymbol* s = x->getAsSymbolNode(), *t = y->getAsSymbolNode(); s || t) return s && t && s->getId() == t->getId();
        if (auto* c = x->getAsConstantUnion(), *d = y->getAsConstantUnion(); c || d)
            return c && d && c->getConstArray() == d->getConstArray();
        return false;
    };
    if (a->getSequence().size() != b->getSequence().size()) return false;
    for (std::size_t i = 0; i < a->getSequence().size(); ++i)
        if (!same(a->getSequence()[i], b->getSequence()[i])) return false;
    return true;
}

// The assignment by which `loop` steps by `call` (a call inside it; see the header), or null.
const Assignment* stepBy(const std::vector<Assignment>& assignments, TIntermAggregate* call,
                         const std::set<TIntermBinary*>& conditional) {
    // The variables the call's point depends on within the loop.
    std::set<long long> point = contentsOf(call->getSequence().front()).symbols;
    // The variables holding the call's result, or values computed from it.
    std::set<long long> result;
    for (bool grew = true; grew;) {
        grew = false;
        for (const Assignment& a : assignments) {
            if (a.target < 0) continue;
            if (point.count(a.target))
                for (long long read : a.reads) grew |= point.insert(read).second;
            // What the call's value reaches, but not through the march's state rewritten from itself
            // (a material that bends the ray, `ray.dir = refract(ray.dir, n, mat.refr)`, does not make
            // the ray's step the material's; `dist = res.x` still carries the value).
            const bool rewritten = point.count(a.target) && a.reads.count(a.target) && a.op == glslang::EOpAssign;
            const bool fromResult =
                a.calls.count(call) ||
                (!rewritten && std::any_of(a.reads.begin(), a.reads.end(), [&](long long s) { return result.count(s) > 0; }));
            if (fromResult && a.target >= 0) grew |= result.insert(a.target).second;
        }
    }
    for (const Assignment& a : assignments) {
        if (a.target < 0 || !point.count(a.target)) continue;
        // `t += d`, `t = t + d`: a step adds. A value rewritten from itself otherwise (a refracted
        // direction, `ray.dir = refract(ray.dir, n, mat.refr)`) is not stepped.
        const TIntermBinary* sum = a.node->getRight()->getAsBinaryNode();
        const bool grows = a.op == glslang::EOpAddAssign || a.op == glslang::EOpSubAssign ||
                           (a.op == glslang::EOpAssign && a.reads.count(a.target) && sum &&
                            (sum->getOp() == glslang::EOpAdd || sum->getOp() == glslang::EOpSub));
        if (!grows) continue;
        if (a.calls.count(call) || std::any_of(a.reads.begin(), a.reads.end(), [&](long long s) { return result.count(s) > 0; }))
            return a.calls.count(call) || !overwrittenBeforeTheStep(assignments, call, a, conditional) ? &a : nullptr;
    }
    return nullptr;
}

// The component of a vector's result the march steps by, read in the step (`t += ds.w;`) or in a
// float the step reads (`float d = h.y; t += d;`): 1..3 (y, z, w), or 0 for x and where the step
// reads no one component alone (`t += d.x * .5` and `t += d` alike keep the x a vec2's field has).
int distanceComponent(const Assignment& step, const std::vector<Assignment>& assignments, const CallResult& result) {
    ComponentReads reads = componentReads(step.node->getRight(), result);
    for (const Assignment& a : assignments) {
        if (a.target < 0 || !step.reads.count(a.target) || !a.node->getType().isScalar()) continue;
        const ComponentReads held = componentReads(a.node->getRight(), result);
        for (int i = 0; i < 4; ++i) reads.single[i] += held.single[i];
    }
    int found = 0;
    for (int i = 1; i < 4; ++i)
        if (reads.single[i] > 0) {
            if (found > 0 || reads.single[0] > 0) return 0;
            found = i;
        }
    return found;
}

using Functions = std::map<std::string, TIntermAggregate*>; // definitions by mangled name

// The file-scope variables (not const, not uniforms) a subtree and the functions it calls read and
// assign, by symbol id with their names. A variable only assigned or updated in place (`glow += x`,
// `matId = 2.0`) is not read: what the field adds up beside its distance is not its input.
struct GlobalUse : glslang::TIntermTraverser {
    explicit GlobalUse(const Functions& all) : functions(all) {}
    const Functions& functions;
    std::set<std::string> entered;
    std::map<long long, std::string> read, written;
    std::set<const TIntermSymbol*> assigned; // symbols on the left of an assignment

    static bool fileScope(const TIntermSymbol* symbol) { return symbol->getQualifier().storage == glslang::EvqGlobal; }
    void visitSymbol(TIntermSymbol* node) override {
        if (fileScope(node) && !assigned.count(node)) read.emplace(node->getId(), node->getName().c_str());
    }
    bool visitBinary(glslang::TVisit, TIntermBinary* node) override {
        if (node->getOp() < glslang::EOpAssign || node->getOp() > glslang::EOpRightShiftAssign) return true;
        TIntermTyped* left = node->getLeft();
        while (TIntermBinary* access = left->getAsBinaryNode()) left = access->getLeft();
        if (TIntermSymbol* symbol = left->getAsSymbolNode(); symbol && fileScope(symbol)) {
            written.emplace(symbol->getId(), symbol->getName().c_str());
            assigned.insert(symbol);
        }
        return true;
    }
    bool visitAggregate(glslang::TVisit, TIntermAggregate* node) override {
        if (node->getOp() != glslang::EOpFunctionCall || !node->isUserDefined()) return true;
        auto callee = functions.find(node->getName().c_str());
        if (callee != functions.end() && entered.insert(callee->first).second) callee->second->traverse(this);
        return true;
    }
};

// A field without parameters after the point that reads file-scope variables mainImage sets before
// it calls the marching function (`radius = 0.5 + 0.1 * sin(iTime); spin = rot(iTime);`, or in a
// function it calls first): the wrapper runs those statements of mainImage first, as it does for
// parameters (traceArguments). Where mainImage marches itself, the statements before its loop
// (`lights[2].rotMat = rotate(...);`). Fills `m`'s prelude and globals; leaves them empty when
// mainImage does not call the marching function, or one that reaches it, (or hold its loop) at the
// top of its body. `host` is mainImage, or else a function that marches after setting them
// (Synesthesia's `vec3 render3D()`; `vec3 render(vec3 ro, vec3 rd)`, its parameters then zero).
void traceGlobals(MarchedFunction& m, TIntermAggregate* field, TIntermAggregate* marcher, TIntermLoop* loop,
                  TIntermAggregate* host, const ComposedShader& composed, const Functions& functions) {
    TIntermAggregate* body = bodyOf(host);
    if (!body) return;
    GlobalUse reads(functions);
    reads.entered.insert(field->getName().c_str());
    field->traverse(&reads);
    // The call of the marching function, or of the function that reaches it (`col = render(ro, rd)`), or
    // mainImage's own march loop, and the statements before it.
    TIntermNode* marcherCall = nullptr;
    int heldFrom = 0; // the line of the loop or `if` that holds the call, where one does
    std::string called;
    std::vector<TIntermNode*> earlier;
    if (marcher == host) { // the loop at the top of its body (`for (float t = 0.; ...)` is a sequence)
        for (TIntermNode* statement : body->getSequence()) {
            TIntermAggregate* sequence = statement->getAsAggregate();
            if (statement == loop || (sequence && sequence->getOp() == glslang::EOpSequence && !sequence->getSequence().empty() &&
                                      sequence->getSequence().back() == loop)) {
                marcherCall = loop;
                break;
            }
            earlier.push_back(statement);
        }
    } else {
        const ReachingStatement found = statementReaching(body, functionsReaching(marcher->getName(), functions));
        if (!found.call) return;
        // The call in a loop or an `if` (dr2's `for (float a = 0.; a < naa; a ++) col += ShowScene (ro, rd);`,
        // antialiasing): the statements before that statement.
        TIntermAggregate* sequence = found.statement->getAsAggregate();
        const bool held =
            isControlFlow(found.statement) || (sequence && sequence->getOp() == glslang::EOpSequence &&
                                               !sequence->getSequence().empty() && isControlFlow(sequence->getSequence().back()));
        marcherCall = found.call, called = plainName(found.call->getName());
        if (held)
            heldFrom = std::min(found.statement->getLoc().line, sequence && !sequence->getSequence().empty()
                                                                    ? sequence->getSequence().front()->getLoc().line
                                                                    : found.statement->getLoc().line);
        for (TIntermNode* statement : body->getSequence()) {
            if (statement == found.statement) break;
            earlier.push_back(statement);
        }
    }
    if (!marcherCall) return;
    GlobalUse sets(functions);
    for (TIntermNode* statement : earlier) statement->traverse(&sets);
    std::set<std::string> shared;
    for (const auto& [id, name] : sets.written)
        if (reads.read.count(id)) shared.insert(name);
    const int file = marcherCall->getLoc().string;
    if (shared.empty() || file < 0 || file >= int(composed.map.files.size()) || host->getLoc().string != file) return;
    // A host with parameters (`vec3 render(vec3 ro, vec3 rd)` setting its lights before its march):
    // the wrapper gives them zeros, so no global the field reads may come from them, directly or
    // through what a statement reading them assigns (its locals, and globals in what it calls).
    const std::vector<TIntermSymbol*> hostParameters = parametersOf(host);
    std::string declared;
    const bool ofMainImage = plainName(host->getName()) == "mainImage";
    if (!ofMainImage && !hostParameters.empty()) {
        std::set<long long> tainted;
        for (TIntermSymbol* parameter : hostParameters) {
            const std::string type = glslTypeName(parameter->getType());
            if (type.empty()) return;
            tainted.insert(parameter->getId());
            declared += type + " " + parameter->getName().c_str() + " = " + zeroValue(parameter->getType()) + "; ";
        }
        for (TIntermNode* statement : earlier) {
            Contents inside;
            inside.everyMove = true;
            statement->traverse(&inside);
            if (std::none_of(inside.symbols.begin(), inside.symbols.end(), [&](long long id) { return tainted.count(id) > 0; }))
                continue;
            GlobalUse writes(functions);
            statement->traverse(&writes);
            for (const auto& [id, name] : writes.written) tainted.insert(id);
            for (TIntermBinary* assignment : inside.assignments) tainted.insert(assignedSymbol(assignment->getLeft()));
        }
        for (const auto& [id, name] : sets.written)
            if (shared.count(name) && tainted.count(id)) return;
    }
    const std::string text = stripComments(composed.map.files[std::size_t(file)].text);
    std::string before;
    int callLineNumber = marcherCall->getLoc().line;
    if (heldFrom > 0)
        callLineNumber = heldFrom;
    else if (marcher != host && (callArguments(text, callLineNumber, called, &before, &callLineNumber).empty() ||
                                 before.find_first_of(";{}") != std::string::npos))
        return;
    const std::size_t open = bodyOpen(text, host), callLine = lineStart(text, callLineNumber);
    if (open == std::string::npos || callLine == std::string::npos || open >= callLine ||
        !wholeStatements(text.substr(open + 1, callLine - open - 1)))
        return;
    m.prelude = declared + text.substr(open + 1, callLine - open - 1);
    m.globals.assign(shared.begin(), shared.end());
    m.setter = plainName(host->getName());
    if (!ofMainImage) // not mainImage's: its pixel and colour under names of ours
        m.coordinate = "sdfwb_hostPixel", m.colour = "sdfwb_hostColour";
    else if (hostParameters.size() == 2)
        m.colour = hostParameters[0]->getName().c_str(), m.coordinate = hostParameters[1]->getName().c_str();
}

// traceGlobals through mainImage, then through the first function between it and the march that
// sets more of what the field reads (dr2's ShowScene: `twRad = 3.; bmHt = 17.;` before its march,
// after mainImage set dstFar): its statements run after mainImage's, in a block of their own.
void traceAllGlobals(MarchedFunction& m, TIntermAggregate* field, TIntermAggregate* marcher, TIntermLoop* loop,
                     TIntermAggregate* mainImage, const std::vector<TIntermAggregate*>& reached, const ComposedShader& composed,
                     const Functions& functions) {
    traceGlobals(m, field, marcher, loop, mainImage, composed, functions);
    for (TIntermAggregate* host : reached) {
        if (host == mainImage) continue;
        MarchedFunction deeper = m;
        deeper.prelude.clear(), deeper.globals.clear();
        traceGlobals(deeper, field, marcher, loop, host, composed, functions);
        if (deeper.prelude.empty()) continue;
        if (m.prelude.empty()) {
            m = std::move(deeper);
            return;
        }
        std::vector<std::string> more;
        for (const std::string& name : deeper.globals)
            if (std::find(m.globals.begin(), m.globals.end(), name) == m.globals.end()) more.push_back(name);
        if (more.empty()) return;
        m.prelude += "\n{\n" + deeper.prelude + "\n}\n";
        m.globals.insert(m.globals.end(), more.begin(), more.end());
        m.setter += " and " + deeper.setter;
        return;
    }
}

// The field's out parameters after the point (`out Material mat`): the variables the march passes
// there, as locals the wrapper declares (a TracedValue without a value). False with why when one
// is not a variable of a type the wrapper can declare.
bool outArguments(TIntermAggregate* call, const std::vector<TIntermSymbol*>& fieldParameters, std::vector<TracedValue>& outs,
                  std::string& why) {
    for (std::size_t i = 1; i < fieldParameters.size() && i < call->getSequence().size(); ++i) {
        if (isInParameter(fieldParameters[i])) continue;
        TIntermSymbol* argument = call->getSequence()[i]->getAsSymbolNode();
        const std::string type = glslTypeName(fieldParameters[i]->getType());
        if (!argument || type.empty()) {
            why = "its out parameter '" + std::string(fieldParameters[i]->getName().c_str()) +
                  "' is not given a variable of a type the wrapper can declare";
            return false;
        }
        outs.push_back({type, argument->getName().c_str(), {}});
    }
    return true;
}

// The field's arguments after the point where mainImage marches it itself (`float a = iTime;` ...
// `float c = g(t, a, m, p);` in its loop): its locals set before the loop, or constants, the values
// the wrapper keeps after running mainImage's statements before the loop; out locals as in
// traceArguments. `fail` says why not.
template <class Fail>
void traceOwnLocals(MarchedFunction& m, TIntermAggregate* call, const std::vector<TIntermSymbol*>& fieldParameters,
                    std::vector<TracedValue> outs, TIntermLoop* loop, const Reached& tree, const ComposedShader& composed,
                    Fail fail) {
    TIntermAggregate* mainImage = tree.mainImage;
    const int file = call->getLoc().string;
    if (file < 0 || file >= int(composed.map.files.size()) || mainImage->getLoc().string != file || loop->getLoc().string != file)
        return fail("the march and mainImage are in different files");
    std::set<long long> earlier; // the symbols of mainImage's statements before the one holding the loop
    if (TIntermAggregate* body = bodyOf(mainImage))
        for (TIntermNode* statement : body->getSequence()) {
            Contents contents = contentsOf(statement);
            if (std::find(contents.loops.begin(), contents.loops.end(), loop) != contents.loops.end()) break;
            earlier.insert(contents.symbols.begin(), contents.symbols.end());
        }
    for (std::size_t i = 1; i < fieldParameters.size() && i < call->getSequence().size(); ++i) {
        if (!isInParameter(fieldParameters[i])) continue;
        TIntermNode* argument = call->getSequence()[i];
        TIntermSymbol* local = argument->getAsSymbolNode();
        const bool before = local && local->getQualifier().storage == glslang::EvqTemporary && earlier.count(local->getId());
        if (!before && !isConstantArgument(argument))
            return fail("mainImage marches it itself with '" + std::string(fieldParameters[i]->getName().c_str()) +
                        "' computed in its loop");
        if (!local || !before) continue; // a constant stays in the call's text
        const std::string type = glslTypeName(local->getType()), name = local->getName().c_str();
        if (type.empty()) return fail("'" + name + "' has a type the wrapper cannot declare");
        if (std::none_of(m.traced.begin(), m.traced.end(), [&](const TracedValue& t) { return t.name == name; }))
            m.traced.push_back({type, name, name});
    }
    const std::string text = stripComments(composed.map.files[std::size_t(file)].text);
    const std::vector<std::string> fieldArguments = callArguments(text, call->getLoc().line, m.name, nullptr);
    if (fieldArguments.size() != fieldParameters.size()) return fail("its call's arguments could not be read");
    const std::size_t open = bodyOpen(text, mainImage), loopLine = lineStart(text, loop->getLoc().line);
    if (open == std::string::npos || loopLine == std::string::npos || open >= loopLine ||
        !wholeStatements(text.substr(open + 1, loopLine - open - 1)))
        return fail("mainImage's code before its march is not whole statements");
    for (std::size_t i = 1; i < fieldArguments.size(); ++i) m.arguments += ", " + fieldArguments[i];
    for (TracedValue& out : outs)
        if (std::none_of(m.traced.begin(), m.traced.end(), [&](const TracedValue& t) { return t.name == out.name; }))
            m.traced.push_back(std::move(out));
    m.prelude = text.substr(open + 1, loopLine - open - 1);
    m.caller = "mainImage";
    const std::vector<TIntermSymbol*> mainParameters = parametersOf(mainImage);
    if (mainParameters.size() == 2) {
        m.colour = mainParameters[0]->getName().c_str();
        m.coordinate = mainParameters[1]->getName().c_str();
    }
}

// What mainImage hands the function that calls the marching function (IQ's `tot += render(ro, rd,
// anim)` in his anti-aliasing loops, where render calls `trace(ro, rd, anim)`): the marching
// function's arguments that are that caller's unchanged parameters, traced one call further to
// mainImage's own call of the caller. `values` receives, for each of the marching function's
// parameters, the expression mainImage passes ("" where the argument is not such a parameter), and
// `prelude` mainImage's code before that call, entered as its loops' first pass (enteredBlocks),
// that copies each expression into a local the wrapper reads after the blocks close. False with
// `why` when mainImage does not call the caller itself or the code cannot be run so.
bool passedByMainImage(TIntermAggregate* marcherCall, const MarcherCall& found, const Reached& tree, const std::string& text,
                       const std::vector<TIntermSymbol*>& marcherParameters, std::vector<std::string>& values,
                       std::string& prelude, std::string& why) {
    TIntermAggregate* caller = nullptr;
    for (TIntermAggregate* function : tree.reached)
        if (function != tree.mainImage && plainName(function->getName()) == found.in) caller = function;
    TIntermAggregate* body = bodyOf(tree.mainImage);
    const ReachingStatement reaching =
        caller && body ? statementReaching(body, {caller->getName().c_str()}) : ReachingStatement{};
    if (!reaching.call || reaching.call->getLoc().string != tree.mainImage->getLoc().string) {
        why = "mainImage does not call " + found.in;
        return false;
    }
    const std::vector<TIntermSymbol*> callerParameters = parametersOf(caller);
    TIntermAggregate* callerBody = bodyOf(caller);
    if (!callerBody) {
        why = found.in + " has no body";
        return false;
    }
    Contents writes;
    writes.everyMove = true;
    callerBody->traverse(&writes);
    std::set<long long> written;
    for (TIntermBinary* assignment : writes.assignments) written.insert(assignedSymbol(assignment->getLeft()));
    std::string before;
    int callLineNumber = reaching.call->getLoc().line;
    const std::vector<std::string> passed = callArguments(text, callLineNumber, found.in, &before, &callLineNumber);
    const std::size_t open = bodyOpen(text, tree.mainImage), callLine = lineStart(text, callLineNumber);
    int opened = 0;
    const std::string entered = open == std::string::npos || callLine == std::string::npos || open >= callLine
                                    ? std::string()
                                    : enteredBlocks(text.substr(open + 1, callLine - open - 1), opened);
    if (passed.size() != callerParameters.size() || before.find_first_of(";{}") != std::string::npos || opened < 0 ||
        !wholeStatements(entered + std::string(std::size_t(opened), '}'))) {
        why = "mainImage's call of " + found.in + " could not be read";
        return false;
    }
    std::string declared, copied;
    values.assign(marcherParameters.size(), std::string());
    for (std::size_t k = 0; k < marcherParameters.size() && k < marcherCall->getSequence().size(); ++k) {
        TIntermSymbol* argument = marcherCall->getSequence()[k]->getAsSymbolNode();
        if (!argument || written.count(argument->getId())) continue;
        for (std::size_t j = 0; j < callerParameters.size(); ++j) {
            if (callerParameters[j]->getId() != argument->getId() || !isInParameter(callerParameters[j])) continue;
            const std::string type = glslTypeName(callerParameters[j]->getType()), local = "sdfwb_passed" + std::to_string(k);
            if (type.empty()) continue;
            declared += type + " " + local + ";\n";
            copied += local + " = " + passed[j] + ";\n";
            values[k] = local;
        }
    }
    prelude = declared + entered + "\n" + copied + std::string(std::size_t(opened), '}') + "\n";
    return true;
}

// Traces the values of a field's parameters after the point (see MarchedFunction) from the march's
// call in `marcher` back to mainImage's call of `marcher` (or to the nearest function's, see
// findMarcherCall). Fills `m`'s prelude, bindings and arguments, or its `unresolved`.
void traceArguments(MarchedFunction& m, TIntermAggregate* call, TIntermAggregate* callee, TIntermAggregate* marcher,
                    TIntermLoop* loop, const Reached& tree, const ComposedShader& composed) {
    TIntermAggregate* mainImage = tree.mainImage;
    auto fail = [&m](std::string reason) {
        m.unresolved = std::move(reason);
        m.prelude.clear(), m.traced.clear(), m.arguments.clear();
    };
    const std::vector<TIntermSymbol*> fieldParameters = parametersOf(callee);
    m.extraParameters = int(fieldParameters.size()) - 1;
    if (m.extraParameters <= 0) return;
    std::vector<TracedValue> outs;
    if (std::string why; !outArguments(call, fieldParameters, outs, why)) return fail(why);
    if (marcher == mainImage) return traceOwnLocals(m, call, fieldParameters, std::move(outs), loop, tree, composed, fail);
    // The march's arguments after the point read only the marching function's parameters and
    // file-scope names (not its locals: what computes those runs inside the march).
    const std::vector<TIntermSymbol*> marcherParameters = parametersOf(marcher);
    std::set<std::string> read;
    struct Symbols : glslang::TIntermTraverser {
        std::vector<TIntermSymbol*> found;
        void visitSymbol(TIntermSymbol* node) override { found.push_back(node); }
    };
    for (std::size_t i = 1; i < call->getSequence().size(); ++i) {
        if (i < fieldParameters.size() && !isInParameter(fieldParameters[i])) continue; // an out local
        Symbols symbols;
        call->getSequence()[i]->traverse(&symbols);
        for (TIntermSymbol* symbol : symbols.found) {
            const bool parameter = std::any_of(marcherParameters.begin(), marcherParameters.end(),
                                               [&](TIntermSymbol* p) { return p->getId() == symbol->getId(); });
            if (parameter)
                read.insert(symbol->getName().c_str());
            else if (symbol->getQualifier().storage == glslang::EvqTemporary)
                return fail("'" + std::string(symbol->getName().c_str()) + "' is computed inside " +
                            plainName(marcher->getName()));
        }
    }
    const int file = call->getLoc().string;
    const MarcherCall found = findMarcherCall(marcher, tree);
    if (!found.call) return fail(found.why);
    if (file < 0 || file >= int(composed.map.files.size()) || mainImage->getLoc().string != file ||
        marcher->getLoc().string != file || found.call->getLoc().string != file)
        return fail("the march and mainImage are in different files");
    const std::string text = stripComments(composed.map.files[std::size_t(file)].text);
    const std::vector<std::string> fieldArguments = callArguments(text, call->getLoc().line, m.name, nullptr);
    if (fieldArguments.size() != fieldParameters.size()) return fail("its call's arguments could not be read");
    for (std::size_t i = 1; i < fieldArguments.size(); ++i) m.arguments += ", " + fieldArguments[i];
    std::string before;
    int callLineNumber = found.call->getLoc().line;
    const std::string marcherName = plainName(marcher->getName());
    const std::vector<std::string> values = callArguments(text, callLineNumber, marcherName, &before, &callLineNumber);
    if (values.size() != marcherParameters.size() || (found.fromMainImage && before.find_first_of(";{}") != std::string::npos))
        return fail("mainImage calls " + marcherName + " inside a loop or a condition");
    std::vector<std::string> passed; // what mainImage hands found.in, where the march reads that (passedByMainImage)
    std::string passedPrelude, passedWhy;
    for (std::size_t k = 0; k < marcherParameters.size(); ++k) {
        const std::string name = marcherParameters[k]->getName().c_str();
        if (!read.count(name)) continue;
        const std::string type = glslTypeName(marcherParameters[k]->getType());
        if (type.empty()) return fail("parameter '" + name + "' has a type the wrapper cannot declare");
        std::string value = values[k];
        if (!found.fromMainImage &&
            (k >= found.call->getSequence().size() || !isConstantArgument(found.call->getSequence()[k]))) {
            if (passed.empty() && passedWhy.empty() &&
                !passedByMainImage(found.call, found, tree, text, marcherParameters, passed, passedPrelude, passedWhy))
                passed.clear();
            if (k >= passed.size() || passed[k].empty())
                return fail(marcherName + "'s '" + name + "' is " + values[k] + " where " + found.in +
                            " calls it, not a constant" + (passedWhy.empty() ? "" : " (" + passedWhy + ")"));
            value = passed[k];
        }
        m.traced.push_back({type, name, value});
    }
    m.caller = found.in;
    for (const TracedValue& out : outs)
        if (std::none_of(m.traced.begin(), m.traced.end(), [&](const TracedValue& t) { return t.name == out.name; }))
            m.traced.push_back(out);
    // The prelude: mainImage's body up to the line of that call.
    const std::size_t open = bodyOpen(text, mainImage);
    const std::size_t callLine = lineStart(text, callLineNumber);
    if (found.fromMainImage && (open == std::string::npos || callLine == std::string::npos || open >= callLine ||
                                !wholeStatements(text.substr(open + 1, callLine - open - 1))))
        return fail("mainImage's code before the march is not whole statements");
    if (found.fromMainImage) m.prelude = text.substr(open + 1, callLine - open - 1);
    if (!passedPrelude.empty()) m.prelude = passedPrelude, m.caller = "mainImage";
    const std::vector<TIntermSymbol*> mainParameters = parametersOf(mainImage);
    if (mainParameters.size() == 2) {
        m.colour = mainParameters[0]->getName().c_str();
        m.coordinate = mainParameters[1]->getName().c_str();
    }
}

} // namespace

std::vector<MarchedFunction> marchedFunctions(const ComposedShader& composed) {
    Reached tree;
    if (!parseReached(composed, tree)) return {};
    TIntermAggregate* mainImage = tree.mainImage;
    const std::vector<TIntermAggregate*>& reached = tree.reached;

    std::vector<MarchedFunction> marched;
    std::vector<MarchSite> sites; // each one's first loop
    for (std::size_t index = 0; index < reached.size(); ++index) {
        TIntermAggregate* function = reached[index];
        for (TIntermLoop* loop : contentsOf(function).loops) {
            Contents inside = contentsOf(loop);
            std::vector<Assignment> assignments;
            for (TIntermBinary* node : inside.assignments) {
                Contents right = contentsOf(node->getRight());
                assignments.push_back({assignedSymbol(node->getLeft()), node->getOp(), right.symbols,
                                       std::set<TIntermAggregate*>(right.calls.begin(), right.calls.end()), node});
            }
            std::set<std::string> counted;                                  // each function once per loop
            std::map<std::string, std::vector<TIntermAggregate*>> stepping; // its calls that step this loop
            const std::set<TIntermBinary*> conditional = conditionalAssignments(loop);
            for (TIntermAggregate* call : inside.calls) {
                auto callee = tree.functions.find(call->getName().c_str());
                if (callee == tree.functions.end() || call->getSequence().empty()) continue;
                TIntermTyped* point = call->getSequence().front()->getAsTyped();
                const glslang::TType& returned = callee->second->getType();
                const CallResult result = resultOf(call, inside.assignments);
                // A vec3 is a field where every call of it in the loop is read for its x alone (not a
                // path's offset, `p -= path(p)`, of which the loop also reads `path(p).x`).
                const bool vec3Field =
                    isFloatVec3(returned) && std::all_of(inside.calls.begin(), inside.calls.end(), [&](auto* other) {
                        return other->getName() != call->getName() ||
                               readsFirstComponentOnly(loop, resultOf(other, inside.assignments));
                    });
                if (!point || !isFloatVec3(point->getType()) ||
                    !(returnsFloats(returned) || returnsStruct(returned) || vec3Field))
                    continue;
                const std::string name = plainName(call->getName());
                const Assignment* step = stepBy(assignments, call, conditional);
                if (!step) continue;
                if (counted.count(name)) { // another call of it this loop steps by, at another point or with other values
                    std::vector<TIntermAggregate*>& seen = stepping[name];
                    if (std::none_of(seen.begin(), seen.end(), [&](TIntermAggregate* c) { return sameArguments(c, call); }))
                        for (MarchedFunction& m : marched)
                            if (m.name == name && m.loopLine == loop->getLoc().line) ++m.stepCalls;
                    seen.push_back(call);
                    continue;
                }
                stepping[name].push_back(call);
                std::string member;
                if (returnsStruct(returned)) {
                    member = distanceMember(loop, result);
                    if (member.empty()) continue;
                }
                const int component = returned.isVector() ? distanceComponent(*step, assignments, result) : 0;
                counted.insert(name);
                auto entry =
                    std::find_if(marched.begin(), marched.end(), [&](const MarchedFunction& m) { return m.name == name; });
                // An overload of the point alone (`map(p)` in a shadow's march beside `map(p, factor)`
                // in the main one): its march is the one the field is read by.
                int loopsBefore = 0;
                if (entry != marched.end() && entry->extraParameters > 0 && parametersOf(callee->second).size() == 1) {
                    loopsBefore = entry->loops;
                    sites.erase(sites.begin() + (entry - marched.begin()));
                    marched.erase(entry);
                    entry = marched.end();
                }
                if (entry == marched.end()) {
                    const glslang::TSourceLoc& loc = call->getLoc();
                    marched.push_back({name, composed.map.fileName(loc.string), loc.line, loopsBefore, loop->getLoc().line,
                                       member.empty() ? std::string() : std::string(returned.getTypeName().c_str()), member,
                                       glslTypeName(returned)});
                    entry = marched.end() - 1;
                    sites.push_back({loop, function});
                    entry->depth = tree.depth[index];
                    if (component > 0) entry->component = std::string(1, "xyzw"[component]);
                    if (mainImage) traceArguments(*entry, call, callee->second, function, loop, tree, composed);
                    if (mainImage && entry->extraParameters <= 0)
                        traceAllGlobals(*entry, callee->second, function, loop, mainImage, reached, composed, tree.functions);
                }
                ++entry->loops;
                if (entry->loopLine == loop->getLoc().line) ++entry->stepCalls;
                if (const detail::HitThreshold hit = detail::hitThreshold(loop, call, result.holders);
                    hit.value > 0.0f && entry->hitThreshold == 0.0f)
                    entry->hitThreshold = hit.value, entry->hitLine = hit.line;
            }
        }
    }
    for (std::size_t second = 0; second < marched.size(); ++second)
        for (std::size_t first = 0; first < marched.size() && marched[second].after.empty(); ++first)
            if (std::string how = first != second ? runsOnlyAfter(sites[second], sites[first], tree) : ""; !how.empty())
                marched[second].after = marched[first].name,
                marched[second].afterHow = how == "where" ? "where " + marched[first].name + "'s march lets it"
                                                          : "given what " + marched[first].name + "'s march found";
    return marched;
}

} // namespace sdfwb::shaders
