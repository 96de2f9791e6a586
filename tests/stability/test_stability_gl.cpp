// Stiff and extreme cases through the real tracer, samplers and audit (SPEC section 7). Every
// case in tests/stability/ must: finish (no hang, no crash), stop each ray within its step budget
// and label every miss (left the box, out of steps, NaN/Inf), report only hits whose |f| is below
// the pixel tolerance, keep normals finite, count bad sample rows exactly, and get its verdict.

#include <renderer/OffscreenRenderer.h>
#include <renderer/SampleCompute.h>
#include <renderer/SdfRenderer.h>
#include <sampling/FieldAudit.h>
#include <sampling/Sampler.h>
#include <sampling/SamplerLibrary.h>
#include <shaders/SdfSource.h>
#include <values/Camera.h>

#include "GlTestContext.h"
#include "common/ExactRays.h"
#include "common/SourceSdfs.h"

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

using namespace sdfwb;
namespace fs = std::filesystem;
using PixelStats = renderer::OffscreenRenderer::PixelStats;

namespace {

constexpr int kWidth = 96, kHeight = 72;

struct TraceSummary {
    int hits = 0, leftBox = 0, outOfSteps = 0, notFinite = 0, other = 0;
    float maxSteps = 0;
    float worstResidualRatio = 0; // max over hits of |f| / (pixel tolerance at t)
    int badNormals = 0;           // hits whose normal is not a finite unit vector
    std::vector<PixelStats> pixels;
};

class StabilityTest : public sdfwb::testing::GlTest {
protected:
    static shaders::PreparedSdf load(const std::string& relative) { return sdfwb::testing::loadSourceSdf(relative); }

    static values::Camera frontCamera(float distance = 3.0f) {
        values::Camera camera;
        camera.position = {0.0f, 0.0f, distance};
        camera.target = {0.0f, 0.0f, 0.0f};
        camera.fovYDegrees = 40.0f;
        return camera;
    }

    static TraceSummary trace(const std::string& file, const values::Camera& camera, values::TraceSettings settings = {}) {
        renderer::SdfRenderer sdfRenderer;
        values::ShadingSettings shading;
        shading.statsOutput = true;
        EXPECT_FALSE(shaders::hasErrors(sdfRenderer.setShading(shading)));
        EXPECT_FALSE(shaders::hasErrors(sdfRenderer.setTrace(settings)));
        EXPECT_FALSE(shaders::hasErrors(sdfRenderer.setSdf(load(file))));
        renderer::OffscreenRenderer offscreen;
        TraceSummary summary;
        summary.pixels = offscreen.renderStats(sdfRenderer, kWidth, kHeight, camera, 0.0f);
        const float pixelAngle = 2.0f * std::tan(glm::radians(camera.fovYDegrees) / 2.0f) / float(kHeight);
        for (const PixelStats& p : summary.pixels) {
            summary.maxSteps = std::max(summary.maxSteps, p.steps);
            if (p.hit()) {
                ++summary.hits;
                const float tolerance = settings.epsilonScale * pixelAngle * p.t;
                // The tolerance applies to the scaled field the tracer marches (f * step factor).
                summary.worstResidualRatio = std::max(summary.worstResidualRatio, p.residual * settings.stepFactor / tolerance);
                if (!std::isfinite(p.normalLength) || std::abs(p.normalLength - 1.0f) > 1e-3f) ++summary.badNormals;
            } else if (p.t == PixelStats::kLeftBox) {
                ++summary.leftBox;
            } else if (p.t == PixelStats::kOutOfSteps) {
                ++summary.outOfSteps;
            } else if (p.t == PixelStats::kNotFinite) {
                ++summary.notFinite;
            } else {
                ++summary.other;
            }
        }
        releaseRenderer(sdfRenderer);
        return summary;
    }
    static void releaseRenderer(renderer::SdfRenderer& r) { r.releaseGl(); }

