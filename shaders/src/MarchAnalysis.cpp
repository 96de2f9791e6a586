#include <shaders/MarchAnalysis.h>

#include <shaders/GlslChecker.h>

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

using glslang::TIntermAggregate;
using glslang::TIntermBinary;
using glslang::TIntermLoop;
using glslang::TIntermSymbol;
using glslang::TIntermTyped;

std::string plainName(const glslang::TString& mangled) {
    const std::string name(mangled.c_str());
    return name.substr(0, name.find('('));
}

// What a subtree holds: assignments, user function calls, loops, and the symbols it reads.
struct Contents : glslang::TIntermTraverser {
    std::vector<TIntermBinary*> assignments;
    std::vector<TIntermAggregate*> calls;
    std::vector<TIntermLoop*> loops;
    std::set<long long> symbols;

    bool visitBinary(glslang::TVisit, TIntermBinary* node) override {
        switch (node->getOp()) {
        case glslang::EOpAssign:
        case glslang::EOpAddAssign:
        case glslang::EOpSubAssign:
            assignments.push_back(node);
            break;
        default:
            break;
        }
        return true;
    }
    bool visitAggregate(glslang::TVisit, TIntermAggregate* node) override {
        if (node->getOp() == glslang::EOpFunctionCall && node->isUserDefined()) calls.push_back(node);
        return true;
    }
    bool visitLoop(glslang::TVisit, TIntermLoop* node) override {
        loops.push_back(node);
        return true;
    }
    void visitSymbol(TIntermSymbol* node) override { symbols.insert(node->getId()); }
};

Contents contentsOf(TIntermNode* node) {
    Contents contents;
    if (node) node->traverse(&contents);
    return contents;
}

// The variable an assignment writes (`p`, `p.xy`, `h[1]`, `hit.t`), or -1.
long long assignedSymbol(TIntermTyped* left) {
    while (TIntermBinary* access = left->getAsBinaryNode()) {
        switch (access->getOp()) {
        case glslang::EOpVectorSwizzle:
        case glslang::EOpIndexDirect:
        case glslang::EOpIndexIndirect:
        case glslang::EOpIndexDirectStruct:
            left = access->getLeft();
            continue;
        default:
            return -1;
        }
    }
    TIntermSymbol* symbol = left->getAsSymbolNode();
    return symbol ? symbol->getId() : -1;
}

bool isFloatVec3(const glslang::TType& type) {
    return type.getBasicType() == glslang::EbtFloat && type.isVector() && type.getVectorSize() == 3 && !type.isArray();
}

// A distance's return: float, vec2 or vec4 (a value and a material id or colour). Not vec3: what a
// march loop calls and returns a vec3 is a normal or a colour (a reflection loop's `ro += nor * eps`
// grows the point by calcNormal's result), and a field returning vec3 is rare enough to be named.
bool returnsFloats(const glslang::TType& type) {
    return type.getBasicType() == glslang::EbtFloat && !type.isArray() &&
           (type.isScalar() || (type.isVector() && type.getVectorSize() != 3));
}

bool returnsStruct(const glslang::TType& type) { return type.getBasicType() == glslang::EbtStruct && !type.isArray(); }

// The float member of the struct `call` returns that the loop reads first, from the call itself
// or from a variable assigned the call (`Hit h = map(p); ... t += h.d;`); empty when none.
std::string distanceMember(TIntermNode* loop, TIntermAggregate* call, const std::vector<TIntermBinary*>& assignments) {
    std::set<long long> holders;
    for (TIntermBinary* a : assignments)
        if (a->getOp() == glslang::EOpAssign && a->getRight() == call) holders.insert(assignedSymbol(a->getLeft()));
    struct Members : glslang::TIntermTraverser {
        TIntermAggregate* call = nullptr;
        const std::set<long long>* holders = nullptr;
        std::string found;
        bool visitBinary(glslang::TVisit, TIntermBinary* node) override {
            if (!found.empty() || node->getOp() != glslang::EOpIndexDirectStruct) return true;
            TIntermTyped* base = node->getLeft();
            TIntermSymbol* symbol = base->getAsSymbolNode();
            if (base != call && !(symbol && holders->count(symbol->getId()))) return true;
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
    members.call = call;
    members.holders = &holders;
    loop->traverse(&members);
    return members.found;
}

struct Assignment {
    long long target;
    glslang::TOperator op;
    std::set<long long> reads;         // symbols of the right-hand side
    std::set<TIntermAggregate*> calls; // calls in the right-hand side
};

// Whether `loop` steps by `call` (a call inside it): see the header.
bool stepsBy(const std::vector<Assignment>& assignments, TIntermAggregate* call) {
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
            const bool fromResult = a.calls.count(call) ||
                                    std::any_of(a.reads.begin(), a.reads.end(), [&](long long s) { return result.count(s) > 0; });
            if (fromResult && a.target >= 0) grew |= result.insert(a.target).second;
        }
    }
    for (const Assignment& a : assignments) {
        if (a.target < 0 || !point.count(a.target)) continue;
        const bool grows = a.op == glslang::EOpAddAssign || a.op == glslang::EOpSubAssign ||
                           (a.op == glslang::EOpAssign && a.reads.count(a.target));
        if (!grows) continue;
        if (a.calls.count(call) || std::any_of(a.reads.begin(), a.reads.end(), [&](long long s) { return result.count(s) > 0; }))
            return true;
    }
    return false;
}

} // namespace

