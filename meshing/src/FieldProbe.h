#pragma once
// The SDF evaluated on the GPU at points the caller gives (the analysis/points.glsl sampler):
// distances, and gradients by central differences. Private to meshing/.

#include <core/Expected.h>
#include <renderer/SampleCompute.h>
#include <shaders/Parameters.h>
#include <shaders/SdfSource.h>

#include <string>
#include <vector>

namespace sdfwb::meshing::detail {

class FieldProbe {
public:
    // `pattern`: "analysis/points.glsl" (the caller's points) or a sampler name ("surface").
    Expected<void> build(const shaders::PreparedSdf& sdf, const std::string& pattern, float time,
                         const std::vector<shaders::ParameterSetting>& parameters);
    // points: 3n floats; distances: n; gradients (3n) when not null. gradientStep: the central
    // difference step.
    Expected<void> evaluate(const std::vector<float>& points, std::vector<float>& distances, std::vector<float>* gradients,
                            float gradientStep = 1e-4f);
    // n rows of a generating sampler (surface): positions, distances and gradients.
    Expected<void> generate(std::uint64_t n, std::uint64_t seed, std::vector<float>& positions, std::vector<float>& distances,
                            std::vector<float>& gradients);
    ~FieldProbe() { m_compute.releaseGl(); }

private:
    renderer::SampleCompute m_compute;
    float m_time = 0.0f;
    std::vector<shaders::ParameterSetting> m_parameters;
    std::vector<float> m_positions, m_scratch; // reused between calls (no page faults per call)
};

} // namespace sdfwb::meshing::detail