    // Pixels whose primary ray (built here, common/ExactRays.h) meets a sphere of `radius` at the
    // origin (the analytic silhouette).
    static int analyticSphereHits(const values::Camera& camera, float radius) {
        const glm::dvec3 o(camera.position);
        int hits = 0;
        for (int y = 0; y < kHeight; ++y)
            for (int x = 0; x < kWidth; ++x) {
                const glm::dvec3 d = sdfwb::testing::pixelRay(camera, x, y, kWidth, kHeight);
                const double b = glm::dot(o, d), c = glm::dot(o, o) - double(radius) * radius;
                hits += b * b - c > 0.0;
            }
        return hits;
    }

    // The silhouette of a sphere of `radius`: hits count within the hit tolerance (half a pixel's
    // footprint by default), so the traced disc lies between the sphere's and one grown by that much.
    static void expectSphereSilhouette(int hits, const values::Camera& camera, float radius,
                                       const values::TraceSettings& settings) {
        const float pixelAngle = 2.0f * std::tan(glm::radians(camera.fovYDegrees) / 2.0f) / float(kHeight);
        const float distance = glm::length(camera.position - camera.target);
        const int inner = analyticSphereHits(camera, radius);
        const int outer = analyticSphereHits(camera, radius + 1.5f * settings.epsilonScale * pixelAngle * distance);
        EXPECT_GE(hits, inner - inner / 100) << "radius " << radius;
        EXPECT_LE(hits, outer + outer / 100) << "radius " << radius;
    }

    // Every ray ended within its budget with a known outcome; every hit is below its tolerance
    // and has a finite unit normal.
    static void expectHonest(const TraceSummary& s, const values::TraceSettings& settings, const std::string& what) {
        EXPECT_LE(s.maxSteps, float(settings.maxSteps)) << what;
        EXPECT_EQ(s.other, 0) << what << ": a miss without a reason";
        EXPECT_EQ(s.hits + s.leftBox + s.outOfSteps + s.notFinite, kWidth * kHeight) << what;
        EXPECT_LE(s.worstResidualRatio, 1.0f) << what << ": a hit reported with |f| above the tolerance";
        EXPECT_EQ(s.badNormals, 0) << what << ": NaN or non-unit normals";
    }

    struct SampleRun {
        sampling::SamplingReport report;
        std::uint64_t nanRows = 0; // counted here, independently of the report
        std::vector<float> positions, distances, gradients;
    };
    static SampleRun sample(const std::string& file, const std::string& pattern, std::uint64_t count) {
        renderer::SampleCompute compute;
        auto piece = sampling::findSampler(pattern, {});
        EXPECT_TRUE(piece.hasValue());
        EXPECT_FALSE(shaders::hasErrors(compute.build(load(file), *piece)));
        sampling::SamplingJob job;
        job.count = count;
        job.seed = 7;
        SampleRun run;
        run.positions.resize(3 * count);
        run.distances.resize(count);
        run.gradients.resize(3 * count);
        auto report = sampling::sampleInto(compute, job, run.positions.data(), run.distances.data(), run.gradients.data(), {});
        EXPECT_TRUE(report.hasValue()) << (report ? "" : report.error().message);
        if (report) run.report = *report;
        for (std::uint64_t i = 0; i < count; ++i) {
            bool finite = std::isfinite(run.distances[i]);
            for (int c = 0; c < 3; ++c)
                finite = finite && std::isfinite(run.positions[3 * i + c]) && std::isfinite(run.gradients[3 * i + c]);
            run.nanRows += !finite;
        }
        compute.releaseGl();
        return run;
    }

    static values::AuditReport audit(const std::string& relative, std::uint64_t samples = 20000) {
        return sdfwb::testing::auditSourceSdf(relative, samples);
    }
};

} // namespace

