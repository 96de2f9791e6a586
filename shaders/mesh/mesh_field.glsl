// A triangle mesh as a signed distance field (meshfield/MeshField.h builds what this reads).
// Composed before the SDF's text when the SDF is a mesh file; the file's text calls sdfwb_meshSdf.
//   SDFWB_MESH_NODES_BINDING        the hierarchy: SDFWB_MESH_NODE vec4 per node (meshfield::kNodeFloats:
//                                   box min + first/left, box max + count, dipole centre + radius,
//                                   dipole, the second moment's three rows)
//   SDFWB_MESH_TRIANGLES_BINDING    three vec4 per triangle (corners), in leaf order; the first
//                                   corner's w is the cumulative share of the area (the last is 1)
//   SDFWB_MESH_PSEUDONORMALS_BINDING (pseudonormal sign only) seven vec4 per triangle:
//                                   face, edges ab bc ca, vertices a b c
//   SDFWB_MESH_LEAF                 the most triangles a leaf holds (meshfield::kMaxLeafTriangles)
//   SDFWB_MESH_STACK                entries of the traversal stack (the hierarchy's depth + 2)
//   SDFWB_MESH_BETA                 winding numbers: a cluster farther than beta radii is a dipole
//   SDFWB_MESH_SIGN_WINDING | SDFWB_MESH_SIGN_PARITY | SDFWB_MESH_SIGN_PSEUDONORMAL
//   SDFWB_MESH_SIGNS                (winding sign) where the sign lattice starts in the nodes' buffer
//   SDFWB_MESH_SURFACE              the SDF is the mesh's own field: samplers may use sdfwb_meshSurfacePoint
//   SDFWB_MESH_FRAGMENT             composed into a fragment shader (see sdfwb_meshIdleLane)
//   SDFWB_MESH_COUNT                count the walks' nodes (benchmarks; sampling/sample.comp reads them)
layout(std430, binding = SDFWB_MESH_NODES_BINDING) readonly buffer sdfwb_MeshNodes { vec4 sdfwb_meshNodes[]; };
layout(std430, binding = SDFWB_MESH_TRIANGLES_BINDING) readonly buffer sdfwb_MeshTriangles { vec4 sdfwb_meshTriangles[]; };
#ifdef SDFWB_MESH_SIGN_PSEUDONORMAL
layout(std430, binding = SDFWB_MESH_PSEUDONORMALS_BINDING) readonly buffer sdfwb_MeshPseudonormals { vec4 sdfwb_meshPseudonormals[]; };
#endif
#ifdef SDFWB_MESH_COUNT
// The invocation's walk counts (benchmarks; sample.comp adds them up): nodes whose children's boxes
// a nearest walk tested, nodes a winding walk opened or took as a dipole, signs the lattice gave,
// and the crossing sign's segment nodes and signs.
uint sdfwb_meshNearestCount = 0u;
uint sdfwb_meshWindingCount = 0u;
uint sdfwb_meshLatticeCount = 0u;
uint sdfwb_meshSegmentCount = 0u; // nodes the crossing sign's segment walks tested
uint sdfwb_meshCrossedCount = 0u; // signs the crossing sign gave
#define SDFWB_MESH_COUNTS(counter) ++counter
#else
#define SDFWB_MESH_COUNTS(counter)
#endif

// A walk that stopped before its stack emptied returns NaN: llvmpipe ends a shader invocation's
// loops after 65535 iterations in all (counted across every call in the invocation: a tracer's
// march multiplies them), and a cut walk's value would be silently wrong. NaN shows as a bad row
// in samples and magenta in the viewport.
float sdfwb_meshCut() { return uintBitsToFloat(0x7fc00000u); }

// A fragment lane whose value no pixel keeps (a helper: outside the primitive, run only for
// derivatives) walks nothing. llvmpipe runs such lanes of a partly covered block through every
// loop but drops their array stores, so their stack walks read stale entries and spin until the
// invocation's shared loop budget (above) is spent, cutting the covered lanes' walks short: lines
// of wrong pixels along every edge of the tracer's proxy box and the full-frame triangle's split.
bool sdfwb_meshIdleLane() {
#ifdef SDFWB_MESH_FRAGMENT
    return gl_HelperInvocation;
#else
    return false;
#endif
}

float sdfwb_meshBoxDistance2(vec3 p, vec3 lo, vec3 hi) {
    vec3 d = max(max(lo - p, p - hi), vec3(0.0));
    return dot(d, d);
}

