#include "MarchOrder.h"

#include <algorithm>
#include <set>
#include <string>
#include <vector>

namespace sdfwb::shaders::detail {
namespace {

using glslang::TIntermSelection;

bool before(const glslang::TSourceLoc& a, const glslang::TSourceLoc& b) {
    return a.line < b.line || (a.line == b.line && a.column < b.column);
}

// Every assignment in a subtree (`*=`, `/=` too) and every branch.
struct Moves : glslang::TIntermTraverser {
    std::vector<TIntermBinary*> assignments;
    std::vector<TIntermSelection*> selections;
    bool visitBinary(glslang::TVisit, TIntermBinary* node) override {
        if (node->getOp() >= glslang::EOpAssign && node->getOp() <= glslang::EOpRightShiftAssign) assignments.push_back(node);
        return true;
    }
    bool visitSelection(glslang::TVisit, TIntermSelection* node) override {
        selections.push_back(node);
        return true;
    }
};

Moves movesOf(TIntermNode* node) {
    Moves moves;
    if (node) node->traverse(&moves);
    return moves;
}

bool holds(TIntermNode* node, TIntermNode* target) {
    if (!node) return false;
    if (node == target) return true;
    const Contents inside = contentsOf(node);
    return std::find(inside.calls.begin(), inside.calls.end(), target) != inside.calls.end() ||
           std::find(inside.loops.begin(), inside.loops.end(), target) != inside.loops.end();
}

bool readsAny(TIntermNode* node, const std::set<long long>& symbols) {
    if (!node) return false;
    const std::set<long long> read = contentsOf(node).symbols;
    return std::any_of(read.begin(), read.end(), [&](long long id) { return symbols.count(id) > 0; });
}

// The node of `context`'s body through which `site`'s loop runs: the loop itself, or the first call
// that reaches its holder.
TIntermNode* anchorIn(TIntermAggregate* context, const MarchSite& site, const Reached& tree) {
    if (context == site.holder) return site.loop;
    const std::set<std::string> reaching = functionsReaching(site.holder->getName(), tree.functions);
    for (TIntermAggregate* call : contentsOf(bodyOf(context)).calls)
        if (reaching.count(call->getName().c_str())) return call;
    return nullptr;
}

// What `anchor` computes in `body`: a loop's assignments, else the variables a call's value is
// assigned to and the ones it writes through out and inout parameters.
std::set<long long> computedBy(TIntermNode* anchor, TIntermAggregate* body, const Reached& tree) {
    std::set<long long> computed;
    if (anchor->getAsLoopNode()) {
        for (TIntermBinary* assignment : movesOf(anchor).assignments) computed.insert(assignedSymbol(assignment->getLeft()));
        return computed;
    }
    TIntermAggregate* call = anchor->getAsAggregate();
    for (TIntermBinary* assignment : movesOf(body).assignments)
        if (holds(assignment->getRight(), call)) computed.insert(assignedSymbol(assignment->getLeft()));
    if (auto callee = tree.functions.find(call->getName().c_str()); callee != tree.functions.end()) {
        const std::vector<TIntermSymbol*> parameters = parametersOf(callee->second);
        for (std::size_t i = 0; i < parameters.size() && i < call->getSequence().size(); ++i) {
            const glslang::TStorageQualifier storage = parameters[i]->getType().getQualifier().storage;
            if (storage == glslang::EvqOut || storage == glslang::EvqInOut)
                if (TIntermTyped* argument = call->getSequence()[i]->getAsTyped()) computed.insert(assignedSymbol(argument));
        }
    }
    computed.erase(-1);
    return computed;
}

} // namespace

std::string runsOnlyAfter(const MarchSite& second, const MarchSite& first, const Reached& tree) {
    if (!second.loop || !first.loop || !second.holder || !first.holder) return "";
    const std::set<std::string> reachFirst = functionsReaching(first.holder->getName(), tree.functions),
                                reachSecond = functionsReaching(second.holder->getName(), tree.functions);
    TIntermAggregate* context = nullptr;
    for (std::size_t i = 0, deepest = 0; i < tree.reached.size(); ++i) {
        const std::string name = tree.reached[i]->getName().c_str();
        if (reachFirst.count(name) && reachSecond.count(name) && (!context || std::size_t(tree.depth[i]) > deepest))
            context = tree.reached[i], deepest = std::size_t(tree.depth[i]);
    }
    TIntermAggregate* body = context ? bodyOf(context) : nullptr;
    TIntermNode* from = body ? anchorIn(context, first, tree) : nullptr;
    TIntermNode* to = body ? anchorIn(context, second, tree) : nullptr;
    if (!from || !to || from == to || !before(from->getLoc(), to->getLoc())) return "";
    // What the first march computed, then what follows from it, by value or by a branch it decides.
    std::set<long long> derived = computedBy(from, body, tree);
    const Moves moves = movesOf(body);
    auto decided = [&](TIntermSelection* branch) {
        return !before(branch->getLoc(), from->getLoc()) && readsAny(branch->getCondition(), derived);
    };
    for (bool grew = true; grew;) {
        grew = false;
        for (TIntermBinary* assignment : moves.assignments)
            if (!before(assignment->getLoc(), from->getLoc()) && readsAny(assignment->getRight(), derived))
                grew |= derived.insert(assignedSymbol(assignment->getLeft())).second;
        for (TIntermSelection* branch : moves.selections)
            if (decided(branch))
                for (TIntermBinary* assignment : movesOf(branch).assignments)
                    grew |= derived.insert(assignedSymbol(assignment->getLeft())).second;
    }
    if (std::any_of(moves.selections.begin(), moves.selections.end(), [&](TIntermSelection* branch) {
            return decided(branch) && (holds(branch->getTrueBlock(), to) || holds(branch->getFalseBlock(), to));
        }))
        return "where";
    // Handed to the call: by values assigned between the two (a value the first march's result
    // changes only after the call, `ro += rd * dstCave` below it, is not handed).
    std::set<long long> given = computedBy(from, body, tree);
    for (bool grew = true; grew;) {
        grew = false;
        for (TIntermBinary* assignment : moves.assignments)
            if (!before(assignment->getLoc(), from->getLoc()) && before(assignment->getLoc(), to->getLoc()) &&
                readsAny(assignment->getRight(), given))
                grew |= given.insert(assignedSymbol(assignment->getLeft())).second;
    }
    if (TIntermAggregate* call = to->getAsAggregate())
        for (TIntermNode* argument : call->getSequence())
            if (readsAny(argument, given)) return "given";
    return "";
}

} // namespace sdfwb::shaders::detail
