// The field audit and the plane readouts must tell apart exact, conservative, non-conservative,
// truncated, discontinuous and NaN fields (tests/stability/ holds the broken ones).

#include <renderer/HeadlessContext.h>
#include <sampling/FieldAudit.h>

#include "GlTestContext.h"
#include "common/SourceSdfs.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

using namespace sdfwb;
namespace fs = std::filesystem;

namespace {

class AuditTest : public sdfwb::testing::GlTest {
protected:

    static shaders::PreparedSdf load(const std::string& relative) { return sdfwb::testing::loadSourceSdf(relative); }
    static sampling::AuditReport audit(const std::string& relative, std::uint64_t samples = 20000) {
        return sdfwb::testing::auditSourceSdf(relative, samples);
    }
};


} // namespace

TEST_F(AuditTest, ExactPrimitivesAreExact) {
    for (const char* file : {"dataset/Geometry/Sphere.glsl", "dataset/Geometry/Torus.glsl", "dataset/Geometry/Box.glsl"}) {
        auto r = audit(file);
        EXPECT_EQ(r.verdict, "exact") << file << ": " << r.reason;
        EXPECT_NEAR(r.lipschitz, 1.0f, 0.01f) << file;
        EXPECT_EQ(r.nanFraction, 0.0);
        EXPECT_LT(r.eikonalMean, 1e-3f);
    }
}

TEST_F(AuditTest, EachBrokenFieldGetsItsVerdict) {
    struct Case {
        const char* file;
        const char* verdict;
    } cases[] = {{"tests/stability/union_of_spheres.glsl", "conservative"},
                 {"tests/stability/steep_sphere.glsl", "non-conservative"},
                 {"tests/stability/truncated.glsl", "truncated"},
                 {"tests/stability/discontinuous.glsl", "discontinuous"},
                 {"tests/stability/nan_region.glsl", "nan"},
                 {"tests/stability/constant.glsl", "no-surface"}};
    for (const Case& c : cases) {
        auto r = audit(c.file);
        EXPECT_EQ(r.verdict, c.verdict) << c.file << ": " << r.reason;
    }
}

TEST_F(AuditTest, FiguresForTheStiffCases) {
    auto steep = audit("tests/stability/steep_sphere.glsl");
    EXPECT_NEAR(steep.lipschitz, 100.0f, 1.0f);
    EXPECT_NEAR(steep.safeStepFactor, 0.01f, 1e-3f);
    auto truncated = audit("tests/stability/truncated.glsl");
    ASSERT_TRUE(truncated.truncationDistance.has_value());
    EXPECT_NEAR(*truncated.truncationDistance, 0.2f, 1e-3f);
    auto broken = audit("tests/stability/nan_region.glsl");
    // x > 0.6 is 20 % of the cube [-1, 1]^3.
    EXPECT_NEAR(broken.nanFraction, 0.2, 5.0 * broken.nanFractionError + 0.01);
    EXPECT_GT(broken.nanFractionError, 0.0);
}

TEST_F(AuditTest, EstimatesTightenWithMoreSamples) {
    sampling::AuditOptions options;
    options.samples = 16000;
    auto report = sampling::auditField(load("dataset/Geometry/Torus.glsl"), options, {});
    ASSERT_TRUE(report.hasValue());
    ASSERT_EQ(report->convergence.size(), 3u);
    EXPECT_EQ(report->convergence[0].samples, 1000u);
    EXPECT_EQ(report->convergence[2].samples, 16000u);
    // The exactness error is bounded by the surface sampling: 16x the points, about 4x finer.
    EXPECT_LT(report->convergence[2].exactnessP99, 0.6f * report->convergence[0].exactnessP99);
}

TEST_F(AuditTest, PlaneReadouts) {
    auto sphere = sampling::analysePlane(load("dataset/Geometry/Sphere.glsl"), {0, 0, 1}, 0.0f, 128, 0.0f);
    ASSERT_TRUE(sphere.hasValue()) << sphere.error().message;
    EXPECT_GT(sphere->points, 128u * 128u / 4);
    EXPECT_NEAR(sphere->minimum, -0.8f, 0.02f);  // the centre of a radius-0.8 sphere
    EXPECT_NEAR(sphere->maximum, std::sqrt(2.0f) - 0.8f, 0.02f);  // the plane's corner (1, 1, 0)
    EXPECT_NEAR(sphere->lipschitzMax, 1.0f, 0.01f);
    EXPECT_EQ(sphere->shareAboveOne, 0.0);
    EXPECT_FALSE(sphere->truncationDistance.has_value());
    EXPECT_EQ(sphere->nanCount, 0u);
    EXPECT_GT(sphere->histogram[20], sphere->points * 9 / 10) << "|grad f| = 1 falls in the centre of bin 20";
    EXPECT_EQ(sphere->discontinuities, 0u);

    auto steep = sampling::analysePlane(load("tests/stability/steep_sphere.glsl"), {0, 0, 1}, 0.0f, 64, 0.0f);
    ASSERT_TRUE(steep.hasValue());
    EXPECT_EQ(steep->discontinuities, 0u) << "steep is not discontinuous";
    EXPECT_NEAR(steep->safeStepFactor, 0.01f, 1e-3f);
    EXPECT_GT(steep->shareAboveOne, 0.99);
    auto truncated = sampling::analysePlane(load("tests/stability/truncated.glsl"), {0, 1, 0}, 0.1f, 64, 0.0f);
    ASSERT_TRUE(truncated.hasValue());
    ASSERT_TRUE(truncated->truncationDistance.has_value());
    EXPECT_NEAR(*truncated->truncationDistance, 0.2f, 1e-3f);
    auto jump = sampling::analysePlane(load("tests/stability/discontinuous.glsl"), {0, 0, 1}, 0.0f, 256, 0.0f);
    ASSERT_TRUE(jump.hasValue());
    EXPECT_GT(jump->discontinuities, 0u);
    auto broken = sampling::analysePlane(load("tests/stability/nan_region.glsl"), {0, 0, 1}, 0.0f, 64, 0.0f);
    ASSERT_TRUE(broken.hasValue());
    EXPECT_NEAR(double(broken->nanCount) / double(broken->points), 0.2, 0.03);
}