// The closest point of triangle abc to p and its feature: 0 the face, 1..3 the corners a b c,
// 4..6 the edges ab bc ca (Ericson's regions; the same as meshfield::closestPointOnTriangle).
vec3 sdfwb_meshClosest(vec3 p, vec3 a, vec3 b, vec3 c, out int feature) {
    vec3 ab = b - a;
    vec3 ac = c - a;
    vec3 ap = p - a;
    float d1 = dot(ab, ap);
    float d2 = dot(ac, ap);
    feature = 1;
    if (d1 <= 0.0 && d2 <= 0.0) return a;
    vec3 bp = p - b;
    float d3 = dot(ab, bp);
    float d4 = dot(ac, bp);
    feature = 2;
    if (d3 >= 0.0 && d4 <= d3) return b;
    float vc = d1 * d4 - d3 * d2;
    feature = 4;
    if (vc <= 0.0 && d1 >= 0.0 && d3 <= 0.0) return a + ab * (d1 / (d1 - d3));
    vec3 cp = p - c;
    float d5 = dot(ab, cp);
    float d6 = dot(ac, cp);
    feature = 3;
    if (d6 >= 0.0 && d5 <= d6) return c;
    float vb = d5 * d2 - d1 * d6;
    feature = 6;
    if (vb <= 0.0 && d2 >= 0.0 && d6 <= 0.0) return a + ac * (d2 / (d2 - d6));
    float va = d3 * d6 - d5 * d4;
    feature = 5;
    if (va <= 0.0 && d4 - d3 >= 0.0 && d5 - d6 >= 0.0) return b + (c - b) * ((d4 - d3) / ((d4 - d3) + (d5 - d6)));
    float sum = va + vb + vc;
    if (!(sum > 0.0)) { // degenerate: the nearest edge
        vec3 q = a;
        float best = 1e38;
        for (int e = 0; e < 3; ++e) {
            vec3 s = e == 0 ? a : (e == 1 ? b : c);
            vec3 d = (e == 0 ? b : (e == 1 ? c : a)) - s;
            float len2 = dot(d, d);
            vec3 r = s + d * (len2 > 0.0 ? clamp(dot(p - s, d) / len2, 0.0, 1.0) : 0.0);
            if (dot(p - r, p - r) < best) {
                best = dot(p - r, p - r);
                q = r;
                feature = 4 + e;
            }
        }
        return q;
    }
    feature = 0;
    return a + ab * (vb / sum) + ac * (vc / sum);
}

// One compare-exchange of a sorting network: order[i] before order[j] when farther.
void sdfwb_meshOrder(inout ivec4 order, vec4 d2, int i, int j) {
    if (d2[order[i]] < d2[order[j]]) {
        int swapped = order[i];
        order[i] = order[j];
        order[j] = swapped;
    }
}

// A stack entry of the four-wide walks: an inner node's index, or a leaf (top bit set, its first
// triangle times 8 plus its count), from a wide node's child slot.
uint sdfwb_meshWideEntry(uint child, uint count) { return count > 0u ? (0x80000000u | (child << 3u) | count) : child; }
bool sdfwb_meshIsLeafEntry(uint entry) { return (entry & 0x80000000u) != 0u; }
uint sdfwb_meshLeafFirst(uint entry) { return (entry & 0x7fffffffu) >> 3u; }
uint sdfwb_meshLeafCount(uint entry) { return entry & 7u; }

