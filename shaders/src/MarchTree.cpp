#include "MarchTree.h"

#include "CallText.h"

#include <shaders/GlslChecker.h>

#include <glslang/MachineIndependent/localintermediate.h>
#include <glslang/Public/ResourceLimits.h>

#include <deque>

namespace sdfwb::shaders::detail {

std::string plainName(const glslang::TString& mangled) {
    const std::string name(mangled.c_str());
    return name.substr(0, name.find('('));
}

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

// A type as GLSL writes it (float, ivec3, mat3, a struct's name); empty for arrays and others.
std::string zeroValue(const glslang::TType& type) {
    if (type.isArray()) {
        const glslang::TArraySizes* sizes = type.getArraySizes();
        if (!sizes || sizes->getNumDims() != 1 || sizes->getOuterSize() <= 0) return {};
        const glslang::TType element(type, 0);
        const std::string name = glslTypeName(element), zero = zeroValue(element);
        if (name.empty() || zero.empty()) return {};
        std::string value = name + "[" + std::to_string(sizes->getOuterSize()) + "](";
        for (int i = 0; i < sizes->getOuterSize(); ++i) value += (i ? ", " : "") + zero;
        return value + ")";
    }
    const std::string name = glslTypeName(type);
    if (name.empty()) return {};
    if (type.getBasicType() != glslang::EbtStruct) return name + "(0)";
    std::string value = name + "(";
    const glslang::TTypeList* members = type.getStruct();
    for (std::size_t i = 0; members && i < members->size(); ++i) {
        const std::string zero = zeroValue(*(*members)[i].type);
        if (zero.empty()) return {};
        value += (i ? ", " : "") + zero;
    }
    return value + ")";
}

std::string glslTypeName(const glslang::TType& type) {
    if (type.isArray()) return {};
    if (type.getBasicType() == glslang::EbtStruct) return type.getTypeName().c_str();
    const char* scalar = nullptr;
    const char* prefix = nullptr;
    switch (type.getBasicType()) {
    case glslang::EbtFloat:
        scalar = "float", prefix = "";
        break;
    case glslang::EbtInt:
        scalar = "int", prefix = "i";
        break;
    case glslang::EbtUint:
        scalar = "uint", prefix = "u";
        break;
    case glslang::EbtBool:
        scalar = "bool", prefix = "b";
        break;
    default:
        return {};
    }
    if (type.isScalar()) return scalar;
    if (type.isVector()) return std::string(prefix) + "vec" + std::to_string(type.getVectorSize());
    if (type.isMatrix() && type.getBasicType() == glslang::EbtFloat) {
        const int columns = type.getMatrixCols(), rows = type.getMatrixRows();
        return "mat" + std::to_string(columns) + (columns == rows ? "" : "x" + std::to_string(rows));
    }
    return {};
}

std::vector<TIntermSymbol*> parametersOf(TIntermAggregate* function) {
    std::vector<TIntermSymbol*> parameters;
    if (function->getSequence().empty()) return parameters;
    if (TIntermAggregate* list = function->getSequence().front()->getAsAggregate())
        for (TIntermNode* node : list->getSequence())
            if (TIntermSymbol* symbol = node->getAsSymbolNode()) parameters.push_back(symbol);
    return parameters;
}

// The offset of the '{' that opens `function`'s body in `text`, or npos. (A definition's location
// is its name's or its body's line: the last mention of the name up to it.)
std::size_t bodyOpen(const std::string& text, TIntermAggregate* function) {
    const std::string name = plainName(function->getName());
    const std::size_t definition = lineStart(text, function->getLoc().line + 1);
    const std::size_t named = text.rfind(name, definition == std::string::npos ? text.size() : definition);
    if (named == std::string::npos) return std::string::npos;
    int depth = 0;
    for (std::size_t i = text.find('(', named); i != std::string::npos && i < text.size(); ++i) {
        if (text[i] == '(') ++depth;
        if (text[i] == ')' && --depth == 0) return text.find('{', i);
    }
    return std::string::npos;
}

bool parseReached(const ComposedShader& composed, Reached& tree) {
    ensureGlslangInitialised();
    const char* text = composed.text.c_str();
    const int length = int(composed.text.size()); // a NUL in a comment does not end it
    tree.shader.setStringsWithLengths(&text, &length, 1);
    if (!tree.shader.parse(GetDefaultResources(), 430, ECoreProfile, false, false, EShMsgDefault)) return false;
    const glslang::TIntermediate* intermediate = tree.shader.getIntermediate();
    if (!intermediate || !intermediate->getTreeRoot()) return false;
    struct Definitions : glslang::TIntermTraverser {
        std::map<std::string, TIntermAggregate*>* functions = nullptr;
        bool visitAggregate(glslang::TVisit, TIntermAggregate* node) override {
            if (node->getOp() != glslang::EOpFunction) return true;
            (*functions)[node->getName().c_str()] = node;
            return false;
        }
    } definitions;
    definitions.functions = &tree.functions;
    intermediate->getTreeRoot()->traverse(&definitions);
    std::set<std::string> seen;
    std::deque<std::pair<std::string, int>> queue;
    for (const auto& [mangled, node] : tree.functions)
        if (plainName(node->getName()) == "mainImage") {
            queue.push_back({mangled, 0});
            tree.mainImage = node;
        }
    while (!queue.empty()) {
        const auto [mangled, depth] = queue.front();
        queue.pop_front();
        auto it = tree.functions.find(mangled);
        if (it == tree.functions.end() || !seen.insert(mangled).second) continue;
        tree.reached.push_back(it->second);
        tree.depth.push_back(depth);
        for (TIntermAggregate* call : contentsOf(it->second).calls) queue.push_back({call->getName().c_str(), depth + 1});
    }
    return true;
}

TIntermAggregate* bodyOf(TIntermAggregate* function) {
    return function->getSequence().size() > 1 ? function->getSequence()[1]->getAsAggregate() : nullptr;
}

// The callers found once, walked back from `target`.
std::set<std::string> functionsReaching(const glslang::TString& target,
                                        const std::map<std::string, TIntermAggregate*>& functions) {
    std::map<std::string, std::vector<std::string>> callers;
    for (const auto& [name, definition] : functions)
        for (TIntermAggregate* c : contentsOf(definition).calls) callers[c->getName().c_str()].push_back(name);
    std::set<std::string> reaching{target.c_str()};
    for (std::vector<std::string> next{target.c_str()}; !next.empty();) {
        const std::string callee = next.back();
        next.pop_back();
        for (const std::string& caller : callers[callee])
            if (reaching.insert(caller).second) next.push_back(caller);
    }
    return reaching;
}

ReachingStatement statementReaching(TIntermAggregate* body, const std::set<std::string>& reaching) {
    for (TIntermNode* statement : body->getSequence())
        for (TIntermAggregate* c : contentsOf(statement).calls)
            if (reaching.count(c->getName().c_str())) return {statement, c};
    return {};
}

bool isControlFlow(TIntermNode* statement) {
    return statement->getAsLoopNode() || statement->getAsSelectionNode() || statement->getAsBranchNode();
}

MarcherCall findMarcherCall(TIntermAggregate* marcher, const Reached& tree) {
    TIntermAggregate* mainImage = tree.mainImage;
    TIntermAggregate* body = bodyOf(mainImage);
    if (!body) return {nullptr, false, "mainImage has no body", {}};
    const std::string name = plainName(marcher->getName());
    if (const ReachingStatement found = statementReaching(body, {marcher->getName().c_str()}); found.call) {
        if (isControlFlow(found.statement))
            return {nullptr, false, "mainImage calls " + name + " inside a loop or a condition", {}};
        return {found.call, true, {}, "mainImage"};
    }
    for (TIntermAggregate* function : tree.reached)
        for (TIntermAggregate* c : contentsOf(function).calls)
            if (function != mainImage && c->getName() == marcher->getName())
                return {c, false, {}, plainName(function->getName())};
    return {nullptr, false, "mainImage does not call " + name, {}};
}

bool isInParameter(const TIntermSymbol* symbol) {
    const glslang::TStorageQualifier storage = symbol->getQualifier().storage;
    return storage == glslang::EvqIn || storage == glslang::EvqConstReadOnly;
}

bool isConstantArgument(TIntermNode* argument) {
    struct Variables : glslang::TIntermTraverser {
        bool found = false;
        void visitSymbol(TIntermSymbol* node) override {
            const glslang::TStorageQualifier storage = node->getQualifier().storage;
            found = found || (storage != glslang::EvqConst && storage != glslang::EvqUniform);
        }
    } variables;
    argument->traverse(&variables);
    return !variables.found;
}

} // namespace sdfwb::shaders::detail