std::vector<MarchedFunction> marchedFunctions(const ComposedShader& composed) {
    ensureGlslangInitialised();
    glslang::TShader shader(EShLangFragment);
    const char* text = composed.text.c_str();
    shader.setStrings(&text, 1);
    if (!shader.parse(GetDefaultResources(), 430, ECoreProfile, false, false, EShMsgDefault)) return {};
    const glslang::TIntermediate* intermediate = shader.getIntermediate();
    if (!intermediate || !intermediate->getTreeRoot()) return {};

    // Function definitions by mangled name.
    struct Definitions : glslang::TIntermTraverser {
        std::map<std::string, TIntermAggregate*> functions;
        bool visitAggregate(glslang::TVisit, TIntermAggregate* node) override {
            if (node->getOp() != glslang::EOpFunction) return true;
            functions[node->getName().c_str()] = node;
            return false;
        }
    } definitions;
    intermediate->getTreeRoot()->traverse(&definitions);

    // The functions mainImage reaches, mainImage first.
    std::vector<TIntermAggregate*> reached;
    std::set<std::string> seen;
    std::deque<std::string> queue;
    for (const auto& [mangled, node] : definitions.functions)
        if (plainName(node->getName()) == "mainImage") queue.push_back(mangled);
    while (!queue.empty()) {
        const std::string mangled = queue.front();
        queue.pop_front();
        auto it = definitions.functions.find(mangled);
        if (it == definitions.functions.end() || !seen.insert(mangled).second) continue;
        reached.push_back(it->second);
        for (TIntermAggregate* call : contentsOf(it->second).calls) queue.push_back(call->getName().c_str());
    }

    std::vector<MarchedFunction> marched;
    for (TIntermAggregate* function : reached) {
        for (TIntermLoop* loop : contentsOf(function).loops) {
            Contents inside = contentsOf(loop);
            std::vector<Assignment> assignments;
            for (TIntermBinary* node : inside.assignments) {
                Contents right = contentsOf(node->getRight());
                assignments.push_back({assignedSymbol(node->getLeft()), node->getOp(), right.symbols,
                                       std::set<TIntermAggregate*>(right.calls.begin(), right.calls.end())});
            }
            std::set<std::string> counted; // each function once per loop
            for (TIntermAggregate* call : inside.calls) {
                auto callee = definitions.functions.find(call->getName().c_str());
                if (callee == definitions.functions.end() || call->getSequence().empty()) continue;
                TIntermTyped* point = call->getSequence().front()->getAsTyped();
                const glslang::TType& returned = callee->second->getType();
                if (!point || !isFloatVec3(point->getType()) || !(returnsFloats(returned) || returnsStruct(returned))) continue;
                const std::string name = plainName(call->getName());
                if (counted.count(name) || !stepsBy(assignments, call)) continue;
                std::string member;
                if (returnsStruct(returned)) {
                    member = distanceMember(loop, call, inside.assignments);
                    if (member.empty()) continue;
                }
                counted.insert(name);
                auto entry =
                    std::find_if(marched.begin(), marched.end(), [&](const MarchedFunction& m) { return m.name == name; });
                if (entry == marched.end()) {
                    const glslang::TSourceLoc& loc = call->getLoc();
                    marched.push_back({name, composed.map.fileName(loc.string), loc.line, 0,
                                       member.empty() ? std::string() : std::string(returned.getTypeName().c_str()), member});
                    entry = marched.end() - 1;
                }
                ++entry->loops;
            }
        }
    }
    return marched;
}

} // namespace sdfwb::shaders
