// The audit's statistics on synthetic profiles, without GL: the noise floor of a straight run,
// the jump along a line search, the plateau along a ray outward from the surface.

#include <sampling/AuditStatistics.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

using namespace sdfwb::sampling;

TEST(AuditStatistics, PercentileByNearestRank) {
    EXPECT_EQ(percentile({}, 0.5), 0.0f);
    EXPECT_EQ(percentile({3, 1, 2}, 0.5), 2.0f);
    EXPECT_EQ(percentile({5, 1, 4, 2, 3}, 0.0), 1.0f);
    EXPECT_EQ(percentile({5, 1, 4, 2, 3}, 1.0), 5.0f);
}

TEST(AuditStatistics, ResidualStepIsTheRoundingStepOfAQuadratic) {
    std::vector<float> run(16);
    for (int k = 0; k < 16; ++k) run[std::size_t(k)] = 0.3f + 0.01f * float(k) + 0.002f * float(k * k);
    EXPECT_LT(quadraticResidualStep(run.data(), 16), 1e-6f) << "a quadratic leaves nothing but float rounding";
    // Rounded to steps of q: the residual step comes out near q (median over many runs).
    const float q = 1e-3f;
    std::vector<float> steps;
    for (int r = 0; r < 400; ++r) {
        for (int k = 0; k < 16; ++k) {
            const double exact = 0.3 + 0.0123 * r + 0.0137 * k + 0.0021 * k * k;
            run[std::size_t(k)] = float(std::round(exact / q) * q);
        }
        steps.push_back(quadraticResidualStep(run.data(), 16));
    }
    EXPECT_NEAR(percentile(steps, 0.5), q, 0.35f * q);
    run[3] = std::numeric_limits<float>::quiet_NaN();
    EXPECT_TRUE(std::isnan(quadraticResidualStep(run.data(), 16)));
}

TEST(AuditStatistics, LargestStepFindsAJumpAndNotASlope) {
    std::vector<float> line(64);
    for (int k = 0; k < 64; ++k) line[std::size_t(k)] = 0.5f + 0.01f * float(k);
    EXPECT_NEAR(largestStep(line.data(), 64).first, 0.0f, 1e-6f) << "a steady slope is no jump";
    for (int k = 40; k < 64; ++k) line[std::size_t(k)] += 0.2f;
    auto [rise, at] = largestStep(line.data(), 64);
    EXPECT_NEAR(rise, 0.2f, 1e-5f);
    EXPECT_EQ(at, 39);
    // sqrt near 0: the largest rise sits at the start and shrinks when the interval does.
    for (int k = 0; k < 64; ++k) line[std::size_t(k)] = std::sqrt(float(k) / 63.0f * 1e-3f);
    const float coarse = largestStep(line.data(), 64).first;
    for (int k = 0; k < 64; ++k) line[std::size_t(k)] = std::sqrt(float(k) / 63.0f * 1e-3f / 63.0f);
    EXPECT_LT(largestStep(line.data(), 64).first, 0.5f * coarse) << "the line search's second level tells it from a jump";
    line[10] = std::numeric_limits<float>::infinity();
    EXPECT_LT(largestStep(line.data(), 64).first, 0.0f);
}

TEST(AuditStatistics, PlateauStartsWhereTheFieldStopsGrowing) {
    constexpr int kProbes = 32;
    float distances[kProbes], f[kProbes];
    for (int k = 0; k < kProbes; ++k) distances[k] = 0.01f + 2.99f * float(k * k) / float((kProbes - 1) * (kProbes - 1));
    for (int k = 0; k < kProbes; ++k) f[k] = distances[k];
    EXPECT_EQ(plateauStart(f, distances, kProbes, 1e-6f), -1) << "an exact field keeps growing";
    for (int k = 0; k < kProbes; ++k) f[k] = std::min(1.0f, 1.9f * distances[k]);
    const int first = plateauStart(f, distances, kProbes, 1e-6f);
    ASSERT_GE(first, 0);
    EXPECT_GE(distances[first], 1.0f / 1.9f);
    EXPECT_LT(distances[first - 1], 1.0f / 1.9f) << "the plateau starts at the first probe past 1/1.9";
    for (int k = 0; k < kProbes; ++k) f[k] = std::min(2.0f, distances[k]);
    EXPECT_GE(plateauStart(f, distances, kProbes, 1e-6f), 0) << "a plateau at 2 within a reach of 3";
    for (int k = 0; k < kProbes; ++k) f[k] = std::min(2.9f, distances[k]);
    EXPECT_EQ(plateauStart(f, distances, kProbes, 1e-6f), -1) << "too short a stretch to call it one";
    for (int k = 0; k < kProbes; ++k) f[k] = distances[k] < 1.0f ? distances[k] : 2.0f - distances[k];
    EXPECT_EQ(plateauStart(f, distances, kProbes, 1e-6f), -1) << "a ray that meets more of the shape is not a plateau";
    for (int k = 0; k < kProbes; ++k) f[k] = std::min(0.5f, distances[k]) + 0.01f * float(k % 2);
    EXPECT_EQ(plateauStart(f, distances, kProbes, 1e-6f), -1) << "noise above the allowance breaks it";
    EXPECT_GE(plateauStart(f, distances, kProbes, 0.02f), 0) << "noise within the allowance does not";
}
