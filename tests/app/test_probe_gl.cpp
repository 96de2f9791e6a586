// The march debugger (`sdfwb --batch probe`, jobs::run(ProbeRequest)): the probed march is the one
// the frame is drawn with (same step count and hit distance as the tracer's per-pixel stats), it
// says why a ray missed, and it shows over-relaxation fallbacks and oversteps.
#include <jobs/JobJson.h>
#include <jobs/Jobs.h>
#include <renderer/OffscreenRenderer.h>
#include <renderer/SdfRenderer.h>

#include "GlTestContext.h"
#include "common/ChildProcess.h"

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include <string>

using namespace sdfwb;

namespace {

constexpr int kWidth = 48, kHeight = 32;
const char* const kSphere = "float sdf(vec3 p) { return length(p) - 0.5; }\n";

class Probe : public sdfwb::testing::GlTest {
protected:
    static values::FrameRequest frame(const std::string& source) {
        values::FrameRequest f;
        f.sdf.source = source;
        f.sdf.sdf = "probe-test";
        f.width = kWidth;
        f.height = kHeight;
        f.camera.position = {0.4f, 0.3f, 3.0f};
        f.camera.target = {0.0f, 0.0f, 0.0f};
        f.camera.fovYDegrees = 40.0f;
        return f;
    }

    // What the tracer itself writes for every pixel of the frame (its stats output).
    static std::vector<renderer::OffscreenRenderer::PixelStats> stats(const values::FrameRequest& f) {
        auto opened = jobs::openSdf(f.sdf, "test");
        EXPECT_TRUE(opened);
        renderer::SdfRenderer tracer;
        values::ShadingSettings shading;
        shading.statsOutput = true;
        EXPECT_FALSE(shaders::hasErrors(tracer.setShading(shading)));
        EXPECT_FALSE(shaders::hasErrors(tracer.setTrace(f.trace)));
        const auto diagnostics = tracer.setSdf(opened->prepared);
        EXPECT_FALSE(shaders::hasErrors(diagnostics)) << (diagnostics.empty() ? "" : diagnostics[0].message);
        renderer::OffscreenRenderer offscreen;
        auto pixels = offscreen.renderStats(tracer, f.width, f.height, f.camera, f.time);
        tracer.releaseGl();
        return pixels;
    }

    static values::ProbeReport probe(const values::FrameRequest& f, int x, int y) {
        auto result = jobs::run(values::ProbeRequest{f, x, y}, {});
        EXPECT_TRUE(result) << result.error.message;
        return result ? *result : values::ProbeReport{};
    }

