#pragma once
// Which function a whole shader marches by, read from glslang's syntax tree: a pasted Shadertoy's
// distance function is called Map, GetDist, sceneDist, field or anything else, but its own ray
// marcher says which one it is. A loop in a function that mainImage's call graph reaches calls a
// user function of a vec3, and a variable the call's point depends on (t in `ro + rd * t`, or the
// point itself) grows by the call's result or its .x (`t += d`, `dO += dS`, `p += rd * h.x`). An
// AO or glow loop, whose accumulator the point does not depend on, does not count.

#include <shaders/ShaderComposer.h>

#include <string>
#include <vector>

namespace sdfwb::shaders {

struct MarchedFunction {
    std::string name; // the function's name
    std::string file; // where its first march call is (the composed map's file name)
    int line = 0;     // that call's line
    int loops = 0;    // loops that step by it
    // A struct return: the struct's name and the float member the march reads (the distance).
    std::string returnType;
    std::string member;
};

// The functions `composed` (a fragment stage holding the user's code and mainImage; no main is
// needed) marches by, in the order of their first march call; empty when the text does not parse
// or has no mainImage.
std::vector<MarchedFunction> marchedFunctions(const ComposedShader& composed);

} // namespace sdfwb::shaders
