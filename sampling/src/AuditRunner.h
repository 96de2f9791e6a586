#pragma once
// What the volume audit (FieldAudit.cpp) and the plane readout (PlaneReadout.cpp) share: a
// compiled sampler run over the same points with several gradient steps, and row tests.

#include <sampling/SampleSet.h>
#include <sampling/Sampler.h>
#include <sampling/SamplerLibrary.h>

#include <renderer/SampleCompute.h>
#include <shaders/Diagnostic.h>
#include <shaders/ShaderComposer.h>

#include <chrono>
#include <cmath>
#include <string>
#include <vector>

namespace sdfwb::sampling::detail {

inline double secondsSince(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

inline bool finiteRow(const SampleSet& s, std::size_t i) {
    if (!std::isfinite(s.distances[i])) return false;
    for (int c = 0; c < 3; ++c)
        if (!std::isfinite(s.positions[3 * i + std::size_t(c)]) || !std::isfinite(s.gradients[3 * i + std::size_t(c)]))
            return false;
    return true;
}

inline float gradientLength(const SampleSet& s, std::size_t i) {
    return std::sqrt(s.gradients[3 * i] * s.gradients[3 * i] + s.gradients[3 * i + 1] * s.gradients[3 * i + 1] +
                     s.gradients[3 * i + 2] * s.gradients[3 * i + 2]);
}

// A compiled sampler that can be run with several gradient steps over the same points.
class Runner {
public:
    // A failed build's diagnostics also go to `diagnosticsOut` when given (the Error holds the first).
    Expected<void> build(const shaders::PreparedSdf& sdf, const std::string& pattern,
                         const std::vector<shaders::ParameterSetting>& parameters,
                         std::vector<shaders::Diagnostic>* diagnosticsOut = nullptr) {
        m_parameters = parameters;
        auto piece = pattern.rfind("analysis/", 0) == 0 ? shaders::builtinPiece(pattern) : findSampler(pattern, {});
        if (!piece) return piece.error();
        auto diagnostics = m_compute.build(sdf, *piece);
        if (shaders::hasErrors(diagnostics)) {
            if (diagnosticsOut) *diagnosticsOut = diagnostics;
            for (const auto& d : diagnostics)
                if (d.severity == shaders::Severity::Error) return makeError("audit: " + shaders::formatDiagnostic(d));
        }
        return {};
    }
    Expected<SampleSet> run(SamplingJob job) {
        SampleSet out;
        out.resize(std::size_t(job.count));
        job.sdfParameters = m_parameters;
        auto report = sampleInto(m_compute, job, out.positions.data(), out.distances.data(), out.gradients.data(), {});
        if (!report) return report.error();
        return out;
    }
    ~Runner() { m_compute.releaseGl(); }

private:
    renderer::SampleCompute m_compute;
    std::vector<shaders::ParameterSetting> m_parameters;
};

} // namespace sdfwb::sampling::detail
