#include <renderer/MeshOverlay.h>

#include "GlObjects.h"

#include <shaders/ShaderComposer.h>

#include <glm/trigonometric.hpp>

#include <algorithm>
#include <cmath>
#include <optional>
#include <string>

namespace sdfwb::renderer {
namespace {

// Compiles and links a built-in vertex stage with a composed fragment stage.
GlProgram buildProgram(const std::string& vertexFile, const Expected<shaders::ComposedShader>& fragment,
                       std::vector<shaders::Diagnostic>& diagnostics) {
    const Expected<shaders::ComposedShader> vertex = shaders::composeBuiltinShader(shaders::Stage::Vertex, vertexFile, {});
    for (const Expected<shaders::ComposedShader>* composed : {&vertex, &fragment})
        if (!*composed) {
            diagnostics.push_back({"<sdfwb>", 0, 0, shaders::Severity::Error, composed->error().message});
            return {};
        }
    CompiledShader vs = compileShader(GL_VERTEX_SHADER, *vertex);
    CompiledShader fs = compileShader(GL_FRAGMENT_SHADER, *fragment);
    diagnostics.insert(diagnostics.end(), vs.diagnostics.begin(), vs.diagnostics.end());
    diagnostics.insert(diagnostics.end(), fs.diagnostics.begin(), fs.diagnostics.end());
    if (shaders::hasErrors(diagnostics)) return {};
    std::string log;
    GlProgram program = linkProgram({vs.shader.id(), fs.shader.id()}, log);
    if (!program)
        diagnostics.push_back({fragment->map.fileName(0), 0, 0, shaders::Severity::Error, "mesh overlay: link failed: " + log});
    return program;
}

} // namespace

struct MeshOverlay::Impl {
    GlProgram mesh, composite;
    GlVertexArray meshArray, emptyArray;
    GlBuffer positions, indices;
    GlFramebuffer framebuffer;
    GlTexture colour;
    GlRenderbuffer depth;
    GlTexture noise;
    std::optional<shaders::PreparedSdf> sdf; // the last good one (rebuilt after releaseGl)
    int frameWidth = 0, frameHeight = 0;
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

    void resizeFrame(int width, int height) {
        if (framebuffer && width == frameWidth && height == frameHeight) return;
        GLuint id = 0;
        if (!framebuffer) {
            glGenFramebuffers(1, &id);
            framebuffer = GlFramebuffer(id);
        }
        glGenTextures(1, &id);
        colour = GlTexture(id);
        glBindTexture(GL_TEXTURE_2D, id);
        glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, width, height, 0, GL_RGBA, GL_UNSIGNED_BYTE, nullptr);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
        glGenRenderbuffers(1, &id);
        depth = GlRenderbuffer(id);
        glBindRenderbuffer(GL_RENDERBUFFER, id);
        glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH_COMPONENT24, width, height);
        glBindFramebuffer(GL_FRAMEBUFFER, framebuffer.id());
        glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, colour.id(), 0);
        glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, depth.id());
        frameWidth = width;
        frameHeight = height;
    }
};

MeshOverlay::MeshOverlay() : m_impl(std::make_unique<Impl>()) {}

MeshOverlay::~MeshOverlay() {
    // GL names cannot be freed without the context; the owner calls releaseGl() first.
    for (auto* name : {&m_impl->mesh, &m_impl->composite}) name->release();
    for (auto* name : {&m_impl->meshArray, &m_impl->emptyArray}) name->release();
    for (auto* name : {&m_impl->positions, &m_impl->indices}) name->release();
    for (auto* name : {&m_impl->colour, &m_impl->noise}) name->release();
    m_impl->framebuffer.release();
    m_impl->depth.release();
}

