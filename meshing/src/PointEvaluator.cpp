#include "PointEvaluator.h"

#include <sampling/Sampler.h>
#include <sampling/SamplerLibrary.h>
#include <shaders/ShaderComposer.h>

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <iterator>

namespace sdfwb::meshing::detail {

Expected<void> PointEvaluator::build(const shaders::PreparedSdf& sdf, const std::string& pattern, float time,
                                     const std::vector<shaders::ParameterSetting>& parameters) {
    m_time = time;
    m_parameters = parameters;
    if (pattern == "analysis/points.glsl") { // the caller's points: the one field evaluator
        for (const auto& d : m_points.build(sdf))
            if (d.severity == shaders::Severity::Error) return makeError("mesh: " + shaders::formatDiagnostic(d));
        return {};
    }
    auto piece = pattern.rfind("analysis/", 0) == 0 ? shaders::builtinPiece(pattern) : sampling::findSampler(pattern, {});
    if (!piece) return piece.error();
    for (const auto& d : m_compute.build(sdf, *piece))
        if (d.severity == shaders::Severity::Error) return makeError("mesh: " + shaders::formatDiagnostic(d));
    return {};
}

void PointEvaluator::setClip(glm::dvec3 low, glm::dvec3 high) {
    m_clip = true;
    m_low = low;
    m_high = high;
}

void PointEvaluator::clip(const float* point, float& distance, float* gradient) {
    // Per axis: how far outside the slab the point lies (negative inside), and which face is nearer.
    glm::dvec3 q, side;
    for (int a = 0; a < 3; ++a) {
        const double below = m_low[a] - double(point[a]), above = double(point[a]) - m_high[a];
        q[a] = std::max(below, above);
        side[a] = above >= below ? 1.0 : -1.0;
    }
    const glm::dvec3 out = glm::max(q, glm::dvec3(0.0));
    const double outside = glm::length(out);
    const int axis = q.x >= q.y && q.x >= q.z ? 0 : (q.y >= q.z ? 1 : 2);
    const double box = outside + std::min(q[axis], 0.0);
    if (!(box > double(distance)) && std::isfinite(distance)) return;
    if (distance < 0.0f && box >= 0.0) ++m_clipped;
    distance = float(box);
    if (!gradient) return;
    glm::dvec3 g(0.0);
    if (outside > 0.0)
        g = out * side / outside;
    else
        g[axis] = side[axis];
    for (int a = 0; a < 3; ++a) gradient[a] = float(g[a]);
}

sampling::SamplingJob PointEvaluator::job(std::uint64_t count) const {
    sampling::SamplingJob job;
    job.count = count;
    job.time = m_time;
    job.sdfParameters = m_parameters;
    job.chunkSize = kChunk;
    return job;
}

Expected<void> PointEvaluator::evaluate(const std::vector<float>& points, std::vector<float>& distances,
                                        std::vector<float>* gradients, float gradientStep) {
    const std::uint64_t n = points.size() / 3;
    distances.resize(n);
    if (gradients) gradients->resize(3 * n);
    if (n == 0) return {};
    sampling::FieldSettings settings;
    settings.time = m_time;
    settings.gradientStep = gradientStep;
    // Central differences even on a mesh's own field: an open mesh's field jumps from -d to +d where
    // its winding number crosses 1/2 (over a hole), and the mesher finds that sheet through the taps'
    // large slope across it (the Lipschitz estimate, the vertices' projection); the exact gradient of
    // the distance does not see it.
    settings.meshGradientTaps = true;
    settings.chunk = kChunk;
    settings.parameters = m_parameters;
    auto report = m_points.evaluate(points.data(), n, distances.data(), gradients ? gradients->data() : nullptr, settings);
    if (!report) return report.error();
    if (m_clip)
        for (std::uint64_t i = 0; i < n; ++i)
            clip(points.data() + 3 * i, distances[i], gradients ? gradients->data() + 3 * i : nullptr);
    return {};
}

Expected<void> PointEvaluator::evaluateLattice(const std::vector<float>& firstPoints, glm::vec3 origin, glm::vec3 step, int block,
                                               int n, std::vector<float>& distances) {
    const std::uint64_t perBlock = std::uint64_t(block + 1) * std::uint64_t(block + 1) * std::uint64_t(block + 1);
    const std::uint64_t count = firstPoints.size() / 3 * perBlock;
    distances.resize(count);
    if (count == 0) return {};
    sampling::SamplingJob job = this->job(count);
    job.inputPoints = firstPoints.data();
    job.inputTableFloats = block == 0 ? 0 : firstPoints.size(); // single points go up chunk by chunk
    const float parameters[8] = {origin.x, origin.y, origin.z, float(block), step.x, step.y, step.z, float(n)};
    std::copy(std::begin(parameters), std::end(parameters), job.parameters);
    auto report = sampling::sampleInto(m_compute, job, nullptr, distances.data(), nullptr, {});
    if (!report) return report.error();
    if (m_clip) {
        // The grid points in the order analysis/lattice.glsl writes them: per block, x fastest.
        const int side = block + 1;
        std::uint64_t i = 0;
        for (std::size_t b = 0; b + 2 < firstPoints.size(); b += 3) {
            // A block inside the box keeps its values: the cut changes no sign there, and the mesher
            // takes only signs from the grid (crossings and normals come from evaluate()).
            bool inside = true;
            for (int a = 0; a < 3; ++a) {
                const double first = double(origin[a]) + double(firstPoints[b + std::size_t(a)]) * double(step[a]);
                const double last =
                    double(origin[a]) + std::min(double(firstPoints[b + std::size_t(a)]) + block, double(n)) * double(step[a]);
                inside = inside && first > m_low[a] && last < m_high[a];
            }
            if (inside) {
                i += std::uint64_t(side) * side * side;
                continue;
            }
            for (int k = 0; k < side; ++k)
                for (int j = 0; j < side; ++j)
                    for (int x = 0; x < side; ++x, ++i) {
                        // Indices past n are clamped to n, as the shader does.
                        auto at = [&](int a, int offset) {
                            const double index = std::min(double(firstPoints[b + std::size_t(a)]) + offset, double(n));
                            return float(double(origin[a]) + index * double(step[a]));
                        };
                        const float p[3] = {at(0, x), at(1, j), at(2, k)};
                        clip(p, distances[i], nullptr);
                    }
        }
    }
    return {};
}

Expected<void> PointEvaluator::generate(std::uint64_t n, std::uint64_t seed, std::vector<float>& positions,
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