// The squared distance to the nearest triangle, which triangle (leaf order), its feature and point;
// `bound2` when no triangle is nearer than its root (then triangle 0 and closest p): a walk that
// needs the distance only below a bound prunes every box beyond it. Among equally near triangles
// the lowest slot wins, so a walk started from any triangle's distance ends at the same one. It walks the four-wide
// hierarchy (meshfield::kWideNodeFloats, from vec4 SDFWB_MESH_WIDE on): one step reads a node's
// eight vec4 and tests its four children's boxes at once, nearest child walked next; a stack entry
// is an inner node, or a leaf (top bit set, its first triangle times 8 plus its count), with the
// distance of its box, so that an entry a nearer triangle has since put out of reach costs no read.
float sdfwb_meshNearestWalk(vec3 p, float bound2, inout uint triangle, inout int feature, inout vec3 closest) {
    if (sdfwb_meshIdleLane()) return 1.0;
    uint stack[SDFWB_MESH_WIDE_STACK];
    float reach[SDFWB_MESH_WIDE_STACK];
    int top = 0;
    stack[0] = 0u;
    reach[0] = 0.0;
    top = 1;
    float best = bound2;
    while (top > 0) {
        --top;
        if (reach[top] > best) continue;
        uint entry = stack[top];
        if (sdfwb_meshIsLeafEntry(entry)) {
            uint first = sdfwb_meshLeafFirst(entry);
            uint count = sdfwb_meshLeafCount(entry);
            // A constant bound: the driver unrolls the leaf, so that its triangles cost no loop budget.
            for (uint k = 0u; k < SDFWB_MESH_LEAF; ++k) {
                if (k >= count) break;
                uint s = first + k;
                int f;
                vec3 q = sdfwb_meshClosest(p, sdfwb_meshTriangles[3u * s].xyz, sdfwb_meshTriangles[3u * s + 1u].xyz,
                                           sdfwb_meshTriangles[3u * s + 2u].xyz, f);
                float d2 = dot(p - q, p - q);
                if (d2 < best || (d2 == best && s < triangle)) { // ties: the lowest slot, as the CPU engine
                    best = d2;
                    triangle = s;
                    feature = f;
                    closest = q;
                }
            }
            continue;
        }
        uint at = SDFWB_MESH_WIDE + 8u * entry;
        SDFWB_MESH_COUNTS(sdfwb_meshNearestCount);
        vec4 dx = max(max(sdfwb_meshNodes[at] - p.x, p.x - sdfwb_meshNodes[at + 3u]), vec4(0.0));
        vec4 dy = max(max(sdfwb_meshNodes[at + 1u] - p.y, p.y - sdfwb_meshNodes[at + 4u]), vec4(0.0));
        vec4 dz = max(max(sdfwb_meshNodes[at + 2u] - p.z, p.z - sdfwb_meshNodes[at + 5u]), vec4(0.0));
        vec4 d2 = dx * dx + dy * dy + dz * dz; // an empty slot's is infinite
        uvec4 child = floatBitsToUint(sdfwb_meshNodes[at + 6u]);
        uvec4 count = floatBitsToUint(sdfwb_meshNodes[at + 7u]);
        // The children by distance, farthest first (five compare-exchanges), pushed while nearer
        // than the best: the nearest ends on top.
        ivec4 order = ivec4(0, 1, 2, 3);
        sdfwb_meshOrder(order, d2, 0, 1);
        sdfwb_meshOrder(order, d2, 2, 3);
        sdfwb_meshOrder(order, d2, 0, 2);
        sdfwb_meshOrder(order, d2, 1, 3);
        sdfwb_meshOrder(order, d2, 1, 2);
        for (int j = 0; j < 4; ++j) {
            int k = order[j];
            if (!(d2[k] <= best) || top >= SDFWB_MESH_WIDE_STACK) continue;
            stack[top] = sdfwb_meshWideEntry(child[k], count[k]);
            reach[top] = d2[k];
            ++top;
        }
    }
    return top > 0 ? sdfwb_meshCut() : best;
}

float sdfwb_meshNearestWithin(vec3 p, float bound2, out uint triangle, out int feature, out vec3 closest) {
    triangle = 0u;
    feature = 0;
    closest = p;
    return sdfwb_meshNearestWalk(p, bound2, triangle, feature, closest);
}

#if defined(SDFWB_MESH_SIGN_WINDING) && defined(SDFWB_MESH_SIGNS)
// The nearest triangle of the sign lattice's point nearest p (MeshQuery::signLattice's seeds,
// after its winding numbers and slopes), or 0xffffffff where there is none: its distance bounds
// p's nearest walk from the start, as the CPU engine's walk starts from the last row's triangle.
uint sdfwb_meshLatticeSeed(vec3 p) {
    vec4 origin = sdfwb_meshNodes[SDFWB_MESH_SIGNS];
    vec4 header = sdfwb_meshNodes[SDFWB_MESH_SIGNS + 1u];
    const uint exponent = 0x7f800000u;
    if (header.x < 2.0 || header.w < 0.5 || any(equal(floatBitsToUint(p) & exponent, uvec3(exponent)))) return 0xffffffffu;
    vec3 at = clamp(floor((p - origin.xyz) / origin.w + 0.5), vec3(0.0), vec3(header.x - 1.0));
    uint n = uint(header.x);
    uint i = 8u + n * n * n * (header.z > 0.5 ? 2u : 1u) + (uint(at.z) * n + uint(at.y)) * n + uint(at.x);
    uint seed = floatBitsToUint(sdfwb_meshNodes[SDFWB_MESH_SIGNS + i / 4u][i % 4u]);
    return seed < uint(sdfwb_meshTriangles.length()) / 3u ? seed : 0xffffffffu;
}
#endif

