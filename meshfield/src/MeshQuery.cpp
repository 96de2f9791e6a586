#include <meshfield/MeshQuery.h>

#include "FloatBits.h"
#include "QueryShared.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <mutex>
#include <numbers>
#include <thread>
#include <unordered_map>

namespace sdfwb::meshfield {
namespace {

using glm::dvec3;

constexpr int kStack = 128; // the hierarchy's depth is at most 60 (MeshField.cpp's kMaxDepth) + 2
// The sign cache's levels whose points start the crossing segments, tried in this order: 2^6 + 1
// points a side, then the finest, whose shorter segments pass nearer an open boundary.
constexpr int kCrossingLevels[2] = {6, 7};
// Where level k (2 .. 7, 2^k + 1 points a side) of the sign cache starts in its one array.
constexpr std::size_t levelOffset(int k) {
    std::size_t offset = 0;
    for (int j = 2; j < k; ++j) offset += std::size_t((1 << j) + 1) * ((1 << j) + 1) * ((1 << j) + 1);
    return offset;
}

using detail::asBits;
using detail::latticePoints;
using detail::roundedUp;
using detail::threadCount;

// Squared distance from p to triangle t (three corners at t[0..2], t[4..6], t[8..10]) in float:
// Ericson's regions, as closestPointOnTriangle, for a quick test before the double one.
inline float closestDistance2(float px, float py, float pz, const float* t) {
    const float ax = t[0], ay = t[1], az = t[2];
    const float abx = t[4] - ax, aby = t[5] - ay, abz = t[6] - az;
    const float acx = t[8] - ax, acy = t[9] - ay, acz = t[10] - az;
    const float apx = px - ax, apy = py - ay, apz = pz - az;
    auto length2 = [](float x, float y, float z) { return x * x + y * y + z * z; };
    const float d1 = abx * apx + aby * apy + abz * apz;
    const float d2 = acx * apx + acy * apy + acz * apz;
    if (d1 <= 0.0f && d2 <= 0.0f) return length2(apx, apy, apz);
    const float bpx = apx - abx, bpy = apy - aby, bpz = apz - abz;
    const float d3 = abx * bpx + aby * bpy + abz * bpz;
    const float d4 = acx * bpx + acy * bpy + acz * bpz;
    if (d3 >= 0.0f && d4 <= d3) return length2(bpx, bpy, bpz);
    const float vc = d1 * d4 - d3 * d2;
    if (vc <= 0.0f && d1 >= 0.0f && d3 <= 0.0f) {
        const float v = d1 / (d1 - d3);
        return length2(apx - v * abx, apy - v * aby, apz - v * abz);
    }
    const float cpx = apx - acx, cpy = apy - acy, cpz = apz - acz;
    const float d5 = abx * cpx + aby * cpy + abz * cpz;
    const float d6 = acx * cpx + acy * cpy + acz * cpz;
    if (d6 >= 0.0f && d5 <= d6) return length2(cpx, cpy, cpz);
    const float vb = d5 * d2 - d1 * d6;
    if (vb <= 0.0f && d2 >= 0.0f && d6 <= 0.0f) {
        const float w = d2 / (d2 - d6);
        return length2(apx - w * acx, apy - w * acy, apz - w * acz);
    }
    const float va = d3 * d6 - d5 * d4;
    if (va <= 0.0f && d4 - d3 >= 0.0f && d5 - d6 >= 0.0f) {
        const float w = (d4 - d3) / ((d4 - d3) + (d5 - d6));
        return length2(bpx - w * (acx - abx), bpy - w * (acy - aby), bpz - w * (acz - abz));
    }
    const float sum = va + vb + vc;
    if (!(sum > 0.0f)) return 0.0f; // degenerate: leave it to the double computation
    const float v = vb / sum, w = vc / sum;
    return length2(apx - abx * v - acx * w, apy - aby * v - acy * w, apz - abz * v - acz * w);
}

// The mesh's boundary as an oriented chain: every edge whose net use (times used a -> b minus times
// used b -> a) is not zero, with that count's absolute value; none on a closed, consistently
// oriented mesh (or several). A hole's rim counts once, a flipped face's rim twice. The winding
// number's gradient is the Biot-Savart integral over that boundary (the solid angle is the
// potential of a current loop), so |grad w(x)| <= sum of weight x length / (4 pi r^2) over the
// edges, r the distance from x to each.
template <class Visit> void forEachOpenEdge(const TriangleMesh& mesh, Visit visit) {
    std::unordered_map<std::uint64_t, int> net;
    net.reserve(mesh.indices.size());
    for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3)
        for (int k = 0; k < 3; ++k) {
            const std::uint64_t a = mesh.indices[t + std::size_t(k)];
            const std::uint64_t b = mesh.indices[t + std::size_t((k + 1) % 3)];
            if (a == b) continue;
            net[std::min(a, b) << 32 | std::max(a, b)] += a < b ? 1 : -1;
        }
    for (const auto& [edge, count] : net)
        if (count != 0)
            visit(glm::dvec3(mesh.vertices[edge >> 32]), glm::dvec3(mesh.vertices[edge & 0xffffffffu]), double(std::abs(count)));
}

double segmentDistance(const dvec3& x, const dvec3& a, const dvec3& b) {
    const dvec3 ab = b - a;
    const double length2 = glm::dot(ab, ab);
    const double t = length2 > 0.0 ? std::clamp(glm::dot(x - a, ab) / length2, 0.0, 1.0) : 0.0;
    return glm::length(x - (a + t * ab));
}

} // namespace

