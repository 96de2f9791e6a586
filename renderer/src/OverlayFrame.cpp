#include "OverlayFrame.h"

#include <glm/trigonometric.hpp>

#include <cmath>

namespace sdfwb::renderer {

GlProgram buildOverlayProgram(const std::string& vertexFile, const Expected<shaders::ComposedShader>& fragment,
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
        diagnostics.push_back({fragment->map.fileName(0), 0, 0, shaders::Severity::Error, "overlay: link failed: " + log});
    return program;
}

void setOverlayCamera(GLuint program, const values::Camera& camera, int width, int height) {
    auto location = [program](const char* name) { return glGetUniformLocation(program, name); };
    const values::CameraBasis basis = cameraBasis(camera);
    glUniform3fv(location("sdfwb_cameraPosition"), 1, &camera.position.x);
    glUniform3fv(location("sdfwb_cameraRight"), 1, &basis.right.x);
    glUniform3fv(location("sdfwb_cameraUp"), 1, &basis.up.x);
    glUniform3fv(location("sdfwb_cameraForward"), 1, &basis.forward.x);
    glUniform1f(location("sdfwb_tanHalfFovY"), std::tan(glm::radians(camera.fovYDegrees) * 0.5f));
    glUniform1f(location("sdfwb_aspect"), float(width) / float(height));
    glUniform1f(location("sdfwb_nearPlane"), camera.nearPlane);
    glUniform1f(location("sdfwb_farPlane"), camera.farPlane);
}

bool OverlayFrame::begin(int width, int height) {
    if (!m_composite) {
        std::vector<shaders::Diagnostic> ignored;
        m_composite =
            buildOverlayProgram("tracer/fullscreen.vert",
                                shaders::composeBuiltinShader(shaders::Stage::Fragment, "overlay/composite.frag", {}), ignored);
        if (!m_composite) return false;
        GLuint id = 0;
        glGenVertexArrays(1, &id);
        m_emptyArray = GlVertexArray(id);
    }
    glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &m_target);
    if (!m_framebuffer || width != m_width || height != m_height) {
        GLuint id = 0;
        if (!m_framebuffer) {
            glGenFramebuffers(1, &id);
            m_framebuffer = GlFramebuffer(id);
        }
        glGenTextures(1, &id);
        m_colour = GlTexture(id);
        glBindTexture(GL_TEXTURE_2D, id);
        glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, width, height, 0, GL_RGBA, GL_UNSIGNED_BYTE, nullptr);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
        glGenRenderbuffers(1, &id);
        m_depth = GlRenderbuffer(id);
        glBindRenderbuffer(GL_RENDERBUFFER, id);
        glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH_COMPONENT24, width, height);
        glBindFramebuffer(GL_FRAMEBUFFER, m_framebuffer.id());
        glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, m_colour.id(), 0);
        glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, m_depth.id());
        m_width = width;
        m_height = height;
    }
    glBindFramebuffer(GL_FRAMEBUFFER, m_framebuffer.id());
    glViewport(0, 0, width, height);
    glClearColor(0.0f, 0.0f, 0.0f, 0.0f);
    glClearDepth(1.0);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glDisable(GL_CULL_FACE);
    glDisable(GL_BLEND);
    return true;
}

void OverlayFrame::composite() {
    glDisable(GL_DEPTH_TEST);
    glBindFramebuffer(GL_FRAMEBUFFER, GLuint(m_target));
    glViewport(0, 0, m_width, m_height);
    glEnable(GL_BLEND);
    glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    glUseProgram(m_composite.id());
    glActiveTexture(GL_TEXTURE0);
    glBindTexture(GL_TEXTURE_2D, m_colour.id());
    glUniform1i(glGetUniformLocation(m_composite.id(), "sdfwb_overlayFrame"), 0);
    glBindVertexArray(m_emptyArray.id());
    glDrawArrays(GL_TRIANGLES, 0, 3);
    glBindVertexArray(0);
    glDisable(GL_BLEND);
    glUseProgram(0);
}

void OverlayFrame::reset() {
    m_composite.reset();
    m_emptyArray.reset();
    m_framebuffer.reset();
    m_colour.reset();
    m_depth.reset();
    m_width = m_height = 0;
}

void OverlayFrame::release() {
    m_composite.release();
    m_emptyArray.release();
    m_framebuffer.release();
    m_colour.release();
    m_depth.release();
}

} // namespace sdfwb::renderer
