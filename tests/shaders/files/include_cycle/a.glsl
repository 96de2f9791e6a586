#include "b.glsl"
float sdf(vec3 p) { return length(p) - 0.5; }
