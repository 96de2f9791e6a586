#include <renderer/MeshOverlay.h>

#include "OverlayFrame.h"

#include <shaders/ShaderComposer.h>

#include <algorithm>
#include <cmath>
#include <optional>
#include <string>

namespace sdfwb::renderer {
struct MeshOverlay::Impl {
    GlProgram mesh;
    GlVertexArray meshArray;
    GlBuffer positions, indices;
    OverlayFrame frame;
    SdfTextures textures;
    std::optional<shaders::PreparedSdf> sdf; // the last good one (rebuilt after releaseGl)
    std::uint64_t indexCount = 0;
    std::vector<float> pendingPositions; // kept until a draw has the context (and after releaseGl)
    std::vector<std::uint32_t> pendingIndices;
    bool uploaded = false;

    GLint location(const char* name) const { return glGetUniformLocation(mesh.id(), name); }

    void upload() {
        if (!meshArray) {
            GLuint id = 0;
            glGenVertexArrays(1, &id);
            meshArray = GlVertexArray(id);
            glGenBuffers(1, &id);
            positions = GlBuffer(id);
            glGenBuffers(1, &id);
            indices = GlBuffer(id);
        }
        glBindVertexArray(meshArray.id());
        glBindBuffer(GL_ARRAY_BUFFER, positions.id());
        glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(pendingPositions.size() * sizeof(float)), pendingPositions.data(),
                     GL_STATIC_DRAW);
        glEnableVertexAttribArray(0);
        glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, 3 * sizeof(float), nullptr);
        glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, indices.id());
        glBufferData(GL_ELEMENT_ARRAY_BUFFER, GLsizeiptr(pendingIndices.size() * sizeof(std::uint32_t)), pendingIndices.data(),
                     GL_STATIC_DRAW);
        glBindVertexArray(0);
        indexCount = pendingIndices.size();
        uploaded = true;
    }
};

MeshOverlay::MeshOverlay() : m_impl(std::make_unique<Impl>()) {}

MeshOverlay::~MeshOverlay() {
    // GL names cannot be freed without the context; the owner calls releaseGl() first.
    m_impl->mesh.release();
    m_impl->meshArray.release();
    for (auto* name : {&m_impl->positions, &m_impl->indices}) name->release();
    m_impl->textures.release();
    m_impl->frame.release();
}

std::vector<shaders::Diagnostic> MeshOverlay::setSdf(const shaders::PreparedSdf& sdf) {
    std::vector<shaders::Diagnostic> diagnostics = sdf.diagnostics;
    if (shaders::hasErrors(diagnostics)) return diagnostics;
    GlProgram program = buildOverlayProgram(
        "overlay/mesh.vert", shaders::composeSdfShader(sdf, shaders::Stage::Fragment, "overlay/mesh_deviation.frag", {}),
        diagnostics);
    if (program) {
        m_impl->mesh = std::move(program);
        m_impl->sdf = sdf;
    }
    return diagnostics;
}

void MeshOverlay::setMesh(const std::vector<float>& positions, const std::vector<std::uint32_t>& indices) {
    m_impl->pendingPositions = positions;
    m_impl->pendingIndices = indices;
    m_impl->uploaded = false;
}

void MeshOverlay::clearMesh() { setMesh({}, {}); }

bool MeshOverlay::hasMesh() const { return !m_impl->pendingIndices.empty(); }

std::uint64_t MeshOverlay::triangleCount() const { return m_impl->pendingIndices.size() / 3; }

void MeshOverlay::draw(int width, int height, const values::Camera& camera, float time,
                       const std::vector<shaders::ParameterSetting>& parameters, float scale) {
    Impl& d = *m_impl;
    if (!d.mesh && d.sdf) (void)setSdf(*d.sdf); // after releaseGl() (a new context)
    if (!d.mesh || d.pendingIndices.empty() || width <= 0 || height <= 0) return;
    if (!d.uploaded) d.upload();
    // 1. The mesh alone, with its own depth test, into the overlay's frame.
    if (!d.frame.begin(width, height)) return;
    glUseProgram(d.mesh.id());
    setOverlayCamera(d.mesh.id(), camera, width, height);
    glUniform1f(d.location("sdfwb_deviationScale"), scale > 0.0f ? scale : 1e-3f);
    if (GLint location = d.location("sdfwb_time"); location >= 0) glUniform1f(location, time);
    for (const char* name : {"g3d_SceneTime", "iTime"}) // uniforms where the file's macro wraps them
        if (GLint location = d.location(name); location >= 0) glUniform1f(location, time);
    bindSdfTextures(d.mesh.id(), d.textures, d.sdf ? d.sdf->channels : decltype(d.sdf->channels){},
                    d.sdf ? d.sdf->mesh : nullptr);
    applyParameters(parameters, [&d](const char* name) { return d.location(name); });
    glBindVertexArray(d.meshArray.id());
    glDrawElements(GL_TRIANGLES, GLsizei(d.indexCount), GL_UNSIGNED_INT, nullptr);
    glBindVertexArray(0);
    // 2. Over the caller's frame, where the mesh was drawn.
    d.frame.composite();
}

void MeshOverlay::releaseGl() {
    Impl& d = *m_impl;
    d.mesh.reset();
    d.meshArray.reset();
    for (auto* name : {&d.positions, &d.indices}) name->reset();
    d.textures.reset();
    d.frame.reset();
    d.uploaded = false;
}

} // namespace sdfwb::renderer
