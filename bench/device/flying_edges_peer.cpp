// The Flying Edges peer for the lent GPU machine (#33 point 5), as strong as a competent C++ user would make it:
// the field written inline in C++ and filled in z-slabs by every thread count tried, then VTK's
// vtkFlyingEdges3D (vtkSMPTools, every thread count tried), normals, gradients and scalars off. Optionally the
// post-processing sdfwb's mesher gets: Newton steps onto the surface at every vertex, and refinement (each triangle cut
// into four, the new vertices projected). Prints one JSON object; writes the post-processed mesh as binary PLY for
// `sdfwb --batch grade`.
//
//   flying_edges_peer SHAPE R THREADS,... OUT.ply [--project N] [--refine K]
//   flying_edges_peer --values SHAPE R OUT.f32
//
//   SHAPE: sphere | torus | box | shell | rotated-box | rotated-cylinder | anvil | capsule | hexagonalprism | mug |
//          mengersponge | sierpinskitetrahedron | hg-arcade | iq-primitives | jw-csg
//
// The options may also come before the positional arguments.
//   --project N  N Newton steps v -= f(v) g / |g|^2 at every output vertex of Flying Edges, g the central-difference
//                gradient of the same inline field (step 1e-4, float); a vertex where f or |g|^2 is not finite or
//                |g|^2 <= 1e-12 stops stepping. Threaded over the vertices with std::thread on every thread count
//                given, the fastest kept ("project_seconds", "project_threads"). Default 0: none.
//   --refine K   after the projection, each triangle cut into four K times (the edges' midpoints shared between the
//                two triangles on the edge), each new vertex projected with the same Newton steps (N of --project,
//                2 when --project is not given; a midpoint whose step would exceed a quarter of its edge stays, as in
//                sdfwb), every thread count tried, the fastest kept ("refine_seconds",
//                "refine_threads"). Default 0: none.
//   --values     writes the field on the (R+1)^3 lattice over [-1,1]^3 (x fastest, then y, then z; raw little-endian
//                float32), the very values Flying Edges is given, for checking the inline fields against sdfwb.
//
// JSON: shape, R, field_seconds/_threads, mesh_seconds/_threads (Flying Edges alone), project_seconds/_threads,
// refine_seconds/_threads (0 and 0 where not asked for), seconds (the sum of the four), triangles and vertices (of the
// written mesh), flying_edges_triangles, project_steps, refine_levels, refine_steps, smp_backend,
// mesh_seconds_by_threads, and flags (the compiler flags this binary was built with, -DPEER_FLAGS by build_peer.sh).
// The copies of the mesh into flat arrays before the post-processing are not timed.
//
// The fields are those of bench/bench_mesh_peers.py (the same radii, half sizes and tilt: 0.3 rad about (1, 2, 3)),
// of the dataset SDFs of the same name (their default parameters) and of three foreign shaders in tests/foreign/
// (42_hg_mercury_arcade.glsl `scene`, 01_iq_primitives.glsl `map`, 43_jw_csg_phong.glsl `sceneSDF`, at iTime = 0),
// written out in float in the GLSL's order of operations, GLSL's mod, sign, clamp and mix spelled out.
// Built by bench/device/build_peer.sh against Debian's VTK 9.1; it is not part of the CMake build.
#include <vtkCellArray.h>
#include <vtkDataArray.h>
#include <vtkFloatArray.h>
#include <vtkFlyingEdges3D.h>
#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkSMPTools.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

