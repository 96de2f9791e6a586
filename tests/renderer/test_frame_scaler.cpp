// The viewport's resolution logic, without GL or Qt: scales while moving, the cap for slow views,
// the timing-frame estimate for a new SDF.

#include <renderer/FrameScaler.h>

#include <gtest/gtest.h>

#include <cmath>

using sdfwb::renderer::FrameScaler;

TEST(FrameScaler, AtRestFullResolutionUntilAFrameIsTooSlow) {
    FrameScaler scaler;
    scaler.setStallLimit(1500.0);
    EXPECT_EQ(scaler.scaleFor(1280, 720, false), 1.0f);
    EXPECT_FALSE(scaler.frameDone(1280, 720, 1.0f, 40.0, false));
    EXPECT_EQ(scaler.scaleFor(1280, 720, false), 1.0f) << "a cheap view is not capped";
    // 6 s for a full frame: over the limit, and the next frames trace 0.8 * 1500 / 6000 of the pixels.
    EXPECT_TRUE(scaler.frameDone(1280, 720, 1.0f, 6000.0, false));
    EXPECT_NEAR(scaler.scaleFor(1280, 720, false), std::sqrt(0.2f), 1e-4f);
    // The cap is a pixel count: twice the side, half the scale.
    EXPECT_NEAR(scaler.cap(2560, 1440), 0.5f * std::sqrt(0.2f), 1e-4f);
    scaler.clearCap();
    EXPECT_EQ(scaler.cap(1280, 720), 1.0f);
}

TEST(FrameScaler, WhileMovingTheScaleAimsAtTheFrameBudget) {
    FrameScaler scaler;
    scaler.setFrameBudget(33.0);
    EXPECT_FALSE(scaler.frameDone(1280, 720, 1.0f, 132.0, false)); // a full frame: 4x the budget
    scaler.startInteraction();
    const float first = scaler.scaleFor(1280, 720, true);
    EXPECT_NEAR(first, std::sqrt(0.8f * 33.0f / 132.0f), 1e-4f) << "the first moving frame starts from the full frame's cost";
    EXPECT_EQ(scaler.scaleFor(1280, 720, false), 1.0f) << "at rest it refines to full resolution";
    // Frames that keep costing 2x the budget at the current scale pull it down, halfway each time.
    float scale = first;
    for (int k = 0; k < 20; ++k) {
        scaler.frameDone(1280, 720, scale, 66.0 * double(scale * scale) / double(first * first), true);
        const float next = scaler.scaleFor(1280, 720, true);
        EXPECT_LE(next, scale + 1e-6f);
        scale = next;
    }
    const double settled = 66.0 * double(scale * scale) / double(first * first);
    EXPECT_NEAR(settled, 0.8 * 33.0, 1.0) << "settles where a frame takes 80 % of the budget";
    // Never below the minimum, whatever a frame costs.
    for (int k = 0; k < 20; ++k) scaler.frameDone(1280, 720, scaler.scaleFor(1280, 720, true), 1e6, true);
    EXPECT_EQ(scaler.scaleFor(1280, 720, true), FrameScaler::kMinimumScale);
}

TEST(FrameScaler, TheTimingFramesEstimateSubtractsFixedCosts) {
    // 2 ms at 5 % of the side: 800 ms for the whole frame if all of it were per pixel.
    EXPECT_NEAR(FrameScaler::estimateFullFrame(2.0), 2.0 / (0.05 * 0.05), 1e-3); // kTimingScale is a float
    // 2 ms at 5 %, 3 ms at 15 %: 1 ms per 0.02 of area; fixed costs do not grow with the area.
    const double estimate = FrameScaler::estimateFullFrame(2.0, std::pair{0.15f, 3.0});
    EXPECT_NEAR(estimate, 2.0 + 1.0 / (0.15 * 0.15 - 0.05 * 0.05) * (1.0 - 0.05 * 0.05), 1e-3);
    EXPECT_LT(estimate, FrameScaler::estimateFullFrame(2.0));
    FrameScaler scaler;
    scaler.setStallLimit(1000.0);
    scaler.capFromEstimate(1000, 1000, 4000.0);
    EXPECT_NEAR(scaler.cap(1000, 1000), std::sqrt(0.2f), 1e-4f);
    EXPECT_GE(scaler.cap(100000, 100000), FrameScaler::kTimingScale) << "never below the timing frame's scale";
}
