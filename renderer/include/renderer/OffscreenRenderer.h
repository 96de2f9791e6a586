#pragma once
// Renders into an offscreen framebuffer and reads the pixels back: screenshots, MP4 frames,
// headless renders. Needs a current GL context for every call, including destruction.

#include <renderer/Camera.h>
#include <renderer/Image.h>
#include <renderer/SdfRenderer.h>

#include <memory>

namespace sdfwb::renderer {

class OffscreenRenderer {
public:
    OffscreenRenderer();
    ~OffscreenRenderer();
    OffscreenRenderer(const OffscreenRenderer&) = delete;
    OffscreenRenderer& operator=(const OffscreenRenderer&) = delete;

    // Renders one frame of `sdf` at width x height and returns it (top row first).
    Image render(SdfRenderer& renderer, int width, int height, const Camera& camera, float time, FrameStats* stats = nullptr);

private:
    struct Impl;
    std::unique_ptr<Impl> m_impl;
};

} // namespace sdfwb::renderer