namespace {

using Clock = std::chrono::steady_clock;
using Field = float (*)(float, float, float);
using Matrix = std::array<float, 9>;

double secondsSince(Clock::time_point start) { return std::chrono::duration<double>(Clock::now() - start).count(); }

// Rodrigues' rotation by `angle` about `axis`, transposed: the field is the upright shape's at R^T p.
Matrix untiltMatrix() {
    const double n = std::sqrt(1.0 + 4.0 + 9.0);
    const double k[3] = {1.0 / n, 2.0 / n, 3.0 / n};
    const double s = std::sin(0.3), c = 1.0 - std::cos(0.3);
    const double K[3][3] = {{0, -k[2], k[1]}, {k[2], 0, -k[0]}, {-k[1], k[0], 0}};
    Matrix t{};
    for (int row = 0; row < 3; ++row) {
        for (int col = 0; col < 3; ++col) {
            double kk = 0.0;
            for (int m = 0; m < 3; ++m) kk += K[row][m] * K[m][col];
            const double r = (row == col ? 1.0 : 0.0) + s * K[row][col] + c * kk;
            t[col * 3 + row] = static_cast<float>(r); // transposed
        }
    }
    return t;
}

const Matrix kUntilt = untiltMatrix();

inline void untilt(float& x, float& y, float& z) {
    const float u = kUntilt[0] * x + kUntilt[1] * y + kUntilt[2] * z;
    const float v = kUntilt[3] * x + kUntilt[4] * y + kUntilt[5] * z;
    const float w = kUntilt[6] * x + kUntilt[7] * y + kUntilt[8] * z;
    x = u, y = v, z = w;
}

inline float sphere(float x, float y, float z) { return std::sqrt(x * x + y * y + z * z) - 0.8f; }

inline float torus(float x, float y, float z) { // the dataset's Torus: tilted 30 degrees about x
    const float c = 0.8660254f, s = 0.5f;
    const float v = c * y + s * z, w = -s * y + c * z;
    const float q = std::sqrt(x * x + w * w) - 0.65f;
    return std::sqrt(q * q + v * v) - 0.25f;
}

inline float boxOf(float x, float y, float z, float hx, float hy, float hz) {
    const float qx = std::fabs(x) - hx, qy = std::fabs(y) - hy, qz = std::fabs(z) - hz;
    const float ox = std::max(qx, 0.0f), oy = std::max(qy, 0.0f), oz = std::max(qz, 0.0f);
    return std::sqrt(ox * ox + oy * oy + oz * oz) + std::min(std::max(qx, std::max(qy, qz)), 0.0f);
}

inline float box(float x, float y, float z) { return boxOf(x, y, z, 0.8f, 0.5f, 0.6f); }

inline float shell(float x, float y, float z) { // a hollow ball, wall 0.03, cut open by the plane y = 0.5
    const float ball = std::fabs(std::sqrt(x * x + y * y + z * z) - 0.7f) - 0.015f;
    return std::max(ball, y - 0.5f);
}

inline float rotatedBox(float x, float y, float z) {
    untilt(x, y, z);
    return boxOf(x, y, z, 0.55f, 0.4f, 0.3f);
}

inline float rotatedCylinder(float x, float y, float z) {
    untilt(x, y, z);
    const float dx = std::sqrt(x * x + z * z) - 0.45f, dy = std::fabs(y) - 0.6f;
    const float ox = std::max(dx, 0.0f), oy = std::max(dy, 0.0f);
    return std::min(std::max(dx, dy), 0.0f) + std::sqrt(ox * ox + oy * oy);
}

// The dataset's Anvil (dataset/Manufactured/Anvil.glsl) and the helpers it calls from shaders/lib/primitives.glsl
// and dataset/lib/modelling.glsl, written out in C++ the same way.
inline float length2(float x, float y) { return std::sqrt(x * x + y * y); }
inline float roundBox(float x, float y, float z, float hx, float hy, float hz, float r) {
    return boxOf(x, y, z, hx - r, hy - r, hz - r) - r;
}
inline float cylinderY(float x, float y, float z, float radius, float halfHeight) {
    const float dx = length2(x, z) - radius, dy = std::fabs(y) - halfHeight;
    return std::min(std::max(dx, dy), 0.0f) + length2(std::max(dx, 0.0f), std::max(dy, 0.0f));
}
inline float segment2(float px, float py, float ax, float ay, float bx, float by) {
    const float pax = px - ax, pay = py - ay, bax = bx - ax, bay = by - ay;
    const float h = std::clamp((pax * bax + pay * bay) / (bax * bax + bay * bay), 0.0f, 1.0f);
    return length2(pax - bax * h, pay - bay * h);
}
inline float frustumY(float x, float y, float z, float r0, float r1, float h) {
    const float qx = length2(x, z), qy = y;
    float d = std::min(segment2(qx, qy, 0.0f, -h, r0, -h), segment2(qx, qy, 0.0f, h, r1, h));
    d = std::min(d, segment2(qx, qy, r0, -h, r1, h));
    const float t = std::clamp((qy + h) / (2.0f * h), 0.0f, 1.0f);
    const bool inside = std::fabs(qy) <= h && qx <= r0 + (r1 - r0) * t;
    return inside ? -d : d;
}
inline float roundCone(float px, float py, float pz, const float a[3], const float b[3], float ra, float rb) {
    const float bax = b[0] - a[0], bay = b[1] - a[1], baz = b[2] - a[2];
    const float pax = px - a[0], pay = py - a[1], paz = pz - a[2];
    const float len = std::sqrt(bax * bax + bay * bay + baz * baz);
    const float ux = bax / len, uy = bay / len, uz = baz / len;
    const float y = pax * ux + pay * uy + paz * uz;
    const float ex = pax - ux * y, ey = pay - uy * y, ez = paz - uz * y;
    const float x = std::sqrt(ex * ex + ey * ey + ez * ez);
    const float s = (ra - rb) / len, c = std::sqrt(1.0f - s * s);
    const float k = -x * s + y * c;
    if (k < 0.0f) return length2(x, y) - ra;
    if (k > len * c) return length2(x, y - len) - rb;
    return x * c + y * s - ra;
}
inline float smoothMin(float a, float b, float k) {
    const float h = std::clamp(0.5f + 0.5f * (b - a) / k, 0.0f, 1.0f);
    return b + (a - b) * h - k * h * (1.0f - h);
}
inline float anvil(float x, float y, float z) {
    float face = roundBox(x + 0.15f, y - 0.32f, z, 0.5f, 0.12f, 0.2f, 0.02f);
    const float hardy = boxOf(x + 0.5f, y - 0.32f, z, 0.04f, 0.2f, 0.04f);
    const float pritchel = cylinderY(x + 0.36f, y - 0.32f, z, 0.025f, 0.2f);
    face = std::max(face, -std::min(hardy, pritchel));
    const float table = roundBox(x - 0.4f, y - 0.28f, z, 0.08f, 0.08f, 0.14f, 0.02f);
    static const float hornA[3] = {0.42f, 0.26f, 0.0f}, hornB[3] = {0.9f, 0.3f, 0.0f};
    float horn = roundCone(x, y, z, hornA, hornB, 0.14f, 0.02f);
    horn = std::max(horn, y - 0.35f);
    const float top = std::min(std::min(face, table), horn);
    const float waist = boxOf(x + 0.12f, y + 0.05f, z, 0.16f, 0.25f, 0.09f);
    float base = frustumY(x + 0.12f, y + 0.45f, z, 0.42f, 0.22f, 0.12f);
    base = std::max(base, boxOf(x + 0.12f, y + 0.45f, z, 0.42f, 0.12f, 0.3f));
    const float notch =
        std::min(boxOf(x + 0.12f, y + 0.58f, z, 0.5f, 0.06f, 0.12f), boxOf(x + 0.12f, y + 0.58f, z, 0.2f, 0.06f, 0.5f));
    base = std::max(base, -notch);
    float body = smoothMin(waist, base, 0.16f);
    body = smoothMin(body, top, 0.14f);
    return body;
}

// GLSL's built-ins where C++'s differ: mod(x, y) = x - y * floor(x / y) (std::fmod truncates), sign (0 at 0).
inline float glslMod(float x, float y) { return x - y * std::floor(x / y); }
inline float glslSign(float x) { return x > 0.0f ? 1.0f : (x < 0.0f ? -1.0f : 0.0f); }
inline float length3(float x, float y, float z) { return std::sqrt(x * x + y * y + z * z); }

// dataset/Geometry/Capsule.glsl: every point within 0.36 of the segment y in [-0.56, 0.56].
inline float capsule(float x, float y, float z) {
    const float nearest = std::clamp(y, -0.56f, 0.56f);
    return length3(x, y - nearest, z) - 0.36f;
}

// dataset/Geometry/HexagonalPrism.glsl: apothem 0.78, half height 0.62, folded into the 30-degree wedge.
inline float hexagonalPrism(float x, float y, float z) {
    const float apothem = 0.78f, halfHeight = 0.62f;
    const float halfSide = apothem * (0.45033f / 0.78f);
    float qx = std::fabs(x), qy = std::fabs(z);
    float t = 2.0f * std::min(qx * 0.8660254f + qy * -0.5f, 0.0f); // mirror60 = (0.8660254, -0.5)
    qx -= t * 0.8660254f, qy -= t * -0.5f;
    t = 2.0f * std::min(qx * 0.5f + qy * -0.8660254f, 0.0f); // mirror30 = (0.5, -0.8660254)
    qx -= t * 0.5f, qy -= t * -0.8660254f;
    const float nearestY = std::clamp(qy, 0.0f, halfSide);
    const float hexagon = length2(qx - apothem, qy - nearestY) * glslSign(qx - apothem);
    const float wx = hexagon, wy = std::fabs(y) - halfHeight;
    return std::min(std::max(wx, wy), 0.0f) + length2(std::max(wx, 0.0f), std::max(wy, 0.0f));
}

// dataset/Manufactured/Mug.glsl (coffee level 0.35, handle thickness 0.07) with sdTorusXY of dataset/lib/modelling.glsl.
inline float torusXY(float x, float y, float z, float R, float r) { return length2(length2(x, y) - R, z) - r; }
inline float mug(float x, float y, float z) {
    const float qx = x - -0.15f, qy = y - -0.05f, qz = z;
    const float outer = cylinderY(qx, qy, qz, 0.5f, 0.55f) - 0.04f;
    const float inner = cylinderY(qx, qy - 0.2f, qz, 0.44f, 0.55f) - 0.02f;
    float cup = std::max(outer, -inner);
    const float coffee = cylinderY(qx, qy - 0.35f, qz, 0.45f, 0.02f);
    cup = std::min(cup, coffee);
    const float hx = qx - 0.5f, hy = qy - 0.02f, hz = qz;
    float handle = torusXY(hx, hy, hz, 0.27f, 0.07f);
    handle = std::max(handle, -0.1f - hx);
    return smoothMin(cup, handle, 0.05f);
}

// dataset/Fractal/MengerSponge.glsl: half size 0.78, four levels of crosses, each wrapped into its cell by mod.
inline float barDistance(float ax, float ay, float halfWidth) {
    const float ox = std::fabs(ax) - halfWidth, oy = std::fabs(ay) - halfWidth;
    return length2(std::max(ox, 0.0f), std::max(oy, 0.0f)) + std::min(std::max(ox, oy), 0.0f);
}
inline float mengerSponge(float x, float y, float z) {
    const float halfSize = 0.78f;
    const float qx = x / halfSize, qy = y / halfSize, qz = z / halfSize;
    const float ox = std::fabs(qx) - 1.0f, oy = std::fabs(qy) - 1.0f, oz = std::fabs(qz) - 1.0f;
    float solid =
        length3(std::max(ox, 0.0f), std::max(oy, 0.0f), std::max(oz, 0.0f)) + std::min(std::max(ox, std::max(oy, oz)), 0.0f);
    float cellSize = 2.0f;
    for (int level = 0; level < 4; ++level) {
        const float lx = glslMod(qx + 1.0f, cellSize) - 0.5f * cellSize;
        const float ly = glslMod(qy + 1.0f, cellSize) - 0.5f * cellSize;
        const float lz = glslMod(qz + 1.0f, cellSize) - 0.5f * cellSize;
        const float halfWidth = cellSize / 6.0f;
        const float cross =
            std::min(barDistance(ly, lz, halfWidth), std::min(barDistance(lx, lz, halfWidth), barDistance(lx, ly, halfWidth)));
        solid = std::max(solid, -cross);
        cellSize /= 3.0f;
    }
    return solid * halfSize;
}

// dataset/Fractal/SierpinskiTetrahedron.glsl: six levels of folds, scale 0.66.
inline float sierpinskiTetrahedron(float x, float y, float z) {
    const float scale = 0.66f;
    const float offX = 0.4082483f * scale, offY = 0.5773503f * scale, offZ = 0.0f * scale;
    const float qx = (x + offX) / scale, qy = (y + offY) / scale, qz = (z + offZ) / scale;
    // z = q.x * frameX + q.y * frameY + q.z * frameZ
    float a = qx * 0.4082483f + qy * 0.5773503f + qz * 0.7071068f;
    float b = qx * 0.4082483f + qy * 0.5773503f + qz * -0.7071068f;
    float c = qx * -0.8164966f + qy * 0.5773503f + qz * 0.0f;
    for (int level = 0; level < 6; ++level) {
        if (a + b < 0.0f) {
            const float t = a;
            a = -b, b = -t;
        }
        if (a + c < 0.0f) {
            const float t = a;
            a = -c, c = -t;
        }
        if (b + c < 0.0f) {
            const float t = b;
            b = -c, c = -t;
        }
        a = 2.0f * a - 1.0f, b = 2.0f * b - 1.0f, c = 2.0f * c - 1.0f;
    }
    const float planes = std::max(std::max(-a - b - c, a + b - c), std::max(-a + b + c, a - b + c));
    const float tetrahedron = (planes - 1.0f) * 0.5773503f;
    return tetrahedron * scale / 64.0f; // float(1 << levels)
}

// tests/foreign/42_hg_mercury_arcade.glsl, `scene`: hg_sdf's fBox, pR, pMod1 and fOpUnionChamfer.
inline float fBox(float x, float y, float z, float bx, float by, float bz) {
    const float dx = std::fabs(x) - bx, dy = std::fabs(y) - by, dz = std::fabs(z) - bz;
    return length3(std::max(dx, 0.0f), std::max(dy, 0.0f), std::max(dz, 0.0f)) +
           std::max(std::max(std::min(dx, 0.0f), std::min(dy, 0.0f)), std::min(dz, 0.0f));
}
inline float chamferUnion(float a, float b, float r) { return std::min(std::min(a, b), (a + b - r) * std::sqrt(0.5f)); }
const float kArcadeCos = std::cos(0.3f), kArcadeSin = std::sin(0.3f);
inline float hgArcade(float x, float y, float z) {
    // pR(p.xz, 0.3): p = cos(a) p + sin(a) vec2(p.y, -p.x) on the (x, z) pair.
    const float px = kArcadeCos * x + kArcadeSin * z, pz = kArcadeCos * z + kArcadeSin * -x, py = y;
    const float floorSlab = fBox(px - 0.0f, py - -0.62f, pz - 0.0f, 0.92f, 0.08f, 0.35f);
    const float roofSlab = fBox(px - 0.0f, py - 0.62f, pz - 0.0f, 0.92f, 0.08f, 0.35f);
    const float size = 0.38f; // pMod1(q.x, SPACING)
    const float cell = std::floor(px / size + 0.5f);
    const float qx = px - size * cell;
    float columns = length2(qx, pz) - 0.07f;
    columns = std::max(columns, std::fabs(px) - 0.86f);
    float d = chamferUnion(columns, floorSlab, 0.04f);
    d = chamferUnion(d, roofSlab, 0.04f);
    return std::max(d, std::fabs(py) - 0.7f);
}

// tests/foreign/01_iq_primitives.glsl, `map(...).x`: the nearest of IQ's primitives (opU keeps the smaller .x).
inline float iqBox(float x, float y, float z, float bx, float by, float bz) {
    const float dx = std::fabs(x) - bx, dy = std::fabs(y) - by, dz = std::fabs(z) - bz;
    return std::min(std::max(dx, std::max(dy, dz)), 0.0f) + length3(std::max(dx, 0.0f), std::max(dy, 0.0f), std::max(dz, 0.0f));
}
inline float iqPrimitives(float x, float y, float z) {
    float d = 1e10f;
    d = std::min(d, iqBox(x - 0.0f, y - -0.62f, z - 0.0f, 0.9f, 0.04f, 0.9f));
    d = std::min(d, length3(x - -0.55f, y - -0.3f, z - -0.4f) - 0.2f);
    { // sdRoundBox(pos - (0, -0.3, -0.4), vec3(0.18), 0.05)
        const float r = 0.05f;
        const float qx = std::fabs(x - 0.0f) - 0.18f + r, qy = std::fabs(y - -0.3f) - 0.18f + r,
                    qz = std::fabs(z - -0.4f) - 0.18f + r;
        d = std::min(d, length3(std::max(qx, 0.0f), std::max(qy, 0.0f), std::max(qz, 0.0f)) +
                            std::min(std::max(qx, std::max(qy, qz)), 0.0f) - r);
    }
    { // sdTorus(pos - (0.55, -0.3, -0.4), vec2(0.17, 0.05))
        const float px = x - 0.55f, py = y - -0.3f, pz = z - -0.4f;
        d = std::min(d, length2(length2(px, pz) - 0.17f, py) - 0.05f);
    }
    { // sdCapsule(pos, a = (-0.65, -0.45, 0.3), b = (-0.45, -0.1, 0.45), 0.07)
        const float pax = x - -0.65f, pay = y - -0.45f, paz = z - 0.3f;
        const float bax = -0.45f - -0.65f, bay = -0.1f - -0.45f, baz = 0.45f - 0.3f;
        const float h = std::clamp((pax * bax + pay * bay + paz * baz) / (bax * bax + bay * bay + baz * baz), 0.0f, 1.0f);
        d = std::min(d, length3(pax - bax * h, pay - bay * h, paz - baz * h) - 0.07f);
    }
    { // sdCappedCylinder(pos - (0, -0.3, 0.4), h = 0.2, r = 0.15)
        const float px = x - 0.0f, py = y - -0.3f, pz = z - 0.4f;
        const float dx = std::fabs(length2(px, pz)) - 0.15f, dy = std::fabs(py) - 0.2f;
        d = std::min(d, std::min(std::max(dx, dy), 0.0f) + length2(std::max(dx, 0.0f), std::max(dy, 0.0f)));
    }
    { // sdOctahedron(pos - (0.55, -0.3, 0.4), 0.25): the cheap bound
        const float px = std::fabs(x - 0.55f), py = std::fabs(y - -0.3f), pz = std::fabs(z - 0.4f);
        d = std::min(d, (px + py + pz - 0.25f) * 0.57735027f);
    }
    d = std::min(d, iqBox(x - 0.0f, y - 0.35f, z - 0.0f, 0.25f, 0.08f, 0.25f));
    return d;
}

// tests/foreign/43_jw_csg_phong.glsl, `sceneSDF` at iTime = 0 (rotateY(0) is the identity): a cube rounded by a
// ball, minus three rods.
inline float jwCylinder(float x, float y, float z, float h, float r) { // capped, along z, length h end to end
    const float qx = length2(x, y) - r, qy = std::fabs(z) - 0.5f * h;
    return std::min(std::max(qx, qy), 0.0f) + length2(std::max(qx, 0.0f), std::max(qy, 0.0f));
}
const float kQuarterTurn = 90.0f * 0.017453292519943295f; // radians(90.0)
const float kQuarterCos = std::cos(kQuarterTurn), kQuarterSin = std::sin(kQuarterTurn);
inline float jwCsg(float x, float y, float z) {
    const float rodZ = jwCylinder(x, y, z, 1.6f, 0.2f);
    // rotateY(theta) * p = (c x - s z, y, s x + c z): mat3's columns (c, 0, s), (0, 1, 0), (-s, 0, c).
    const float rodX = jwCylinder(kQuarterCos * x - kQuarterSin * z, y, kQuarterSin * x + kQuarterCos * z, 1.6f, 0.2f);
    const float rodY = jwCylinder(z, x, y, 1.6f, 0.2f); // samplePoint.zxy
    const float cube = boxOf(x, y, z, 0.45f, 0.45f, 0.45f);
    const float ball = (length3(x / 0.6f, y / 0.6f, z / 0.6f) - 1.0f) * 0.6f;
    const float rounded = std::max(cube, ball);
    const float rods = std::min(rodZ, std::min(rodX, rodY));
    return std::max(rounded, -rods);
}

// The (R+1)^3 lattice over [-1,1]^3, x fastest, in z-slabs over `threads` threads.
template <Field F> void fill(std::vector<float>& values, int R, int threads) {
    const int n = R + 1;
    const float h = 2.0f / static_cast<float>(R);
    auto slab = [&](int z0, int z1) {
        for (int k = z0; k < z1; ++k) {
            const float z = -1.0f + h * static_cast<float>(k);
            for (int j = 0; j < n; ++j) {
                const float y = -1.0f + h * static_cast<float>(j);
                float* row = values.data() + (static_cast<size_t>(k) * n + j) * n;
                for (int i = 0; i < n; ++i) row[i] = F(-1.0f + h * static_cast<float>(i), y, z);
            }
        }
    };
    std::vector<std::thread> pool;
    for (int t = 0; t < threads; ++t) {
        const int z0 = n * t / threads, z1 = n * (t + 1) / threads;
        pool.emplace_back(slab, z0, z1);
    }
    for (auto& thread : pool) thread.join();
}

// [first, end) cut into `threads` contiguous pieces, each run by a std::thread (one piece runs on the caller).
template <class Body> void parallelFor(size_t first, size_t end, int threads, const Body& body) {
    const size_t count = end > first ? end - first : 0;
    if (threads <= 1 || count < 1024) {
        body(first, end);
        return;
    }
    std::vector<std::thread> pool;
    for (int t = 1; t < threads; ++t) pool.emplace_back(body, first + count * t / threads, first + count * (t + 1) / threads);
    body(first, first + count / threads);
    for (auto& thread : pool) thread.join();
}

// `steps` Newton steps v -= f(v) g / |g|^2 at the vertices [first, end) of `xyz` (x, y, z each), g the central
// difference of the field with step 1e-4, threaded over the vertices. With `limits` (refinement: a quarter of each
// midpoint's edge, indexed from `first`), a vertex that would move farther stays where it was, as sdfwb's refinement
// keeps a midpoint whose step is longer than a quarter of its edge (a step across a thin wall to the other sheet).
template <Field F> void project(float* xyz, size_t first, size_t end, int steps, int threads, const float* limits) {
    parallelFor(first, end, threads, [xyz, steps, first, limits](size_t begin, size_t stop) {
        const float e = 1e-4f, inverse = 1.0f / (2.0f * e);
        for (size_t v = begin; v < stop; ++v) {
            const float x0 = xyz[3 * v], y0 = xyz[3 * v + 1], z0 = xyz[3 * v + 2];
            float x = x0, y = y0, z = z0;
            for (int step = 0; step < steps; ++step) {
                const float f = F(x, y, z);
                const float gx = (F(x + e, y, z) - F(x - e, y, z)) * inverse;
                const float gy = (F(x, y + e, z) - F(x, y - e, z)) * inverse;
                const float gz = (F(x, y, z + e) - F(x, y, z - e)) * inverse;
                const float g2 = gx * gx + gy * gy + gz * gz;
                if (!std::isfinite(f) || !std::isfinite(g2) || !(g2 > 1e-12f)) break;
                const float s = f / g2;
                x -= s * gx, y -= s * gy, z -= s * gz;
            }
            if (limits) {
                const float limit = limits[v - first];
                if (!((x - x0) * (x - x0) + (y - y0) * (y - y0) + (z - z0) * (z - z0) <= limit * limit)) continue;
            }
            xyz[3 * v] = x, xyz[3 * v + 1] = y, xyz[3 * v + 2] = z;
        }
    });
}

struct Shape {
    const char* name;
    void (*fill)(std::vector<float>&, int, int);
    void (*project)(float*, size_t, size_t, int, int, const float*);
};

template <Field F> constexpr Shape shapeOf(const char* name) { return {name, fill<F>, project<F>}; }

const Shape kShapes[] = {
    shapeOf<sphere>("sphere"),
    shapeOf<torus>("torus"),
    shapeOf<box>("box"),
    shapeOf<shell>("shell"),
    shapeOf<rotatedBox>("rotated-box"),
    shapeOf<rotatedCylinder>("rotated-cylinder"),
    shapeOf<anvil>("anvil"),
    shapeOf<capsule>("capsule"),
    shapeOf<hexagonalPrism>("hexagonalprism"),
    shapeOf<mug>("mug"),
    shapeOf<mengerSponge>("mengersponge"),
    shapeOf<sierpinskiTetrahedron>("sierpinskitetrahedron"),
    shapeOf<hgArcade>("hg-arcade"),
    shapeOf<iqPrimitives>("iq-primitives"),
    shapeOf<jwCsg>("jw-csg"),
};

void flyingEdges(std::vector<float>& values, int R, vtkPolyData* out) {
    vtkNew<vtkFloatArray> scalars;
    scalars->SetArray(values.data(), static_cast<vtkIdType>(values.size()), 1); // no copy
    vtkNew<vtkImageData> image;
    image->SetDimensions(R + 1, R + 1, R + 1);
    image->SetSpacing(2.0 / R, 2.0 / R, 2.0 / R);
    image->SetOrigin(-1.0, -1.0, -1.0);
    image->GetPointData()->SetScalars(scalars);
    vtkNew<vtkFlyingEdges3D> mesher;
    mesher->SetInputData(image);
    mesher->SetValue(0, 0.0);
    mesher->ComputeNormalsOff();
    mesher->ComputeGradientsOff();
    mesher->ComputeScalarsOff();
    mesher->InterpolateAttributesOff();
    mesher->Update();
    out->ShallowCopy(mesher->GetOutput());
}

// A triangle mesh as flat arrays: x, y, z per vertex; three vertex indices per triangle.
struct Mesh {
    std::vector<float> xyz;
    std::vector<uint32_t> indices;
    size_t vertexCount() const { return xyz.size() / 3; }
    size_t triangleCount() const { return indices.size() / 3; }
};

Mesh meshOf(vtkPolyData* polyData) { // untimed: the flat arrays the post-processing and the writer take
    Mesh mesh;
    const vtkIdType vertices = polyData->GetNumberOfPoints();
    mesh.xyz.resize(3 * static_cast<size_t>(vertices));
    for (vtkIdType v = 0; v < vertices; ++v) {
        double p[3];
        polyData->GetPoint(v, p);
        for (int a = 0; a < 3; ++a) mesh.xyz[3 * static_cast<size_t>(v) + a] = static_cast<float>(p[a]);
    }
    vtkCellArray* cells = polyData->GetPolys();
    const vtkIdType faces = cells ? cells->GetNumberOfCells() : 0;
    mesh.indices.resize(3 * static_cast<size_t>(faces));
    vtkIdType count = 0;
    const vtkIdType* ids = nullptr;
    for (vtkIdType f = 0; f < faces; ++f) {
        cells->GetCellAtId(f, count, ids);
        for (int k = 0; k < 3; ++k) mesh.indices[3 * static_cast<size_t>(f) + k] = static_cast<uint32_t>(ids[k]);
    }
    return mesh;
}

// Refinement: each triangle's edges as indices into `ends` (edge k joins its vertices k and k + 1).
struct Edges {
    std::vector<std::array<uint32_t, 2>> ends;
    std::vector<std::array<uint32_t, 3>> ofTriangle;
};

// The coarse mesh's edges by sorting the triangles' sides: an edge shared by two triangles gets one index.
Edges findEdges(const Mesh& mesh) {
    const size_t triangles = mesh.triangleCount();
    std::vector<std::pair<uint64_t, uint32_t>> sides(3 * triangles); // ((low vertex, high vertex), side)
    for (size_t t = 0; t < triangles; ++t)
        for (size_t k = 0; k < 3; ++k) {
            const uint32_t a = mesh.indices[3 * t + k], b = mesh.indices[3 * t + (k + 1) % 3];
            sides[3 * t + k] = {(uint64_t(std::min(a, b)) << 32) | std::max(a, b), uint32_t(3 * t + k)};
        }
    std::sort(sides.begin(), sides.end());
    Edges edges;
    edges.ofTriangle.resize(triangles);
    for (size_t i = 0; i < sides.size(); ++i) {
        if (i == 0 || sides[i].first != sides[i - 1].first)
            edges.ends.push_back({uint32_t(sides[i].first >> 32), uint32_t(sides[i].first & 0xffffffffu)});
        edges.ofTriangle[sides[i].second / 3][sides[i].second % 3] = uint32_t(edges.ends.size() - 1);
    }
    return edges;
}

// One level: vertex V + e is the midpoint of edge e; edge e's halves become edges 2e (from its first end) and
// 2e + 1, and each triangle t adds the three edges between its midpoints, 2E + 3t + k, so the finer level's edges
// need no search. The last level needs no edges.
void split(Mesh& mesh, Edges& edges, bool last, int threads) {
    const size_t triangles = mesh.triangleCount(), edgeCount = edges.ends.size();
    const auto firstMidpoint = uint32_t(mesh.vertexCount());
    mesh.xyz.resize(3 * (mesh.vertexCount() + edgeCount));
    Edges fine;
    if (!last) {
        fine.ends.resize(2 * edgeCount + 3 * triangles);
        fine.ofTriangle.resize(4 * triangles);
    }
    std::vector<uint32_t> indices(12 * triangles);
    parallelFor(0, edgeCount, threads, [&](size_t first, size_t end) {
        for (size_t e = first; e < end; ++e) {
            const auto [a, b] = edges.ends[e];
            const size_t m = firstMidpoint + e;
            for (int k = 0; k < 3; ++k) mesh.xyz[3 * m + k] = 0.5f * (mesh.xyz[3 * size_t(a) + k] + mesh.xyz[3 * size_t(b) + k]);
            if (last) continue;
            fine.ends[2 * e] = {a, uint32_t(m)};
            fine.ends[2 * e + 1] = {uint32_t(m), b};
        }
    });
    parallelFor(0, triangles, threads, [&](size_t first, size_t end) {
        for (size_t t = first; t < end; ++t) {
            const uint32_t* v = &mesh.indices[3 * t];
            const auto& e = edges.ofTriangle[t];
            const uint32_t m[3] = {firstMidpoint + e[0], firstMidpoint + e[1], firstMidpoint + e[2]};
            const uint32_t children[12] = {v[0], m[0], m[2], v[1], m[1], m[0], v[2], m[2], m[1], m[0], m[1], m[2]};
            std::copy(children, children + 12, indices.begin() + std::ptrdiff_t(12 * t));
            if (last) continue;
            auto half = [&](int k, uint32_t corner) { // the half of edge k that touches `corner`
                return uint32_t(2 * e[k] + (edges.ends[e[k]][0] == corner ? 0 : 1));
            };
            const auto inner = uint32_t(2 * edgeCount + 3 * t);
            fine.ends[inner] = {m[0], m[1]};
            fine.ends[inner + 1] = {m[1], m[2]};
            fine.ends[inner + 2] = {m[2], m[0]};
            fine.ofTriangle[4 * t] = {half(0, v[0]), inner + 2, half(2, v[0])};
            fine.ofTriangle[4 * t + 1] = {half(1, v[1]), inner, half(0, v[1])};
            fine.ofTriangle[4 * t + 2] = {half(2, v[2]), inner + 1, half(1, v[2])};
            fine.ofTriangle[4 * t + 3] = {inner, inner + 1, inner + 2};
        }
    });
    mesh.indices = std::move(indices);
    edges = std::move(fine);
}

// `levels` times: every triangle cut into four at its edges' midpoints, each new vertex projected.
void refine(Mesh& mesh, const Shape& shape, int levels, int steps, int threads) {
    if (levels <= 0 || mesh.indices.empty()) return;
    Edges edges = findEdges(mesh);
    for (int level = 0; level < levels; ++level) {
        const size_t firstMidpoint = mesh.vertexCount();
        std::vector<float> limits(edges.ends.size()); // a quarter of each edge: the farthest its midpoint may move
        for (size_t e = 0; e < edges.ends.size(); ++e) {
            const float* a = &mesh.xyz[3 * size_t(edges.ends[e][0])];
            const float* b = &mesh.xyz[3 * size_t(edges.ends[e][1])];
            limits[e] =
                0.25f * std::sqrt((b[0] - a[0]) * (b[0] - a[0]) + (b[1] - a[1]) * (b[1] - a[1]) + (b[2] - a[2]) * (b[2] - a[2]));
        }
        split(mesh, edges, level + 1 == levels, threads);
        shape.project(mesh.xyz.data(), firstMidpoint, mesh.vertexCount(), steps, threads, limits.data());
    }
}

void writePly(const Mesh& mesh, const std::string& path) {
    std::ofstream file(path, std::ios::binary);
    file << "ply\nformat binary_little_endian 1.0\nelement vertex " << mesh.vertexCount()
         << "\nproperty float x\nproperty float y\nproperty float z\nelement face " << mesh.triangleCount()
         << "\nproperty list uchar int vertex_indices\nend_header\n";
    file.write(reinterpret_cast<const char*>(mesh.xyz.data()), std::streamsize(mesh.xyz.size() * sizeof(float)));
    for (size_t t = 0; t < mesh.triangleCount(); ++t) {
        const unsigned char three = 3;
        const int tri[3] = {int(mesh.indices[3 * t]), int(mesh.indices[3 * t + 1]), int(mesh.indices[3 * t + 2])};
        file.write(reinterpret_cast<const char*>(&three), 1);
        file.write(reinterpret_cast<const char*>(tri), sizeof tri);
    }
}

std::vector<int> parseThreads(const std::string& text) {
    std::vector<int> threads;
    std::stringstream stream(text);
    for (std::string item; std::getline(stream, item, ',');) threads.push_back(std::max(1, std::stoi(item)));
    return threads;
}

const Shape* findShape(const std::string& name) {
    for (const Shape& shape : kShapes)
        if (name == shape.name) return &shape;
    return nullptr;
}

int usage() {
    std::cerr << "usage: flying_edges_peer SHAPE R THREADS,... OUT.ply [--project N] [--refine K]\n"
                 "       flying_edges_peer --values SHAPE R OUT.f32\n"
                 "SHAPE:";
    for (const Shape& shape : kShapes) std::cerr << ' ' << shape.name;
    std::cerr << '\n';
    return 2;
}

} // namespace

