float sdf(vec3 p) { return length(p) - 0.5; }
#include "does_not_exist.glsl"
