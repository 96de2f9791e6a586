#pragma once
// The SDF evaluated on the GPU at points the caller gives (the analysis/points.glsl sampler):
// distances, and gradients by central differences. Private to meshing/.

#include <core/Expected.h>
#include <renderer/SampleCompute.h>
#include <sampling/FieldEvaluator.h>
#include <sampling/Sampler.h>
#include <shaders/Parameters.h>
#include <shaders/SdfSource.h>

#include <glm/vec3.hpp>

#include <string>
#include <vector>

namespace sdfwb::meshing::detail {

class PointEvaluator {
public:
    // `pattern`: "analysis/points.glsl" (the caller's points) or a sampler name ("surface").
    Expected<void> build(const shaders::PreparedSdf& sdf, const std::string& pattern, float time,
                         const std::vector<shaders::ParameterSetting>& parameters);
    // points: 3n floats; distances: n; gradients (3n) when not null (else the field alone: one
    // evaluation per point, not seven). gradientStep: the central difference step.
    Expected<void> evaluate(const std::vector<float>& points, std::vector<float>& distances, std::vector<float>* gradients,
                            float gradientStep = 1e-4f);
    // With the analysis/lattice.glsl pattern: the field at every grid point of each block, (B+1)^3
    // per block in x-fastest order. firstPoints: each block's first grid index (3 floats). block 0:
    // a list of single grid points (any number: they are uploaded chunk by chunk).
    Expected<void> evaluateLattice(const std::vector<float>& firstPoints, glm::vec3 origin, glm::vec3 step, int block, int n,
                                   std::vector<float>& distances);
    // n rows of a generating sampler (surface): positions, distances and gradients.
    Expected<void> generate(std::uint64_t n, std::uint64_t seed, std::vector<float>& positions, std::vector<float>& distances,
                            std::vector<float>& gradients);
    // Cuts the field by a box: evaluate() and evaluateLattice() give max(f, box(p)), where box is
    // the box's exact SDF, and its gradient where the box's value wins: a shape that leaves the box
    // is closed on the box's faces. evaluateLattice() cuts only blocks not wholly inside the box (the
    // others keep f, whose signs the cut would not change). clipped() counts the values whose sign
    // the cut changed.
    void setClip(glm::dvec3 low, glm::dvec3 high);
    std::uint64_t clipped() const { return m_clipped; }
    ~PointEvaluator() { m_compute.releaseGl(); }

private:
    static constexpr std::uint32_t kChunk = 1u << 16;     // dispatches of 64 k points: their buffers stay in cache
    sampling::SamplingJob job(std::uint64_t count) const; // this evaluator's time and parameters
    sampling::FieldEvaluator m_points;                    // built for analysis/points.glsl
    renderer::SampleCompute m_compute;                    // built for any other pattern
    void clip(const float* point, float& distance, float* gradient);
    bool m_clip = false;
    glm::dvec3 m_low{0.0}, m_high{0.0};
    std::uint64_t m_clipped = 0;
    float m_time = 0.0f;
    std::vector<shaders::ParameterSetting> m_parameters;
};

} // namespace sdfwb::meshing::detail
