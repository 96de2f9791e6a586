#pragma once
// WebGL (Shadertoy, twigl, GLSL Sandbox, three.js) gives a variable declared without a value zero,
// and golfed shaders count on it (`float i, d; vec3 p; p.z -= 4.;`, `for (float i, g; ...)`); desktop
// GL leaves it undefined (Mesa's llvmpipe reads what the register held). Private to shaders/.

#include <string>

namespace sdfwb::shaders::detail {

// `text` (comments kept) with `= T(0)` written after each scalar, vector or matrix variable declared
// without a value in a function: locals and a for loop's own; an array declared alone (`vec4 c[3];`)
// zeroed by a loop after it. Not globals (zero already), a struct's members, parameters, structs, or
// anything with a qualifier (const). Every line keeps its number.
std::string zeroInitialised(const std::string& text);

} // namespace sdfwb::shaders::detail
