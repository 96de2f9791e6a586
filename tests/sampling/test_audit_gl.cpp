// The field audit and the plane readouts must tell apart exact, conservative, non-conservative,
// truncated, discontinuous and NaN fields (tests/stability/ holds the broken ones).

#include <renderer/HeadlessContext.h>
#include <sampling/FieldAudit.h>

#include "GlTestContext.h"
#include "common/SourceSdfs.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>

using namespace sdfwb;
namespace fs = std::filesystem;

namespace {

class AuditTest : public sdfwb::testing::GlTest {
protected:
    static shaders::PreparedSdf load(const std::string& relative) { return sdfwb::testing::loadSourceSdf(relative); }
    static values::AuditReport audit(const std::string& relative, std::uint64_t samples = 20000) {
        return sdfwb::testing::auditSourceSdf(relative, samples);
    }
};

} // namespace

TEST_F(AuditTest, ExactPrimitivesAreExact) {
    for (const char* file : {"dataset/Geometry/Sphere.glsl", "dataset/Geometry/Torus.glsl", "dataset/Geometry/Box.glsl"}) {
        auto r = audit(file);
        EXPECT_EQ(std::string(values::findingName(r.verdict)), "exact") << file << ": " << r.reason;
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
        EXPECT_EQ(std::string(values::findingName(r.verdict)), c.verdict) << c.file << ": " << r.reason;
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
    EXPECT_NEAR(sphere->minimum, -0.8f, 0.02f);                  // the centre of a radius-0.8 sphere
    EXPECT_NEAR(sphere->maximum, std::sqrt(2.0f) - 0.8f, 0.02f); // the plane's corner (1, 1, 0)
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

namespace {

values::AuditReport auditText(const std::string& glsl, std::uint64_t samples = 20000, float truncationReach = 3.0f) {
    auto sdf = shaders::prepareSdf(glsl, "known.glsl", {}, shaders::IncludeOptions{});
    EXPECT_TRUE(sdf.ok()) << glsl;
    sampling::AuditOptions options;
    options.samples = samples;
    options.seed = 7;
    options.convergence = false;
    options.truncationReach = truncationReach;
    auto report = sampling::auditField(sdf, options, {});
    EXPECT_TRUE(report.hasValue()) << (report ? "" : report.error().message);
    return report ? *report : values::AuditReport{};
}

std::vector<std::string> flagNames(const values::AuditReport& r) {
    std::vector<std::string> names;
    for (const auto& f : r.flags) names.push_back(values::findingName(f.finding));
    std::sort(names.begin(), names.end());
    return names;
}

using Names = std::vector<std::string>;

} // namespace

// Issue 14, point 6: fields whose construction fixes the findings, with a fixed seed.
TEST_F(AuditTest, KnownFieldsGiveKnownFlagSets) {
    // The paper's snake (its Figure 13): steeper than a distance and capped. Both are reported.
    auto snake = auditText("float sdf(vec3 p) { return min(1.0, 1.9 * (length(p) - 0.5)); }");
    EXPECT_EQ(flagNames(snake), (Names{"non-conservative", "truncated"})) << snake.reason;
    EXPECT_EQ(std::string(values::findingName(snake.verdict)), "truncated");
    const auto* cap = values::findFlag(snake.flags, values::Finding::Truncated);
    ASSERT_TRUE(cap);
    EXPECT_NEAR(cap->value, 1.0f, 1e-3f);
    EXPECT_NEAR(cap->start, 1.0f / 1.9f, 0.08f) << "the plateau starts where 1.9 d reaches 1";
    EXPECT_GT(cap->share, 0.9);
    const auto* steep = values::findFlag(snake.flags, values::Finding::NonConservative);
    ASSERT_TRUE(steep);
    EXPECT_NEAR(steep->value, 1.9f, 0.02f);
    ASSERT_FALSE(steep->examples.empty());
    EXPECT_NEAR(snake.truncationDistance.value_or(0.0f), 1.0f, 1e-3f);

    auto capped = auditText("float sdf(vec3 p) { return min(0.1, length(p) - 0.5); }");
    EXPECT_EQ(flagNames(capped), (Names{"truncated"})) << capped.reason;
    ASSERT_TRUE(values::findFlag(capped.flags, values::Finding::Truncated));
    EXPECT_NEAR(values::findFlag(capped.flags, values::Finding::Truncated)->value, 0.1f, 1e-3f);
    EXPECT_NEAR(values::findFlag(capped.flags, values::Finding::Truncated)->start, 0.1f, 0.05f);

    // A plateau beyond the unit cube (f reaches 2 at 2.5 from the origin) is found by probing outward.
    auto far = auditText("float sdf(vec3 p) { return min(2.0, length(p) - 0.5); }");
    EXPECT_EQ(flagNames(far), (Names{"truncated"})) << far.reason;
    auto shortReach = auditText("float sdf(vec3 p) { return min(2.0, length(p) - 0.5); }", 20000, 1.0f);
    EXPECT_EQ(flagNames(shortReach), Names{}) << "probing only to 1: the plateau at 2 is out of reach";

    // A jump of 0.2 across the plane z = 0.2, located there.
    auto jump = auditText("float sdf(vec3 p) { return length(p) - 0.5 + (p.z > 0.2 ? 0.2 : 0.0); }");
    EXPECT_EQ(flagNames(jump), (Names{"discontinuous"})) << jump.reason;
    const auto* step = values::findFlag(jump.flags, values::Finding::Discontinuous);
    ASSERT_TRUE(step);
    EXPECT_NEAR(step->value, 0.2f, 0.01f);
    ASSERT_FALSE(step->examples.empty());
    EXPECT_LE(step->examples.size(), values::kMaxExamples);
    for (const glm::vec3& e : step->examples) EXPECT_NEAR(e.z, 0.2f, 1e-3f) << "example off the jump plane";

    // Domain repetition whose cell cuts an off-centre sphere: f jumps at the cell walls (x = +-0.25, ...).
    auto repeated =
        auditText("float sdf(vec3 p) { vec3 q = mod(p + 0.25, 0.5) - 0.25; return length(q - vec3(0.1, 0.0, 0.0)) - 0.2; }");
    EXPECT_EQ(flagNames(repeated), (Names{"discontinuous"})) << repeated.reason;
    for (const glm::vec3& e : values::findFlag(repeated.flags, values::Finding::Discontinuous)->examples) {
        const float wall = std::abs(std::fmod(std::abs(e.x) + 0.25f, 0.5f)); // 0 or 0.5 on a wall x = 0.25 + 0.5 k
        EXPECT_LT(std::min(wall, 0.5f - wall), 2e-3f) << e.x;
    }

    // Two spheres' max: a crease, not a jump, and 1-Lipschitz.
    auto kinked =
        auditText("float sdf(vec3 p) { return max(length(p - vec3(0.2, 0, 0)) - 0.5, length(p + vec3(0.2, 0, 0)) - 0.5); }");
    EXPECT_EQ(flagNames(kinked), Names{}) << kinked.reason;

    // NaN where x > 0.5, with the examples there.
    auto broken = auditText("float sdf(vec3 p) { return p.x > 0.5 ? sqrt(-1.0 - p.x) : length(p) - 0.4; }");
    EXPECT_EQ(flagNames(broken), (Names{"nan"})) << broken.reason;
    EXPECT_NEAR(values::findFlag(broken.flags, values::Finding::Nan)->share, 0.25, 0.02);
    for (const glm::vec3& e : values::findFlag(broken.flags, values::Finding::Nan)->examples) EXPECT_GT(e.x, 0.5f);
}

TEST_F(AuditTest, PlaneReadoutsGiveTheSameFlags) {
    auto snake = shaders::prepareSdf("float sdf(vec3 p) { return min(0.3, 1.9 * (length(p) - 0.5)); }", "snake.glsl", {}, {});
    auto r = sampling::analysePlane(snake, {0, 0, 1}, 0.0f, 128, 0.0f);
    ASSERT_TRUE(r.hasValue());
    std::vector<std::string> names;
    for (const auto& f : r->flags) names.push_back(values::findingName(f.finding));
    std::sort(names.begin(), names.end());
    EXPECT_EQ(names, (Names{"non-conservative", "truncated"}));
    auto jump =
        shaders::prepareSdf("float sdf(vec3 p) { return length(p) - 0.5 + (p.x > 0.2 ? 0.2 : 0.0); }", "jump.glsl", {}, {});
    auto j = sampling::analysePlane(jump, {0, 0, 1}, 0.0f, 128, 0.0f);
    ASSERT_TRUE(j.hasValue());
    const auto* flag = values::findFlag(j->flags, values::Finding::Discontinuous);
    ASSERT_TRUE(flag);
    EXPECT_NEAR(flag->value, 0.2f, 0.03f);
    for (const glm::vec3& e : flag->examples) EXPECT_NEAR(e.x, 0.2f, 0.03f);
}