std::vector<shaders::Diagnostic> MeshOverlay::setSdf(const shaders::PreparedSdf& sdf) {
    std::vector<shaders::Diagnostic> diagnostics = sdf.diagnostics;
    if (shaders::hasErrors(diagnostics)) return diagnostics;
    GlProgram program =
        buildProgram("overlay/mesh.vert",
                     shaders::composeSdfShader(sdf, shaders::Stage::Fragment, "overlay/mesh_deviation.frag", {}), diagnostics);
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

void MeshOverlay::draw(int width, int height, const Camera& camera, float time,
                       const std::vector<shaders::ParameterSetting>& parameters, float scale) {
    Impl& d = *m_impl;
    if (!d.mesh && d.sdf) (void)setSdf(*d.sdf); // after releaseGl() (a new context)
    if (!d.mesh || d.pendingIndices.empty() || width <= 0 || height <= 0) return;
    if (!d.composite) {
        std::vector<shaders::Diagnostic> ignored;
        d.composite =
            buildProgram("tracer/fullscreen.vert",
                         shaders::composeBuiltinShader(shaders::Stage::Fragment, "overlay/composite.frag", {}), ignored);
        if (!d.composite) return;
        GLuint id = 0;
        glGenVertexArrays(1, &id);
        d.emptyArray = GlVertexArray(id);
    }
    if (!d.uploaded) d.upload();
    GLint target = 0;
    glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &target);
    d.resizeFrame(width, height);

    // 1. The mesh alone, with its own depth test, into the overlay's frame.
    glBindFramebuffer(GL_FRAMEBUFFER, d.framebuffer.id());
    glViewport(0, 0, width, height);
    glClearColor(0.0f, 0.0f, 0.0f, 0.0f);
    glClearDepth(1.0);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glDisable(GL_CULL_FACE);
    glDisable(GL_BLEND);
    glUseProgram(d.mesh.id());
    const CameraBasis basis = cameraBasis(camera);
    glUniform3fv(d.location("sdfwb_cameraPosition"), 1, &camera.position.x);
    glUniform3fv(d.location("sdfwb_cameraRight"), 1, &basis.right.x);
    glUniform3fv(d.location("sdfwb_cameraUp"), 1, &basis.up.x);
    glUniform3fv(d.location("sdfwb_cameraForward"), 1, &basis.forward.x);
    glUniform1f(d.location("sdfwb_tanHalfFovY"), std::tan(glm::radians(camera.fovYDegrees) * 0.5f));
    glUniform1f(d.location("sdfwb_aspect"), float(width) / float(height));
    glUniform1f(d.location("sdfwb_nearPlane"), camera.nearPlane);
    glUniform1f(d.location("sdfwb_farPlane"), camera.farPlane);
    glUniform1f(d.location("sdfwb_deviationScale"), scale > 0.0f ? scale : 1e-3f);
    if (GLint location = d.location("sdfwb_time"); location >= 0) glUniform1f(location, time);
    if (GLint location = d.location("g3d_SceneTime"); location >= 0) glUniform1f(location, time);
    bindNoiseTextureIfUsed(d.mesh.id(), d.noise);
    applyParameters(parameters, [&d](const char* name) { return d.location(name); });
    glBindVertexArray(d.meshArray.id());
    glDrawElements(GL_TRIANGLES, GLsizei(d.indexCount), GL_UNSIGNED_INT, nullptr);
    glDisable(GL_DEPTH_TEST);

    // 2. Over the caller's frame, where the mesh was drawn.
    glBindFramebuffer(GL_FRAMEBUFFER, GLuint(target));
    glViewport(0, 0, width, height);
    glEnable(GL_BLEND);
    glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    glUseProgram(d.composite.id());
    glActiveTexture(GL_TEXTURE0);
    glBindTexture(GL_TEXTURE_2D, d.colour.id());
    glUniform1i(glGetUniformLocation(d.composite.id(), "sdfwb_overlayFrame"), 0);
    glBindVertexArray(d.emptyArray.id());
    glDrawArrays(GL_TRIANGLES, 0, 3);
    glBindVertexArray(0);
    glDisable(GL_BLEND);
    glUseProgram(0);
}

void MeshOverlay::releaseGl() {
    Impl& d = *m_impl;
    for (auto* name : {&d.mesh, &d.composite}) name->reset();
    for (auto* name : {&d.meshArray, &d.emptyArray}) name->reset();
    for (auto* name : {&d.positions, &d.indices}) name->reset();
    for (auto* name : {&d.colour, &d.noise}) name->reset();
    d.framebuffer.reset();
    d.depth.reset();
    d.frameWidth = d.frameHeight = 0;
    d.uploaded = false;
}

} // namespace sdfwb::renderer