// The nearest triangle (see sdfwb_meshNearestWithin), the walk bounded from the start by the
// lattice's seed where the field has one: the same triangle as without it (among equally near
// triangles the lowest slot wins, as in the CPU engine's walk).
float sdfwb_meshNearest(vec3 p, out uint triangle, out int feature, out vec3 closest) {
#if defined(SDFWB_MESH_SIGN_WINDING) && defined(SDFWB_MESH_SIGNS)
    uint seed = sdfwb_meshLatticeSeed(p);
    if (seed != 0xffffffffu) {
        triangle = seed;
        closest = sdfwb_meshClosest(p, sdfwb_meshTriangles[3u * seed].xyz, sdfwb_meshTriangles[3u * seed + 1u].xyz,
                                    sdfwb_meshTriangles[3u * seed + 2u].xyz, feature);
        return sdfwb_meshNearestWalk(p, dot(p - closest, p - closest), triangle, feature, closest);
    }
#endif
    return sdfwb_meshNearestWithin(p, 3.0e38, triangle, feature, closest);
}

// The unsigned distance, or `bound` when it is larger.
float sdfwb_meshDistanceWithin(vec3 p, float bound) {
    uint t;
    int f;
    vec3 q;
    return sqrt(sdfwb_meshNearestWithin(p, bound * bound, t, f, q));
}

float sdfwb_meshDistance(vec3 p) {
    uint t;
    int f;
    vec3 q;
    return sqrt(sdfwb_meshNearest(p, t, f, q));
}

// Signed solid angle of triangle abc seen from p (van Oosterom and Strackee).
float sdfwb_meshSolidAngle(vec3 p, vec3 a, vec3 b, vec3 c) {
    vec3 A = a - p;
    vec3 B = b - p;
    vec3 C = c - p;
    float la = length(A);
    float lb = length(B);
    float lc = length(C);
    float det = dot(A, cross(B, C));
    float den = la * lb * lc + dot(A, B) * lc + dot(B, C) * la + dot(C, A) * lb;
    return 2.0 * atan(det, den);
}

// The generalized winding number: 1 inside a closed, outward-facing mesh, 0 outside; near clusters
// add their triangles' solid angles, far ones their dipole and second moment (Barill et al. 2018).
float sdfwb_meshWinding(vec3 p) {
    if (sdfwb_meshIdleLane()) return 0.0;
    uint stack[2 * SDFWB_MESH_STACK];
    int top = 0;
    stack[top++] = 0u;
    float sum = 0.0;
    while (top > 0) {
        uint n = stack[--top];
        SDFWB_MESH_COUNTS(sdfwb_meshWindingCount);
        vec4 centre = sdfwb_meshNodes[SDFWB_MESH_NODE * n + 2u];
        vec3 d = centre.xyz - p;
        float dist2 = dot(d, d);
        float reach = SDFWB_MESH_BETA * centre.w;
        if (dist2 > reach * reach) {
            // The dipole's term and the second moment's: trace(M) / |d|^3 - 3 d.M d / |d|^5
            // (meshfield's farCluster).
            float inverse3 = 1.0 / (dist2 * sqrt(dist2));
            // M's rows as columns: M^T, whose trace and d.M d are M's.
            mat3 moment = mat3(sdfwb_meshNodes[SDFWB_MESH_NODE * n + 4u].xyz, sdfwb_meshNodes[SDFWB_MESH_NODE * n + 5u].xyz,
                               sdfwb_meshNodes[SDFWB_MESH_NODE * n + 6u].xyz);
            float trace = moment[0][0] + moment[1][1] + moment[2][2];
            sum += (dot(sdfwb_meshNodes[SDFWB_MESH_NODE * n + 3u].xyz, d) + trace - 3.0 * dot(d, moment * d) / dist2) * inverse3;
            continue;
        }
        uint first = floatBitsToUint(sdfwb_meshNodes[SDFWB_MESH_NODE * n].w);
        uint count = floatBitsToUint(sdfwb_meshNodes[SDFWB_MESH_NODE * n + 1u].w);
        if (count > 0u) {
            for (uint k = 0u; k < SDFWB_MESH_LEAF; ++k) {
                if (k >= count) break;
                uint s = first + k;
                sum += sdfwb_meshSolidAngle(p, sdfwb_meshTriangles[3u * s].xyz, sdfwb_meshTriangles[3u * s + 1u].xyz,
                                            sdfwb_meshTriangles[3u * s + 2u].xyz);
            }
        } else {
            stack[top++] = first;
            stack[top++] = first + 1u;
        }
    }
    return top > 0 ? sdfwb_meshCut() : sum / (4.0 * 3.14159265358979);
}