// The parity sign's three ray directions (MeshField.cpp; the same in shaders/mesh/mesh_field.glsl).
const std::array<glm::dvec3, 3>& parityDirections();

// An inner node of the hierarchy as the CPU walks it: MeshField's four-wide node (kWideNodeFloats),
// the children's boxes side by side, so that one step tests four boxes in one vector operation
// without touching the children. child[k] is an inner node's index (count[k] == 0) or a leaf's
// first triangle slot (count[k] triangles); an empty slot has an empty box (lo +inf, hi -inf),
// whose distance is infinite.
struct alignas(64) MeshQuery::Node {
    float lo[3][4];
    float hi[3][4];
    std::uint32_t child[4];
    std::uint32_t count[4];
};

MeshQuery::MeshQuery(const MeshField& field) : m_field(field) {
    static_assert(sizeof(Node) == kWideNodeFloats * sizeof(float), "MeshQuery::Node is MeshField's four-wide node");
    m_nodes.resize(field.wideNodes.size() / kWideNodeFloats);
    if (!m_nodes.empty()) std::memcpy(static_cast<void*>(m_nodes.data()), field.wideNodes.data(), m_nodes.size() * sizeof(Node));
    const std::size_t slots = field.triangles.size() / kTriangleFloats;
    m_corners.resize(slots * 9);
    for (std::size_t s = 0; s < slots; ++s)
        for (int k = 0; k < 3; ++k)
            for (int a = 0; a < 3; ++a)
                m_corners[s * 9 + std::size_t(k * 3 + a)] = field.triangles[s * kTriangleFloats + std::size_t(k * 4 + a)];

    m_scale = std::max({std::abs(field.bounds.lo.x), std::abs(field.bounds.lo.y), std::abs(field.bounds.lo.z),
                        std::abs(field.bounds.hi.x), std::abs(field.bounds.hi.y), std::abs(field.bounds.hi.z)});
    if (!std::isfinite(m_scale)) m_scale = 0.0;
    // The sign cache's box also orders the rows (Morton codes over it), whatever the sign method.
    double side = 0.0;
    m_cacheLo = mortonBoxCorner(field, side);
    m_cacheSide = 128;
    m_cacheStep = side / m_cacheSide;
    if (field.options.sign == SignMethod::Winding) {
        m_useCache = true;
        m_boundaryLength = 0.0;
        forEachOpenEdge(field.mesh, [&](const dvec3& a, const dvec3& b, double weight) {
            m_boundary.push_back({a, b, weight});
            m_boundaryLength += weight * glm::length(b - a);
        });
        // Levels of 2^k + 1 points a side (k = 2 .. 7), coarsest first, in one array.
        std::size_t total = 0;
        for (int k = 2; k <= 7; ++k) total += std::size_t((1 << k) + 1) * ((1 << k) + 1) * ((1 << k) + 1);
        m_cache = std::make_unique<std::atomic<float>[]>(total);
        for (std::size_t i = 0; i < total; ++i)
            m_cache[i].store(std::numeric_limits<float>::quiet_NaN(), std::memory_order_relaxed);
        if (!m_boundary.empty())
            for (int k = 0; k < 2; ++k) {
                const std::size_t points = latticePoints(kCrossingLevels[k]);
                m_slopes[k] = std::make_unique<std::atomic<float>[]>(points);
                for (std::size_t i = 0; i < points; ++i)
                    m_slopes[k][i].store(std::numeric_limits<float>::quiet_NaN(), std::memory_order_relaxed);
            }
    }
}