TEST_F(StabilityTest, SteepFieldMissesHonestlyAtStepOneAndHitsWithItsStepFactor) {
    const auto camera = frontCamera();
    const int expected = analyticSphereHits(camera, 0.5f);
    // f = 100 (|p| - 0.5): steps of f overshoot the surface by 99 times the distance.
    values::TraceSettings plain;
    auto overshoot = trace("tests/stability/steep_sphere.glsl", camera, plain);
    expectHonest(overshoot, plain, "step factor 1");
    EXPECT_LT(overshoot.hits, expected / 2) << "most rays jump through the sphere; they must not count as hits";

    auto report = audit("tests/stability/steep_sphere.glsl");
    EXPECT_EQ(std::string(values::findingName(report.verdict)), "non-conservative");
    values::TraceSettings safe;
    safe.stepFactor = report.safeStepFactor;
    auto traced = trace("tests/stability/steep_sphere.glsl", camera, safe);
    expectHonest(traced, safe, "audit's step factor");
    expectSphereSilhouette(traced.hits, camera, 0.5f, safe);

    // The surface sampler still finds the surface: every row on it (|f| / 100 = distance).
    auto rows = sample("tests/stability/steep_sphere.glsl", "surface", 4096);
    EXPECT_EQ(rows.report.badRows, rows.nanRows);
    std::uint64_t off = 0;
    for (std::size_t i = 0; i < rows.distances.size(); ++i)
        off += std::isfinite(rows.distances[i]) && std::abs(rows.distances[i]) > 1e-3f;
    EXPECT_EQ(off, 0u);
}

TEST_F(StabilityTest, ThinShellIsFoundWithFiniteNormalsFacingTheCamera) {
    const auto camera = frontCamera();
    values::TraceSettings settings;
    auto traced = trace("tests/stability/thin_shell.glsl", camera, settings);
    expectHonest(traced, settings, "thin shell");
    expectSphereSilhouette(traced.hits, camera, 0.6f, settings);

    // The normals (shading mode "normals": colour = n / 2 + 1/2) face the camera: the gradient
    // step is matched to the hit distance but must not straddle the 1e-4 shell.
    renderer::SdfRenderer sdfRenderer;
    ASSERT_FALSE(shaders::hasErrors(sdfRenderer.setSdf(load("tests/stability/thin_shell.glsl"))));
    renderer::OffscreenRenderer offscreen;
    auto image = offscreen.render(sdfRenderer, kWidth, kHeight, camera, 0.0f);
    int facing = 0, away = 0;
    for (int y = 0; y < kHeight; ++y)
        for (int x = 0; x < kWidth; ++x) {
            if (!traced.pixels[std::size_t(y * kWidth + x)].hit()) continue;
            const std::uint8_t* p = image.pixel(x, y);
            float nz = p[2] / 255.0f * 2.0f - 1.0f; // camera on +Z: a front-facing normal has nz > 0
            (nz > 0.0f ? facing : away)++;
        }
    sdfRenderer.releaseGl();
    EXPECT_EQ(away, 0) << facing << " normals face the camera";
    EXPECT_GT(facing, 0);
}

TEST_F(StabilityTest, CameraFarFromTheOriginSeesTheSameSilhouette) {
    // A camera 1e4 away with a narrow lens frames the unit sphere as one 3 units away does: the
    // tracer marches from the box entry, so steps below float32's spacing at t = 1e4 (~0.001) still count.
    values::Camera far = frontCamera(1e4f);
    far.fovYDegrees = float(glm::degrees(2.0 * std::atan(1.0 / 1e4)));
    far.farPlane = 2e4f;
    values::Camera near = frontCamera(3.0f);
    near.fovYDegrees = float(glm::degrees(2.0 * std::atan(1.0 / 3.0)));
    values::TraceSettings settings;
    auto traced = trace("dataset/Geometry/Sphere.glsl", far, settings);
    expectHonest(traced, settings, "camera at 1e4");
    auto reference = trace("dataset/Geometry/Sphere.glsl", near, settings);
    expectSphereSilhouette(traced.hits, far, 0.8f, settings);
    expectSphereSilhouette(reference.hits, near, 0.8f, settings);
    EXPECT_LT(traced.maxSteps, 64.0f) << "marching from 1e4 must not crawl";
}

