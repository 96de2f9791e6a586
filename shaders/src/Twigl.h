#pragma once
// A twigl.app shader in its geeker or geekest mode: the text is the body of main (no function of its
// own), reading `FC` (gl_FragCoord), `r` (the resolution), `t` (the time) and writing `o` (the colour),
// with twigl's helpers rotate2D, rotate3D and hsv. Read for ForeignHosts.cpp. Private to shaders/.

#include <optional>
#include <string>

namespace sdfwb::shaders::detail {

// The text inside a mainImage that declares twigl's inputs in Shadertoy's terms, the helpers it
// calls before it (all on the first line), and the closing brace after its last code (same lines).
// Nothing where the text defines a function, reads no `FC`, writes no `o` or ends in a directive.
std::optional<std::string> adaptTwigl(const std::string& text);

} // namespace sdfwb::shaders::detail