// Where the line origin + t direction meets triangle slot s (Moller-Trumbore): its t, or -1e38
// when it passes the triangle or runs parallel to it.
float sdfwb_meshRayTriangle(vec3 origin, vec3 direction, uint s) {
    vec3 a = sdfwb_meshTriangles[3u * s].xyz;
    vec3 e1 = sdfwb_meshTriangles[3u * s + 1u].xyz - a;
    vec3 e2 = sdfwb_meshTriangles[3u * s + 2u].xyz - a;
    vec3 h = cross(direction, e2);
    float det = dot(e1, h);
    if (det == 0.0) return -1e38;
    vec3 o = origin - a;
    float u = dot(o, h) / det;
    vec3 q = cross(o, e1);
    float v = dot(direction, q) / det;
    return u >= 0.0 && v >= 0.0 && u + v <= 1.0 ? dot(e2, q) / det : -1e38;
}

// Crossings of the ray p + t d (t > 0) with the mesh.
int sdfwb_meshCrossings(vec3 p, vec3 d) {
    if (sdfwb_meshIdleLane()) return 0;
    vec3 inverse = 1.0 / d;
    uint stack[2 * SDFWB_MESH_STACK];
    int top = 0;
    stack[top++] = 0u;
    int crossings = 0;
    while (top > 0) {
        uint n = stack[--top];
        vec4 lo = sdfwb_meshNodes[SDFWB_MESH_NODE * n];
        vec4 hi = sdfwb_meshNodes[SDFWB_MESH_NODE * n + 1u];
        vec3 t0 = (lo.xyz - p) * inverse;
        vec3 t1 = (hi.xyz - p) * inverse;
        vec3 tmin = min(t0, t1);
        vec3 tmax = max(t0, t1);
        if (max(max(tmin.x, tmin.y), max(tmin.z, 0.0)) > min(min(tmax.x, tmax.y), tmax.z)) continue;
        uint first = floatBitsToUint(lo.w);
        uint count = floatBitsToUint(hi.w);
        if (count > 0u) {
            for (uint k = 0u; k < SDFWB_MESH_LEAF; ++k) {
                if (k >= count) break;
                if (sdfwb_meshRayTriangle(p, d, first + k) > 0.0) ++crossings;
            }
        } else {
            stack[top++] = first;
            stack[top++] = first + 1u;
        }
    }
    return top > 0 ? -1 : crossings;
}

// The first triangle the ray origin + t direction meets for t in [tMin, tMax]: its t, and its slot
// in `triangle` (0xffffffff and tMax when none does; NaN when the walk was cut). Nearer child
// first, and a box is entered only when it starts before the best hit so far: one walk a pixel
// where a sphere tracer calls the whole field (nearest triangle and sign) at every step.
float sdfwb_meshRaycast(vec3 origin, vec3 direction, float tMin, float tMax, out uint triangle) {
    triangle = 0xffffffffu;
    if (sdfwb_meshIdleLane()) return tMax;
    vec3 inverse = 1.0 / direction;
    uint stack[SDFWB_MESH_STACK];
    float stackEnter[SDFWB_MESH_STACK]; // where the ray enters each pushed node's box
    int top = 0;
    stack[top] = 0u;
    stackEnter[top++] = tMin;
    float best = tMax;
    while (top > 0) {
        --top;
        if (stackEnter[top] > best) continue; // a nearer hit was found since it was pushed
        uint n = stack[top];
        vec4 lo = sdfwb_meshNodes[SDFWB_MESH_NODE * n];
        vec4 hi = sdfwb_meshNodes[SDFWB_MESH_NODE * n + 1u];
        uint first = floatBitsToUint(lo.w);
        uint count = floatBitsToUint(hi.w);
        if (count > 0u) {
            for (uint k = 0u; k < SDFWB_MESH_LEAF; ++k) { // unrolled, as in sdfwb_meshNearest
                if (k >= count) break;
                float t = sdfwb_meshRayTriangle(origin, direction, first + k);
                if (t >= tMin && t < best) {
                    best = t;
                    triangle = first + k;
                }
            }
            continue;
        }
        // Where the ray enters each child's box (within [tMin, best]); +inf when it does not.
        vec2 enter = vec2(3.0e38);
        for (int c = 0; c < 2; ++c) {
            uint child = first + uint(c);
            vec3 t0 = (sdfwb_meshNodes[SDFWB_MESH_NODE * child].xyz - origin) * inverse;
            vec3 t1 = (sdfwb_meshNodes[SDFWB_MESH_NODE * child + 1u].xyz - origin) * inverse;
            vec3 tNear = min(t0, t1);
            vec3 tFar = max(t0, t1);
            float from = max(max(tNear.x, tNear.y), max(tNear.z, tMin));
            float to = min(min(tFar.x, tFar.y), min(tFar.z, best));
            if (from <= to) enter[c] = from;
        }
        bool leftFirst = enter.x <= enter.y;
        float nearEnter = leftFirst ? enter.x : enter.y;
        float farEnter = leftFirst ? enter.y : enter.x;
        if (farEnter < 3.0e38) {
            stack[top] = leftFirst ? first + 1u : first;
            stackEnter[top++] = farEnter;
        }
        if (nearEnter < 3.0e38) {
            stack[top] = leftFirst ? first : first + 1u;
            stackEnter[top++] = nearEnter;
        }
    }
    if (top > 0) return sdfwb_meshCut();
    return best;
}

