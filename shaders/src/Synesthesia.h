#pragma once
// A Synesthesia scene's main.glsl (the Synesthesia Shader Format: `vec4 renderMain()`, no main), read
// in Shadertoy's terms for ForeignHosts.cpp. Private to shaders/.

#include <shaders/Parameters.h>

#include <optional>
#include <string>
#include <vector>

namespace sdfwb::shaders::detail {

// The text with renderMain called from a mainImage added before its first line of code, Synesthesia's inputs
// (TIME, RENDERSIZE, _xy, _uv, _uvc, the mouse's) as Shadertoy's, its audio levels silent (its audio
// clocks the time), its built-in functions that the text uses and does not define (_rotate,
// _smin, _nsin, _hsv2rgb, ...) and PI declared before the first line of code, and `controls`
// (scene.json's, Parameters.cpp: syntax Isf) declared as uniforms there. Every line keeps its
// number. Nothing where the text defines no renderMain, or defines main or mainImage.
std::optional<std::string> adaptSynesthesia(const std::string& text, const std::vector<Parameter>& controls);

} // namespace sdfwb::shaders::detail
