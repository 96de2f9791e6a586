#pragma once
// Field analysis: is an SDF exact, conservative, non-conservative, truncated, discontinuous, or
// does it yield NaN/Inf? Two entry points:
//   analysePlane: readouts for the cutting plane (value range, |grad f| statistics, truncation,
//                 discontinuities, NaN/Inf, a histogram, the safe step factor 1/L);
//   auditField:   the volume audit behind `sdfwb --batch audit` (difference quotients at several
//                 scales on random and near-surface points, eikonal error, exactness against the
//                 true distance to a dense set of surface points through a k-d tree, a verdict).
// Both run on the GPU compute path: the GL context must be current on the calling thread.

#include <core/Expected.h>
#include <core/Progress.h>
#include <meshfield/MeshField.h>
#include <shaders/SdfSource.h>
#include <values/Audit.h>

#include <glm/vec3.hpp>

#include <cstdint>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace sdfwb::sampling {

// A mesh SDF's points whose generalized winding number lies within kSignUncertainBand of 1/2
// (neither clearly inside, near 1, nor clearly outside, near 0): flag "sign-uncertain" with its
// count, share, median winding number (value) and examples, over the first `limit` of `points`.
inline constexpr double kSignUncertainBand = 0.25;
struct SampleSet;
values::AuditFlag signUncertainty(const meshfield::MeshField& mesh, const SampleSet& points, std::size_t limit = 50000);

// Grid of resolution^2 points over the plane dot(normal, p) = offset within the box, with the
// SDF's parameters at `parameters` (the others at their defaults). When the SDF's shader does not
// compile, `diagnostics` (when given) receives the compiler's messages.
Expected<values::PlaneReadout> analysePlane(const shaders::PreparedSdf& sdf, glm::vec3 normal, float offset, int resolution,
                                            float time, const std::vector<shaders::ParameterSetting>& parameters = {},
                                            std::vector<shaders::Diagnostic>* diagnostics = nullptr);

struct AuditOptions {
    std::uint64_t samples = 100000; // random points; as many near-surface points and surface points
    std::uint64_t seed = 0;
    float time = 0.0f;
    bool convergence = true;                                 // also run N/16 and N/4 to show how the estimates tighten
    std::vector<shaders::Diagnostic>* diagnostics = nullptr; // receives the compiler's messages when the SDF does not compile
    float truncationReach = 3.0f;                            // truncation: probe outward from the surface this far (plateaus
                                                             // beyond the unit cube are found too)
    std::vector<shaders::ParameterSetting> parameters;       // the SDF's parameter values (others: defaults)
};

Expected<values::AuditReport> auditField(const shaders::PreparedSdf& sdf, const AuditOptions& options,
                                         const ProgressSink& progress);

} // namespace sdfwb::sampling
