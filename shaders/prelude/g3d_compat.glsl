// Compatibility with SDF files written for the original sdf-explorer (G3D shading dialect), and
// Shadertoy's inputs and GLSL ES idioms (whole Shadertoy shaders open unmodified).
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
// Where the file's own macro wraps the name (`#define iTime (iTime - 25. + mx)`), the name it
// wraps must be a variable: a uniform the renderer sets to the same time.
#if defined(SDFWB_COMPAT_g3d_SceneTime) && defined(SDFWB_COMPAT_WRAPPED_g3d_SceneTime)
uniform float g3d_SceneTime;
#elif defined(SDFWB_COMPAT_g3d_SceneTime)
#define g3d_SceneTime sdfwb_time
#endif
// Shadertoy's time uniform, which its code uses without declaring.
#if defined(SDFWB_COMPAT_iTime) && defined(SDFWB_COMPAT_WRAPPED_iTime)
uniform float iTime;
#elif defined(SDFWB_COMPAT_iTime)
#define iTime sdfwb_time
#endif

// A 256 x 256 RGBA texture of independent uniform values in [0, 1], the same on every run
// (renderer/NoiseTexture.h makes it from a hash), repeating, linearly filtered; bound to the
// unit below by the renderer and the sampler runner.
#ifdef SDFWB_COMPAT_g3d_uniformRandom
layout(binding = SDFWB_NOISE_TEXTURE_UNIT) uniform sampler2D g3d_uniformRandom;
#endif

// Shadertoy's inputs, declared under their Shadertoy names and types when a file (a whole shader
// pasted from shadertoy.com) uses them without declaring them. The values are fixed, so the
// field sdfwb traces is the field it samples: a 640 x 360 frame, the mouse never pressed, frame 0
// at 60 frames a second, a fixed date. The Shadertoy picture (renderer/ShadertoyPicture.h) sets
// the frame's own values. Time is sdfwb's scene time (iTime above).
#ifdef SDFWB_COMPAT_iResolution
uniform vec3 iResolution = vec3(640.0, 360.0, 1.0);
#endif
#ifdef SDFWB_COMPAT_iTimeDelta
uniform float iTimeDelta = 1.0 / 60.0;
#endif
#ifdef SDFWB_COMPAT_iFrame
uniform int iFrame = 0;
#endif
#ifdef SDFWB_COMPAT_iFrameRate
uniform float iFrameRate = 60.0;
#endif
#ifdef SDFWB_COMPAT_iMouse
uniform vec4 iMouse = vec4(0.0);
#endif
#ifdef SDFWB_COMPAT_iDate
uniform vec4 iDate = vec4(2026.0, 0.0, 1.0, 43200.0); // year, month - 1, day, seconds since midnight
#endif
#ifdef SDFWB_COMPAT_iSampleRate
uniform float iSampleRate = 44100.0;
#endif
#ifdef SDFWB_COMPAT_iChannelTime
uniform float iChannelTime[4] = float[4](0.0, 0.0, 0.0, 0.0);
#endif
#ifdef SDFWB_COMPAT_iChannelResolution
uniform vec3 iChannelResolution[4] = vec3[4](vec3(256.0, 256.0, 1.0), vec3(256.0, 256.0, 1.0), vec3(256.0, 256.0, 1.0),
                                             vec3(256.0, 256.0, 1.0));
