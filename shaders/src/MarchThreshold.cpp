#include "MarchThreshold.h"

#include <glslang/Include/intermediate.h>

#include <cstddef>
#include <vector>

namespace sdfwb::shaders::detail {
namespace {

using glslang::TIntermBinary;
using glslang::TIntermTyped;

// The node a distance is read through, with the reads around it taken off: a component or member
// (`h.x`, `h[1]`, `hit.d`) and abs().
TIntermTyped* underReads(TIntermTyped* node) {
    for (;;) {
        if (TIntermBinary* binary = node->getAsBinaryNode()) {
            const glslang::TOperator op = binary->getOp();
            if (op != glslang::EOpVectorSwizzle && op != glslang::EOpIndexDirect && op != glslang::EOpIndexDirectStruct)
                return node;
            node = binary->getLeft();
        } else if (glslang::TIntermUnary* unary = node->getAsUnaryNode(); unary && unary->getOp() == glslang::EOpAbs) {
            node = unary->getOperand();
        } else {
            return node;
        }
    }
}

// A positive float constant (a literal, or a const variable or macro glslang folded), else 0.
float positiveConstant(TIntermTyped* node) {
    glslang::TIntermConstantUnion* constant = node->getAsConstantUnion();
    if (!constant || !constant->getType().isScalar()) return 0.0f;
    const glslang::TConstUnion& value = constant->getConstArray()[0];
    double number = 0.0;
    switch (value.getType()) {
    case glslang::EbtFloat:
    case glslang::EbtDouble:
        number = value.getDConst();
        break;
    default:
        return 0.0f;
    }
    return number > 0.0 ? float(number) : 0.0f;
}

struct Finder : glslang::TIntermTraverser {
    glslang::TIntermAggregate* call = nullptr;
    std::set<long long> holders;
    std::vector<TIntermBinary*> assignments;
    std::vector<TIntermBinary*> comparisons;
    bool visitBinary(glslang::TVisit, TIntermBinary* node) override {
        switch (node->getOp()) {
        case glslang::EOpAssign:
            assignments.push_back(node);
            break;
        case glslang::EOpLessThan:
        case glslang::EOpLessThanEqual:
        case glslang::EOpGreaterThan:
        case glslang::EOpGreaterThanEqual:
            comparisons.push_back(node);
            break;
        default:
            break;
        }
        return true;
    }
    bool isDistance(TIntermTyped* node) const {
        TIntermTyped* under = underReads(node);
        glslang::TIntermSymbol* symbol = under->getAsSymbolNode();
        return under == call || (symbol && holders.count(symbol->getId()));
    }
};

} // namespace

HitThreshold hitThreshold(glslang::TIntermLoop* loop, glslang::TIntermAggregate* call, std::set<long long> holders) {
    Finder finder;
    finder.call = call;
    finder.holders = std::move(holders);
    if (loop->getBody()) loop->getBody()->traverse(&finder);
    const std::size_t inBody = finder.comparisons.size();
    if (loop->getTest()) loop->getTest()->traverse(&finder);
    if (loop->getTerminal()) loop->getTerminal()->traverse(&finder);
    // `float d = h.x;` reads the distance too (two rounds: a chain of two such assignments).
    for (int round = 0; round < 2; ++round)
        for (TIntermBinary* a : finder.assignments)
            if (glslang::TIntermSymbol* left = a->getLeft()->getAsSymbolNode(); left && finder.isDistance(a->getRight()))
                finder.holders.insert(left->getId());
    HitThreshold found;
    for (std::size_t i = 0; i < finder.comparisons.size(); ++i) {
        TIntermBinary* comparison = finder.comparisons[i];
        // The body stops when the distance is below it (`d < EPS`), the loop's test goes on while it
        // is above (`h > 1e-3`); the other way round is an escape (`d > 20.`), not a hit.
        const glslang::TOperator op = comparison->getOp();
        const bool below = op == glslang::EOpLessThan || op == glslang::EOpLessThanEqual;
        const bool hitWhenBelow = i < inBody;
        float value = 0.0f;
        if (finder.isDistance(comparison->getLeft()) && below == hitWhenBelow)
            value = positiveConstant(comparison->getRight());
        else if (finder.isDistance(comparison->getRight()) && below != hitWhenBelow)
            value = positiveConstant(comparison->getLeft());
        if (value > 0.0f && (found.value == 0.0f || value < found.value)) found = {value, comparison->getLoc().line};
    }
    return found;
}

} // namespace sdfwb::shaders::detail
