#pragma once
// Which of two marches a shader runs only after the other has answered: a refraction's march
// inside `if (t.x > 0.)` of the primary ray's hit, a second pass in the `else` of a test on the
// first pass's colour. MarchAnalysis names it (MarchedFunction::after) so that the choice of the
// field prefers the primary ray's march. Private to shaders/.

#include "MarchTree.h"

namespace sdfwb::shaders::detail {

// A march loop and the function that holds it.
struct MarchSite {
    TIntermLoop* loop = nullptr;
    TIntermAggregate* holder = nullptr;
};

// Whether `second` runs only after `first` has answered, and how, for the reason: in the deepest
// function that reaches both, the statement that reaches `second` lies in a branch (an if, an else,
// a ?:) whose condition reads a value that the statement reaching `first` computed, directly,
// through assignments after it, or through assignments made in branches that such a value decides
// ("where"); or the call that reaches `second` is handed such a value (a smoke's march given the
// scene's distance: "given"). Empty when neither.
std::string runsOnlyAfter(const MarchSite& second, const MarchSite& first, const Reached& tree);

} // namespace sdfwb::shaders::detail
