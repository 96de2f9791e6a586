#pragma once
// The glslang tree of a whole shader as the march analysis reads it (MarchAnalysis.cpp,
// InlineMarches.cpp): the functions mainImage reaches, what a subtree holds, and small readers of
// types, parameters and bodies. Private to shaders/.

#include <shaders/ShaderComposer.h>

#include <glslang/Include/intermediate.h>
#include <glslang/Public/ShaderLang.h>

#include <map>
#include <set>
#include <string>
#include <vector>

namespace sdfwb::shaders::detail {

using glslang::TIntermAggregate;
using glslang::TIntermBinary;
using glslang::TIntermLoop;
using glslang::TIntermSymbol;
using glslang::TIntermTyped;

// A function's name without glslang's mangled parameter types.
std::string plainName(const glslang::TString& mangled);

// What a subtree holds: assignments, user function calls, loops, and the symbols it reads.
struct Contents : glslang::TIntermTraverser {
    std::vector<TIntermBinary*> assignments;
    std::vector<TIntermAggregate*> calls;
    std::vector<TIntermLoop*> loops;
    std::set<long long> symbols;
    bool everyMove = false; // every assignment (`*=`, `/=`, ...), not only =, += and -=

    bool visitBinary(glslang::TVisit, TIntermBinary* node) override {
        if (everyMove && node->getOp() >= glslang::EOpAssign && node->getOp() <= glslang::EOpRightShiftAssign) {
            assignments.push_back(node);
            return true;
        }
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

Contents contentsOf(TIntermNode* node);

// The variable an assignment writes (`p`, `p.xy`, `h[1]`, `hit.t`), or -1.
long long assignedSymbol(TIntermTyped* left);

bool isFloatVec3(const glslang::TType& type);

struct Assignment {
    long long target;
    glslang::TOperator op;
    std::set<long long> reads;         // symbols of the right-hand side
    std::set<TIntermAggregate*> calls; // calls in the right-hand side
    TIntermBinary* node = nullptr;
};

// A type as GLSL writes it (float, ivec3, mat3, a struct's name); empty for arrays and others.
std::string glslTypeName(const glslang::TType& type);

// A value of `type` whose every component is zero, as GLSL writes it (`vec3(0)`, a struct's
// constructor of its members' zeros, `float[3](float(0), ...)`); empty where none can be written.
std::string zeroValue(const glslang::TType& type);

// The parameters of a function definition, in order.
std::vector<TIntermSymbol*> parametersOf(TIntermAggregate* function);

// The offset of the '{' that opens `function`'s body in `text`, or npos. (A definition's location
// is its name's or its body's line: the last mention of the name up to it.)
std::size_t bodyOpen(const std::string& text, TIntermAggregate* function);

// A shader's tree and the functions mainImage reaches, mainImage first.
struct Reached {
    glslang::TShader shader{EShLangFragment};
    std::map<std::string, TIntermAggregate*> functions; // definitions by mangled name
    TIntermAggregate* mainImage = nullptr;
    std::vector<TIntermAggregate*> reached;
    std::vector<int> depth; // of each reached function: calls from mainImage (breadth first)
};

// Parses `composed` (a fragment stage holding the user's code and mainImage) and fills `tree`;
// false when it does not parse.
bool parseReached(const ComposedShader& composed, Reached& tree);

// The body of a function definition (null for a prototype).
TIntermAggregate* bodyOf(TIntermAggregate* function);

// The mangled names of `target` and of every function that calls it, directly or through others.
std::set<std::string> functionsReaching(const glslang::TString& target,
                                        const std::map<std::string, TIntermAggregate*>& functions);

// The first statement of `body` that calls a function in `reaching` (mangled names), with that call.
struct ReachingStatement {
    TIntermNode* statement = nullptr;
    TIntermAggregate* call = nullptr;
};
ReachingStatement statementReaching(TIntermAggregate* body, const std::set<std::string>& reaching);

// Whether a statement runs its calls conditionally or repeatedly.
bool isControlFlow(TIntermNode* statement);

// The call that gives the marching function its arguments: mainImage's own, at the top of its body
// (the statements before it are the prelude), else the first call in the function nearest mainImage
// that calls it (`col = render(ro, rd)`, whose `castRay(ro, rd, mat, 1.0, true)` casts the primary
// ray), whose values the wrapper can use where they are constants. Null with why when neither is.
struct MarcherCall {
    TIntermAggregate* call = nullptr;
    bool fromMainImage = false;
    std::string why;
    std::string in; // the function that makes the call
};
MarcherCall findMarcherCall(TIntermAggregate* marcher, const Reached& tree);

// Whether a parameter is an `in` one (`in`, `const in` or none).
bool isInParameter(const TIntermSymbol* symbol);

// Whether an argument reads no variable: literals, constants and uniforms only.
bool isConstantArgument(TIntermNode* argument);

} // namespace sdfwb::shaders::detail
