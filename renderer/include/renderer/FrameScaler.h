#pragma once
// How much of a frame the viewport traces: while the camera moves, a scale chosen from the last
// frames' cost so a frame takes about the frame budget; at rest, full resolution unless a frame
// would hold the UI past the stall limit, in which case a pixel cap (which survives resizes: a
// 4K window gets a lower scale). A new SDF is first measured on a timing frame at kTimingScale.
// GL-free and Qt-free: the viewport feeds it frame times (tests/renderer/test_frame_scaler.cpp).

#include <optional>
#include <utility>

namespace sdfwb::renderer {

class FrameScaler {
public:
    static constexpr float kTimingScale = 0.05f; // side of the timing frame: 0.25 % of the pixels
    static constexpr float kMinimumScale = 0.1f; // while moving

    void setFrameBudget(double milliseconds) { m_frameBudget = milliseconds; }
    void setStallLimit(double milliseconds) { m_stallLimit = milliseconds; }
    double stallLimit() const { return m_stallLimit; }

    // The scale of the next frame of width x height pixels.
    float scaleFor(int width, int height, bool interacting) const;
    // The largest scale allowed at this size (1 without a cap).
    float cap(int width, int height) const;
    // A frame at `scale` took `milliseconds`. Returns true when a full frame (at rest) went over
    // the stall limit: from now on frames are capped.
    bool frameDone(int width, int height, float scale, double milliseconds, bool interacting);
    // The camera starts moving: start from the scale the last full frame suggests.
    void startInteraction();
    // A new SDF whose full frame is estimated over the frame budget: moving frames start, until
    // its first full frame is measured, from a scale that costs half the budget.
    void seedScale(double estimateMilliseconds);
    double frameBudget() const { return m_frameBudget; }
    // A new SDF: no cap until its timing frame says otherwise.
    void clearCap() { m_maxPixels = 0.0; }

    // The cost of a full frame estimated from a timing frame at kTimingScale and, when small frames are
    // dominated by fixed costs, a second one at `largerScale`.
    static double estimateFullFrame(double timingMilliseconds, std::optional<std::pair<float, double>> larger = std::nullopt);
    // Caps frames of width x height so one is expected to take 80 % of the stall limit.
    void capFromEstimate(int width, int height, double estimateMilliseconds);

private:
    double m_frameBudget = 33.0;
    double m_stallLimit = 1500.0;
    double m_maxPixels = 0.0; // pixels a frame may trace within the stall limit (0: no cap)
    double m_fullFrameMilliseconds = 0.0;
    float m_scale = 1.0f; // while moving
};

} // namespace sdfwb::renderer
