#pragma once
// What the mesh-SDF tests on GL share: the fixture (the field at given points through
// analysis/points.glsl), the engine switch, uniform points and a sampler's rows on either engine.
#include "GlTestContext.h"
#include "TestMeshes.h"
#include "common/ExactRays.h"

#include <jobs/JobJson.h>
#include <jobs/Jobs.h>
#include <meshfield/MeshField.h>
#include <meshfield/MeshQuery.h>
#include <renderer/OffscreenRenderer.h>
#include <renderer/SampleCompute.h>
#include <renderer/SdfRenderer.h>
#include <sampling/FieldAudit.h>
#include <sampling/SampleFile.h>
#include <sampling/Sampler.h>
#include <sampling/SamplerLibrary.h>
#include <shaders/SdfSource.h>
#include <shaders/ShaderComposer.h>

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <random>
#include <unistd.h>

namespace sdfwb::meshsdftest {

using glm::dvec3;
namespace fs = std::filesystem;

class MeshSdfTest : public testing::GlTest {
protected:
    // The field at `points` (xyz triples) through analysis/points.glsl; `counters` (optional)
    // receives the mesh walks' counts (SampleCompute::addMeshCounters).
    static std::vector<float> evaluate(const shaders::PreparedSdf& sdf, const std::vector<float>& points,
                                       meshfield::QueryCounters* counters = nullptr) {
        renderer::SampleCompute compute;
        auto stage = shaders::builtinPiece("analysis/points.glsl");
        EXPECT_TRUE(stage.hasValue());
        auto diagnostics = compute.build(sdf, *stage);
        EXPECT_FALSE(shaders::hasErrors(diagnostics)) << (diagnostics.empty() ? "" : shaders::formatDiagnostic(diagnostics[0]));
        if (counters) { EXPECT_TRUE(compute.countsMeshWalks()); }
        sampling::SamplingJob job;
        job.count = points.size() / 3;
        job.inputPoints = points.data();
        std::vector<float> distances(job.count);
        auto report = sampling::sampleInto(compute, job, nullptr, distances.data(), nullptr, {});
        EXPECT_TRUE(report.hasValue()) << (report ? "" : report.error().message);
        if (counters) compute.addMeshCounters(*counters);
        compute.releaseGl();
        return distances;
    }
};

// Sets SDFWB_MESH_ENGINE for one scope (meshfield::chooseMeshEngine reads it when a sampler builds).
class EngineScope {
public:
    explicit EngineScope(const char* engine) { setenv("SDFWB_MESH_ENGINE", engine, 1); }
    ~EngineScope() { unsetenv("SDFWB_MESH_ENGINE"); }
};

// `n` points uniform in [-reach, reach]^3, as xyz triples.
inline std::vector<float> uniformPoints(int n, unsigned seed, float reach) {
    std::mt19937 random(seed);
    std::uniform_real_distribution<float> u(-reach, reach);
    std::vector<float> points;
    for (int i = 0; i < n; ++i) points.insert(points.end(), {u(random), u(random), u(random)});
    return points;
}

struct Rows {
    std::vector<float> positions, distances, gradients;
    std::string engine;
    bool positionsOnly = false; // the sampler's program computed positions only (the values elsewhere)
    bool sortedRows = false;    // the GLSL field evaluated each chunk's rows grouped by cell
};

inline Rows sampleRows(const shaders::PreparedSdf& sdf, const shaders::ShaderPiece& sampler, std::uint64_t n, const char* engine,
                       bool taps = false, std::uint32_t chunk = 0) {
    const std::string& pattern = sampler.name;
    EngineScope scope(engine);
    renderer::SampleCompute compute;
    auto diagnostics = compute.build(sdf, sampler);
    EXPECT_FALSE(shaders::hasErrors(diagnostics));
    sampling::SamplingJob job;
    job.count = n;
    job.seed = 5;
    job.meshGradientTaps = taps;
    job.chunkSize = chunk;
    Rows rows{std::vector<float>(3 * n),
              std::vector<float>(n),
              std::vector<float>(3 * n),
              compute.meshEngine(),
              compute.source().find("#define SDFWB_POSITIONS_ONLY") != std::string::npos,
              compute.source().find("#define SDFWB_SORT_ROWS") != std::string::npos};
    auto report = sampling::sampleInto(compute, job, rows.positions.data(), rows.distances.data(), rows.gradients.data(), {});
    EXPECT_TRUE(report.hasValue()) << (report ? "" : report.error().message);
    EXPECT_EQ(report ? report->badRows : 1u, 0u) << pattern << ' ' << engine;
    compute.releaseGl();
    return rows;
}

inline Rows sampleRows(const shaders::PreparedSdf& sdf, const std::string& pattern, std::uint64_t n, const char* engine,
                       bool taps = false, std::uint32_t chunk = 0) {
    auto sampler = sampling::findSampler(pattern, sampling::samplerFolders());
    EXPECT_TRUE(sampler.hasValue());
    if (!sampler) return {};
    return sampleRows(sdf, *sampler, n, engine, taps, chunk);
}

} // namespace sdfwb::meshsdftest