MeshQuery::~MeshQuery() = default;

std::size_t MeshQuery::bytes() const {
    std::size_t cache = 0;
    if (m_useCache)
        for (int k = 2; k <= 7; ++k) cache += std::size_t((1 << k) + 1) * ((1 << k) + 1) * ((1 << k) + 1) * sizeof(float);
    for (int k = 0; k < 2; ++k)
        if (m_slopes[k]) cache += latticePoints(kCrossingLevels[k]) * sizeof(float);
    cache += m_boundary.size() * sizeof(BoundaryEdge);
    return m_nodes.size() * sizeof(Node) + m_corners.size() * sizeof(double) + cache;
}

double MeshQuery::nearest(const dvec3& p, std::uint32_t& slot, int& feature, dvec3& closest, std::uint64_t* visits,
                          std::uint32_t seed) const {
    double best = std::numeric_limits<double>::infinity();
    slot = 0;
    feature = 0;
    closest = p;
    if (m_nodes.empty()) return best;
    if (seed < m_corners.size() / 9) { // a triangle near the last row's: its distance bounds the walk
        const double* c = m_corners.data() + std::size_t(seed) * 9;
        closest = closestPointOnTriangle(p, dvec3(c[0], c[1], c[2]), dvec3(c[3], c[4], c[5]), dvec3(c[6], c[7], c[8]), &feature);
        best = glm::dot(p - closest, p - closest);
        slot = seed;
    }
    const float px = float(p.x), py = float(p.y), pz = float(p.z);
    // A box is skipped when its float distance exceeds the best by more than float rounding can
    // explain (boxes are rounded outward already; the slack keeps exact ties walked).
    // `limit` is that threshold as a float no smaller, so that the test is one float comparison
    // (four at once for a node's children).
    const float infinity = std::numeric_limits<float>::infinity();
    float limit = infinity;
    auto setLimit = [&] { limit = std::isfinite(best) ? roundedUp(best * (1.0 + 1e-5) + 1e-30) : infinity; };
    setLimit();
    // Float rounding of a point-triangle distance: a few units in the last place of the coordinates.
    const double margin = 1e-6 * (m_scale + std::abs(p.x) + std::abs(p.y) + std::abs(p.z));
    double bound = std::numeric_limits<double>::infinity();
    if (std::isfinite(best)) bound = (std::sqrt(best) + margin) * (std::sqrt(best) + margin);
    float boundFloat = roundedUp(bound); // the triangles' float pre-test against `bound`
    struct Entry {
        std::uint32_t node;  // an inner node, or a leaf's first triangle slot
        std::uint32_t count; // 0: an inner node; else the leaf's triangles
        float distance2;
    };
    auto testLeaf = [&](std::uint32_t first, std::uint32_t count) {
        for (std::uint32_t s = first; s < first + count; ++s) {
            // A float distance first: a triangle farther than the best by more than float rounding
            // can explain is not computed again in double.
            const float* t = m_field.triangles.data() + std::size_t(s) * kTriangleFloats;
            if (closestDistance2(px, py, pz, t) > boundFloat) continue;
            const double* c = m_corners.data() + std::size_t(s) * 9;
            int f = 0;
            const dvec3 q =
                closestPointOnTriangle(p, dvec3(c[0], c[1], c[2]), dvec3(c[3], c[4], c[5]), dvec3(c[6], c[7], c[8]), &f);
            const double d2 = glm::dot(p - q, p - q);
            // The lowest slot among equally near triangles: the answer does not depend on the walk's
            // order or on a seed.
            if (d2 < best || (d2 == best && s < slot)) {
                best = d2;
                slot = s;
                feature = f;
                closest = q;
                const double reach = std::sqrt(best) + margin;
                bound = reach * reach;
                boundFloat = roundedUp(bound);
                setLimit();
            }
        }
    };
    using Float4 = float __attribute__((vector_size(16)));
    const Float4 vx = {px, px, px, px}, vy = {py, py, py, py}, vz = {pz, pz, pz, pz};
    const Float4 zero = {0.0f, 0.0f, 0.0f, 0.0f};
    Entry stack[kStack];
    int top = 0;
    stack[top++] = {0, 0, 0.0f};
    std::uint64_t tested = 0;
    while (top > 0) {
        const Entry entry = stack[--top];
        if (entry.distance2 > limit) continue;
        if (entry.count > 0) {
            testLeaf(entry.node, entry.count);
            continue;
        }
        const Node& node = m_nodes[entry.node];
        ++tested;
        Float4 lx, ly, lz, hx, hy, hz;
        std::memcpy(&lx, node.lo[0], 16);
        std::memcpy(&ly, node.lo[1], 16);
        std::memcpy(&lz, node.lo[2], 16);
        std::memcpy(&hx, node.hi[0], 16);
        std::memcpy(&hy, node.hi[1], 16);
        std::memcpy(&hz, node.hi[2], 16);
        auto gap = [&](Float4 lo, Float4 hi, Float4 v) {
            const Float4 below = lo - v, above = v - hi;
            const Float4 larger = below > above ? below : above;
            return larger > zero ? larger : zero;
        };
        const Float4 dx = gap(lx, hx, vx), dy = gap(ly, hy, vy), dz = gap(lz, hz, vz);
        const Float4 d2 = dx * dx + dy * dy + dz * dz;
        // The children that may hold a nearer triangle, farthest first onto the stack so that the
        // nearest is walked next. An empty slot's distance is infinite: above any finite limit.
        const Float4 limits = {limit, limit, limit, limit};
        const auto open = d2 <= limits;
        int order[4];
        int n = 0;
        for (int k = 0; k < 4; ++k) {
            if (!open[k] || (limit == infinity && node.count[k] == 0 && node.child[k] == 0)) continue; // (0 is the root)
            int at = n++;
            while (at > 0 && d2[order[at - 1]] < d2[k]) {
                order[at] = order[at - 1];
                --at;
            }
            order[at] = k;
        }
        for (int j = 0; j < n && top < kStack; ++j) {
            const int k = order[j];
            stack[top++] = {node.child[k], node.count[k], d2[k]};
        }
    }
    if (visits) *visits += tested;
    return best;
}

