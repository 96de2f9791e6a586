#pragma once
// Whole shaders written for other hosts than Shadertoy, read in sdfwb's terms with every line kept
// where it was (diagnostics keep their line numbers):
//  - A `void main()` fragment shader (glslViewer and The Book of Shaders, GLSL Sandbox, Bonzomatic,
//    KodeLife, three.js, a WebGL page): main becomes Shadertoy's mainImage, gl_FragColor (or the file's one
//    `out vec4`) its colour and gl_FragCoord in it its coordinate, so the march analysis finds the
//    field as in a Shadertoy. The host's inputs (u_time, time, fGlobalTime, u_resolution,
//    resolution, v2Resolution, u_mouse, mouse, uTime, ...) become Shadertoy's, which sdfwb sets; a
//    file's own declarations of Shadertoy's inputs go (sdfwb declares and sets them); varyings and
//    input blocks become plain globals; a host's textures sdfwb has no image for read an empty unit. A file with
//    mainImage and a main() that only calls it (a port's wrapper) loses the wrapper.
//  - A Fragmentarium fragment: its directives (#info, #group, #camera, #preset blocks, ...) and the
//    annotations after its uniforms (slider[...], read by Parameters.h) are blanked, each such
//    uniform gets its default as an initializer, its system includes (DE-Raytracer.frag,
//    MathUtils.frag, ...) become what the code uses of them (orbitTrap, rotationMatrix3, time),
//    and its init() runs before the field.

#include <shaders/Parameters.h>

#include <string>
#include <vector>

namespace sdfwb::shaders::detail {

struct HostAdaptation {
    std::string text;         // the text to read instead of the original: the same lines
    std::string host;         // the host recognised ("glslViewer", "Fragmentarium", ...); empty: none
    std::string entryPrelude; // statements the entry wrapper runs before calling the field ("init();")
};

// Texture units no texture is bound to: a host's textures sdfwb has no image for read (0, 0, 0, 1)
// there, one unit a sampler type (a program may not give one unit two types); -1 for others.
inline int emptyUnit(const std::string& samplerType) {
    if (samplerType == "sampler1D") return 12;
    if (samplerType == "sampler2D") return 13;
    if (samplerType == "sampler3D") return 14;
    if (samplerType == "samplerCube") return 15;
    return -1;
}

// `parameters`: parseParameters(text)'s (Fragmentarium's defaults become initializers).
HostAdaptation adaptForeignHost(const std::string& text, const std::vector<Parameter>& parameters);

} // namespace sdfwb::shaders::detail
