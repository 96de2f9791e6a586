// g3d_math.glsl
//
// Helpers in the G3D shading dialect of the original sdf-explorer
// (Point3/Vector3/float3, pi, saturate, lerp, square provided by the
// host, include guards, no #version). Written for sdfwb's tests.
// Included by lib/g3d_shapes.glsl (next to this file) and directly by
// some tests; the guard makes the second inclusion empty.
#ifndef G3D_MATH_GLSL
#define G3D_MATH_GLSL

/** Rotates v about the y axis by angle radians. */
Vector3 rotateY(Vector3 v, float angle) {
    float c = cos(angle), s = sin(angle);
    return Vector3(c * v.x + s * v.z, v.y, c * v.z - s * v.x);
}

/** Rotates v about the x axis by angle radians. */
Vector3 rotateX(Vector3 v, float angle) {
    float c = cos(angle), s = sin(angle);
    return Vector3(v.x, c * v.y - s * v.z, s * v.y + c * v.z);
}

/** Converts degrees to radians. */
float radians2(float degrees) {
    return degrees * (pi / 180.0);
}

/** Largest component. */
float maxComponent(float3 v) {
    return max(v.x, max(v.y, v.z));
}

#endif