// A far cluster's share of 4 pi times the winding number (MeshField.cpp).
double farCluster(const float* n, const dvec3& d, double dist2);

double MeshQuery::winding(const dvec3& p, std::uint64_t* visits) const {
    const std::vector<float>& nodes = m_field.nodes;
    if (nodes.empty()) return 0.0;
    const double beta2 = m_field.options.beta * m_field.options.beta;
    double sum = 0.0;
    std::uint32_t stack[kStack];
    int top = 0;
    stack[top++] = 0;
    std::uint64_t opened = 0;
    while (top > 0) {
        const float* n = nodes.data() + std::size_t(stack[--top]) * kNodeFloats;
        ++opened;
        const dvec3 d = dvec3(n[8], n[9], n[10]) - p;
        const double dist2 = glm::dot(d, d);
        if (dist2 > beta2 * double(n[11]) * double(n[11])) {
            sum += farCluster(n, d, dist2);
            continue;
        }
        const std::uint32_t first = asBits(n[3]);
        const std::uint32_t count = asBits(n[7]);
        if (count > 0) {
            for (std::uint32_t s = first; s < first + count; ++s) {
                const double* c = m_corners.data() + std::size_t(s) * 9;
                sum += solidAngle(p, dvec3(c[0], c[1], c[2]), dvec3(c[3], c[4], c[5]), dvec3(c[6], c[7], c[8]));
            }
        } else if (top + 2 <= kStack) {
            stack[top++] = first;
            stack[top++] = first + 1;
        }
    }
    if (visits) *visits += opened;
    return sum / (4.0 * std::numbers::pi);
}

std::size_t MeshQuery::nearestLatticePoint(const dvec3& p, int level, dvec3& q) const {
    const int side = (1 << level) + 1;
    const double step = m_cacheStep * double(m_cacheSide >> level);
    int at[3];
    for (int a = 0; a < 3; ++a) {
        at[a] = int(std::clamp(std::floor((p[a] - m_cacheLo[a]) / step + 0.5), 0.0, double(side - 1)));
        q[a] = m_cacheLo[a] + double(at[a]) * step;
    }
    return (std::size_t(at[2]) * side + std::size_t(at[1])) * side + std::size_t(at[0]);
}

float MeshQuery::latticeWinding(std::size_t slot, const dvec3& q, std::uint64_t* visits) const {
    float w = m_cache[slot].load(std::memory_order_relaxed);
    if (std::isnan(w)) {
        w = float(winding(q, visits));
        m_cache[slot].store(w, std::memory_order_relaxed);
    }
    return w;
}