#if defined(SDFWB_MESH_SIGN_WINDING) && defined(SDFWB_MESH_SIGNS)
// The sign from the lattice of winding numbers after the hierarchy (MeshQuery::signLattice): 1
// inside, 0 outside, -1 when it cannot decide. No triangle lies within the nearest distance d of
// p, so the winding number changes along the segment from p to a lattice point q in that ball
// only by the open boundary's field: at most L s / (4 pi (d - s)^2) (L the boundary's length, s
// = |p - q|; nothing on a closed, oriented mesh). q's winding number farther from 1/2 than that
// plus 1/4 (the hierarchy's approximation at p and at q) decides p's sign without a walk, as the
// CPU engine's sign cache does.
float sdfwb_meshLatticeInside(vec3 p, float d) {
    vec4 origin = sdfwb_meshNodes[SDFWB_MESH_SIGNS];
    vec4 header = sdfwb_meshNodes[SDFWB_MESH_SIGNS + 1u];
    float side = header.x;
    if (side < 2.0 || !(d > 0.0)) return -1.0;
    vec3 at = clamp(floor((p - origin.xyz) / origin.w + 0.5), vec3(0.0), vec3(side - 1.0));
    float s = length(p - (origin.xyz + at * origin.w));
    if (!(s < d * 0.999)) return -1.0;
    float change = header.y * s / (12.566370614 * (d - s) * (d - s));
    if (!(change < 0.25)) return -1.0;
    uint n = uint(side);
    uint i = (uint(at.z) * n + uint(at.y)) * n + uint(at.x) + 8u;
    float w = sdfwb_meshNodes[SDFWB_MESH_SIGNS + i / 4u][i % 4u];
    return abs(w - 0.5) >= change + 0.25 ? (w > 0.5 ? 1.0 : 0.0) : -1.0;
}

