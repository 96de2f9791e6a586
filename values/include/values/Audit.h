#pragma once
// What the field audit and the cutting plane's readout find, as plain values: the findings with
// their evidence, the plane's readout and the volume audit's report. sampling/FieldAudit.h computes
// them (on the GPU); the job reports, the CLI, Python and the plane panel carry and show them.

#include <core/NameTable.h>

#include <glm/vec3.hpp>

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace sdfwb::values {

// What the audit can find about a field. A report's verdict is its most severe flag, or else
// no-surface, exact or conservative; sign-uncertain is a finding beside the verdict. The names are
// what the reports (JSON), the CLI and Python show.
enum class Finding { Exact, Conservative, NonConservative, Truncated, Discontinuous, Nan, NoSurface, SignUncertain };
inline constexpr std::pair<Finding, const char*> kFindingNames[] = {
    {Finding::Exact, "exact"},
    {Finding::Conservative, "conservative"},
    {Finding::NonConservative, "non-conservative"},
    {Finding::Truncated, "truncated"},
    {Finding::Discontinuous, "discontinuous"},
    {Finding::Nan, "nan"},
    {Finding::NoSurface, "no-surface"},
    {Finding::SignUncertain, "sign-uncertain"},
};
inline const char* findingName(Finding finding) { return nameOf(kFindingNames, finding); }

// One finding of the audit, with its evidence. `finding` is one of
//   non-conservative  |grad f| > 1.05 somewhere: value = the Lipschitz estimate, share = of the probed
//                     points above 1.05, examples = where the quotient is largest;
//   truncated         the field stops growing away from the surface: value = the plateau's f,
//                     start = its distance from the surface, share = of the outward probe rays (or
//                     of the plane's outside points) that end on it, examples = where it starts;
//   discontinuous     f jumps: value = the median jump |delta f| (jumps below the float noise floor
//                     do not count), maximum = the largest, count = points found at a jump,
//                     examples = points on the jump;
//   nan               f or its gradient is NaN/Inf: share and count of points, examples = where.
struct AuditFlag {
    Finding finding = Finding::NonConservative;
    std::string evidence; // one sentence with the figures
    float value = 0.0f;
    float maximum = 0.0f;
    float start = 0.0f;
    double share = 0.0;
    std::uint64_t count = 0;
    std::vector<glm::vec3> examples; // at most kMaxExamples
};

inline constexpr std::size_t kMaxExamples = 16;

// The figures particular to a flag's kind, by the names reports use: truncated: value, start;
// discontinuous: jump, jump_max; non-conservative: lipschitz, lipschitz_max; nan: none.
std::vector<std::pair<const char*, float>> namedFigures(const AuditFlag& flag);

// The flag of that finding, or null.
const AuditFlag* findFlag(const std::vector<AuditFlag>& flags, Finding finding);

struct PlaneReadout {
    int resolution = 0;                      // grid side on the plane
    std::uint64_t points = 0;                // grid points inside the [-1,1]^3 box
    float minimum = 0.0f, maximum = 0.0f;    // f over those points (finite ones)
    float lipschitzMax = 0.0f;               // max |grad f| (central differences, step 1e-2)
    float lipschitz99 = 0.0f;                // 99th percentile
    double shareAboveOne = 0.0;              // fraction of points with |grad f| > 1.02
    std::optional<float> truncationDistance; // where the field stops growing, if it does
    std::uint64_t discontinuities = 0;       // neighbouring grid points whose difference the local slope cannot explain
    std::uint64_t nanCount = 0;              // NaN or Inf values or gradients
    std::vector<std::uint64_t>
        histogram;                // |grad f| in bins of 0.05 centred on k * 0.05 (bin 20 holds 1 +- 0.025); bin 40 holds >= 1.975
    float safeStepFactor = 1.0f;  // 1 / max(1, lipschitzMax)
    std::vector<AuditFlag> flags; // as the volume audit's, from the plane's grid
    double seconds = 0.0;
};

struct QuotientScale {
    float step = 0.0f; // the difference quotient's scale (2h for central differences)
    float p50 = 0, p99 = 0, p999 = 0, max = 0;
};

struct ConvergencePoint {
    std::uint64_t samples = 0;
    float lipschitz = 0.0f;
    float exactnessP99 = 0.0f;
    double seconds = 0.0;
};

struct AuditReport {
    Finding verdict = Finding::Conservative; // the most severe finding (never sign-uncertain)
    std::string reason;                      // one sentence: why this verdict
    std::vector<AuditFlag> flags;            // every finding, most severe first
    float lipschitz = 0.0f;                  // estimate: 99.9th percentile of |grad f| over all scales but the largest
    float lipschitzMax = 0.0f;               // the largest quotient seen (an outlier-prone upper estimate)
    float lipschitzUncertainty = 0.0f;       // spread between the two (the estimate is a lower bound of the true L)
    float safeStepFactor = 1.0f;
    std::optional<float> truncationDistance;
    double nanFraction = 0.0;
    double nanFractionError = 0.0; // binomial standard error
    std::uint64_t discontinuities = 0;
    double discontinuityShare = 0.0;
    float eikonalMean = 0.0f; // mean of | |grad f| - 1 | near the surface
    float eikonalP95 = 0.0f;
    std::uint64_t surfacePoints = 0; // dense surface set used for the true distance
    float surfaceSpacing = 0.0f;     // mean nearest-neighbour distance within that set: the true
                                     // distance is known to about this much
    float exactnessP99 = 0.0f;       // 99th percentile of | |f| - true distance |
    float exactnessMax = 0.0f;
    double overestimateShare = 0.0; // points where |f| exceeds the true distance beyond tolerance
    float surfaceGradient = 0.0f;   // median |grad f| at the surface points (1 for a distance;
                                    // near 0 when the gradient vanishes there, as for f = d^3)
    float noiseFloor = 0.0f;        // the precision floor: rounding noise in f itself (median over
                                    // short straight runs of what a quadratic cannot fit, times
                                    // sqrt 12: the size of a float32 rounding step of the values)
    std::vector<QuotientScale> scales;
    std::vector<ConvergencePoint> convergence;
    std::uint64_t samples = 0;
    double seconds = 0.0;
};

} // namespace sdfwb::values
