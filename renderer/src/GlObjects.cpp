#include "GlObjects.h"

#include <core/Log.h>
#include <renderer/GlInfo.h>
#include <shaders/DiagnosticParser.h>
#include <shaders/LoopLimits.h>

#include <algorithm>
#include <atomic>
#include <cstdio>
#include <mutex>
#include <set>

#include <string>

namespace sdfwb::renderer {

namespace {
std::atomic<long> g_liveObjects{0};
}

void countGlObject(int delta) { g_liveObjects += delta; }
long liveGlObjects() { return g_liveObjects.load(); }

void logGlErrors(const char* where) {
    for (int i = 0; i < 8; ++i) { // a lost context can report errors forever: stop after a few
        GLenum error = glGetError();
        if (error == GL_NO_ERROR) return;
        char text[96];
        std::snprintf(text, sizeof text, "GL error 0x%04X after %s", unsigned(error), where);
        log::error("gl", text);
    }
}

GlTexture makeColorTexture(int width, int height, GLenum filter, GLenum format) {
    GLuint id = 0;
    glGenTextures(1, &id);
    glBindTexture(GL_TEXTURE_2D, id);
    glTexImage2D(GL_TEXTURE_2D, 0, format, width, height, 0, GL_RGBA, GL_UNSIGNED_BYTE, nullptr);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, filter);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, filter);
    glBindTexture(GL_TEXTURE_2D, 0);
    return GlTexture(id);
}

void makeColorTarget(int width, int height, GLenum filter, GlTexture& texture, GlFramebuffer& framebuffer, GLenum format) {
    texture = makeColorTexture(width, height, filter, format);
    GLuint id = 0;
    glGenFramebuffers(1, &id);
    framebuffer = GlFramebuffer(id);
    glBindFramebuffer(GL_FRAMEBUFFER, id);
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, texture.id(), 0);
}

void deleteProgram(GLuint id) { glDeleteProgram(id); }
void deleteShader(GLuint id) { glDeleteShader(id); }
void deleteVertexArray(GLuint id) { glDeleteVertexArrays(1, &id); }
void deleteFramebuffer(GLuint id) { glDeleteFramebuffers(1, &id); }
void deleteRenderbuffer(GLuint id) { glDeleteRenderbuffers(1, &id); }
void deleteTexture(GLuint id) { glDeleteTextures(1, &id); }
void deleteBuffer(GLuint id) { glDeleteBuffers(1, &id); }
void deleteProgramPipeline(GLuint id) { glDeleteProgramPipelines(1, &id); }
void deleteQuery(GLuint id) { glDeleteQueries(1, &id); }

GlProgram linkProgram(std::initializer_list<GLuint> shaders, std::string& log, bool separable) {
    GlProgram program(glCreateProgram());
    if (separable) glProgramParameteri(program.id(), GL_PROGRAM_SEPARABLE, GL_TRUE);
    for (GLuint shader : shaders) glAttachShader(program.id(), shader);
    glLinkProgram(program.id());
    GLint linked = 0;
    glGetProgramiv(program.id(), GL_LINK_STATUS, &linked);
    if (linked) return program;
    GLint length = 0;
    glGetProgramiv(program.id(), GL_INFO_LOG_LENGTH, &length);
    log.assign(std::size_t(std::max(length, 1)), '\0');
    glGetProgramInfoLog(program.id(), length, nullptr, log.data());
    return {};
}

CompiledShader compileShader(GLenum type, const shaders::ComposedShader& composed) {
    CompiledShader result;
    result.shader = GlShader(glCreateShader(type));
    const char* text = composed.text.c_str();
    const GLint length = GLint(composed.text.size()); // all of it: a NUL byte in a comment does not end the code
    glShaderSource(result.shader.id(), 1, &text, &length);
    glCompileShader(result.shader.id());
    GLint status = 0, logLength = 0;
    glGetShaderiv(result.shader.id(), GL_COMPILE_STATUS, &status);
    glGetShaderiv(result.shader.id(), GL_INFO_LOG_LENGTH, &logLength);
    if (logLength > 1) {
        std::string log(std::size_t(logLength), '\0');
        glGetShaderInfoLog(result.shader.id(), logLength, nullptr, log.data());
        result.diagnostics = shaders::parseInfoLog(log, composed.map);
        if (!status && !shaders::hasErrors(result.diagnostics))
            result.diagnostics.push_back({composed.map.fileName(0), 0, 0, shaders::Severity::Error, "driver: " + log});
    } else if (!status) {
        result.diagnostics.push_back(
            {composed.map.fileName(0), 0, 0, shaders::Severity::Error,
             std::string("driver rejected the ") + shaders::stageName(composed.stage) + " shader without a message"});
    }
    return result;
}

std::vector<shaders::Diagnostic> driverLoopWarnings(const shaders::PreparedSdf& sdf, const shaders::ComposedShader& composed) {
    const char* rendererName = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
    const std::string name = rendererName ? rendererName : "";
    const std::uint64_t limit = shaders::loopLimitOf(name);
    shaders::setDriverLoopLimit(limit);
    std::vector<shaders::Diagnostic> warnings = shaders::findLongLoops(sdf, composed, limit, "Mesa's llvmpipe");
    static std::mutex mutex;
    static std::set<std::string> logged;
    std::lock_guard lock(mutex);
    for (const shaders::Diagnostic& warning : warnings) {
        const std::string text = shaders::formatDiagnostic(warning);
        if (logged.insert(text).second) log::warning("shaders", text);
    }
    return warnings;
}

} // namespace sdfwb::renderer
