#include "f1.glsl"
float sdf(vec3 p) { return length(p) - 1.0; }
%%
// sdfwb modelling helpers: building blocks shared by the modelled objects of the dataset
// (Animal, Nature, Manufactured, Vehicle, Misc). Include with #include "../lib/modelling.glsl".
//
// Every function here returns either an exact signed distance or a conservative bound
// (|gradient| <= 1 and never larger than the true distance); each comment says which.
#pragma once
#include "primitives.glsl"

const float MODEL_PI = 3.14159265358979;
const float MODEL_TAU = 6.28318530717959;

// ---------------------------------------------------------------------------------------------
// Coordinate helpers (rigid motions keep distances exact)

// Rotates v counter-clockwise by angle a (radians).
vec2 rotate2(vec2 v, float a) {
    float c = cos(a), s = sin(a);
    return vec2(c * v.x - s * v.y, s * v.x + c * v.y);
}

// ---------------------------------------------------------------------------------------------
// Blends (all are bounds: smooth minimum of two 1-Lipschitz fields is 1-Lipschitz because its
// gradient is a convex combination h*grad(a) + (1-h)*grad(b)).

float smoothMin(float a, float b, float k) { return opSmoothUnion(a, b, k); }
float smoothMax(float a, float b, float k) { return -opSmoothUnion(-a, -b, k); }
// Carves b out of a with a rounded seam.
float smoothSubtract(float a, float b, float k) { return smoothMax(a, -b, k); }

// Skips an expensive part while the point is well away from its bounding volume. `bound` must
// be a lower bound of the part's distance (e.g. the distance to a sphere that contains it).
// max(bound, min(part, margin)) equals `bound` beyond the margin, so the lazy version below is
// continuous, 1-Lipschitz and never exceeds the part's own distance.
#define BOUNDED_PART(bound, margin, part) \
    ((bound) > (margin) ? (bound) : max((bound), min((part), (margin))))

// ---------------------------------------------------------------------------------------------
// 2D exact distances

float sdSegment2(vec2 p, vec2 a, vec2 b) {
    vec2 pa = p - a, ba = b - a;
    float h = clamp(dot(pa, ba) / dot(ba, ba), 0.0, 1.0);
    return length(pa - ba * h);
}

float sdBox2(vec2 p, vec2 halfSize) {
    vec2 q = abs(p) - halfSize;
    return length(max(q, 0.0)) + min(max(q.x, q.y), 0.0);
}

float sdRoundBox2(vec2 p, vec2 halfSize, float radius) { return sdBox2(p, halfSize - radius) - radius; }

// Extrudes an exact 2D distance d2 along an axis coordinate z to half thickness h (exact).
float opExtrude(float d2, float z, float h) {
    vec2 w = vec2(d2, abs(z) - h);
    return min(max(w.x, w.y), 0.0) + length(max(w, 0.0));
}

// Trapezoid in the (radius, height) half plane: radius r0 at y = -h, r1 at y = +h, axis at x = 0.
// Exact 2D distance (point-to-segment distances with an inside test); revolve it for a frustum.
float sdTrapezoid2(vec2 q, float r0, float r1, float h) {
    vec2 a = vec2(r0, -h), b = vec2(r1, h);
    float d = min(sdSegment2(q, vec2(0.0, -h), a), sdSegment2(q, vec2(0.0, h), b));
    d = min(d, sdSegment2(q, a, b));
    float t = clamp((q.y + h) / (2.0 * h), 0.0, 1.0);
    bool inside = abs(q.y) <= h && q.x <= mix(r0, r1, t);
    return inside ? -d : d;
}

// Triangle a, b, c (either winding): distance to the nearest edge, negative inside (exact).
float sdTriangle2(vec2 p, vec2 a, vec2 b, vec2 c) {
    float d = min(sdSegment2(p, a, b), min(sdSegment2(p, b, c), sdSegment2(p, c, a)));
    // Inside when p lies on the same side of all three edges.
    float s1 = (b.x - a.x) * (p.y - a.y) - (b.y - a.y) * (p.x - a.x);
    float s2 = (c.x - b.x) * (p.y - b.y) - (c.y - b.y) * (p.x - b.x);
    float s3 = (a.x - c.x) * (p.y - c.y) - (a.y - c.y) * (p.x - c.x);
    bool inside = (s1 >= 0.0 && s2 >= 0.0 && s3 >= 0.0) || (s1 <= 0.0 && s2 <= 0.0 && s3 <= 0.0);
    return inside ? -d : d;
}

// ---------------------------------------------------------------------------------------------
// 3D primitives

// Frustum along Y, centred at the origin: radius r0 at y = -h, r1 at y = +h (exact; either
// radius may be 0 for a cone).
float sdFrustum(vec3 p, float r0, float r1, float h) {
    return sdTrapezoid2(vec2(length(p.xz), p.y), r0, r1, h);
}

// Ellipsoid with semi-axes r: a conservative bound. (|p/r| - 1) * min(r) has gradient <= 1;
// the box with the same half sizes contains the ellipsoid, so its distance is a lower bound too,
// and the larger of the two bounds keeps rays fast near the long ends. The box bound is pulled
// in by a quarter of the smallest radius so that it only takes over well away from the surface
// (where the two meet at the ends of the axes it would otherwise flatten the shading).
float sdEllipsoid(vec3 p, vec3 r) {
    float smallest = min(r.x, min(r.y, r.z));
    float scaled = (length(p / r) - 1.0) * smallest;
    return max(scaled, sdBox(p, r) - 0.25 * smallest);
}