#ifndef PEER_FLAGS
#define PEER_FLAGS "unknown"
#endif

int main(int argc, char** argv) {
    // Options anywhere; the rest positional.
    std::vector<std::string> positional;
    int steps = 0, levels = 0;
    bool projectGiven = false, valuesMode = false;
    for (int i = 1; i < argc; ++i) {
        const std::string arg = argv[i];
        if (arg == "--values") {
            valuesMode = true;
        } else if (arg == "--project" || arg == "--refine") {
            if (i + 1 >= argc) return usage();
            const int value = std::stoi(argv[++i]);
            if (value < 0) return usage();
            if (arg == "--project")
                steps = value, projectGiven = true;
            else
                levels = value;
        } else if (arg.size() > 2 && arg.compare(0, 2, "--") == 0) {
            return usage();
        } else {
            positional.push_back(arg);
        }
    }
    if (positional.size() != (valuesMode ? 3u : 4u)) return usage();
    const std::string shapeName = positional[0];
    const int R = std::stoi(positional[1]);
    const Shape* shape = findShape(shapeName);
    if (!shape || R < 2) {
        std::cerr << "flying_edges_peer: unknown shape '" << shapeName << "' or R < 2\n";
        return usage();
    }
    std::vector<float> values(static_cast<size_t>(R + 1) * (R + 1) * (R + 1));
    if (valuesMode) {
        shape->fill(values, R, std::max(1, int(std::thread::hardware_concurrency())));
        std::ofstream file(positional[2], std::ios::binary);
        file.write(reinterpret_cast<const char*>(values.data()), std::streamsize(values.size() * sizeof(float)));
        return file ? 0 : 1;
    }
    const std::vector<int> threads = parseThreads(positional[2]);
    const std::string outPath = positional[3];
    const int refineSteps = projectGiven ? steps : 2;
    shape->fill(values, R, threads.back()); // warm-up: pages touched, as a user's second call would find them

    // The field: every thread count once, the fastest kept.
    double fieldBest = 1e30;
    int fieldThreads = 1;
    for (int k : threads) {
        const auto start = Clock::now();
        shape->fill(values, R, k);
        const double t = secondsSince(start);
        if (t < fieldBest) fieldBest = t, fieldThreads = k;
    }
    // Flying Edges: every thread count once (after one warm-up), the fastest kept.
    vtkNew<vtkPolyData> polyData;
    vtkSMPTools::Initialize(threads.back());
    flyingEdges(values, R, polyData);
    double meshBest = 1e30;
    int meshThreads = 1;
    std::ostringstream perThreads;
    for (int k : threads) {
        vtkSMPTools::Initialize(k);
        vtkNew<vtkPolyData> out;
        const auto start = Clock::now();
        flyingEdges(values, R, out);
        const double t = secondsSince(start);
        perThreads << (perThreads.tellp() > 0 ? ", " : "") << "\"" << k << "\": " << t;
        if (t < meshBest) meshBest = t, meshThreads = k;
    }
    vtkSMPTools::Initialize(meshThreads);
    flyingEdges(values, R, polyData);
    const Mesh extracted = meshOf(polyData);
    const size_t flyingEdgesTriangles = extracted.triangleCount();

    // Projection: every thread count once on a fresh copy of the vertices (the copy untimed), the fastest kept.
    Mesh mesh = extracted;
    double projectBest = 0.0, refineBest = 0.0;
    int projectThreads = 0, refineThreads = 0;
    if (steps > 0) {
        projectBest = 1e30;
        for (int k : threads) {
            Mesh trial = extracted;
            const auto start = Clock::now();
            shape->project(trial.xyz.data(), 0, trial.vertexCount(), steps, k, nullptr);
            const double t = secondsSince(start);
            if (t < projectBest) projectBest = t, projectThreads = k, mesh = std::move(trial);
        }
    }
    // Refinement of the projected mesh: every thread count once on a copy (untimed), the fastest kept.
    if (levels > 0) {
        refineBest = 1e30;
        const Mesh projected = mesh;
        for (int k : threads) {
            Mesh trial = projected;
            const auto start = Clock::now();
            refine(trial, *shape, levels, refineSteps, k);
            const double t = secondsSince(start);
            if (t < refineBest) refineBest = t, refineThreads = k, mesh = std::move(trial);
        }
    }
    writePly(mesh, outPath);
    std::printf("{\"shape\": \"%s\", \"R\": %d, \"field_seconds\": %.6f, \"field_threads\": %d, \"mesh_seconds\": %.6f, "
                "\"mesh_threads\": %d, \"project_seconds\": %.6f, \"project_threads\": %d, \"project_steps\": %d, "
                "\"refine_seconds\": %.6f, \"refine_threads\": %d, \"refine_levels\": %d, \"refine_steps\": %d, "
                "\"seconds\": %.6f, \"triangles\": %zu, \"vertices\": %zu, \"flying_edges_triangles\": %zu, "
                "\"smp_backend\": \"%s\", \"flags\": \"%s\", \"mesh_seconds_by_threads\": {%s}}\n",
                shapeName.c_str(), R, fieldBest, fieldThreads, meshBest, meshThreads, projectBest, projectThreads, steps,
                refineBest, refineThreads, levels, levels > 0 ? refineSteps : 0, fieldBest + meshBest + projectBest + refineBest,
                mesh.triangleCount(), mesh.vertexCount(), flyingEdgesTriangles, vtkSMPTools::GetBackend(), PEER_FLAGS,
                perThreads.str().c_str());
    return 0;
}
