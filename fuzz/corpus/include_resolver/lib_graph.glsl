#include "f1.glsl"
#include "f2.glsl"
float sdf(vec3 p) { return f1(p) + f2(p); }
%%
#pragma once
#include "f3.glsl"
float f1(vec3 p) { return f3(p) * saturate(p.x); }
%%
#include "f3.glsl"
#include "f4.glsl"
float f2(Point3 p) { return length(p) - pi; }
%%
#pragma once
float f3(vec3 p) { return lerp(p.x, p.y, 0.5); }
%%
#include "f1.glsl"
float3 f4v;