// Core of the round cone: the hull of a circle of radius ra at (0, 0) and one of radius rb at
// (0, len), measured at (x, y) with x >= 0 the distance from the axis (exact).
float roundConeProfile(float x, float y, float len, float ra, float rb) {
    if (len < 1e-5) return length(vec2(x, y)) - max(ra, rb);
    // Slope of the tangent line; if one disc swallows the other the hull is that disc.
    float s = (ra - rb) / len;
    if (abs(s) >= 1.0) return ra > rb ? length(vec2(x, y)) - ra : length(vec2(x, y - len)) - rb;
    float c = sqrt(1.0 - s * s);
    // Coordinate along the tangent line: the tangent points sit at k = 0 and k = len * c.
    float k = -x * s + y * c;
    if (k < 0.0) return length(vec2(x, y)) - ra;
    if (k > len * c) return length(vec2(x, y - len)) - rb;
    return x * c + y * s - ra;
}

// Two spheres (radii ra at a, rb at b) and the cone tangent to both: the convex hull, exact.
float sdRoundCone(vec3 p, vec3 a, vec3 b, float ra, float rb) {
    vec3 ba = b - a, pa = p - a;
    float len = length(ba);
    vec3 axis = len < 1e-5 ? vec3(0.0, 1.0, 0.0) : ba / len;
    float y = dot(pa, axis);
    // Distance from the axis as the length of the perpendicular part (stable near the axis,
    // unlike sqrt(|pa|^2 - y^2), which loses precision there).
    float x = length(pa - axis * y);
    return roundConeProfile(x, y, len, ra, rb);
}

// 2D teardrop: the hull of a disc of radius ra at a and one of radius rb at b (exact).
float sdRoundCone2(vec2 p, vec2 a, vec2 b, float ra, float rb) {
    vec2 ba = b - a, pa = p - a;
    float len = length(ba);
    vec2 axis = len < 1e-5 ? vec2(0.0, 1.0) : ba / len;
    float y = dot(pa, axis);
    float x = abs(pa.x * axis.y - pa.y * axis.x);
    return roundConeProfile(x, y, len, ra, rb);
}

// A flat plate with a fully rounded rim: the 2D outline d2 (exact 2D distance) given a
// thickness of 2 * halfThickness across z. The outline is kept; the rim is a half round (exact
// for exact d2).
float sdPlate(float d2, float z, float halfThickness) {
    return opExtrude(d2 + halfThickness, z, 0.0) - halfThickness;
}

// Capsule of radius r along Y from y = -h to y = +h (exact).
float sdCapsuleY(vec3 p, float h, float r) {
    p.y -= clamp(p.y, -h, h);
    return length(p) - r;
}

// Cylinder of radius r and half length h whose axis runs along X (exact).
float sdCylinderX(vec3 p, float r, float h) { return sdCylinder(p.yxz, r, h); }
// Cylinder along Z (exact).
float sdCylinderZ(vec3 p, float r, float h) { return sdCylinder(p.xzy, r, h); }

// Torus whose ring lies in the XY plane (axis along Z), exact.
float sdTorusXY(vec3 p, float R, float r) { return sdTorus(p.xzy, R, r); }
// Torus whose ring lies in the YZ plane (axis along X), exact.
float sdTorusYZ(vec3 p, float R, float r) { return sdTorus(p.yxz, R, r); }

// Hexagonal prism along Y: inradius (apothem) r, half height h. Intersection of three slabs and
// a height slab: exact inside, a bound near the corners outside (conservative).
float sdHexPrismY(vec3 p, float r, float h) {
    vec2 q = p.xz;
    const vec2 n1 = vec2(0.8660254, 0.5), n2 = vec2(0.8660254, -0.5);
    float d2 = max(abs(q.y), max(abs(dot(q, n1)), abs(dot(q, n2)))) - r;
    return max(d2, abs(p.y) - h);
}

// ---------------------------------------------------------------------------------------------
// Repetition

// atan(y, x) that is defined at the origin (GLSL leaves atan(0, 0) undefined).
float safeAtan(float y, float x) { return (abs(x) + abs(y) < 1e-9) ? 0.0 : atan(y, x); }

// Angular repetition in a plane: maps v into the sector of `count` equal sectors that contains
// it, rotated so the sector's centre line is the +x axis. An element placed symmetrically about
// +x is then repeated `count` times around the origin; the map is a piecewise rotation and is
// continuous for such elements, so the repeated field keeps the element's Lipschitz bound.
vec2 sectorFold(vec2 v, float count) {
    float sector = MODEL_TAU / count;
    float a = safeAtan(v.y, v.x);
    a = mod(a + 0.5 * sector, sector) - 0.5 * sector;
    return length(v) * vec2(cos(a), sin(a));
}

// Tube of radius r along a circular arc of radius R in the XZ plane, centred on the +x axis
// and spanning +-halfAngle (radians). The nearest arc point is at the clamped angle (exact).
float sdArcTubeXZ(vec3 p, float R, float halfAngle, float r) {
    float a = clamp(safeAtan(p.z, p.x), -halfAngle, halfAngle);
    return length(p - vec3(R * cos(a), 0.0, R * sin(a))) - r;
}
