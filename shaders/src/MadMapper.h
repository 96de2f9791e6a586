#pragma once
// A MadMapper material (`/*{ "RESOURCE_TYPE": "Material For MadMapper", "INPUTS": [...],
// "GENERATORS": [...] }*/`, then `vec4 materialColorForPixel(vec2 texCoord)`): its header's INPUTS
// are ISF's (ForeignHosts.cpp's adaptIsf declares them), its GENERATORS globals (a time_base the
// time, others zero), its `#include "MadCommon.glsl"` the PI it gives, its vertex stage's outputs (`flat in vec3 vro;`) plain
// globals (zero), and a mainImage that calls materialColorForPixel with the pixel over the frame. Private to shaders/.

#include "TextEdits.h"

#include <string>
#include <vector>

namespace sdfwb::shaders::detail {

// The edits of `text` (`stripped`: with comments blanked); none where the text is no material.
std::vector<Edit> madMapperEdits(const std::string& text, const std::string& stripped);

} // namespace sdfwb::shaders::detail