// The sign cache. Every point of the open ball of radius `distance` (the nearest distance) around
// p is joined to p by a segment no triangle crosses, along which the winding number changes by at
// most boundary length x s / (4 pi (distance - s)^2) (s the segment's length; see boundaryLength):
// nothing at all on a closed, consistently oriented mesh. So a lattice point q inside that ball
// whose winding number is farther from 1/2 than that bound, plus 1/4 for the hierarchy's
// approximation at p and at q, gives p's sign, and its winding number is computed once for every
// row that can use it. Levels from coarse (5^3 points over 1.5 times the bounds) to fine (129^3):
// the coarsest level that decides, so that far rows share a few coarse values.
bool MeshQuery::cachedWindingInside(const dvec3& p, double distance, bool& fromCache, QueryCounters* counters) const {
    fromCache = false;
    std::uint64_t* visits = counters ? &counters->windingNodes : nullptr;
    if (m_useCache && distance > 0.0 && std::isfinite(distance)) {
        const double reach2 = distance * distance * 0.998;
        // The coarsest level whose every point of a cell lies inside the ball (half a cell's
        // diagonal shorter than the distance) near enough for the boundary's bound below, and one
        // coarser, whose nearest point may be: the coarser levels hardly ever hold one, and trying
        // them cost a fifth of a row's time.
        int coarsest = 7;
        for (int k = 2; k < 7; ++k) {
            const double half = m_cacheStep * double(m_cacheSide >> k) * 0.8661;
            if (half < distance * 0.999 &&
                m_boundaryLength * half < 0.25 * 4.0 * std::numbers::pi * (distance - half) * (distance - half)) {
                coarsest = k;
                break;
            }
        }
        for (int k = std::max(2, coarsest - 1); k <= 7; ++k) {
            dvec3 q;
            const std::size_t here = levelOffset(k) + nearestLatticePoint(p, k, q);
            const double s2 = glm::dot(q - p, q - p);
            if (!(s2 < reach2)) continue;
            const double s = std::sqrt(s2);
            const double change = m_boundaryLength * s / (4.0 * std::numbers::pi * (distance - s) * (distance - s));
            if (!(change < 0.25)) continue; // a finer level comes closer
            const float w = latticeWinding(here, q, visits);
            if (std::abs(double(w) - 0.5) >= change + 0.25) {
                fromCache = true;
                return w > 0.5f;
            }
        }
    }
    if (bool in = false; distance > 0.0 && crossedWindingInside(p, in, counters)) {
        if (counters) ++counters->crossedSigns;
        return in;
    }
    return winding(p, visits) > 0.5;
}

// The crossing sign, for rows too near the surface for the ball above to hold a lattice point (or
// too near an open boundary for its bound). Along a segment from a lattice point q to p the winding
// number jumps by exactly 1 wherever the segment crosses a triangle (down when it leaves through
// the front, up through the back) and between crossings changes only as the open boundary's field
// allows: |w(p) - w(q) - crossings| <= slope(q) x |p - q| (boundarySlope; zero on a closed,
// oriented mesh, however many shells overlap). So w(q), once computed for the rows around it, and
// one short segment walk give p's sign wherever that estimate is farther from 1/2 than the bound
// plus 1/4 for the hierarchy's approximation at p and q, as in the ball's test. A crossing too near
// a triangle's edge or corner, or an end on a triangle's plane, could be counted twice or missed:
// the row then tries the finer level's point, and then takes the walk.
bool MeshQuery::crossedWindingInside(const dvec3& p, bool& inside, QueryCounters* counters) const {
    if (!m_useCache) return false;
    for (int k = 0; k < 2; ++k) {
        const int level = kCrossingLevels[k];
        const double step = m_cacheStep * double(m_cacheSide >> level);
        const double reach = step * std::sqrt(3.0) * 0.5 * (1.0 + 1e-9); // a lattice cell's half diagonal
        dvec3 q;
        const std::size_t index = nearestLatticePoint(p, level, q);
        const double s = glm::length(p - q);
        if (!(s <= reach)) return false; // outside the lattice
        double slope = 0.0;
        if (m_slopes[k]) {
            float stored = m_slopes[k][index].load(std::memory_order_relaxed);
            if (std::isnan(stored)) {
                stored = roundedUp(boundarySlope(q, reach));
                m_slopes[k][index].store(stored, std::memory_order_relaxed);
            }
            slope = double(stored);
        }
        const double change = slope * s;
        if (!(change < 0.25)) continue; // the finer level's segment is shorter
        const float w = latticeWinding(levelOffset(level) + index, q, counters ? &counters->windingNodes : nullptr);
        int net = 0;
        if (!segmentCrossings(q, p, net, counters ? &counters->segmentNodes : nullptr)) continue; // another segment
        const double estimate = double(w) + double(net);
        if (!(std::abs(estimate - 0.5) >= change + 0.25)) continue;
        inside = estimate > 0.5;
        return true;
    }
    return false;
}

