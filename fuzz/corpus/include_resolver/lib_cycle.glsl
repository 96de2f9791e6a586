#include "f1.glsl"
float sdf(const vec3 p) { return 0.0; }
%%
#include "f2.glsl"
%%
#include "f1.glsl"
