#pragma once
// The constant a whole shader's march compares its distance with to stop (`if (d < 0.001) break;`):
// the level set its pictures show. An unsigned field (never negative) has its surface there, and
// --level takes it. Private to shaders/; MarchAnalysis calls it for each marched function.

#include <set>

namespace glslang {
class TIntermAggregate;
class TIntermLoop;
} // namespace glslang

namespace sdfwb::shaders::detail {

struct HitThreshold {
    float value = 0.0f; // 0: none found
    int line = 0;       // the comparison's line
};

// In `loop` (its test included): the smallest positive float constant compared with the distance
// (`d < EPS`, `abs(h.x) < .001`, `SURF_DIST > dS`, `d > 1e-3` in the loop's test), where the distance
// is `call` itself, a variable in `holders` (assigned the call) or one assigned a component, member or
// abs() of them (`float d = h.x;`). A threshold that is not one constant (`d < 0.001 * t`) is none.
HitThreshold hitThreshold(glslang::TIntermLoop* loop, glslang::TIntermAggregate* call, std::set<long long> holders);

} // namespace sdfwb::shaders::detail