double MeshQuery::boundarySlope(const dvec3& q, double reach) const {
    double sum = 0.0;
    for (const BoundaryEdge& e : m_boundary) {
        const double r = segmentDistance(q, e.a, e.b) - reach;
        if (!(r > 0.0)) return std::numeric_limits<double>::infinity();
        sum += e.weight * glm::length(e.b - e.a) / (r * r);
    }
    return sum / (4.0 * std::numbers::pi) * (1.0 + 1e-9);
}

bool MeshQuery::segmentCrossings(const dvec3& q, const dvec3& p, int& net, std::uint64_t* visits) const {
    net = 0;
    if (m_nodes.empty()) return true;
    const dvec3 direction = p - q;
    // Boxes widened by more than the float rounding of the ends and of the boxes' own test.
    const float slack = float(1e-5 * (m_scale + 1.0));
    using Float4 = float __attribute__((vector_size(16)));
    auto splat = [](float v) { return Float4{v, v, v, v}; };
    Float4 origin[3], inverse[3];
    for (int a = 0; a < 3; ++a) {
        origin[a] = splat(float(q[a]));
        const float d = float(direction[a]);
        inverse[a] = splat(1.0f / (std::abs(d) > 1e-30f ? d : 1e-30f));
    }
    const double tolerance = 1e-9 * (m_scale + 1.0); // an end this near a triangle's plane is on it
    constexpr double kEdge = 1e-7;                   // a crossing this near an edge (barycentric) is on it
    struct Entry {
        std::uint32_t node, count;
    };
    Entry stack[kStack];
    int top = 0;
    stack[top++] = {0, 0};
    std::uint64_t tested = 0;
    bool certain = true;
    while (top > 0 && certain) {
        const Entry entry = stack[--top];
        if (entry.count > 0) {
            for (std::uint32_t slot = entry.node; slot < entry.node + entry.count; ++slot) {
                const double* c = m_corners.data() + std::size_t(slot) * 9;
                const dvec3 a(c[0], c[1], c[2]), b(c[3], c[4], c[5]), d(c[6], c[7], c[8]);
                const dvec3 n = glm::cross(b - a, d - a);
                const double area2 = glm::dot(n, n);
                if (!(area2 > 0.0)) continue; // no area: its solid angle is zero everywhere
                const dvec3 unit = n / std::sqrt(area2);
                const double sq = glm::dot(q - a, unit), sp = glm::dot(p - a, unit);
                if ((sq > tolerance && sp > tolerance) || (sq < -tolerance && sp < -tolerance)) continue;
                if (std::abs(sq) <= tolerance || std::abs(sp) <= tolerance) {
                    certain = false; // an end on the triangle's plane, and the boxes met
                    break;
                }
                const dvec3 x = q + direction * (sq / (sq - sp));
                const double la = glm::dot(glm::cross(d - b, x - b), n) / area2;
                const double lb = glm::dot(glm::cross(a - d, x - d), n) / area2;
                const double lc = glm::dot(glm::cross(b - a, x - a), n) / area2;
                if (la < -kEdge || lb < -kEdge || lc < -kEdge) continue; // beside the triangle
                if (la <= kEdge || lb <= kEdge || lc <= kEdge) {
                    certain = false;
                    break;
                }
                net += glm::dot(direction, n) > 0.0 ? -1 : 1; // out through the front: w falls by one
            }
            continue;
        }
        const Node& node = m_nodes[entry.node];
        ++tested;
        Float4 near = splat(0.0f), far = splat(1.0f);
        for (int a = 0; a < 3; ++a) {
            Float4 lo, hi;
            std::memcpy(&lo, node.lo[a], 16);
            std::memcpy(&hi, node.hi[a], 16);
            const Float4 t0 = (lo - slack - origin[a]) * inverse[a];
            const Float4 t1 = (hi + slack - origin[a]) * inverse[a];
            const Float4 enter = t0 < t1 ? t0 : t1, leave = t0 < t1 ? t1 : t0;
            near = enter > near ? enter : near;
            far = leave < far ? leave : far;
        }
        for (int k = 0; k < 4 && top < kStack; ++k) {
            if (node.count[k] == 0 && node.child[k] == 0) continue; // an empty slot (0 is the root)
            if (near[k] <= far[k] * (1.0f + 1e-5f) + 1e-5f) stack[top++] = {node.child[k], node.count[k]};
        }
    }
    if (visits) *visits += tested;
    return certain;
}

