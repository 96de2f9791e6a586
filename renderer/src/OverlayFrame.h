#pragma once
// What the viewport's overlays (a mesh, a point cloud) share: their own colour and depth target,
// so they need no depth buffer from the caller, laid over the caller's frame by alpha; and the
// link of a built-in vertex stage with a fragment stage. Private to renderer/; every call needs
// the GL context that was current at the first one.

#include "GlObjects.h"

#include <values/Camera.h>

#include <string>
#include <vector>

namespace sdfwb::renderer {

// Compiles and links the built-in `vertexFile` with a composed fragment stage; diagnostics on failure.
GlProgram buildOverlayProgram(const std::string& vertexFile, const Expected<shaders::ComposedShader>& fragment,
                              std::vector<shaders::Diagnostic>& diagnostics);

// Sets overlay/mesh.vert's camera uniforms: the tracer's pinhole, so what lies on the zero set
// covers the traced surface's pixels exactly.
void setOverlayCamera(GLuint program, const values::Camera& camera, int width, int height);

class OverlayFrame {
public:
    // Remembers the bound draw framebuffer, then binds the overlay's own (width x height),
    // cleared to transparent with depth 1 and the depth test on. False without GL resources.
    bool begin(int width, int height);
    // Back to the remembered framebuffer, with the overlay laid over it where it drew.
    void composite();
    void reset();   // frees the GL names (context current)
    void release(); // forgets them (context gone)

private:
    GlProgram m_composite;
    GlVertexArray m_emptyArray;
    GlFramebuffer m_framebuffer;
    GlTexture m_colour;
    GlRenderbuffer m_depth;
    int m_width = 0, m_height = 0;
    GLint m_target = 0;
};

} // namespace sdfwb::renderer
