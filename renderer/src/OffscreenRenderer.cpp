#include <renderer/OffscreenRenderer.h>

#include "GlObjects.h"

#include <algorithm>
#include <cstring>

namespace sdfwb::renderer {
namespace {

// The bound framebuffer's RGBA pixels, top row first (GL rows run bottom up).
template <class T> std::vector<T> readTopDown(int width, int height, GLenum type) {
    const std::size_t row = std::size_t(width) * 4;
    std::vector<T> bottomUp(row * std::size_t(height)), topDown(bottomUp.size());
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadPixels(0, 0, width, height, GL_RGBA, type, bottomUp.data());
    glPixelStorei(GL_PACK_ALIGNMENT, 4);
    for (int y = 0; y < height; ++y)
        std::memcpy(topDown.data() + std::size_t(y) * row, bottomUp.data() + std::size_t(height - 1 - y) * row, row * sizeof(T));
    return topDown;
}

} // namespace

struct OffscreenRenderer::Impl {
    // Textures, not renderbuffers: the compute tracer stores into them directly.
    GlFramebuffer framebuffer;
    GlTexture color;
    int width = 0;
    int height = 0;
    GlFramebuffer floatFramebuffer;
    GlTexture floatColor;
    int floatWidth = 0;
    int floatHeight = 0;

    void ensureFloatSize(int w, int h) {
        if (floatFramebuffer && w == floatWidth && h == floatHeight) return;
        makeColorTarget(w, h, GL_NEAREST, floatColor, floatFramebuffer, GL_RGBA32F);
        floatWidth = w;
        floatHeight = h;
    }

    void ensureSize(int w, int h) {
        if (framebuffer && w == width && h == height) return;
        makeColorTarget(w, h, GL_NEAREST, color, framebuffer);
        width = w;
        height = h;
    }
};

OffscreenRenderer::OffscreenRenderer() : m_impl(std::make_unique<Impl>()) {}
OffscreenRenderer::~OffscreenRenderer() = default;

Image OffscreenRenderer::render(SdfRenderer& renderer, int width, int height, const values::Camera& camera, float time,
                                FrameStats* stats, float scale) {
    m_impl->ensureSize(width, height);
    glBindFramebuffer(GL_FRAMEBUFFER, m_impl->framebuffer.id());
    FrameStats frame = renderer.renderScaled(width, height, scale, camera, time, true);
    if (stats) *stats = frame;

    Image image{width, height, readTopDown<std::uint8_t>(width, height, GL_UNSIGNED_BYTE), {}};
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    return image;
}

Image OffscreenRenderer::renderPicture(ShadertoyPicture& picture, int width, int height, const ShadertoyInputs& inputs) {
    m_impl->ensureSize(width, height);
    glBindFramebuffer(GL_FRAMEBUFFER, m_impl->framebuffer.id());
    (void)picture.render(width, height, inputs, true);
    Image image{width, height, readTopDown<std::uint8_t>(width, height, GL_UNSIGNED_BYTE), {}};
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    return image;
}

FloatImage OffscreenRenderer::renderFloat(SdfRenderer& renderer, int width, int height, const values::Camera& camera, float time,
                                          FrameStats* stats) {
    m_impl->ensureFloatSize(width, height);
    glBindFramebuffer(GL_FRAMEBUFFER, m_impl->floatFramebuffer.id());
    FrameStats frame = renderer.render(width, height, camera, time, true);
    if (stats) *stats = frame;
    FloatImage image{width, height, readTopDown<float>(width, height, GL_FLOAT), {}};
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    return image;
}

std::vector<OffscreenRenderer::PixelStats> OffscreenRenderer::renderStats(SdfRenderer& renderer, int width, int height,
                                                                          const values::Camera& camera, float time,
                                                                          FrameStats* stats) {
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

// The probe's storage binding point, tracer/probe.glsl's SDFWB_BINDING_PROBE.
constexpr GLuint kBindingProbe = 4;

OffscreenRenderer::ProbeTrace OffscreenRenderer::probe(SdfRenderer& renderer, int width, int height, const values::Camera& camera,
                                                       float time, int x, int y, int capacity) {
    ProbeTrace trace;
    m_impl->ensureFloatSize(width, height);
    GLuint id = 0;
    glGenBuffers(1, &id);
    GlBuffer buffer(id);
    const std::size_t bytes = 16 + std::size_t(capacity) * 32;
    std::vector<std::uint8_t> zeros(bytes, 0);
    glBindBuffer(GL_SHADER_STORAGE_BUFFER, id);
    glBufferData(GL_SHADER_STORAGE_BUFFER, GLsizeiptr(bytes), zeros.data(), GL_DYNAMIC_READ);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kBindingProbe, id);
    glBindFramebuffer(GL_FRAMEBUFFER, m_impl->floatFramebuffer.id());
    // One fragment: the pixel's, in GL's bottom-up rows.
    const int row = height - 1 - y;
    glEnable(GL_SCISSOR_TEST);
    glScissor(x, row, 1, 1);
    renderer.render(width, height, camera, time, true);
    glDisable(GL_SCISSOR_TEST);
    float pixel[4] = {0, 0, 0, 0};
    glPixelStorei(GL_PACK_ALIGNMENT, 4);
    glReadPixels(x, row, 1, 1, GL_RGBA, GL_FLOAT, pixel);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    trace.pixel = {pixel[0], pixel[1], pixel[2], pixel[3]};
    glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
    std::vector<float> rows(bytes / 4);
    glGetBufferSubData(GL_SHADER_STORAGE_BUFFER, 0, GLsizeiptr(bytes), rows.data());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kBindingProbe, 0);
    glBindBuffer(GL_SHADER_STORAGE_BUFFER, 0);
    std::uint32_t count = 0;
    std::memcpy(&count, rows.data(), sizeof count);
    const std::uint32_t kept = std::min<std::uint32_t>(count, std::uint32_t(capacity));
    trace.dropped = count - kept;
    for (std::uint32_t k = 0; k < kept; ++k) {
        const float* r = rows.data() + 4 + std::size_t(k) * 8;
        trace.events.push_back({ProbeEvent::Kind(int(r[0])), r[1], r[2], r[3], {r[4], r[5], r[6]}});
    }
    return trace;
}

} // namespace sdfwb::renderer