bool MeshQuery::parityInside(const dvec3& p) const {
    int votes = 0;
    for (const dvec3& direction : parityDirections()) {
        const dvec3 inverse = 1.0 / direction;
        int crossings = 0;
        std::uint32_t stack[kStack];
        int top = 0;
        stack[top++] = 0;
        const std::vector<float>& nodes = m_field.nodes;
        while (top > 0 && !nodes.empty()) {
            const float* n = nodes.data() + std::size_t(stack[--top]) * kNodeFloats;
            double t0 = 0.0;
            double t1 = std::numeric_limits<double>::infinity();
            for (int a = 0; a < 3; ++a) {
                double u = (double(n[a]) - p[a]) * inverse[a];
                double v = (double(n[4 + a]) - p[a]) * inverse[a];
                if (u > v) std::swap(u, v);
                t0 = std::max(t0, u);
                t1 = std::min(t1, v);
            }
            if (t0 > t1) continue;
            const std::uint32_t first = asBits(n[3]);
            const std::uint32_t count = asBits(n[7]);
            if (count > 0) {
                for (std::uint32_t s = first; s < first + count; ++s) {
                    const double* c = m_corners.data() + std::size_t(s) * 9;
                    const dvec3 a(c[0], c[1], c[2]);
                    const dvec3 e1 = dvec3(c[3], c[4], c[5]) - a;
                    const dvec3 e2 = dvec3(c[6], c[7], c[8]) - a;
                    const dvec3 h = glm::cross(direction, e2);
                    const double det = glm::dot(e1, h);
                    if (det == 0.0) continue;
                    const dvec3 o = p - a;
                    const double u = glm::dot(o, h) / det;
                    const dvec3 q = glm::cross(o, e1);
                    const double v = glm::dot(direction, q) / det;
                    if (u >= 0.0 && u <= 1.0 && v >= 0.0 && u + v <= 1.0 && glm::dot(e2, q) / det > 0.0) ++crossings;
                }
            } else if (top + 2 <= kStack) {
                stack[top++] = first;
                stack[top++] = first + 1;
            }
        }
        votes += crossings & 1;
    }
    return votes >= 2;
}

bool MeshQuery::inside(const dvec3& p, double distance, std::uint32_t slot, int feature, const dvec3& closest,
                       QueryCounters* counters) const {
    switch (m_field.options.sign) {
    case SignMethod::Winding: {
        bool fromCache = false;
        const bool in = cachedWindingInside(p, distance, fromCache, counters);
        if (counters && fromCache) ++counters->cachedSigns;
        return in;
    }
    case SignMethod::Parity:
        return parityInside(p);
    case SignMethod::Pseudonormal: {
        static constexpr int kSlotOfFeature[7] = {0, 4, 5, 6, 1, 2, 3};
        const float* normal =
            m_field.pseudonormals.data() + std::size_t(slot) * kPseudonormalFloats + std::size_t(kSlotOfFeature[feature]) * 4;
        return glm::dot(p - closest, dvec3(normal[0], normal[1], normal[2])) < 0.0;
    }
    }
    return false;
}

double MeshQuery::signedDistance(const dvec3& p, dvec3* gradient, QueryCounters* counters) const {
    std::uint32_t seed = kNoSeed;
    return seededDistance(p, gradient, counters, seed);
}

double MeshQuery::seededDistance(const dvec3& p, dvec3* gradient, QueryCounters* counters, std::uint32_t& seed) const {
    std::uint32_t slot = 0;
    int feature = 0;
    dvec3 closest(0.0);
    const double distance = std::sqrt(nearest(p, slot, feature, closest, counters ? &counters->nearestNodes : nullptr, seed));
    seed = slot;
    const bool in = inside(p, distance, slot, feature, closest, counters);
    if (gradient) {
        if (distance > 0.0) {
            *gradient = (p - closest) / distance * (in ? -1.0 : 1.0);
        } else { // on the surface: the face's normal
            const double* c = m_corners.data() + std::size_t(slot) * 9;
            const dvec3 n =
                glm::cross(dvec3(c[3] - c[0], c[4] - c[1], c[5] - c[2]), dvec3(c[6] - c[0], c[7] - c[1], c[8] - c[2]));
            const double length = glm::length(n);
            *gradient = length > 0.0 ? n / length : dvec3(0.0);
        }
    }
    return in ? -distance : distance;
}

