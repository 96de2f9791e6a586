#include <renderer/GlInfo.h>

#include <shaders/LoopLimits.h>

#include <epoxy/gl.h>

#include <cstring>

namespace sdfwb::renderer {
namespace {

std::string glString(GLenum name) {
    const GLubyte* text = glGetString(name);
    return text ? reinterpret_cast<const char*>(text) : "";
}

} // namespace

GlInfo queryGlInfo() {
    GlInfo info;
    info.vendor = glString(GL_VENDOR);
    info.renderer = glString(GL_RENDERER);
    info.version = glString(GL_VERSION);
    info.glslVersion = glString(GL_SHADING_LANGUAGE_VERSION);
    int version = epoxy_gl_version(); // e.g. 45
    info.major = version / 10;
    info.minor = version % 10;
    if (version >= 32) {
        GLint mask = 0;
        glGetIntegerv(GL_CONTEXT_PROFILE_MASK, &mask);
        info.coreProfile = (mask & GL_CONTEXT_CORE_PROFILE_BIT) != 0;
    }
    if (version >= 43 || epoxy_has_gl_extension("GL_ARB_compute_shader")) {
        GLint count = 0;
        glGetIntegeri_v(GL_MAX_COMPUTE_WORK_GROUP_COUNT, 0, &count);
        info.maxComputeWorkGroupCount = count;
        info.computeShaders = count > 0;
    }
    while (glGetError() != GL_NO_ERROR) {}
    // The driver's loop limit, for the editor's checks (shaders/LoopLimits.h: llvmpipe's 65535).
    shaders::setDriverLoopLimit(shaders::loopLimitOf(info.renderer));
    return info;
}

Expected<void> requireGl43(const GlInfo& info) {
    if (info.major * 10 + info.minor < 43)
        return makeError("renderer: OpenGL 4.3 core is required (compute shaders, SSBOs), but this context is " + info.version +
                         " on " + info.renderer + " (" + info.vendor + ")");
    if (!info.computeShaders)
        return makeError("renderer: compute shaders are not available on " + info.renderer + " (" + info.version + ")");
    return {};
}

std::string describe(const GlInfo& info) {
    return info.renderer + " / " + info.vendor + " / " + info.version + (info.coreProfile ? " [core]" : "") + " / GLSL " +
           info.glslVersion + (info.computeShaders ? " / compute" : " / no compute");
}

bool softwareRasteriser() {
    const char* name = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
    return name && (std::strstr(name, "llvmpipe") || std::strstr(name, "softpipe"));
}

} // namespace sdfwb::renderer
