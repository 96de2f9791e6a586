// g3d_shapes.glsl
//
// Shape library in the G3D dialect of the original sdf-explorer: Point3
// arguments, float3/float2 types, lerp/saturate, #ifndef include guard,
// and a nested #include resolved relative to THIS file (lib/), not to
// the file that includes lib/g3d_shapes.glsl. Written for sdfwb's tests.
#ifndef G3D_SHAPES_GLSL
#define G3D_SHAPES_GLSL

#include "g3d_math.glsl"

/** Ball of radius r centred at C. Exact. */
float ballSDF(Point3 X, Point3 C, float r) {
    return length(X - C) - r;
}

/** Axis-aligned box centred at C with half extents h. Exact. */
float boxSDF(Point3 X, Point3 C, Vector3 h) {
    float3 d = abs(X - C) - h;
    return length(max(d, float3(0.0))) + min(maxComponent(d), 0.0);
}

/** Box with rounded edges; h includes the rounding radius r. Exact. */
float roundedBoxSDF(Point3 X, Point3 C, Vector3 h, float r) {
    return boxSDF(X, C, h - float3(r)) - r;
}

/** Capsule from A to B with radius r. Exact. */
float capsuleSDF(Point3 X, Point3 A, Point3 B, float r) {
    Vector3 AB = B - A;
    float t = saturate(dot(X - A, AB) / dot(AB, AB));
    return length(X - lerp(A, B, t)) - r;
}

/** Torus around the y axis through C. Exact. */
float torusSDF(Point3 X, Point3 C, float majorRadius, float minorRadius) {
    Vector3 v = X - C;
    float2 q = float2(length(v.xz) - majorRadius, v.y);
    return length(q) - minorRadius;
}

/** Polynomial smooth minimum (blend width k); 1-Lipschitz like min. */
float smoothUnion(float a, float b, float k) {
    float h = saturate(0.5 + 0.5 * (b - a) / k);
    return lerp(b, a, h) - k * h * (1.0 - h);
}

#endif
