#include <renderer/SampleCompute.h>

#include "GlObjects.h"

#include <core/Log.h>
#include <renderer/SamplingBindings.h>
#include <shaders/DiagnosticParser.h>

#include <chrono>
#include <cmath>

namespace sdfwb::renderer {
namespace {

std::string glErrorName(GLenum error) {
    switch (error) {
    case GL_OUT_OF_MEMORY:
        return "GL_OUT_OF_MEMORY";
    case GL_INVALID_VALUE:
        return "GL_INVALID_VALUE";
    case GL_INVALID_OPERATION:
        return "GL_INVALID_OPERATION";
    case GL_INVALID_ENUM:
        return "GL_INVALID_ENUM";
    default:
        return "GL error " + std::to_string(error);
    }
}

} // namespace

std::uint32_t cubeSide(std::uint64_t count) {
    std::uint64_t n = std::uint64_t(std::cbrt(double(count)));
    while (n * n * n < count) ++n;
    while (n > 1 && (n - 1) * (n - 1) * (n - 1) >= count) --n;
    return std::uint32_t(std::max<std::uint64_t>(n, 1));
}

std::uint32_t squareSide(std::uint64_t count) {
    std::uint64_t n = std::uint64_t(std::sqrt(double(count)));
    while (n * n < count) ++n;
    while (n > 1 && (n - 1) * (n - 1) >= count) --n;
    return std::uint32_t(std::max<std::uint64_t>(n, 1));
}

struct SampleCompute::Impl {
    GlProgram program;
    GlBuffer buffers[3];
    GlBuffer inputs; // caller's points (analysis/points.glsl)
    GlTexture noise; // g3d_uniformRandom, made when the program reads it
    std::uint32_t capacity = 0;
    std::string source;
    GLint location(const char* name) const { return glGetUniformLocation(program.id(), name); }
};

SampleCompute::SampleCompute() : m_impl(std::make_unique<Impl>()) {}

SampleCompute::~SampleCompute() {
    m_impl->program.release();
    for (GlBuffer& buffer : m_impl->buffers) buffer.release();
    m_impl->inputs.release();
    m_impl->noise.release();
}

const std::string& SampleCompute::source() const { return m_impl->source; }

std::vector<shaders::Diagnostic> SampleCompute::build(const shaders::PreparedSdf& sdf, const shaders::ShaderPiece& sampler) {
    std::vector<shaders::Diagnostic> diagnostics = sdf.diagnostics;
    if (shaders::hasErrors(diagnostics)) return diagnostics;
    std::vector<shaders::ShaderPiece> pieces;
    for (const char* file : {"sampling/bindings.glsl", "sampling/common.glsl"}) {
        auto piece = shaders::builtinPiece(file);
        if (!piece) return {{"<sdfwb>", 0, 0, shaders::Severity::Error, piece.error().message}};
        pieces.push_back(std::move(*piece));
    }
    pieces.push_back(sampler);
    auto stage = shaders::builtinPiece("sampling/sample.comp");
    if (!stage) return {{"<sdfwb>", 0, 0, shaders::Severity::Error, stage.error().message}};
    pieces.push_back(std::move(*stage));
    shaders::ComposedShader composed = shaders::composeSdfShader(sdf, shaders::Stage::Compute, pieces, {});

    auto start = std::chrono::steady_clock::now();
    CompiledShader compiled = compileShader(GL_COMPUTE_SHADER, composed);
    diagnostics.insert(diagnostics.end(), compiled.diagnostics.begin(), compiled.diagnostics.end());
    if (shaders::hasErrors(diagnostics)) return diagnostics;
    std::string log;
    GlProgram program = linkProgram({compiled.shader.id()}, log);
    if (!program) {
        diagnostics.push_back({composed.map.fileName(0), 0, 0, shaders::Severity::Error, "link failed: " + log});
        return diagnostics;
    }
    double milliseconds = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    log::info("sampling", "compiled " + sdf.source.map.fileName(0) + " with " + sampler.name + " in " +
                              std::to_string(int(milliseconds)) + " ms");
    m_impl->program = std::move(program);
    m_impl->source = std::move(composed.text);
    return diagnostics;
}

Expected<void> SampleCompute::run(const SampleUniforms& uniforms, std::uint32_t first, std::uint32_t count, float* positions,
                                  float* distances, float* gradients) {
    if (!m_impl->program) return makeError("sampling: no compiled sampler");
    if (count == 0) return {};
    if (count > kMaxChunk)
        return makeError("sampling: chunk of " + std::to_string(count) + " exceeds " + std::to_string(kMaxChunk));
    while (glGetError() != GL_NO_ERROR) {}
    if (count > m_impl->capacity) {
        const GLsizeiptr sizes[3] = {GLsizeiptr(count) * 12, GLsizeiptr(count) * 4, GLsizeiptr(count) * 12};
        for (int i = 0; i < 3; ++i) {
            GLuint id = 0;
            glGenBuffers(1, &id);
            m_impl->buffers[i] = GlBuffer(id);
            glBindBuffer(GL_SHADER_STORAGE_BUFFER, id);
            glBufferData(GL_SHADER_STORAGE_BUFFER, sizes[i], nullptr, GL_DYNAMIC_READ);
        }
        if (GLenum error = glGetError(); error != GL_NO_ERROR) {
            for (GlBuffer& buffer : m_impl->buffers) buffer.reset();
            m_impl->capacity = 0;
            return makeError("sampling: cannot allocate buffers for " + std::to_string(count) + " samples (" +
                             glErrorName(error) + "); try a smaller --chunk");
        }
        m_impl->capacity = count;
    }
    glUseProgram(m_impl->program.id());
    glUniform1ui(m_impl->location("sdfwb_sampleCount"), uniforms.sampleCount);
    glUniform2ui(m_impl->location("sdfwb_seed"), GLuint(uniforms.seed & 0xffffffffu), GLuint(uniforms.seed >> 32));
    glUniform1f(m_impl->location("sdfwb_gradientStep"), uniforms.gradientStep);
    glUniform1ui(m_impl->location("sdfwb_cubeSide"), cubeSide(uniforms.sampleCount));
    glUniform1ui(m_impl->location("sdfwb_squareSide"), squareSide(uniforms.sampleCount));
    if (GLint location = m_impl->location("sdfwb_time"); location >= 0) glUniform1f(location, uniforms.time);
    if (GLint location = m_impl->location("g3d_SceneTime"); location >= 0)
        glUniform1f(location, uniforms.time); // declared by the file
    bindNoiseTextureIfUsed(m_impl->program.id(), m_impl->noise);
    if (GLint location = m_impl->location("sdfwb_parameters"); location >= 0) glUniform4fv(location, 4, uniforms.parameters);
    if (GLint location = m_impl->location("sdfwb_surfaceTolerance"); location >= 0)
        glUniform1f(location, uniforms.surfaceTolerance);
    if (GLint location = m_impl->location("sdfwb_tetrahedralGradient"); location >= 0)
        glUniform1i(location, uniforms.tetrahedralGradient ? 1 : 0);
    applyParameters(uniforms.sdfParameters, [this](const char* name) { return m_impl->location(name); });
    // A null target is not wanted: the shader skips it (the gradient's six evaluations included).
    if (GLint location = m_impl->location("sdfwb_writePosition"); location >= 0) glUniform1i(location, positions ? 1 : 0);
    if (GLint location = m_impl->location("sdfwb_writeGradient"); location >= 0) glUniform1i(location, gradients ? 1 : 0);
    glUniform1ui(m_impl->location("sdfwb_chunkFirst"), first);
    glUniform1ui(m_impl->location("sdfwb_chunkCount"), count);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kBindingPositions, m_impl->buffers[0].id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kBindingDistances, m_impl->buffers[1].id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kBindingGradients, m_impl->buffers[2].id());
    if (uniforms.inputPoints) {
        if (!m_impl->inputs) {
            GLuint id = 0;
            glGenBuffers(1, &id);
            m_impl->inputs = GlBuffer(id);
        }
        glBindBuffer(GL_SHADER_STORAGE_BUFFER, m_impl->inputs.id());
        if (uniforms.inputTableFloats > 0)
            glBufferData(GL_SHADER_STORAGE_BUFFER, GLsizeiptr(uniforms.inputTableFloats * sizeof(float)), uniforms.inputPoints,
                         GL_STREAM_DRAW);
        else
            glBufferData(GL_SHADER_STORAGE_BUFFER, GLsizeiptr(count) * 12, uniforms.inputPoints + 3 * std::size_t(first),
                         GL_STREAM_DRAW);
        glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kBindingInputs, m_impl->inputs.id());
    }
    glDispatchCompute((count + 63u) / 64u, 1, 1);
    glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
    float* targets[3] = {positions, distances, gradients};
    const GLsizeiptr sizes[3] = {GLsizeiptr(count) * 12, GLsizeiptr(count) * 4, GLsizeiptr(count) * 12};
    for (int i = 0; i < 3; ++i) {
        if (!targets[i]) continue;
        glBindBuffer(GL_SHADER_STORAGE_BUFFER, m_impl->buffers[i].id());
        glGetBufferSubData(GL_SHADER_STORAGE_BUFFER, 0, sizes[i], targets[i]);
    }
    glBindBuffer(GL_SHADER_STORAGE_BUFFER, 0);
    glUseProgram(0);
    if (GLenum error = glGetError(); error != GL_NO_ERROR)
        return makeError("sampling: dispatch of " + std::to_string(count) + " samples failed (" + glErrorName(error) +
                         "); try a smaller --chunk");
    return {};
}

void SampleCompute::releaseGl() {
    m_impl->program.reset();
    for (GlBuffer& buffer : m_impl->buffers) buffer.reset();
    m_impl->inputs.reset();
    m_impl->noise.reset();
    m_impl->capacity = 0;
}

} // namespace sdfwb::renderer
