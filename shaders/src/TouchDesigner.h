#pragma once
// A TouchDesigner GLSL TOP pixel shader (its `void main()` writes `out vec4 fragColor` through
// TDOutputSwizzle, reads vUV and uTDOutputInfo, which TouchDesigner declares): what TouchDesigner
// provides, in Shadertoy's terms, for ForeignHosts.cpp after its adaptMain. Private to shaders/.

#include "TextEdits.h"

#include <string>
#include <vector>

namespace sdfwb::shaders::detail {

// The edits that give a pixel shader TouchDesigner's built-ins it uses: TDOutputSwizzle (the
// colour as it is: an RGBA output), TDDither (no dither), TDHSVToRGB and TDRGBToHSV, declared on
// its first line of code; vUV the pixel over the frame (its z 0) and uTDOutputInfo's res (1/w,
// 1/h, w, h) from iResolution. None where the text uses none of them or declares vUV itself.
std::vector<Edit> touchDesignerEdits(const std::string& stripped);

} // namespace sdfwb::shaders::detail