TEST_F(StabilityTest, FieldEvaluatedFarFromTheOriginReportsItsPrecisionFloor) {
    // The shape is fine, but every value is rounded to float32's spacing near 1e4 (2^-10).
    auto report = audit("tests/stability/far_from_origin.glsl");
    EXPECT_GT(report.noiseFloor, 1e-4f) << "rounding noise of ~1e-3 must show";
    EXPECT_LT(report.noiseFloor, 1e-2f);
    EXPECT_NE(report.reason.find("precision"), std::string::npos) << report.reason;
    // Judged by its shape (an exact sphere), with the noise taken off the quotients.
    EXPECT_TRUE(report.verdict == values::Finding::Exact || report.verdict == values::Finding::Conservative)
        << values::findingName(report.verdict) << ": " << report.reason;
    EXPECT_NEAR(report.lipschitz, 1.0f, 0.05f);
    auto clean = audit("dataset/Geometry/Sphere.glsl");
    EXPECT_LT(clean.noiseFloor, 1e-5f) << "a field computed near the origin is clean";
    EXPECT_EQ(clean.reason.find("precision"), std::string::npos) << clean.reason;

    // Tracing it still works at the pixel scale, and the samplers report no bad rows.
    values::TraceSettings settings;
    auto traced = trace("tests/stability/far_from_origin.glsl", frontCamera(), settings);
    expectHonest(traced, settings, "far field");
    expectSphereSilhouette(traced.hits, frontCamera(), 0.5f, settings);
    auto rows = sample("tests/stability/far_from_origin.glsl", "near", 4096);
    EXPECT_EQ(rows.report.badRows, rows.nanRows);
}

TEST_F(StabilityTest, GrazingRaysRunOutOfStepsAndSaySo) {
    // Eye 0.01 above the plane y = -0.3, looking along it: rays near the horizon crawl.
    values::Camera camera;
    camera.position = {0.0f, -0.29f, 1.05f};
    camera.target = {0.0f, -0.30f, -1.0f};
    camera.fovYDegrees = 30.0f;
    values::TraceSettings small;
    small.maxSteps = 24;
    auto starved = trace("tests/stability/grazing_plane.glsl", camera, small);
    expectHonest(starved, small, "budget 24");
    EXPECT_GT(starved.outOfSteps, 0) << "some grazing rays need more than 24 steps";
    values::TraceSettings large;
    large.maxSteps = 1024;
    auto fed = trace("tests/stability/grazing_plane.glsl", camera, large);
    expectHonest(fed, large, "budget 1024");
    EXPECT_LT(fed.outOfSteps, starved.outOfSteps);
    EXPECT_GT(fed.hits, starved.hits);
}

TEST_F(StabilityTest, DeepFractalFinishesWithFiniteNormals) {
    values::TraceSettings settings;
    auto traced = trace("tests/stability/deep_mandelbulb.glsl", frontCamera(2.5f), settings);
    expectHonest(traced, settings, "Mandelbulb, 64 iterations");
    EXPECT_GT(traced.hits, kWidth * kHeight / 10);
    auto rows = sample("tests/stability/deep_mandelbulb.glsl", "near", 2048);
    EXPECT_EQ(rows.report.badRows, rows.nanRows);
    auto report = audit("tests/stability/deep_mandelbulb.glsl", 8000);
    EXPECT_EQ(report.nanFraction, 0.0) << "the estimate must stay finite where dr overflows";
}

TEST_F(StabilityTest, NanRegionEndsRaysAsNotFiniteAndCountsBadRows) {
    values::Camera camera = frontCamera();
    camera.fovYDegrees = 60.0f;
    values::TraceSettings settings;
    auto traced = trace("tests/stability/nan_region.glsl", camera, settings);
    expectHonest(traced, settings, "NaN region");
    EXPECT_GT(traced.notFinite, 0) << "rays through x > 0.6 meet NaN";
    EXPECT_GT(traced.hits, 0);

    auto rows = sample("tests/stability/nan_region.glsl", "rand", 20000);
    EXPECT_EQ(rows.report.badRows, rows.nanRows);
    EXPECT_NEAR(double(rows.nanRows) / 20000.0, 0.2, 0.015) << "x > 0.6 is 20 % of the cube";
    auto report = audit("tests/stability/nan_region.glsl");
    EXPECT_EQ(std::string(values::findingName(report.verdict)), "nan");
}

