#include <renderer/OffscreenRenderer.h>

#include "GlObjects.h"

#include <cstring>

namespace sdfwb::renderer {

struct OffscreenRenderer::Impl {
    GlFramebuffer framebuffer;
    GlRenderbuffer color;
    int width = 0;
    int height = 0;
    GlFramebuffer floatFramebuffer;
    GlRenderbuffer floatColor;
    int floatWidth = 0;
    int floatHeight = 0;

    void ensureFloatSize(int w, int h) {
        if (floatFramebuffer && w == floatWidth && h == floatHeight) return;
        GLuint id = 0;
        glGenRenderbuffers(1, &id);
        floatColor = GlRenderbuffer(id);
        glBindRenderbuffer(GL_RENDERBUFFER, id);
        glRenderbufferStorage(GL_RENDERBUFFER, GL_RGBA32F, w, h);
        glGenFramebuffers(1, &id);
        floatFramebuffer = GlFramebuffer(id);
        glBindFramebuffer(GL_FRAMEBUFFER, id);
        glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, floatColor.id());
        floatWidth = w;
        floatHeight = h;
    }

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

Image OffscreenRenderer::render(SdfRenderer& renderer, int width, int height, const Camera& camera, float time, FrameStats* stats,
                                float scale) {
    m_impl->ensureSize(width, height);
    glBindFramebuffer(GL_FRAMEBUFFER, m_impl->framebuffer.id());
    FrameStats frame = renderer.renderScaled(width, height, scale, camera, time, true);
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
        std::memcpy(image.rgba.data() + std::size_t(y) * rowBytes, bottomUp.data() + std::size_t(height - 1 - y) * rowBytes,
                    rowBytes);
    return image;
}

std::vector<OffscreenRenderer::PixelStats> OffscreenRenderer::renderStats(SdfRenderer& renderer, int width, int height,
                                                                          const Camera& camera, float time, FrameStats* stats) {
    m_impl->ensureFloatSize(width, height);
    glBindFramebuffer(GL_FRAMEBUFFER, m_impl->floatFramebuffer.id());
    FrameStats frame = renderer.render(width, height, camera, time, true);
    if (stats) *stats = frame;
    std::vector<float> raw(std::size_t(width) * std::size_t(height) * 4);
    glPixelStorei(GL_PACK_ALIGNMENT, 4);
    glReadPixels(0, 0, width, height, GL_RGBA, GL_FLOAT, raw.data());
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    std::vector<PixelStats> out(std::size_t(width) * std::size_t(height));
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            const float* p = raw.data() + (std::size_t(height - 1 - y) * std::size_t(width) + std::size_t(x)) * 4;
            out[std::size_t(y) * std::size_t(width) + std::size_t(x)] = {p[0], p[1], p[2], p[3]};
        }
    return out;
}

} // namespace sdfwb::renderer
