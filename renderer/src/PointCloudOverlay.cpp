#include <renderer/PointCloudOverlay.h>

#include "OverlayFrame.h"

#include <core/Log.h>

#include <algorithm>
#include <cmath>

namespace sdfwb::renderer {

struct PointCloudOverlay::Impl {
    GlProgram program;
    GlVertexArray array;
    GlBuffer buffer; // interleaved position, gradient
    OverlayFrame frame;
    std::vector<float> pending; // 6 floats per drawn point, kept for uploads after releaseGl
    bool uploaded = false;
};

PointCloudOverlay::PointCloudOverlay() : m_impl(std::make_unique<Impl>()) {}

PointCloudOverlay::~PointCloudOverlay() {
    // GL names cannot be freed without the context; the owner calls releaseGl() first.
    m_impl->program.release();
    m_impl->array.release();
    m_impl->buffer.release();
    m_impl->frame.release();
}

void PointCloudOverlay::setPoints(const std::vector<float>& positions, const std::vector<float>& gradients) {
    std::vector<float>& out = m_impl->pending;
    out.clear();
    const std::size_t n = positions.size() / 3;
    out.reserve(n * 6);
    for (std::size_t i = 0; i < n; ++i) {
        const float* p = positions.data() + 3 * i;
        if (!std::isfinite(p[0]) || !std::isfinite(p[1]) || !std::isfinite(p[2])) continue;
        const float* g = 3 * i + 2 < gradients.size() ? gradients.data() + 3 * i : nullptr;
        const bool finite = g && std::isfinite(g[0]) && std::isfinite(g[1]) && std::isfinite(g[2]);
        out.insert(out.end(), {p[0], p[1], p[2], finite ? g[0] : 0.0f, finite ? g[1] : 0.0f, finite ? g[2] : 0.0f});
    }
    m_impl->uploaded = false;
}

void PointCloudOverlay::clear() { setPoints({}, {}); }

bool PointCloudOverlay::hasPoints() const { return !m_impl->pending.empty(); }

std::uint64_t PointCloudOverlay::pointCount() const { return m_impl->pending.size() / 6; }

void PointCloudOverlay::draw(int width, int height, const values::Camera& camera, float pointSize) {
    Impl& d = *m_impl;
    if (d.pending.empty() || width <= 0 || height <= 0) return;
    if (!d.program) {
        std::vector<shaders::Diagnostic> diagnostics;
        d.program = buildOverlayProgram(
            "overlay/mesh.vert", shaders::composeBuiltinShader(shaders::Stage::Fragment, "overlay/points.frag", {}), diagnostics);
        if (!d.program) {
            for (const auto& diagnostic : diagnostics)
                log::warning("render", "point cloud: " + shaders::formatDiagnostic(diagnostic));
            return;
        }
    }
    if (!d.uploaded) {
        GLuint id = 0;
        if (!d.array) {
            glGenVertexArrays(1, &id);
            d.array = GlVertexArray(id);
            glGenBuffers(1, &id);
            d.buffer = GlBuffer(id);
        }
        glBindVertexArray(d.array.id());
        glBindBuffer(GL_ARRAY_BUFFER, d.buffer.id());
        glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(d.pending.size() * sizeof(float)), d.pending.data(), GL_STATIC_DRAW);
        glEnableVertexAttribArray(0);
        glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, 6 * sizeof(float), nullptr);
        glEnableVertexAttribArray(1);
        glVertexAttribPointer(1, 3, GL_FLOAT, GL_FALSE, 6 * sizeof(float), reinterpret_cast<const void*>(3 * sizeof(float)));
        glBindVertexArray(0);
        d.uploaded = true;
    }
    if (!d.frame.begin(width, height)) return;
    glEnable(GL_PROGRAM_POINT_SIZE);
    glUseProgram(d.program.id());
    setOverlayCamera(d.program.id(), camera, width, height);
    glUniform1f(glGetUniformLocation(d.program.id(), "sdfwb_pointSize"), std::clamp(pointSize, 1.0f, 64.0f));
    glBindVertexArray(d.array.id());
    glDrawArrays(GL_POINTS, 0, GLsizei(d.pending.size() / 6));
    glBindVertexArray(0);
    glDisable(GL_PROGRAM_POINT_SIZE);
    d.frame.composite();
}

void PointCloudOverlay::releaseGl() {
    m_impl->program.reset();
    m_impl->array.reset();
    m_impl->buffer.reset();
    m_impl->frame.reset();
    m_impl->uploaded = false;
}

} // namespace sdfwb::renderer