    static int marchEvaluations(const values::ProbeReport& r) {
        int count = 0;
        for (const auto& e : r.events)
            count += e.event == values::MarchEvent::Step || e.event == values::MarchEvent::RelaxedStep ||
                     e.event == values::MarchEvent::Fallback || e.event == values::MarchEvent::Hit ||
                     e.event == values::MarchEvent::NotFinite;
        return count;
    }
};

TEST_F(Probe, ReplaysTheMarchTheFrameIsDrawnWith) {
    for (float relaxation : {1.0f, 1.8f}) {
        values::FrameRequest f = frame(kSphere);
        f.trace.overRelaxation = relaxation;
        const auto pixels = stats(f);
        int hits = 0, misses = 0;
        // Every fourth pixel: the middle of the sphere, its silhouette, and the rays that miss it.
        for (int y = 1; y < kHeight; y += 4)
            for (int x = 1; x < kWidth; x += 4) {
                const auto& expected = pixels[std::size_t(y) * kWidth + std::size_t(x)];
                const values::ProbeReport r = probe(f, x, y);
                ASSERT_EQ(r.steps, int(expected.steps)) << x << "," << y << " omega " << relaxation;
                EXPECT_EQ(marchEvaluations(r), r.steps) << x << "," << y;
                if (expected.hit()) {
                    ++hits;
                    ASSERT_EQ(r.outcome, values::MarchEvent::Hit) << x << "," << y;
                    EXPECT_EQ(*r.hitT, expected.t) << x << "," << y; // the same float: the same arithmetic
                    for (const auto& e : r.events)
                        if (e.event == values::MarchEvent::Hit) {
                            EXPECT_LT(std::abs(glm::length(e.position) - 0.5f), 1.01f * r.footprint); // within the hit tolerance
                        }
                } else {
                    ++misses;
                    EXPECT_TRUE(r.outcome == values::MarchEvent::LeftBox || r.outcome == values::MarchEvent::MissedBox)
                        << x << "," << y << ": " << r.reason;
                }
                // The march moves by d (times omega when relaxed) from each step's point.
                for (std::size_t k = 0; k + 1 < r.events.size(); ++k) {
                    if (r.events[k].event == values::MarchEvent::Step && r.events[k + 1].event != values::MarchEvent::LeftBox) {
                        EXPECT_NEAR(r.events[k].step, r.events[k].f, 1e-5f * (1.0f + r.events[k].t)) << k;
                    }
                }
                EXPECT_NEAR(glm::length(r.direction), 1.0f, 1e-6f);
            }
        EXPECT_GT(hits, 10);
        EXPECT_GT(misses, 20);
    }
}

TEST_F(Probe, SaysWhyARayMissed) {
    values::FrameRequest f = frame(kSphere);
    f.trace.maxSteps = 1;
    values::ProbeReport r = probe(f, kWidth / 2, kHeight / 2);
    EXPECT_EQ(r.outcome, values::MarchEvent::OutOfSteps);
    EXPECT_EQ(r.events.back().event, values::MarchEvent::OutOfSteps);
    EXPECT_NE(r.reason.find("step budget of 1"), std::string::npos) << r.reason;

    f = frame("float sdf(vec3 p) { return length(p) - 0.5 + 1e-3 * sqrt(p.z - 2.0); }\n"); // NaN inside the box
    r = probe(f, kWidth / 2, kHeight / 2);
    EXPECT_EQ(r.outcome, values::MarchEvent::NotFinite);
    EXPECT_EQ(r.events.size(), 1u);
    EXPECT_NE(r.reason.find("NaN or Inf"), std::string::npos);

    f = frame(kSphere);
    f.camera.position = {0.0f, 3.0f, 3.0f};
    f.camera.target = {0.0f, 3.0f, 0.0f}; // looking past the box
    r = probe(f, kWidth / 2, kHeight / 2);
    EXPECT_EQ(r.outcome, values::MarchEvent::MissedBox);
    EXPECT_EQ(r.steps, 0);
}

TEST_F(Probe, ShowsFallbacksAndOversteps) {
    // A field 1.6 times steeper than a distance: full steps pass the surface.
    values::FrameRequest f = frame("float sdf(vec3 p) { return 1.6 * (length(p) - 0.5); }\n");
    values::ProbeReport r = probe(f, kWidth / 2, kHeight / 2);
    EXPECT_GE(r.oversteps, 1u) << r.reason;
    bool marked = false;
    for (std::size_t k = 0; k + 1 < r.events.size(); ++k)
        if (r.events[k].overstep) {
            marked = true;
            EXPECT_GT(r.events[k].f, 0.0f);
            EXPECT_LT(r.events[k + 1].f, 0.0f); // the next evaluation is inside
        }
    EXPECT_TRUE(marked);
    EXPECT_NEAR(r.events.front().gradientLength, 1.6f, 0.05f); // |grad f| shows the steepness
    // With the step factor the audit suggests (1/L), no step passes the surface.
    f.trace.stepFactor = 1.0f / 1.6f;
    r = probe(f, kWidth / 2, kHeight / 2);
    EXPECT_EQ(r.oversteps, 0u);
    EXPECT_EQ(r.outcome, values::MarchEvent::Hit);
    // Over-relaxation takes long steps and falls back when they went too far.
    f = frame(kSphere);
    f.trace.overRelaxation = 1.9f;
    std::uint64_t fallbacks = 0;
    for (int x = 2; x < kWidth; x += 3) fallbacks += probe(f, x, kHeight / 2).fallbacks;
    EXPECT_GE(fallbacks, 1u);
}

TEST_F(Probe, CommandLineForm) {
    auto result = sdfwb::testing::runCommand(SDFWB_BINARY, "--batch probe --sdf Sphere --size 64x36 --pixel 32,18 --json");
    ASSERT_EQ(result.exitCode, 0) << result.output;
    auto report = jobs::reportFromJson<values::ProbeReport>(result.standardOutput);
    ASSERT_TRUE(report) << report.error().message << "\n" << result.output;
    EXPECT_EQ(report->outcome, values::MarchEvent::Hit);
    EXPECT_EQ(int(report->events.size()) >= report->steps, true);
    result = sdfwb::testing::runCommand(SDFWB_BINARY, "--batch probe --sdf Torus --size 64x36 --pixel 64,0");
    EXPECT_EQ(result.exitCode, 2);
    EXPECT_NE(result.output.find("--pixel: 64,0 lies outside the 64x36 frame"), std::string::npos) << result.output;
    result = sdfwb::testing::runCommand(SDFWB_BINARY, "--batch probe --sdf Torus --pixel ten,3");
    EXPECT_EQ(result.exitCode, 2);
    EXPECT_NE(result.output.find("--pixel: expected X,Y"), std::string::npos) << result.output;
    result = sdfwb::testing::runCommand(SDFWB_BINARY, "--batch probe --sdf Sphere --size 64x36 --pixel 32,18");
    ASSERT_EQ(result.exitCode, 0) << result.output;
    EXPECT_NE(result.output.find("hit at t = "), std::string::npos) << result.output;
    EXPECT_NE(result.output.find("|grad f|"), std::string::npos);
}

} // namespace
