// Common
// ------
// The "Common" tab of a multi-tab Shadertoy, as its author keeps it: code
// Shadertoy prepends to every pass (Image, Buffer A..D, Sound), so it may
// not use the per-pass inputs (iTime, iResolution, iChannel0, ...). Hash
// functions, a rotation matrix, a few distance functions and operators,
// shared by the passes.
//
// Written for sdfwb's tests (tests/foreign/39_st_common_tab.glsl includes it
// as `#include "lib/shadertoy_common.glsl"`); a library, not an SDF: no
// sdf()/map() here.

#define PI 3.14159265359
#define TAU 6.28318530718

const float EPSILON = 0.0005;

// ---- hashes (no sin(): same answer on every GPU) ---------------------------

float hash11(float p)
{
    p = fract(p * 0.1319);
    p *= p + 41.27;
    p *= p + p;
    return fract(p);
}

float hash12(vec2 p)
{
    vec3 q = fract(vec3(p.xyx) * 0.1319);
    q += dot(q, q.yzx + 27.73);
    return fract((q.x + q.y) * q.z);
}

vec2 hash22(vec2 p)
{
    vec3 q = fract(vec3(p.xyx) * vec3(0.1319, 0.1211, 0.1093));
    q += dot(q, q.yzx + 27.73);
    return fract((q.xx + q.yz) * q.zy);
}

vec3 hash31(float p)
{
    vec3 q = fract(vec3(p) * vec3(0.1319, 0.1211, 0.1093));
    q += dot(q, q.yzx + 27.73);
    return fract((q.xxy + q.yzz) * q.zyx);
}

// ---- transforms ------------------------------------------------------------

mat2 rot2D(float a)
{
    float s = sin(a), c = cos(a);
    return mat2(c, s, -s, c);
}

// ---- distances -------------------------------------------------------------

float sdSphere(vec3 p, float r)
{
    return length(p) - r;
}

float sdBox(vec3 p, vec3 b)
{
    vec3 q = abs(p) - b;
    return length(max(q, 0.0)) + min(max(q.x, max(q.y, q.z)), 0.0);
}

float sdRoundBox(vec3 p, vec3 b, float r)
{
    return sdBox(p, b - r) - r;
}

float sdCapsule(vec3 p, vec3 a, vec3 b, float r)
{
    vec3 pa = p - a, ba = b - a;
    float h = clamp(dot(pa, ba) / dot(ba, ba), 0.0, 1.0);
    return length(pa - ba * h) - r;
}

// ---- operators -------------------------------------------------------------

// polynomial smooth minimum; k is the blend width
float opSmoothUnion(float d1, float d2, float k)
{
    float h = clamp(0.5 + 0.5 * (d2 - d1) / k, 0.0, 1.0);
    return mix(d2, d1, h) - k * h * (1.0 - h);
}

float opSmoothSubtraction(float d1, float d2, float k)
{
    return -opSmoothUnion(-d2, d1, k);
}

// ---- colour ----------------------------------------------------------------

vec3 palette(float t, vec3 a, vec3 b, vec3 c, vec3 d)
{
    return a + b * cos(TAU * (c * t + d));
}
