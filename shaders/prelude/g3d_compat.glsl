// Compatibility with SDF files written for the original sdf-explorer (G3D shading dialect), and
// Shadertoy's iTime.
// The composer defines SDFWB_COMPAT_<symbol> only for symbols the file uses and does not
// declare itself, so nothing here can collide with a file's own definitions.

#ifdef SDFWB_COMPAT_pi
const float pi = 3.14159265358979323846;
#endif

#ifdef SDFWB_COMPAT_Point3
#define Point3 vec3
#endif
#ifdef SDFWB_COMPAT_Vector3
#define Vector3 vec3
#endif
#ifdef SDFWB_COMPAT_Color3
#define Color3 vec3
#endif
#ifdef SDFWB_COMPAT_Radiance3
#define Radiance3 vec3
#endif
#ifdef SDFWB_COMPAT_float2
#define float2 vec2
#endif
#ifdef SDFWB_COMPAT_float3
#define float3 vec3
#endif
#ifdef SDFWB_COMPAT_float4
#define float4 vec4
#endif

#ifdef SDFWB_COMPAT_lerp
#define lerp mix
#endif
#ifdef SDFWB_COMPAT_frac
#define frac fract
#endif

#ifdef SDFWB_COMPAT_saturate
float saturate(float x) { return clamp(x, 0.0, 1.0); }
vec2 saturate(vec2 x) { return clamp(x, 0.0, 1.0); }
vec3 saturate(vec3 x) { return clamp(x, 0.0, 1.0); }
vec4 saturate(vec4 x) { return clamp(x, 0.0, 1.0); }
#endif

#ifdef SDFWB_COMPAT_square
float square(float x) { return x * x; }
vec2 square(vec2 x) { return x * x; }
vec3 square(vec3 x) { return x * x; }
vec4 square(vec4 x) { return x * x; }
#endif

#ifdef SDFWB_COMPAT_lengthSquared
float lengthSquared(vec2 v) { return dot(v, v); }
float lengthSquared(vec3 v) { return dot(v, v); }
float lengthSquared(vec4 v) { return dot(v, v); }
#endif

// The scene time: the composer declares `uniform float sdfwb_time` before this prelude.
#ifdef SDFWB_COMPAT_g3d_SceneTime
#define g3d_SceneTime sdfwb_time
#endif
// Shadertoy's time uniform, which its code uses without declaring.
#ifdef SDFWB_COMPAT_iTime
#define iTime sdfwb_time
#endif

// A 256 x 256 RGBA texture of independent uniform values in [0, 1], the same on every run
// (renderer/NoiseTexture.h makes it from a hash), repeating, linearly filtered; bound to the
// unit below by the renderer and the sampler runner.
#ifdef SDFWB_COMPAT_g3d_uniformRandom
layout(binding = SDFWB_NOISE_TEXTURE_UNIT) uniform sampler2D g3d_uniformRandom;
#endif