#endif
// Channels: the G3D noise texels (256 x 256 RGBA uniform values, repeating,
// linearly filtered, with green and alpha the red and blue channels moved by (37, 17) texels like
// Shadertoy's "RGBA noise" textures: renderer/NoiseTexture.h), or an image the user picked
// (--channel N=FILE, the GUI's Shadertoy channels); a channel read with a direction is a cube map
// with that image on each face (SDFWB_COMPAT_CUBE_iChannelN). Bound to unit SDFWB_CHANNELN_UNIT (GLSL 4.30
// takes a literal binding, not an expression).
#if defined(SDFWB_COMPAT_CUBE_iChannel0)
layout(binding = SDFWB_CHANNEL0_UNIT) uniform samplerCube iChannel0;
#elif defined(SDFWB_COMPAT_iChannel0)
layout(binding = SDFWB_CHANNEL0_UNIT) uniform sampler2D iChannel0;
#endif
#if defined(SDFWB_COMPAT_CUBE_iChannel1)
layout(binding = SDFWB_CHANNEL1_UNIT) uniform samplerCube iChannel1;
#elif defined(SDFWB_COMPAT_iChannel1)
layout(binding = SDFWB_CHANNEL1_UNIT) uniform sampler2D iChannel1;
#endif
#if defined(SDFWB_COMPAT_CUBE_iChannel2)
layout(binding = SDFWB_CHANNEL2_UNIT) uniform samplerCube iChannel2;
#elif defined(SDFWB_COMPAT_iChannel2)
layout(binding = SDFWB_CHANNEL2_UNIT) uniform sampler2D iChannel2;
#endif
#if defined(SDFWB_COMPAT_CUBE_iChannel3)
layout(binding = SDFWB_CHANNEL3_UNIT) uniform samplerCube iChannel3;
#elif defined(SDFWB_COMPAT_iChannel3)
layout(binding = SDFWB_CHANNEL3_UNIT) uniform sampler2D iChannel3;
#endif
// Shadertoy defines this (1 on desktop GPUs) for `#if HW_PERFORMANCE == 0` quality switches.
#ifdef SDFWB_COMPAT_HW_PERFORMANCE
#define HW_PERFORMANCE 1
#endif

// GLSL ES 1.0's texture functions, which Shadertoy still accepts.
#ifdef SDFWB_COMPAT_texture2D
#define texture2D texture
#endif
#ifdef SDFWB_COMPAT_texture2DLod
#define texture2DLod textureLod
#endif
#ifdef SDFWB_COMPAT_textureCube
#define textureCube texture
#endif
#ifdef SDFWB_COMPAT_textureCubeLod
#define textureCubeLod textureLod
#endif

// Derivatives outside a fragment shader (the composer defines these only there): zero, as for a
// constant. Only uncalled code (a Shadertoy's mainImage) should reach them.
// The pixel's position outside a fragment shader (the composer renames the code's gl_FragCoord,
// a name no macro may take): the origin.
#ifdef SDFWB_COMPAT_gl_FragCoord
const vec4 sdfwb_FragCoord = vec4(0.0, 0.0, 0.0, 1.0);
#endif
// discard exists in fragment shaders only (the composer renames it elsewhere, a keyword no macro
// may take): a statement that does nothing, in the mainImage no other stage calls.
#ifdef SDFWB_COMPAT_discard
void sdfwb_discard() {}
#endif
// texture()'s bias form exists in fragment shaders only; elsewhere the composer renames the code's
// three-argument texture, texture2D and textureCube calls to these (overloading texture itself
// would hide its built-in forms on Mesa): the level-0 lookup, what texture() does there anyway.
#ifdef SDFWB_COMPAT_texture
vec4 sdfwb_textureBias(sampler2D s, vec2 uv, float bias) { return textureLod(s, uv, 0.0); }
vec4 sdfwb_textureBias(sampler3D s, vec3 uvw, float bias) { return textureLod(s, uvw, 0.0); }
vec4 sdfwb_textureBias(samplerCube s, vec3 direction, float bias) { return textureLod(s, direction, 0.0); }
#endif
#ifdef SDFWB_COMPAT_dFdx
#define dFdx(x) ((x) - (x))
#endif
#ifdef SDFWB_COMPAT_dFdy
#define dFdy(x) ((x) - (x))
#endif
#ifdef SDFWB_COMPAT_fwidth
#define fwidth(x) ((x) - (x))
#endif
