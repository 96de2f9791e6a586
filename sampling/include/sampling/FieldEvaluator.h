#pragma once
// The field of an SDF at the caller's points: analysis/points.glsl compiled once through
// renderer::SampleCompute (the same composed SDF, gradient stencil and step as the samplers, so a
// value is bit-equal to what a sampler writes at that position). The one evaluator behind
// sdfwb.evaluate, the audit's point passes, meshing's probes and the viewport's plane hover. A
// current GL context is needed for every call, destruction included.

#include <core/Expected.h>
#include <core/Progress.h>
#include <renderer/SampleCompute.h>
#include <sampling/Sampler.h>
#include <shaders/Diagnostic.h>
#include <shaders/Parameters.h>

#include <cstdint>
#include <vector>

namespace sdfwb::shaders {
struct PreparedSdf;
}

namespace sdfwb::sampling {

struct FieldSettings {
    float time = 0.0f;
    float gradientStep = 1e-3f;                        // central-difference step of the gradient
    bool meshGradientTaps = false;                     // a mesh's own field: taps, not its exact gradient
    std::uint32_t chunk = 0;                           // points a dispatch (0: the driver's; the values do not change)
    std::vector<shaders::ParameterSetting> parameters; // the SDF's parameter values (others: defaults)
};

class FieldEvaluator {
public:
    FieldEvaluator() = default;
    FieldEvaluator(const FieldEvaluator&) = delete;
    FieldEvaluator& operator=(const FieldEvaluator&) = delete;
    ~FieldEvaluator() { releaseGl(); }

    // Compiles `sdf` with the points stage: the driver's and glslang's diagnostics (errors when it
    // does not compile; evaluate() then fails).
    std::vector<shaders::Diagnostic> build(const shaders::PreparedSdf& sdf);
    bool built() const { return m_built; }

    // The field at `count` points (xyz triples, read in place) into `distances` (count floats) and,
    // when not null, `gradients` (3 count floats, raw central differences); without gradients one
    // evaluation a point instead of seven. The report counts rows with NaN or Inf.
    Expected<SamplingReport> evaluate(const float* points, std::uint64_t count, float* distances, float* gradients,
                                      const FieldSettings& settings, const ProgressSink& progress = {});

    // The native CPU engine's hierarchy work since build() (renderer::SampleCompute::addMeshCounters),
    // and which engine ran ("cpu", "gpu", or "" for GLSL).
    void addMeshCounters(meshfield::QueryCounters& into) const { m_compute.addMeshCounters(into); }
    const char* meshEngine() const { return m_compute.meshEngine(); }
    bool countsMeshWalks() const { return m_compute.countsMeshWalks(); }

    void releaseGl();

private:
    renderer::SampleCompute m_compute;
    bool m_built = false;
};

} // namespace sdfwb::sampling
