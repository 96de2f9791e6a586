#pragma once
// GLSL written in dialects around OpenGL's, read as OpenGL's before a host's shader is adapted
// (ForeignHosts.cpp), with every line kept where it was:
//  - sokol-shdc's annotated files (`@vs NAME ... @end`, `@fs NAME ... @end`, `@block`, `@program`,
//    `@ctype`): the first fragment stage and the blocks it may include are kept, the vertex stages
//    and the annotation lines blanked.
//  - Max/Jitter's shader files (`<jittershader>` XML with `<program type="fragment"><![CDATA[...]]>`):
//    the fragment program's text kept, the XML and the vertex program blanked.
//  - RetroArch's GLSL shaders (libretro's glsl-shaders: both stages in one file, `#if defined(VERTEX)
//    ... #elif defined(FRAGMENT) ... #endif`): the fragment part kept.
//  - Vulkan GLSL (vulkano, ash, wgpu): a `layout(push_constant) uniform Block { ... } name;` is a
//    struct and a global of it (zero: nothing pushes here), `set = N` leaves its layout.
//  - A uniform block without an instance name (`uniform Params { vec2 iResolution; float iTime; };`,
//    sokol's and many engines'): its members become plain uniforms, which the host's adaptation then
//    reads as it reads any uniform (Shadertoy's names and the hosts' become what sdfwb sets).
// Private to shaders/.

#include <string>

namespace sdfwb::shaders::detail {

struct DialectText {
    std::string text;    // the text read as OpenGL's GLSL: the same lines
    std::string dialect; // "Max/Jitter", "sokol-shdc", "Vulkan GLSL", "RetroArch", or empty where nothing was changed
};

DialectText readGlslDialect(const std::string& text);

} // namespace sdfwb::shaders::detail