// The oriented crossings of the segment q -> p with the mesh in `net` (w(p) - w(q) on the surface's
// account: -1 out through a triangle's front, +1 in through its back); false when a crossing lies
// too near a triangle's edge or corner, or an end too near its plane, to be counted with certainty
// in float (MeshQuery::segmentCrossings with float tolerances), or the walk was cut.
bool sdfwb_meshSegmentCrossings(vec3 q, vec3 p, out int net) {
    net = 0;
    vec3 direction = p - q;
    // A zero component's slab test is left to the boxes' other axes (as the CPU engine's walk).
    vec3 inverse = 1.0 / mix(vec3(1e-30), direction, greaterThan(abs(direction), vec3(1e-30)));
    float scale = max(max(abs(q.x), abs(q.y)), max(abs(q.z), 1.0));
    float slack = 1e-5 * scale;     // boxes widened by more than the float rounding of the ends
    float tolerance = 1e-6 * scale; // an end this near a triangle's plane is on it
    const float edge = 1e-4;        // a crossing this near an edge (barycentric) is on it
    // The four-wide hierarchy, as sdfwb_meshNearestWalk walks it: a step tests a node's four
    // children's boxes at once (half the steps of the two-child walk; sdfwb_meshWideEntry).
    uint stack[SDFWB_MESH_WIDE_STACK];
    int top = 0;
    stack[top++] = 0u;
    while (top > 0) {
        uint entry = stack[--top];
        if (sdfwb_meshIsLeafEntry(entry)) {
            uint first = sdfwb_meshLeafFirst(entry);
            uint count = sdfwb_meshLeafCount(entry);
            for (uint k = 0u; k < SDFWB_MESH_LEAF; ++k) {
                if (k >= count) break;
                uint s = first + k;
                vec3 a = sdfwb_meshTriangles[3u * s].xyz;
                vec3 b = sdfwb_meshTriangles[3u * s + 1u].xyz;
                vec3 c = sdfwb_meshTriangles[3u * s + 2u].xyz;
                vec3 normal = cross(b - a, c - a);
                float area2 = dot(normal, normal);
                if (!(area2 > 0.0)) continue; // no area: its solid angle is zero everywhere
                float unit = inversesqrt(area2);
                float sq = dot(q - a, normal) * unit;
                float sp = dot(p - a, normal) * unit;
                if ((sq > tolerance && sp > tolerance) || (sq < -tolerance && sp < -tolerance)) continue;
                if (abs(sq) <= tolerance || abs(sp) <= tolerance) return false;
                vec3 x = q + direction * (sq / (sq - sp));
                float la = dot(cross(c - b, x - b), normal) / area2;
                float lb = dot(cross(a - c, x - c), normal) / area2;
                float lc = dot(cross(b - a, x - a), normal) / area2;
                if (la < -edge || lb < -edge || lc < -edge) continue; // beside the triangle
                if (la <= edge || lb <= edge || lc <= edge) return false;
                net += dot(direction, normal) > 0.0 ? -1 : 1;
            }
            continue;
        }
        uint at = SDFWB_MESH_WIDE + 8u * entry;
        SDFWB_MESH_COUNTS(sdfwb_meshSegmentCount);
        vec4 loX = sdfwb_meshNodes[at], loY = sdfwb_meshNodes[at + 1u], loZ = sdfwb_meshNodes[at + 2u];
        vec4 hiX = sdfwb_meshNodes[at + 3u], hiY = sdfwb_meshNodes[at + 4u], hiZ = sdfwb_meshNodes[at + 5u];
        vec4 t0x = (loX - slack - q.x) * inverse.x, t1x = (hiX + slack - q.x) * inverse.x;
        vec4 t0y = (loY - slack - q.y) * inverse.y, t1y = (hiY + slack - q.y) * inverse.y;
        vec4 t0z = (loZ - slack - q.z) * inverse.z, t1z = (hiZ + slack - q.z) * inverse.z;
        vec4 enter = max(max(min(t0x, t1x), min(t0y, t1y)), max(min(t0z, t1z), vec4(0.0)));
        vec4 leave = min(min(max(t0x, t1x), max(t0y, t1y)), min(max(t0z, t1z), vec4(1.0)));
        uvec4 child = floatBitsToUint(sdfwb_meshNodes[at + 6u]);
        uvec4 count = floatBitsToUint(sdfwb_meshNodes[at + 7u]);
        for (int k = 0; k < 4; ++k) {
            if (loX[k] > hiX[k] || enter[k] > leave[k] * 1.00001 + 1e-5) continue; // an empty slot, or missed
            if (top >= SDFWB_MESH_WIDE_STACK) return false;
            stack[top++] = sdfwb_meshWideEntry(child[k], count[k]);
        }
    }
    return top == 0;
}

// The crossing sign (MeshQuery::crossedWindingInside), for rows too near the surface for a lattice
// point to lie in their empty ball: from the nearest lattice point q, w(p) = w(q) + the segment's
// oriented crossings, give or take the open boundary's field along it (its slope bound at q times
// |p - q|; none on a closed, oriented mesh). 1 inside, 0 outside, -1 when that cannot decide.
float sdfwb_meshCrossedInside(vec3 p) {
    vec4 origin = sdfwb_meshNodes[SDFWB_MESH_SIGNS];
    vec4 header = sdfwb_meshNodes[SDFWB_MESH_SIGNS + 1u];
    float side = header.x;
    if (side < 2.0) return -1.0;
    vec3 at = floor((p - origin.xyz) / origin.w + 0.5);
    if (any(lessThan(at, vec3(0.0))) || any(greaterThan(at, vec3(side - 1.0)))) return -1.0; // outside the lattice
    vec3 q = origin.xyz + at * origin.w;
    uint n = uint(side);
    uint i = (uint(at.z) * n + uint(at.y)) * n + uint(at.x) + 8u;
    float slope = header.z > 0.5 ? sdfwb_meshNodes[SDFWB_MESH_SIGNS + (i + n * n * n) / 4u][(i + n * n * n) % 4u] : 0.0;
    float change = slope * length(p - q);
    if (!(change < 0.25)) return -1.0;
    int net;
    if (!sdfwb_meshSegmentCrossings(q, p, net)) return -1.0;
    float estimate = sdfwb_meshNodes[SDFWB_MESH_SIGNS + i / 4u][i % 4u] + float(net);
    return abs(estimate - 0.5) >= change + 0.25 ? (estimate > 0.5 ? 1.0 : 0.0) : -1.0;
}
#endif

