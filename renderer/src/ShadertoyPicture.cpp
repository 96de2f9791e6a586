#include <renderer/ShadertoyPicture.h>

#include "GlObjects.h"

#include <shaders/ShaderComposer.h>

#include <array>
#include <chrono>
#include <optional>
#include <string>

namespace sdfwb::renderer {

struct ShadertoyPicture::Impl {
    GlProgram program;
    GlVertexArray vertexArray;
    SdfTextures textures;
    std::array<std::string, shaders::kShadertoyChannels> channels;
    std::shared_ptr<const meshfield::MeshField> mesh;
    std::vector<shaders::ParameterSetting> parameters;
    GLint location(const char* name) const { return glGetUniformLocation(program.id(), name); }
};

ShadertoyPicture::ShadertoyPicture() : m_impl(std::make_unique<Impl>()) {}

ShadertoyPicture::~ShadertoyPicture() {
    // GL names cannot be freed without the context; the owner calls releaseGl() first.
    m_impl->program.release();
    m_impl->vertexArray.release();
    m_impl->textures.release();
}

std::vector<shaders::Diagnostic> ShadertoyPicture::setSdf(const shaders::PreparedSdf& sdf) {
    std::vector<shaders::Diagnostic> diagnostics = sdf.diagnostics;
    if (shaders::hasErrors(diagnostics)) return diagnostics;
    if (!sdf.shadertoyMainImage) {
        diagnostics.push_back({sdf.source.map.fileName(0), 1, 1, shaders::Severity::Error,
                               "no Shadertoy picture here: the file defines no `void mainImage(out vec4 fragColor, in vec2 "
                               "fragCoord)`"});
        return diagnostics;
    }
    auto picture = shaders::builtinPiece("shadertoy/picture.frag");
    auto vertex = shaders::composeBuiltinShader(shaders::Stage::Vertex, "tracer/fullscreen.vert", {});
    if (!picture || !vertex) return {{"<sdfwb>", 0, 0, shaders::Severity::Error, "built-in shaders missing"}};
    shaders::ComposedShader fragment = shaders::composeSdfShader(sdf, shaders::Stage::Fragment, {*picture}, {});
    CompiledShader compiledVertex = compileShader(GL_VERTEX_SHADER, *vertex);
    CompiledShader compiledFragment = compileShader(GL_FRAGMENT_SHADER, fragment);
    for (auto* compiled : {&compiledVertex, &compiledFragment})
        diagnostics.insert(diagnostics.end(), compiled->diagnostics.begin(), compiled->diagnostics.end());
    if (shaders::hasErrors(diagnostics)) return diagnostics;
    for (shaders::Diagnostic& warning : driverLoopWarnings(sdf, fragment)) diagnostics.push_back(std::move(warning));
    std::string log;
    GlProgram program = linkProgram({compiledVertex.shader.id(), compiledFragment.shader.id()}, log);
    if (!program) {
        diagnostics.push_back({fragment.map.fileName(0), 0, 0, shaders::Severity::Error, "link failed: " + log});
        return diagnostics;
    }
    m_impl->program = std::move(program);
    m_impl->channels = sdf.channels;
    m_impl->mesh = sdf.mesh;
    return diagnostics;
}

void ShadertoyPicture::setParameters(std::vector<shaders::ParameterSetting> parameters) {
    m_impl->parameters = std::move(parameters);
}

bool ShadertoyPicture::hasProgram() const { return bool(m_impl->program); }

double ShadertoyPicture::render(int width, int height, const ShadertoyInputs& inputs, bool finish) {
    const auto start = std::chrono::steady_clock::now();
    draw(width, height, inputs);
    if (finish) glFinish();
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

void ShadertoyPicture::draw(int width, int height, const ShadertoyInputs& inputs) {
    Impl& d = *m_impl;
    glViewport(0, 0, width, height);
    if (!d.program) {
        glClearColor(0.0f, 0.0f, 0.0f, 1.0f);
        glClear(GL_COLOR_BUFFER_BIT);
        return;
    }
    if (!d.vertexArray) {
        GLuint id = 0;
        glGenVertexArrays(1, &id);
        d.vertexArray = GlVertexArray(id);
    }
    glUseProgram(d.program.id());
    if (GLint at = d.location("iResolution"); at >= 0) glUniform3f(at, float(width), float(height), 1.0f);
    for (const char* name : {"sdfwb_time", "g3d_SceneTime", "iTime"}) // the last two: uniforms where a macro wraps them
        if (GLint at = d.location(name); at >= 0) glUniform1f(at, inputs.time);
    if (GLint at = d.location("iTimeDelta"); at >= 0) glUniform1f(at, inputs.timeDelta);
    if (GLint at = d.location("iFrameRate"); at >= 0) glUniform1f(at, inputs.timeDelta > 0.0f ? 1.0f / inputs.timeDelta : 60.0f);
    if (GLint at = d.location("iFrame"); at >= 0) glUniform1i(at, inputs.frame);
    if (GLint at = d.location("iMouse"); at >= 0) glUniform4f(at, inputs.mouse.x, inputs.mouse.y, inputs.mouse.z, inputs.mouse.w);
    if (GLint at = d.location("iDate"); at >= 0) glUniform4f(at, inputs.date.x, inputs.date.y, inputs.date.z, inputs.date.w);
    bindSdfTextures(d.program.id(), d.textures, d.channels, d.mesh);
    applyParameters(d.parameters, [&d](const char* name) { return d.location(name); });
    glDisable(GL_DEPTH_TEST);
    glDisable(GL_BLEND);
    glBindVertexArray(d.vertexArray.id());
    glDrawArrays(GL_TRIANGLES, 0, 3);
    glBindVertexArray(0);
    glUseProgram(0);
}

void ShadertoyPicture::releaseGl() {
    m_impl->program.reset();
    m_impl->vertexArray.reset();
    m_impl->textures.reset();
}

} // namespace sdfwb::renderer