TEST_F(StabilityTest, TruncatedAndDiscontinuousFieldsTraceAndGetTheirVerdicts) {
    values::TraceSettings settings;
    const auto camera = frontCamera();
    auto truncated = trace("tests/stability/truncated.glsl", camera, settings);
    expectHonest(truncated, settings, "truncated");
    expectSphereSilhouette(truncated.hits, camera, 0.5f, settings);
    EXPECT_EQ(std::string(values::findingName(audit("tests/stability/truncated.glsl").verdict)), "truncated");

    auto jump = trace("tests/stability/discontinuous.glsl", camera, settings);
    expectHonest(jump, settings, "discontinuous");
    EXPECT_GT(jump.hits, 0);
    EXPECT_EQ(std::string(values::findingName(audit("tests/stability/discontinuous.glsl").verdict)), "discontinuous");
}

TEST_F(StabilityTest, ConstantFieldHasNoSurfaceAnywhere) {
    values::TraceSettings settings;
    auto traced = trace("tests/stability/constant.glsl", frontCamera(), settings);
    expectHonest(traced, settings, "constant");
    EXPECT_EQ(traced.hits, 0);
    EXPECT_EQ(traced.leftBox, kWidth * kHeight) << "every ray leaves the box: none runs out of steps";

    auto rows = sample("tests/stability/constant.glsl", "surface", 512);
    EXPECT_EQ(rows.report.badRows, 512u) << "no surface: every surface row is bad and counted";
    EXPECT_EQ(rows.nanRows, 512u);
    auto report = audit("tests/stability/constant.glsl", 8000);
    EXPECT_EQ(std::string(values::findingName(report.verdict)), "no-surface") << report.reason;
}

TEST_F(StabilityTest, VanishingGradientAtTheSurfaceIsFlagged) {
    // f = (|p| - 0.5)^3: |grad f| = 0 on the zero set, so |f| is tiny well before the surface.
    values::TraceSettings settings;
    const auto camera = frontCamera();
    auto traced = trace("tests/stability/cubed_sphere.glsl", camera, settings);
    expectHonest(traced, settings, "cubed sphere");
    EXPECT_GE(traced.hits, analyticSphereHits(camera, 0.5f));
    auto report = audit("tests/stability/cubed_sphere.glsl");
    EXPECT_EQ(std::string(values::findingName(report.verdict)), "non-conservative");
    EXPECT_LT(report.surfaceGradient, 0.05f) << "the audit measures |grad f| at the surface";
    EXPECT_NE(report.reason.find("vanishes"), std::string::npos) << report.reason;
    auto sphere = audit("dataset/Geometry/Sphere.glsl");
    EXPECT_NEAR(sphere.surfaceGradient, 1.0f, 0.01f);
}

TEST_F(StabilityTest, EveryCaseCountsItsBadRowsAndGetsItsVerdict) {
    // Every file of tests/stability/: the samplers' bad-row count is exactly the NaN rows they
    // wrote, and the audit names what the file is. (The textbook Mandelbulb estimate jumps where
    // orbits escape at different iterations: discontinuous is its right verdict.)
    struct Case {
        const char* file;
        const char* verdict; // nullptr: not asserted here (see the tests above)
    } cases[] = {{"steep_sphere", "non-conservative"}, {"thin_shell", "exact"},
                 {"far_from_origin", "exact"},         {"grazing_plane", "exact"},
                 {"deep_mandelbulb", "discontinuous"}, {"nan_region", "nan"},
                 {"truncated", "truncated"},           {"discontinuous", "discontinuous"},
                 {"constant", "no-surface"},           {"cubed_sphere", "non-conservative"},
                 {"union_of_spheres", "conservative"}};
    for (const Case& c : cases) {
        const std::string file = std::string("tests/stability/") + c.file + ".glsl";
        for (const char* pattern : {"rand", "surface"}) {
            auto rows = sample(file, pattern, 2048);
            EXPECT_EQ(rows.report.badRows, rows.nanRows) << file << " " << pattern;
        }
        if (c.verdict) {
            auto report = audit(file, 8000);
            EXPECT_EQ(std::string(values::findingName(report.verdict)), c.verdict) << file << ": " << report.reason;
        }
    }
}
