#pragma once
// Renders into an offscreen framebuffer and reads the pixels back: screenshots, MP4 frames,
// headless renders. Needs a current GL context for every call, including destruction.

#include <renderer/Camera.h>
#include <renderer/Image.h>
#include <renderer/SdfRenderer.h>

#include <memory>
#include <vector>

namespace sdfwb::renderer {

class OffscreenRenderer {
public:
    OffscreenRenderer();
    ~OffscreenRenderer();
    OffscreenRenderer(const OffscreenRenderer&) = delete;
    OffscreenRenderer& operator=(const OffscreenRenderer&) = delete;

    // Renders one frame at width x height and returns it (top row first). scale < 1 traces fewer
    // pixels and stretches them, as the viewport does while the camera moves.
    Image render(SdfRenderer& renderer, int width, int height, const Camera& camera, float time, FrameStats* stats = nullptr,
                 float scale = 1.0f);

    // Per-pixel tracing statistics (the renderer's shading must have statsOutput on): for each
    // pixel, top row first, {steps, hit distance t, |f| at the hit, length of the shading normal}.
    // A miss has t < 0 telling why: kLeftBox, kOutOfSteps or kNotFinite.
    struct PixelStats {
        float steps, t, residual, normalLength;
        static constexpr float kLeftBox = -1.0f;    // passed through the box: nothing there
        static constexpr float kOutOfSteps = -2.0f; // the step budget ran out
        static constexpr float kNotFinite = -3.0f;  // f was NaN or Inf along the ray
        bool hit() const { return t >= 0.0f; }
    };
    std::vector<PixelStats> renderStats(SdfRenderer& renderer, int width, int height, const Camera& camera, float time,
                                        FrameStats* stats = nullptr);

private:
    struct Impl;
    std::unique_ptr<Impl> m_impl;
};

} // namespace sdfwb::renderer
