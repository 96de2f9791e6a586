#include <renderer/FrameScaler.h>

#include <algorithm>
#include <cmath>
#include <utility>

namespace sdfwb::renderer {

float FrameScaler::cap(int width, int height) const {
    if (m_maxPixels <= 0.0) return 1.0f;
    const double pixels = std::max(1.0, double(width) * double(height));
    return std::clamp(float(std::sqrt(m_maxPixels / pixels)), kTimingScale, 1.0f);
}

float FrameScaler::scaleFor(int width, int height, bool interacting) const {
    return std::min(interacting ? m_scale : 1.0f, cap(width, height));
}

bool FrameScaler::frameDone(int width, int height, float scale, double milliseconds, bool interacting) {
    const double traced = double(width) * height * scale * scale;
    if (!interacting) {
        // The pixel budget follows the last full frame's cost per pixel (so a resize to 4K lowers
        // the scale before the slow frame, not after it).
        if (milliseconds > 0.0) m_maxPixels = traced * 0.8 * m_stallLimit / milliseconds;
        m_fullFrameMilliseconds = milliseconds;
        return milliseconds > m_stallLimit;
    }
    if (milliseconds > 0.0) {
        // Cost grows with the pixel count, i.e. with scale^2: aim at 80 % of the budget, halfway.
        const float next = scale * float(std::sqrt(0.8 * m_frameBudget / milliseconds));
        m_scale = std::clamp(0.5f * (m_scale + next), kMinimumScale, 1.0f);
    }
    return false;
}

void FrameScaler::startInteraction() {
    if (m_fullFrameMilliseconds > 0.0)
        m_scale = std::clamp(float(std::sqrt(0.8 * m_frameBudget / m_fullFrameMilliseconds)), kMinimumScale, 1.0f);
}

void FrameScaler::seedScale(double estimateMilliseconds) {
    // Half the budget: an estimate from timing frames is rough (moving frames then aim at 0.8 of it).
    if (estimateMilliseconds > 0.0)
        m_scale = std::clamp(float(std::sqrt(0.5 * m_frameBudget / estimateMilliseconds)), kMinimumScale, 1.0f);
}

double FrameScaler::estimateFullFrame(double timingMilliseconds, std::optional<std::pair<float, double>> larger) {
    if (!larger) return timingMilliseconds / double(kTimingScale * kTimingScale);
    // Fixed costs (stretching, synchronisation) cancel in the difference: extrapolate the cost per area.
    const auto [scale, milliseconds] = *larger;
    const double perArea = std::max(0.0, milliseconds - timingMilliseconds) / double(scale * scale - kTimingScale * kTimingScale);
    return timingMilliseconds + perArea * double(1.0f - kTimingScale * kTimingScale);
}

void FrameScaler::capFromEstimate(int width, int height, double estimateMilliseconds) {
    if (estimateMilliseconds > 0.0) m_maxPixels = double(width) * height * 0.8 * m_stallLimit / estimateMilliseconds;
}

} // namespace sdfwb::renderer
