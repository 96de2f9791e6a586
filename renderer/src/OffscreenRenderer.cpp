#include <renderer/OffscreenRenderer.h>

#include "GlObjects.h"

#include <cstring>

namespace sdfwb::renderer {

struct OffscreenRenderer::Impl {
    GlFramebuffer framebuffer;
    GlRenderbuffer color;
    int width = 0;
    int height = 0;

    void ensureSize(int w, int h) {
        if (framebuffer && w == width && h == height) return;
        GLuint id = 0;
        glGenRenderbuffers(1, &id);
        color = GlRenderbuffer(id);
        glBindRenderbuffer(GL_RENDERBUFFER, color.id());
        glRenderbufferStorage(GL_RENDERBUFFER, GL_RGBA8, w, h);
        glGenFramebuffers(1, &id);
        framebuffer = GlFramebuffer(id);
        glBindFramebuffer(GL_FRAMEBUFFER, framebuffer.id());
        glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, color.id());
        width = w;
        height = h;
    }
};

OffscreenRenderer::OffscreenRenderer() : m_impl(std::make_unique<Impl>()) {}
OffscreenRenderer::~OffscreenRenderer() = default;

Image OffscreenRenderer::render(SdfRenderer& renderer, int width, int height, const Camera& camera, float time, FrameStats* stats) {
    m_impl->ensureSize(width, height);
    glBindFramebuffer(GL_FRAMEBUFFER, m_impl->framebuffer.id());
    FrameStats frame = renderer.render(width, height, camera, time, true);
    if (stats) *stats = frame;

    Image image;
    image.width = width;
    image.height = height;
    image.rgba.resize(std::size_t(width) * std::size_t(height) * 4);
    std::vector<std::uint8_t> bottomUp(image.rgba.size());
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadPixels(0, 0, width, height, GL_RGBA, GL_UNSIGNED_BYTE, bottomUp.data());
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    const std::size_t rowBytes = std::size_t(width) * 4;
    for (int y = 0; y < height; ++y)
        std::memcpy(image.rgba.data() + std::size_t(y) * rowBytes, bottomUp.data() + std::size_t(height - 1 - y) * rowBytes, rowBytes);
    return image;
}

} // namespace sdfwb::renderer
