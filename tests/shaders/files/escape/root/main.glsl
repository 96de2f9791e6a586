// Reaches out of its folder (line 2).
#include "../secret.glsl"
float sdf(vec3 p) { return length(p) - 0.5; }