// 1 inside, 0 outside, NaN when a walk was cut (see sdfwb_meshCut).
float sdfwb_meshInside(vec3 p, uint triangle, int feature, vec3 closest) {
#if defined(SDFWB_MESH_SIGN_PARITY)
    // The majority of three skewed rays (meshfield's parityDirections()); the third is cast only
    // when the first two disagree. One call site in a loop: the walk is compiled once.
    const vec3 directions[3] = vec3[3](vec3(1.0, 0.3183, 0.1415), vec3(-0.2718, 1.0, 0.5772), vec3(0.1618, -0.4142, 1.0));
    int odd = 0;
    for (int r = 0; r < 3; ++r) {
        if (r == 2 && odd != 1) break;
        int crossings = sdfwb_meshCrossings(p, normalize(directions[r]));
        if (crossings < 0) return sdfwb_meshCut();
        odd += crossings & 1;
    }
    return odd >= 2 ? 1.0 : 0.0;
#elif defined(SDFWB_MESH_SIGN_PSEUDONORMAL)
    const int slot[7] = int[7](0, 4, 5, 6, 1, 2, 3);
    return dot(p - closest, sdfwb_meshPseudonormals[7u * triangle + uint(slot[feature])].xyz) < 0.0 ? 1.0 : 0.0;
#else
#if defined(SDFWB_MESH_SIGNS)
    float d = length(p - closest);
    float cached = sdfwb_meshLatticeInside(p, d);
    if (cached >= 0.0) {
        SDFWB_MESH_COUNTS(sdfwb_meshLatticeCount);
        return cached;
    }
    float crossed = d > 0.0 ? sdfwb_meshCrossedInside(p) : -1.0;
    if (crossed >= 0.0) {
        SDFWB_MESH_COUNTS(sdfwb_meshCrossedCount);
        return crossed;
    }
#endif
    float winding = sdfwb_meshWinding(p);
    return isnan(winding) ? winding : (winding > 0.5 ? 1.0 : 0.0);
#endif
}

float sdfwb_meshSdf(vec3 p) {
    uint triangle;
    int feature;
    vec3 closest;
    float d = sqrt(sdfwb_meshNearest(p, triangle, feature, closest));
    float inside = sdfwb_meshInside(p, triangle, feature, closest);
    return isnan(inside) ? inside : (inside > 0.5 ? -d : d);
}

// The signed distance and its exact gradient: the unit vector from the closest point to p, times
// the sign (the face's unit normal where p is on the surface). NaN where a walk was cut.
float sdfwb_meshSdfGradient(vec3 p, out vec3 gradient) {
    uint triangle;
    int feature;
    vec3 closest;
    float d = sqrt(sdfwb_meshNearest(p, triangle, feature, closest));
    float inside = sdfwb_meshInside(p, triangle, feature, closest);
    float sign = inside > 0.5 ? -1.0 : 1.0;
    if (d > 0.0) {
        gradient = (p - closest) * (sign / d);
    } else {
        vec3 a = sdfwb_meshTriangles[3u * triangle].xyz;
        vec3 n = cross(sdfwb_meshTriangles[3u * triangle + 1u].xyz - a, sdfwb_meshTriangles[3u * triangle + 2u].xyz - a);
        float length2 = dot(n, n);
        gradient = length2 > 0.0 ? n * inversesqrt(length2) : vec3(0.0);
    }
    if (isnan(inside) || isnan(d)) gradient = vec3(sdfwb_meshCut());
    return isnan(inside) ? inside : sign * d;
}

// A point uniform by area on the mesh, and its triangle's unit normal (zero for a degenerate one),
// from three uniform numbers in [0, 1): u.x picks the triangle (binary search of the cumulative
// areas), u.yz the point in it. The surface and near samplers take their points from here when
// the SDF is the mesh's own field (SDFWB_MESH_SURFACE): exact, and no ray to march.
void sdfwb_meshSurfacePoint(vec3 u, out vec3 point, out vec3 normal) {
    uint lo = 0u;
    uint hi = uint(sdfwb_meshTriangles.length()) / 3u - 1u;
    while (lo < hi) {
        uint mid = (lo + hi) / 2u;
        if (sdfwb_meshTriangles[3u * mid].w <= u.x)
            lo = mid + 1u;
        else
            hi = mid;
    }
    vec3 a = sdfwb_meshTriangles[3u * lo].xyz;
    vec3 b = sdfwb_meshTriangles[3u * lo + 1u].xyz;
    vec3 c = sdfwb_meshTriangles[3u * lo + 2u].xyz;
    float s = sqrt(u.y);
    point = a * (1.0 - s) + b * (s * (1.0 - u.z)) + c * (s * u.z);
    vec3 n = cross(b - a, c - a);
    float length2 = dot(n, n);
    normal = length2 > 0.0 ? n * inversesqrt(length2) : vec3(0.0);
}
