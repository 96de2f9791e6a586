#pragma once
// The field audit's statistics as pure functions (no GL): what the audit concludes from the values
// the GPU computed. Unit-tested on synthetic profiles (tests/sampling/test_audit_statistics.cpp).

#include <utility>
#include <vector>

namespace sdfwb::sampling {

// The q-quantile (0..1) of `values` by nearest rank; 0 for none.
float percentile(std::vector<float> values, double q);

// Rounding noise of one straight run of `count` equally spaced values (count >= 4): sqrt(12) x the
// RMS residual of a least-squares quadratic, i.e. the step of a uniform rounding that would leave
// that residual. A smooth field's run is a quadratic far below float noise, so what remains is the
// rounding. NaN when a value is not finite.
float quadraticResidualStep(const float* values, int count);

// The largest rise between consecutive values beyond the typical one (the median rise: the field's
// own slope), and where: between values k and k + 1. {-1, 0} when a value is not finite.
std::pair<float, int> largestStep(const float* values, int count);

// Where a profile of f along a ray outward from the surface ends on a plateau: from some probe on, f
// changes by less than 0.02 per unit of distance (plus `noise`) from probe to probe and to the end,
// at a positive value, over at least the last 3 probes and 10 % of the reach. Returns the first
// probe of the plateau, or -1 when the field keeps growing (or falls: the ray met more of the shape).
int plateauStart(const float* values, const float* distances, int count, float noise);

} // namespace sdfwb::sampling
