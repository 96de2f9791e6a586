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

} // namespace sdfwb::shaders::detail
