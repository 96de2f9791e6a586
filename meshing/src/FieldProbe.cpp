#include "FieldProbe.h"

#include <sampling/Sampler.h>
#include <sampling/SamplerLibrary.h>
#include <shaders/ShaderComposer.h>

#include <algorithm>
#include <iterator>

namespace sdfwb::meshing::detail {

Expected<void> FieldProbe::build(const shaders::PreparedSdf& sdf, const std::string& pattern, float time,
                                 const std::vector<shaders::ParameterSetting>& parameters) {
    m_time = time;
    m_parameters = parameters;
    auto piece = pattern.rfind("analysis/", 0) == 0 ? shaders::builtinPiece(pattern) : sampling::findSampler(pattern, {});
    if (!piece) return piece.error();
    for (const auto& d : m_compute.build(sdf, *piece))
        if (d.severity == shaders::Severity::Error) return makeError("mesh: " + shaders::formatDiagnostic(d));
    return {};
}

sampling::SamplingJob FieldProbe::job(std::uint64_t count) const {
    sampling::SamplingJob job;
    job.count = count;
    job.time = m_time;
    job.sdfParameters = m_parameters;
    job.chunkSize = 1u << 16; // dispatches of 64 k points: their buffers stay in cache
    return job;
}

Expected<void> FieldProbe::evaluate(const std::vector<float>& points, std::vector<float>& distances,
                                    std::vector<float>* gradients, float gradientStep) {
    const std::uint64_t n = points.size() / 3;
    distances.resize(n);
    if (gradients) gradients->resize(3 * n);
    if (n == 0) return {};
    sampling::SamplingJob job = this->job(n);
    job.gradientStep = gradientStep;
    job.inputPoints = points.data();
    // The points are the caller's: no positions back, and no gradient taps unless asked for.
    auto report = sampling::sampleInto(m_compute, job, nullptr, distances.data(), gradients ? gradients->data() : nullptr, {});
    if (!report) return report.error();
    return {};
}

Expected<void> FieldProbe::evaluateLattice(const std::vector<float>& firstPoints, glm::vec3 origin, glm::vec3 step, int block,
                                           int n, std::vector<float>& distances) {
    const std::uint64_t perBlock = std::uint64_t(block + 1) * std::uint64_t(block + 1) * std::uint64_t(block + 1);
    const std::uint64_t count = firstPoints.size() / 3 * perBlock;
    distances.resize(count);
    if (count == 0) return {};
    sampling::SamplingJob job = this->job(count);
    job.inputPoints = firstPoints.data();
    job.inputTableFloats = firstPoints.size();
    const float parameters[8] = {origin.x, origin.y, origin.z, float(block), step.x, step.y, step.z, float(n)};
    std::copy(std::begin(parameters), std::end(parameters), job.parameters);
    auto report = sampling::sampleInto(m_compute, job, nullptr, distances.data(), nullptr, {});
    if (!report) return report.error();
    return {};
}

Expected<void> FieldProbe::generate(std::uint64_t n, std::uint64_t seed, std::vector<float>& positions,
                                    std::vector<float>& distances, std::vector<float>& gradients) {
    positions.assign(3 * n, 0.0f);
    distances.assign(n, 0.0f);
    gradients.assign(3 * n, 0.0f);
    sampling::SamplingJob job = this->job(n);
    job.seed = seed;
    auto report = sampling::sampleInto(m_compute, job, positions.data(), distances.data(), gradients.data(), {});
    if (!report) return report.error();
    return {};
}

} // namespace sdfwb::meshing::detail