float MeshQuery::floatField(const glm::vec3& p) const { return float(signedDistance(dvec3(p), nullptr)); }

std::uint64_t MeshQuery::evaluate(const RowView& rows, std::size_t count, const GradientMode& mode, unsigned threads,
                                  QueryCounters* counters) const {
    constexpr std::size_t kBlock = 1024;
    constexpr std::size_t kAhead = 4;
    const unsigned workers = unsigned(std::min<std::size_t>(threadCount(threads), (count + kBlock - 1) / kBlock));
    // Rows in Morton order (10 bits an axis over the cache's box): neighbours in the order are
    // neighbours in space, so each row's walk starts from the last row's triangle (seeded within a
    // block of the order, so the rows do not depend on the threads) and finds the caches warm.
    const std::vector<std::uint64_t> order =
        mortonOrder(rows.positions, rows.positionStride, count, m_cacheLo, m_cacheStep * double(m_cacheSide));
    std::atomic<std::size_t> next{0};
    std::atomic<std::uint64_t> bad{0};
    std::mutex countersMutex;
    auto work = [&] {
        QueryCounters local;
        std::uint64_t localBad = 0;
        for (;;) {
            const std::size_t begin = next.fetch_add(kBlock);
            if (begin >= count) break;
            const std::size_t end = std::min(count, begin + kBlock);
            std::uint32_t seed = kNoSeed;
            for (std::size_t j = begin; j < end; ++j) {
                // Rows in Morton order are scattered in memory: the row a few ahead is fetched now,
                // so that its position (and where its values go) is in the cache when it comes.
                if (j + kAhead < end) {
                    const std::size_t ahead = std::size_t(order[j + kAhead] & 0xffffffffu);
                    __builtin_prefetch(rows.positions + ahead * rows.positionStride);
                    __builtin_prefetch(rows.distances + ahead * rows.distanceStride, 1);
                    if (rows.gradients) __builtin_prefetch(rows.gradients + ahead * rows.gradientStride, 1);
                }
                const std::size_t i = std::size_t(order[j] & 0xffffffffu);
                const float* xyz = rows.positions + i * rows.positionStride;
                const glm::vec3 pf(xyz[0], xyz[1], xyz[2]);
                float* value = rows.distances + i * rows.distanceStride;
                float* gradient = rows.gradients ? rows.gradients + i * rows.gradientStride : nullptr;
                bool finite = std::isfinite(pf.x) && std::isfinite(pf.y) && std::isfinite(pf.z);
                if (!finite) {
                    const float nan = std::numeric_limits<float>::quiet_NaN();
                    *value = nan;
                    if (gradient) gradient[0] = gradient[1] = gradient[2] = nan;
                    ++localBad;
                    continue;
                }
                dvec3 exact(0.0);
                const bool wantExact = gradient && mode.exact;
                *value = float(seededDistance(dvec3(pf), wantExact ? &exact : nullptr, &local, seed));
                if (gradient) {
                    if (mode.exact) {
                        gradient[0] = float(exact.x);
                        gradient[1] = float(exact.y);
                        gradient[2] = float(exact.z);
                    } else { // sample.comp's six taps, in float
                        const float h = mode.step;
                        gradient[0] = (floatField(pf + glm::vec3(h, 0, 0)) - floatField(pf - glm::vec3(h, 0, 0))) / (2.0f * h);
                        gradient[1] = (floatField(pf + glm::vec3(0, h, 0)) - floatField(pf - glm::vec3(0, h, 0))) / (2.0f * h);
                        gradient[2] = (floatField(pf + glm::vec3(0, 0, h)) - floatField(pf - glm::vec3(0, 0, h))) / (2.0f * h);
                    }
                    finite = std::isfinite(gradient[0]) && std::isfinite(gradient[1]) && std::isfinite(gradient[2]);
                }
                if (!std::isfinite(*value) || !finite) ++localBad;
            }
        }
        bad += localBad;
        if (counters) {
            std::lock_guard lock(countersMutex);
            counters->nearestNodes += local.nearestNodes;
            counters->windingNodes += local.windingNodes;
            counters->cachedSigns += local.cachedSigns;
            counters->crossedSigns += local.crossedSigns;
            counters->segmentNodes += local.segmentNodes;
        }
    };
    std::vector<std::thread> pool;
    for (unsigned t = 1; t < workers; ++t) pool.emplace_back(work);
    work();
    for (std::thread& thread : pool) thread.join();
    return bad.load();
}

} // namespace sdfwb::meshfield
