#pragma once
// What the current GL context is. Query with a context current.

#include <core/Expected.h>

#include <string>

namespace sdfwb::renderer {

struct GlInfo {
    std::string vendor;
    std::string renderer;
    std::string version;     // GL_VERSION string
    std::string glslVersion; // GL_SHADING_LANGUAGE_VERSION
    int major = 0;
    int minor = 0;
    bool coreProfile = false;
    bool computeShaders = false;      // GL 4.3 or ARB_compute_shader, and a non-zero work group limit
    int maxComputeWorkGroupCount = 0; // in X
};

// Needs a current context (loaded through libepoxy).
GlInfo queryGlInfo();

// Fails with a message that names what is missing when the context is below GL 4.3 or lacks
// compute shaders: "renderer: OpenGL 4.3 core is required ...".
Expected<void> requireGl43(const GlInfo& info);

// "llvmpipe (LLVM 15.0.6, 256 bits) / Mesa / 4.5 (Core Profile) Mesa 22.3.6"
std::string describe(const GlInfo& info);

// Whether the current context runs on the CPU (Mesa's llvmpipe or softpipe): its draws and
// dispatches run when they are flushed, and its timer queries end before the work they time.
bool softwareRasteriser();

// GL objects (programs, shaders, buffers, textures, framebuffers, vertex arrays) the renderer
// holds right now, over all contexts: a count that keeps growing is a leak.
long liveGlObjects();

// Logs every pending glGetError() as an error in category "gl", naming `where`.
void logGlErrors(const char* where);

} // namespace sdfwb::renderer
