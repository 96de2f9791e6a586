// Dual contouring (Ju et al. 2002) on a grid whose values come from the GPU: blocks of 8^3 cells
// that a Lipschitz bound proves empty are skipped; in the others, every patch of surface in a cell
// (its crossings joined along the cell's faces) gets one vertex, the minimiser of a QEF built from
// the patch's edge crossings and the field's normals there (so the vertex sits on sharp edges and
// corners, where marching cubes cuts them); every grid edge with a sign change becomes a polygon
// joining the vertices of its four cells, with a vertex on a face between two cells whose patches
// both join that face's two segments (a tunnel thinner than a cell), so the mesh stays manifold.
#include <meshing/Mesh.h>

#include "PointEvaluator.h"
#include "Refine.h"

#include <core/Parallel.h>

#include <glm/geometric.hpp>

#include <algorithm>
#include <array>
#include <bit>
#include <bitset>
#include <chrono>
#include <cmath>
#include <iterator>
#include <limits>
#include <optional>
#include <unordered_map>
#include <utility>
#include <vector>

namespace sdfwb::meshing {
namespace {

// Eigen-decomposition of a symmetric 3x3 matrix by Jacobi rotations.
void symmetricEigen(std::array<std::array<double, 3>, 3> a, std::array<double, 3>& values,
                    std::array<std::array<double, 3>, 3>& vectors) {
    vectors = {{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}};
    for (int sweep = 0; sweep < 32; ++sweep) {
        const double off = a[0][1] * a[0][1] + a[0][2] * a[0][2] + a[1][2] * a[1][2];
        if (off < 1e-22) break;
        for (int p = 0; p < 2; ++p)
            for (int q = p + 1; q < 3; ++q) {
                if (std::abs(a[p][q]) < 1e-30) continue;
                const double theta = (a[q][q] - a[p][p]) / (2.0 * a[p][q]);
                const double t = (theta >= 0 ? 1.0 : -1.0) / (std::abs(theta) + std::sqrt(theta * theta + 1.0));
                const double c = 1.0 / std::sqrt(t * t + 1.0), s = t * c;
                for (int k = 0; k < 3; ++k) { // a = J^T a J
                    const double akp = a[k][p], akq = a[k][q];
                    a[k][p] = c * akp - s * akq;
                    a[k][q] = s * akp + c * akq;
                }
                for (int k = 0; k < 3; ++k) {
                    const double apk = a[p][k], aqk = a[q][k];
                    a[p][k] = c * apk - s * aqk;
                    a[q][k] = s * apk + c * aqk;
                }
                for (int k = 0; k < 3; ++k) {
                    const double vkp = vectors[k][p], vkq = vectors[k][q];
                    vectors[k][p] = c * vkp - s * vkq;
                    vectors[k][q] = s * vkp + c * vkq;
                }
            }
    }
    for (int i = 0; i < 3; ++i) values[std::size_t(i)] = a[std::size_t(i)][std::size_t(i)];
}

// The point minimising sum (n . (x - p))^2 nearest the mass point: a pseudo-inverse that drops
// directions the normals do not constrain (a flat face constrains one, an edge two, a corner three).
// `free` holds the dropped directions: every point + span(free) minimises the sum as well.
struct QefSolution {
    glm::dvec3 point{0.0};
    glm::dvec3 mass{0.0}; // the crossings' mean
    std::array<glm::dvec3, 3> free{};
    int freeCount = 0;
};

QefSolution solveQef(const glm::dvec3* points, const glm::dvec3* normals, int count) {
    glm::dvec3 mass(0.0);
    for (int i = 0; i < count; ++i) mass += points[i];
    mass /= double(count);
    std::array<std::array<double, 3>, 3> ata{};
    glm::dvec3 atb(0.0);
    for (int i = 0; i < count; ++i) {
        const glm::dvec3& n = normals[i];
        const double d = glm::dot(n, points[i] - mass);
        for (int r = 0; r < 3; ++r) {
            for (int c = 0; c < 3; ++c) ata[std::size_t(r)][std::size_t(c)] += n[r] * n[c];
            atb[r] += n[r] * d;
        }
    }
    std::array<double, 3> values{};
    std::array<std::array<double, 3>, 3> vectors{};
    symmetricEigen(ata, values, vectors);
    const double largest = std::max({std::abs(values[0]), std::abs(values[1]), std::abs(values[2])});
    QefSolution out;
    glm::dvec3 x(0.0);
    for (int k = 0; k < 3; ++k) {
        const glm::dvec3 v(vectors[0][std::size_t(k)], vectors[1][std::size_t(k)], vectors[2][std::size_t(k)]);
        if (largest <= 0.0 || std::abs(values[std::size_t(k)]) < 0.1 * largest) { // unconstrained direction
            out.free[std::size_t(out.freeCount++)] = v;
            continue;
        }
        x += v * (glm::dot(v, atb) / values[std::size_t(k)]);
    }
    out.point = mass + x;
    out.mass = mass;
    return out;
}

// The part [t0, t1] of the line p + t d inside the box [lo, hi]; false when it misses the box.
bool clipLine(const glm::dvec3& p, const glm::dvec3& d, const glm::dvec3& lo, const glm::dvec3& hi, double& t0, double& t1) {
    t0 = -std::numeric_limits<double>::infinity();
    t1 = std::numeric_limits<double>::infinity();
    for (int a = 0; a < 3; ++a) {
        if (std::abs(d[a]) < 1e-12) {
            if (p[a] < lo[a] || p[a] > hi[a]) return false;
            continue;
        }
        double enter = (lo[a] - p[a]) / d[a], leave = (hi[a] - p[a]) / d[a];
        if (enter > leave) std::swap(enter, leave);
        t0 = std::max(t0, enter);
        t1 = std::min(t1, leave);
    }
    return t0 <= t1;
}

// Where a cell's vertex goes. The QEF's minimiser when it lies in the cell. A sharp edge (one free
// direction) is a line of minimisers: the point of that line nearest the minimiser inside the cell,
// else inside the cell grown by `margin` on every side (an edge that passes just beside the cell,
// whose two faces the cell's crossings see: clamping would pull the vertex off the edge by up to
// the margin). A corner (no free direction) within the margin goes there too, also when the cell it
// lies in has a vertex of its own: that cell may see only two of the corner's faces and put its
// vertex on their edge, and clamping this one left the corner cut off (a rotated box at 32^3: a
// Hausdorff distance of 0.1 cell; placed, 40x less). Anything else is clamped into the cell. `left` counts vertices placed
// outside their cell, `clamped` those moved off their QEF's minimisers.
glm::dvec3 placeVertex(const QefSolution& qef, const glm::dvec3& lo, const glm::dvec3& hi, double margin, std::uint64_t& left,
                       std::uint64_t& clamped) {
    const glm::dvec3& x = qef.point;
    if (glm::all(glm::greaterThanEqual(x, lo)) && glm::all(glm::lessThanEqual(x, hi))) return x;
    if (qef.freeCount == 0 && glm::all(glm::greaterThanEqual(x, lo - margin)) && glm::all(glm::lessThanEqual(x, hi + margin))) {
        ++left; // a corner whose tip pokes into the next cell
        return x;
    }
    if (qef.freeCount == 1) {
        double t0 = 0.0, t1 = 0.0;
        const glm::dvec3& d = qef.free[0];
        if (clipLine(x, d, lo, hi, t0, t1)) return x + d * std::clamp(0.0, t0, t1);
        if (clipLine(x, d, lo - margin, hi + margin, t0, t1)) {
            ++left;
            return x + d * std::clamp(0.0, t0, t1);
        }
    }
    // From the crossings' mean (inside the cell) towards the minimiser, as far as the cell allows:
    // clamping coordinate by coordinate put vertices of neighbouring cells on one grid point or one
    // grid line, and triangles between them had zero area.
    ++clamped;
    double t0 = 0.0, t1 = 0.0;
    if (clipLine(qef.mass, x - qef.mass, lo, hi, t0, t1)) return qef.mass + (x - qef.mass) * std::clamp(1.0, t0, t1);
    return glm::clamp(x, lo, hi);
}

struct Grid {
    int n; // cells per axis
    glm::dvec3 origin, step;
    glm::vec3 point(std::int64_t i, std::int64_t j, std::int64_t k) const {
        return glm::vec3(origin + glm::dvec3(double(i), double(j), double(k)) * step);
    }
};

// A block's (B+1)^3 grid points, B^3 cells and the 3 (B+1)^3 edge slots (point * 3 + axis; the
// slots whose end leaves the block are never set). Edges and cells that the surface crosses are
// found from the block's own values, so a cell's twelve edges are all its block's; a bitset with
// running counts turns a local slot into an index of the global arrays with no hash map.
constexpr int kBlock = 8;
constexpr int kSide = kBlock + 1;
constexpr int kPoints = kSide * kSide * kSide;
constexpr int kEdgeSlots = 3 * kPoints;
constexpr int kCells = kBlock * kBlock * kBlock;
constexpr int kStride[3] = {1, kSide, kSide* kSide};
// Sub-blocks: the cubes of kSub^3 cells a block is cut into (64 a block), in octants of kOctant^3.
constexpr int kSub = 2;
constexpr int kSubsPerAxis = kBlock / kSub;
constexpr int kOctant = kBlock / 2;
static_assert(kSubsPerAxis * kSubsPerAxis * kSubsPerAxis == 64, "a sub-block mask is one 64-bit word");
constexpr int subIndex(int x, int y, int z) { return (z * kSubsPerAxis + y) * kSubsPerAxis + x; }
// The local grid point at sub-block s's lowest corner (the inverse of subIndex, in points).
constexpr std::array<int, 3> subCorner(int s) {
    return {kSub * (s % kSubsPerAxis), kSub * (s / kSubsPerAxis % kSubsPerAxis), kSub * (s / (kSubsPerAxis * kSubsPerAxis))};
}

template <int Bits> struct RankedBits {
    static constexpr int kWords = (Bits + 63) / 64;
    std::array<std::uint64_t, kWords> bits{};
    std::array<std::uint32_t, kWords> before{}; // global index of the first set bit of each word
    void set(int i) { bits[std::size_t(i >> 6)] |= std::uint64_t(1) << (i & 63); }
    bool test(int i) const { return (bits[std::size_t(i >> 6)] >> (i & 63)) & 1u; }
    // After every bit is set: number the set bits from `first`; returns the next free number.
    std::uint32_t number(std::uint32_t first) {
        for (int w = 0; w < kWords; ++w) {
            before[std::size_t(w)] = first;
            first += std::uint32_t(std::popcount(bits[std::size_t(w)]));
        }
        return first;
    }
    std::uint32_t rank(int i) const {
        const std::uint64_t below = bits[std::size_t(i >> 6)] & ((std::uint64_t(1) << (i & 63)) - 1);
        return before[std::size_t(i >> 6)] + std::uint32_t(std::popcount(below));
    }
};

// The cube's corners c = x + 2y + 4z and its edges l = axis * 4 + (offset along axis+1) +
// 2 * (offset along axis+2), with the corners each edge joins.
struct CubeTables {
    int edgeCorner[12][2];
    int edgeOffset[12][3]; // the edge's start corner
    // Each face (w, side): its edges (u at v = 0, u at v = 1, v at u = 0, v at u = 1) and corners
    // (00, 10, 01, 11 in (u, v)).
    int faceEdges[6][4];
    int faceCorners[6][4];
    CubeTables() {
        for (int axis = 0; axis < 3; ++axis)
            for (int b = 0; b < 4; ++b) {
                const int l = axis * 4 + b;
                int offset[3] = {0, 0, 0};
                offset[(axis + 1) % 3] = b & 1;
                offset[(axis + 2) % 3] = b >> 1;
                for (int a = 0; a < 3; ++a) edgeOffset[l][a] = offset[a];
                edgeCorner[l][0] = offset[0] + 2 * offset[1] + 4 * offset[2];
                offset[axis] = 1;
                edgeCorner[l][1] = offset[0] + 2 * offset[1] + 4 * offset[2];
            }
        auto localEdge = [](int axis, const int offset[3]) {
            return axis * 4 + offset[(axis + 1) % 3] + 2 * offset[(axis + 2) % 3];
        };
        for (int w = 0; w < 3; ++w)
            for (int side = 0; side < 2; ++side) {
                const int face = 2 * w + side, up = (w + 1) % 3, vp = (w + 2) % 3;
                auto edgeAt = [&](int axis, int offU, int offV) {
                    int offset[3] = {0, 0, 0};
                    offset[w] = side;
                    offset[up] = offU;
                    offset[vp] = offV;
                    return localEdge(axis, offset);
                };
                faceEdges[face][0] = edgeAt(up, 0, 0);
                faceEdges[face][1] = edgeAt(up, 0, 1);
                faceEdges[face][2] = edgeAt(vp, 0, 0);
                faceEdges[face][3] = edgeAt(vp, 1, 0);
                for (int q = 0; q < 4; ++q) {
                    int offset[3] = {0, 0, 0};
                    offset[w] = side;
                    offset[up] = q & 1;
                    offset[vp] = q >> 1;
                    faceCorners[face][q] = offset[0] + 2 * offset[1] + 4 * offset[2];
                }
            }
    }
};
const CubeTables& cube() {
    static const CubeTables tables;
    return tables;
}

bool inside(float f) { return f < 0.0f; }
bool crosses(float f0, float f1) { return std::isfinite(f0) && std::isfinite(f1) && inside(f0) != inside(f1); }

struct Edge {
    std::int32_t i, j, k; // start point on the grid
    std::int8_t axis;
    bool startInside;
    bool owned; // the block that makes this edge's quad (a face edge is found by both blocks)
};

struct CellRecord {
    std::uint32_t firstVertex;
    std::uint32_t vertexOfEdge;   // 2 bits per local edge: which of the cell's vertices (patches) it feeds
    std::uint8_t jointFaces = 0;  // ambiguous faces (bit = face) whose two segments one patch of this cell joins
    std::uint8_t crossPaired = 0; // ambiguous faces whose segments pair edges (0, 2) and (1, 3), not (0, 3) and (2, 1)
};

// The two segments of an ambiguous face, as indices into CubeTables::faceEdges.
constexpr int kSegments[2][2][2] = {{{0, 3}, {2, 1}}, {{0, 2}, {1, 3}}}; // [crossPaired][segment][end]

// Cells around a point where the surface meets a grid line (a cone's apex on the axis) can put
// their vertices at the very same position; the quads between them then hold triangles of zero
// area. Vertices that share a triangle and a position (to `tolerance`, a millionth of a cell: 4e-19 apart is
// a triangle of zero area in float) become one, the triangles that
// repeat a vertex then go (each such merge is the collapse of an edge of length zero, which keeps
// the surface closed and its orientation), and vertices no triangle uses any more are dropped.
// A collapse that would pinch the surface (the two vertices have a neighbour in common that no
// triangle of their edge holds: both sides of a split face, splitJoinedFaces) is not made; the
// two are moved a hundredth of the way towards the middle of their other neighbours instead, which
// parts them. Meshes without such triangles (nearly all) are left as they are.
void weldCoincidentVertices(Mesh& mesh, float tolerance) {
    std::vector<std::uint32_t>& indices = mesh.indices;
    auto same = [&](std::uint32_t a, std::uint32_t b) { return glm::length(mesh.vertices[a] - mesh.vertices[b]) <= tolerance; };
    std::vector<std::pair<std::uint32_t, std::uint32_t>> pairs;
    for (std::size_t t = 0; t + 2 < indices.size(); t += 3)
        for (std::size_t e = 0; e < 3; ++e) {
            const std::uint32_t a = indices[t + e], b = indices[t + (e + 1) % 3];
            if (a != b && same(a, b)) pairs.emplace_back(std::min(a, b), std::max(a, b));
        }
    if (pairs.empty()) return;
    std::sort(pairs.begin(), pairs.end());
    pairs.erase(std::unique(pairs.begin(), pairs.end()), pairs.end());
    // The triangles around each vertex involved; a merge hands the merged vertex's to the survivor.
    std::unordered_map<std::uint32_t, std::vector<std::uint32_t>> around;
    for (const auto& [a, b] : pairs) around[a], around[b];
    for (std::size_t t = 0; t + 2 < indices.size(); t += 3)
        for (std::size_t e = 0; e < 3; ++e)
            if (const auto it = around.find(indices[t + e]); it != around.end()) it->second.push_back(std::uint32_t(t / 3));
    std::unordered_map<std::uint32_t, std::uint32_t> parent; // union-find over the vertices merged
    auto find = [&](std::uint32_t v) {
        for (auto it = parent.find(v); it != parent.end() && it->second != v; it = parent.find(v)) v = it->second;
        return v;
    };
    // The neighbours of v in the mesh as merged so far, and how many of v's triangles hold `other`.
    std::vector<std::uint32_t> ringA, ringB;
    auto ring = [&](std::uint32_t v, std::uint32_t other, std::vector<std::uint32_t>& out) {
        out.clear();
        std::size_t holding = 0;
        for (std::uint32_t t : around[v]) {
            const std::uint32_t f[3] = {find(indices[3 * t]), find(indices[3 * t + 1]), find(indices[3 * t + 2])};
            if (f[0] == f[1] || f[1] == f[2] || f[0] == f[2]) continue; // collapsed already
            holding += f[0] == other || f[1] == other || f[2] == other;
            for (std::uint32_t n : f)
                if (n != v) out.push_back(n);
        }
        std::sort(out.begin(), out.end());
        out.erase(std::unique(out.begin(), out.end()), out.end());
        return holding;
    };
    std::vector<std::uint32_t> common;
    for (const auto& [a, b] : pairs) {
        const std::uint32_t ra = find(a), rb = find(b);
        if (ra == rb) continue;
        const std::size_t shared = ring(ra, rb, ringA);
        ring(rb, ra, ringB);
        common.clear();
        std::set_intersection(ringA.begin(), ringA.end(), ringB.begin(), ringB.end(), std::back_inserter(common));
        if (common.size() == shared) {
            const std::uint32_t keep = std::min(ra, rb), gone = std::max(ra, rb);
            parent[keep] = keep;
            parent[gone] = keep;
            std::vector<std::uint32_t>& into = around[keep];
            const std::vector<std::uint32_t>& from = around[gone];
            into.insert(into.end(), from.begin(), from.end());
            continue;
        }
        for (const auto& [v, others] : {std::pair{ra, &ringA}, std::pair{rb, &ringB}}) {
            glm::vec3 middle(0.0f);
            int count = 0;
            for (std::uint32_t n : *others)
                if (n != ra && n != rb) {
                    middle += mesh.vertices[n];
                    ++count;
                }
            if (count > 0) mesh.vertices[v] += 0.01f * (middle / float(count) - mesh.vertices[v]);
        }
    }
    if (parent.empty()) return;
    std::size_t kept = 0;
    for (std::size_t t = 0; t + 2 < indices.size(); t += 3) {
        const std::uint32_t a = find(indices[t]), b = find(indices[t + 1]), c = find(indices[t + 2]);
        if (a == b || b == c || a == c) continue;
        indices[kept++] = a;
        indices[kept++] = b;
        indices[kept++] = c;
    }
    indices.resize(kept);
    std::vector<std::uint32_t> renumber(mesh.vertices.size(), 0xffffffffu);
    for (std::uint32_t v : indices) renumber[v] = 0;
    std::uint32_t next = 0;
    for (std::size_t v = 0; v < mesh.vertices.size(); ++v)
        if (renumber[v] == 0) {
            renumber[v] = next;
            mesh.vertices[next++] = mesh.vertices[v];
        }
    mesh.vertices.resize(next);
    for (std::uint32_t& v : indices) v = renumber[v];
}

} // namespace

std::pair<glm::vec3, glm::vec3> cutBox(const MeshOptions& options) {
    const glm::dvec3 step = (glm::dvec3(options.boundsMax) - glm::dvec3(options.boundsMin)) / double(options.resolution);
    return {glm::vec3(glm::dvec3(options.boundsMin) - 0.5 * step), glm::vec3(glm::dvec3(options.boundsMax) + 0.5 * step)};
}

namespace {

// One extraction (extractMesh): the state its steps hand on, each step a member function.
class Extraction {
public:
    Extraction(const shaders::PreparedSdf& sdf, const MeshOptions& options, const ProgressSink& progress)
        : sdf(sdf), options(options), progress(progress) {}
    Expected<std::pair<Mesh, MeshStats>> run();

private:
    Expected<void> selectBlocks();
    float estimateBound(const std::vector<float>& centreValues, const std::vector<float>& centreGradients) const;
    void keep(std::size_t block);
    Expected<void> evaluateBlocks();
    bool maySurface(float f, double halfDiagonal) const;
    Expected<void> selectSubBlocks(detail::PointEvaluator& lattice, std::size_t from, std::size_t to);
    Expected<void> evaluateWanted(detail::PointEvaluator& lattice);
    bool wantMoreSubBlocks();
    void keepNeighboursAcrossCrossedFaces(std::size_t slot);
    void findEdges();
    Expected<void> placeCrossings();
    void placeVertices();
    bool cellCorners(const std::int64_t c[3], float corner[8]) const;
    std::optional<std::pair<glm::dvec3, glm::dvec3>> creaseOnUpperFace(const glm::dvec3* points, const glm::dvec3* patchNormals,
                                                                       int count, const QefSolution& qef,
                                                                       const std::int32_t cell[3], const glm::dvec3& hi) const;
    const CellRecord* recordAt(const std::int64_t c[3]) const;
    std::uint32_t crossingOf(const std::int64_t c[3], int l) const;
    template <class Visit> void forEachCrossingOf(const std::int64_t c[3], Visit&& visit) const;
    // The block next to block b across its face (axis, side: 0 below, 1 above); none past the grid.
    std::optional<std::size_t> neighbourBlock(const std::array<int, 3>& b, int axis, int side) const {
        std::array<int, 3> next = b;
        next[std::size_t(axis)] += side ? 1 : -1;
        if (next[std::size_t(axis)] < 0 || next[std::size_t(axis)] >= blocksPerAxis) return std::nullopt;
        return (std::size_t(next[2]) * std::size_t(blocksPerAxis) + std::size_t(next[1])) * std::size_t(blocksPerAxis) +
               std::size_t(next[0]);
    }
    std::size_t blockIndexOf(const std::int64_t c[3]) const {
        return std::size_t(((c[2] / kBlock) * blocksPerAxis + c[1] / kBlock) * blocksPerAxis + c[0] / kBlock);
    }
    void splitJoinedFaces();
    Expected<void> projectVertices();
    Expected<void> connectQuads();

    const shaders::PreparedSdf& sdf;
    const MeshOptions& options;
    const ProgressSink& progress;
    Grid grid{};
    glm::dvec3 clipLow{0.0}, clipHigh{0.0};
    MeshStats stats;
    detail::PointEvaluator field; // f (and its gradient) at the points each step chooses
    const CubeTables& tables = cube();
    int blocksPerAxis = 0;
    std::vector<std::array<int, 3>> kept;                 // the blocks that may hold surface
    std::vector<std::int32_t> blockSlot;                  // each block's index in kept, or -1
    std::vector<float> values;                            // the kept blocks' grid points, kPoints a block
    std::vector<std::uint64_t> wantedSubs, evaluatedSubs; // per kept block: a bit per sub-block (subIndex)
    std::vector<std::bitset<kPoints>> evaluatedPoints;    // per kept block: the points holding f, not a centre's value
    std::vector<RankedBits<kEdgeSlots>> blockEdges;
    std::vector<Edge> edges;       // with a sign change
    std::vector<float> edgeValues; // f at the start and the end of each edge
    std::vector<float> crossings, crossingValues, normals;
    float normalStep = 0.0f;   // the normals' difference step
    double vertexMargin = 0.0; // how far a vertex on a sharp edge may leave its cell
    Mesh mesh;
    std::vector<RankedBits<kCells>> blockCells;
    std::vector<CellRecord> cellRecords;
    std::vector<std::array<std::int32_t, 3>> vertexCell;
    std::vector<std::array<std::int32_t, 3>> jointCells; // cells with a jointFaces bit
    // The vertex of each segment of an ambiguous face that the patches on both sides join, by
    // faceKey (see splitJoinedFaces).
    std::unordered_map<std::uint64_t, std::uint32_t> faceVertices;
    std::size_t cellVertexCount = 0; // the cells' vertices come first, the face vertices after them
    std::uint64_t faceKey(const std::int64_t lower[3], int axis, int segment) const {
        return ((std::uint64_t((lower[2] * grid.n + lower[1]) * grid.n + lower[0])) * 3 + std::uint64_t(axis)) * 2 +
               std::uint64_t(segment);
    }
};

Expected<std::pair<Mesh, MeshStats>> Extraction::run() {
    const auto start = std::chrono::steady_clock::now();
    // One cell of padding on every side, and the field cut by a box half a cell beyond the bounds:
    // a shape that leaves the bounds is closed there (flat caps, sharp rims), so every mesh is
    // closed. A shape inside the bounds is meshed as before: the cut changes no sign there.
    const glm::dvec3 step = (glm::dvec3(options.boundsMax) - glm::dvec3(options.boundsMin)) / double(options.resolution);
    grid = Grid{options.resolution + 2, glm::dvec3(options.boundsMin) - step, step};
    const auto [cutLow, cutHigh] = cutBox(options);
    clipLow = glm::dvec3(cutLow);
    clipHigh = glm::dvec3(cutHigh);
    if (auto ok = field.build(sdf, "analysis/points.glsl", options.time, options.parameters); !ok) return ok.error();
    field.setClip(clipLow, clipHigh);

    // A hundredth of a cell: with a twentieth, a crossing that near a crease got a normal mixed from
    // both faces, whose plane put a rotated box's corner 2.3e-3 off at 128 cells.
    normalStep = float(0.01 * std::min({grid.step.x, grid.step.y, grid.step.z}));
    vertexMargin = 0.5 * std::min({grid.step.x, grid.step.y, grid.step.z});
    auto phaseStart = start;
    auto phase = [&](const char* name) {
        const auto now = std::chrono::steady_clock::now();
        stats.phaseSeconds.emplace_back(name, std::chrono::duration<double>(now - phaseStart).count());
        phaseStart = now;
    };
    phase("compile");
    if (auto ok = selectBlocks(); !ok) return ok.error();
    phase("select blocks");
    progress(1, 4);
    if (auto ok = evaluateBlocks(); !ok) return ok.error();
    phase("evaluate blocks");
    if (progress.isCancelled()) return makeError("mesh: cancelled");
    progress(2, 4);
    findEdges();
    phase("find edges");
    if (auto ok = placeCrossings(); !ok) return ok.error();
    phase("place crossings");
    progress(3, 4);
    placeVertices();
    splitJoinedFaces();
    phase("place vertices");
    if (auto ok = projectVertices(); !ok) return ok.error();
    phase("project vertices");
    if (auto ok = connectQuads(); !ok) return ok.error();
    const auto weldTolerance = float(1e-6 * std::min({grid.step.x, grid.step.y, grid.step.z}));
    weldCoincidentVertices(mesh, weldTolerance);
    stats.collinearFlips = flipCollinearTriangles(mesh);
    phase("connect");
    if (options.refine > 0) {
        const Topology coarse = checkTopology(mesh);
        const std::uint64_t coarseTriangles = mesh.triangleCount();
        auto refined = detail::refineOntoSurface(mesh, field, options.refine, normalStep, options.refineTriangleLimit);
        if (!refined) return refined.error();
        stats.pointsEvaluated += refined->pointsEvaluated;
        stats.midpointsKept = refined->midpointsKept;
        stats.topology = subdividedTopology(coarse, coarseTriangles, options.refine);
        // Two vertices at one position that the weld had to keep apart (a pinch in a fractal's
        // tunnels) give their edges' midpoints one position too, and the triangles between those
        // zero area: welded and flipped as the coarse mesh was, and then checked afresh.
        if (countDegenerateTriangles(mesh) > 0) {
            weldCoincidentVertices(mesh, weldTolerance);
            stats.collinearFlips += flipCollinearTriangles(mesh);
            stats.topology = checkTopology(mesh);
        }
        phase("refine");
    }
    progress(4, 4);
    stats.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return std::pair<Mesh, MeshStats>{std::move(mesh), stats};
}

// 1. Block centres: which blocks may hold surface.
Expected<void> Extraction::selectBlocks() {
    blocksPerAxis = (grid.n + kBlock - 1) / kBlock;
    std::vector<float> centres;
    centres.reserve(3 * std::size_t(blocksPerAxis) * blocksPerAxis * blocksPerAxis);
    for (int bk = 0; bk < blocksPerAxis; ++bk)
        for (int bj = 0; bj < blocksPerAxis; ++bj)
            for (int bi = 0; bi < blocksPerAxis; ++bi) {
                const glm::dvec3 lo = glm::dvec3(bi, bj, bk) * double(kBlock);
                const glm::dvec3 hi = glm::min(lo + double(kBlock), glm::dvec3(grid.n));
                const glm::dvec3 c = grid.origin + 0.5 * (lo + hi) * grid.step;
                centres.insert(centres.end(), {float(c.x), float(c.y), float(c.z)});
            }
    std::vector<float> centreValues, centreGradients;
    const float gradientStep = float(0.25 * std::min({grid.step.x, grid.step.y, grid.step.z}));
    if (auto ok = field.evaluate(centres, centreValues, options.estimateLipschitz ? &centreGradients : nullptr, gradientStep);
        !ok)
        return ok.error();
    stats.pointsEvaluated += centreValues.size() * (options.estimateLipschitz ? 7 : 1);
    stats.blocks = centreValues.size();
    const float bound = options.estimateLipschitz ? estimateBound(centreValues, centreGradients) : options.lipschitz;
    stats.lipschitzUsed = bound;
    const double halfDiagonal = 0.5 * glm::length(grid.step * double(kBlock));
    blockSlot.assign(centreValues.size(), -1);
    for (std::size_t b = 0; b < centreValues.size(); ++b)
        if (maySurface(centreValues[b], halfDiagonal)) keep(b);
    return {};
}

// The bound the blocks are skipped by when it is estimated: 1.25 x the steepest |grad f| at a block
// centre (a quarter-cell central difference) or quotient between neighbouring centres, at least 1.
float Extraction::estimateBound(const std::vector<float>& centreValues, const std::vector<float>& centreGradients) const {
    float steepest = 0.0f;
    for (std::size_t b = 0; b < centreValues.size(); ++b) {
        const glm::vec3 g(centreGradients[3 * b], centreGradients[3 * b + 1], centreGradients[3 * b + 2]);
        if (std::isfinite(centreValues[b]) && std::isfinite(glm::length(g))) steepest = std::max(steepest, glm::length(g));
    }
    const std::size_t n = std::size_t(blocksPerAxis);
    for (std::size_t b = 0; b < centreValues.size(); ++b) {
        const std::size_t at[3] = {b % n, b / n % n, b / (n * n)};
        const std::size_t stride[3] = {1, n, n * n};
        for (int a = 0; a < 3; ++a) {
            if (at[a] + 2 >= n) continue; // the last block may be short: its centre is off the spacing
            const float quotient = std::abs(centreValues[b + stride[a]] - centreValues[b]) / float(grid.step[a] * kBlock);
            if (std::isfinite(quotient)) steepest = std::max(steepest, quotient);
        }
    }
    return std::max(1.0f, 1.25f * steepest);
}

void Extraction::keep(std::size_t block) {
    blockSlot[block] = std::int32_t(kept.size());
    const std::size_t n = std::size_t(blocksPerAxis);
    kept.push_back({int(block % n), int(block / n % n), int(block / (n * n))});
    stats.blocksKept = kept.size();
}

// 2. The grid points of the kept blocks, (B+1)^3 per block in a dense array (a point on a face
// two kept blocks share is evaluated by both, at the same coordinates, so to the same value). Only
// the points of sub-blocks that may hold surface are evaluated (selectSubBlocks); the others hold
// the value at the centre of the octant or sub-block the bound skipped. A skipped block whose face
// with a kept block the surface crosses is kept and evaluated after all, until no crossed face
// leads to a skipped block: a bound that was too low loses no connected surface.
Expected<void> Extraction::evaluateBlocks() {
    detail::PointEvaluator lattice;
    if (auto ok = lattice.build(sdf, "analysis/lattice.glsl", options.time, options.parameters); !ok) return ok.error();
    lattice.setClip(clipLow, clipHigh);
    for (std::size_t from = 0; from < kept.size();) {
        const std::size_t to = kept.size();
        values.resize(to * std::size_t(kPoints));
        wantedSubs.resize(to, 0);
        evaluatedSubs.resize(to, 0);
        evaluatedPoints.resize(to);
        if (auto ok = selectSubBlocks(lattice, from, to); !ok) return ok.error();
        do {
            if (auto ok = evaluateWanted(lattice); !ok) return ok.error();
        } while (wantMoreSubBlocks());
        // Every block again: a repair in a later round can change an earlier block's face.
        for (std::size_t slot = 0; slot < to; ++slot) keepNeighboursAcrossCrossedFaces(slot);
        from = to;
        if (progress.isCancelled()) return makeError("mesh: cancelled");
    }
    stats.boundsCutPoints = lattice.clipped();
    return {};
}

bool Extraction::maySurface(float f, double halfDiagonal) const {
    const float bound = stats.lipschitzUsed;
    return bound <= 0.0f || !std::isfinite(f) || std::abs(double(f)) <= double(bound) * halfDiagonal * 1.001 + 1e-6;
}

// 2a. Which sub-blocks of blocks [from, to) may hold surface: the field at the centres of each
// block's eight octants, then at the centres of the eight sub-blocks of each octant that may (each
// by the bound and its half diagonal, as the blocks were). The centres are grid points and keep
// their values; the other points of a skipped cube take its centre's. A block cut short by the
// grid's end is evaluated whole, and so are the blocks of a round of fewer than
// kFewestBlocksForSubBlocks: there the two extra dispatches cost more than they save (a 16^3 grid
// took 0.6 ms longer with them).
Expected<void> Extraction::selectSubBlocks(detail::PointEvaluator& lattice, std::size_t from, std::size_t to) {
    struct Cube {
        std::size_t slot;
        std::array<int, 3> lo; // local corner, in cells
    };
    std::vector<float> indices, f;
    auto centres = [&](const std::vector<Cube>& cubes, int size) -> Expected<void> {
        if (cubes.empty()) return {};
        indices.clear();
        indices.reserve(3 * cubes.size());
        for (const Cube& c : cubes)
            for (int a = 0; a < 3; ++a)
                indices.push_back(float(kept[c.slot][std::size_t(a)] * kBlock + c.lo[std::size_t(a)] + size / 2));
        if (auto ok = lattice.evaluateLattice(indices, glm::vec3(grid.origin), glm::vec3(grid.step), 0, grid.n, f); !ok)
            return ok.error();
        stats.pointsEvaluated += f.size();
        for (std::size_t q = 0; q < cubes.size(); ++q) {
            const Cube& c = cubes[q];
            const int p = (c.lo[2] + size / 2) * kStride[2] + (c.lo[1] + size / 2) * kStride[1] + c.lo[0] + size / 2;
            values[c.slot * std::size_t(kPoints) + std::size_t(p)] = f[q];
            evaluatedPoints[c.slot].set(std::size_t(p));
        }
        return {};
    };
    // The points of a skipped cube not evaluated already take its centre's value.
    auto fill = [&](const Cube& c, int size, float value) {
        float* v = values.data() + c.slot * std::size_t(kPoints);
        const std::bitset<kPoints>& done = evaluatedPoints[c.slot];
        for (int k = c.lo[2]; k <= c.lo[2] + size; ++k)
            for (int j = c.lo[1]; j <= c.lo[1] + size; ++j)
                for (int i = c.lo[0]; i <= c.lo[0] + size; ++i)
                    if (const int p = (k * kSide + j) * kSide + i; !done.test(std::size_t(p))) v[p] = value;
    };
    constexpr std::size_t kFewestBlocksForSubBlocks = 64;
    std::vector<Cube> octants, subs;
    for (std::size_t slot = from; slot < to; ++slot) {
        const auto& b = kept[slot];
        if (to - from < kFewestBlocksForSubBlocks || b[0] * kBlock + kBlock > grid.n || b[1] * kBlock + kBlock > grid.n ||
            b[2] * kBlock + kBlock > grid.n) {
            wantedSubs[slot] = ~std::uint64_t(0);
            continue;
        }
        for (int o = 0; o < 8; ++o) octants.push_back({slot, {(o & 1) * kOctant, (o >> 1 & 1) * kOctant, (o >> 2) * kOctant}});
    }
    if (auto ok = centres(octants, kOctant); !ok) return ok.error();
    const double octantHalfDiagonal = 0.5 * glm::length(grid.step * double(kOctant));
    for (std::size_t q = 0; q < octants.size(); ++q) {
        const Cube& o = octants[q];
        if (!maySurface(f[q], octantHalfDiagonal)) {
            fill(o, kOctant, f[q]);
            continue;
        }
        for (int s = 0; s < 8; ++s)
            subs.push_back({o.slot, {o.lo[0] + (s & 1) * kSub, o.lo[1] + (s >> 1 & 1) * kSub, o.lo[2] + (s >> 2) * kSub}});
    }
    if (auto ok = centres(subs, kSub); !ok) return ok.error();
    const double subHalfDiagonal = 0.5 * glm::length(grid.step * double(kSub));
    for (std::size_t q = 0; q < subs.size(); ++q) {
        const Cube& s = subs[q];
        if (maySurface(f[q], subHalfDiagonal))
            wantedSubs[s.slot] |= std::uint64_t(1) << subIndex(s.lo[0] / kSub, s.lo[1] / kSub, s.lo[2] / kSub);
        else
            fill(s, kSub, f[q]);
    }
    return {};
}

// 2b. The grid points of every wanted sub-block not evaluated yet, each once per block: a lattice
// of single points, so each has the float position any block's lattice gives it. Chunks of blocks
// list their points on several threads, and write the values back the same way.
Expected<void> Extraction::evaluateWanted(detail::PointEvaluator& lattice) {
    const std::size_t count = wantedSubs.size();
    const std::size_t chunks = chunkCount(count, 256);
    std::vector<std::vector<std::uint16_t>> local(chunks); // per chunk, per block in order: its new points
    std::vector<std::vector<std::uint32_t>> perBlock(chunks);
    // Points past the grid's end (in a block it cuts short) have the index of the last point on
    // their line, so its value: they are copied from it, not evaluated again.
    std::vector<std::vector<std::size_t>> beyond(chunks);
    forEachChunk(count, chunks, [&](std::size_t chunk, std::size_t first, std::size_t end) {
        for (std::size_t slot = first; slot < end; ++slot) {
            std::uint64_t fresh = wantedSubs[slot] & ~evaluatedSubs[slot];
            evaluatedSubs[slot] |= fresh;
            std::bitset<kPoints>& done = evaluatedPoints[slot];
            const auto& b = kept[slot];
            const int last[3] = {grid.n - b[0] * kBlock, grid.n - b[1] * kBlock, grid.n - b[2] * kBlock};
            const std::size_t before = local[chunk].size();
            for (; fresh != 0; fresh &= fresh - 1) {
                const int s = std::countr_zero(fresh);
                const std::array<int, 3> lo = subCorner(s);
                for (int k = lo[2]; k <= lo[2] + kSub; ++k)
                    for (int j = lo[1]; j <= lo[1] + kSub; ++j)
                        for (int i = lo[0]; i <= lo[0] + kSub; ++i)
                            if (const int p = (k * kSide + j) * kSide + i; !done.test(std::size_t(p))) {
                                done.set(std::size_t(p));
                                if (i > last[0] || j > last[1] || k > last[2])
                                    beyond[chunk].push_back(slot * std::size_t(kPoints) + std::size_t(p));
                                else
                                    local[chunk].push_back(std::uint16_t(p));
                            }
            }
            perBlock[chunk].push_back(std::uint32_t(local[chunk].size() - before));
        }
    });
    std::vector<std::size_t> offset(chunks + 1, 0);
    for (std::size_t c = 0; c < chunks; ++c) offset[c + 1] = offset[c] + local[c].size();
    std::vector<float> indices(3 * offset[chunks]), fresh;
    auto walk = [&](std::size_t chunk, std::size_t first, std::size_t end, auto&& visit) {
        std::size_t at = offset[chunk], q = 0;
        for (std::size_t slot = first; slot < end; ++slot)
            for (std::uint32_t n = perBlock[chunk][slot - first]; n > 0; --n, ++q, ++at) visit(slot, local[chunk][q], at);
    };
    forEachChunk(count, chunks, [&](std::size_t chunk, std::size_t first, std::size_t end) {
        walk(chunk, first, end, [&](std::size_t slot, int p, std::size_t at) {
            const auto& b = kept[slot];
            indices[3 * at] = float(b[0] * kBlock + p % kSide);
            indices[3 * at + 1] = float(b[1] * kBlock + p / kSide % kSide);
            indices[3 * at + 2] = float(b[2] * kBlock + p / (kSide * kSide));
        });
    });
    if (auto ok = lattice.evaluateLattice(indices, glm::vec3(grid.origin), glm::vec3(grid.step), 0, grid.n, fresh); !ok)
        return ok.error();
    forEachChunk(count, chunks, [&](std::size_t chunk, std::size_t first, std::size_t end) {
        walk(chunk, first, end,
             [&](std::size_t slot, int p, std::size_t at) { values[slot * std::size_t(kPoints) + std::size_t(p)] = fresh[at]; });
        for (const std::size_t at : beyond[chunk]) {
            const std::size_t slot = at / std::size_t(kPoints);
            const int p = int(at % std::size_t(kPoints));
            const auto& b = kept[slot];
            const int i = std::min(p % kSide, grid.n - b[0] * kBlock), j = std::min(p / kSide % kSide, grid.n - b[1] * kBlock),
                      k = std::min(p / (kSide * kSide), grid.n - b[2] * kBlock);
            values[at] = values[slot * std::size_t(kPoints) + std::size_t((k * kSide + j) * kSide + i)];
        }
    });
    stats.pointsEvaluated += fresh.size();
    return {};
}

// The sub-blocks of a block that hold local grid point (i, j, k).
std::uint64_t subsHolding(int i, int j, int k) {
    std::uint64_t bits = 0;
    auto candidates = [](int c, int out[2]) {
        int count = 0;
        if (c / kSub < kSubsPerAxis) out[count++] = c / kSub;
        if (c % kSub == 0 && c > 0) out[count++] = c / kSub - 1;
        return count;
    };
    int x[2], y[2], z[2];
    const int nx = candidates(i, x), ny = candidates(j, y), nz = candidates(k, z);
    for (int a = 0; a < nx; ++a)
        for (int b = 0; b < ny; ++b)
            for (int c = 0; c < nz; ++c) bits |= std::uint64_t(1) << subIndex(x[a], y[b], z[c]);
    return bits;
}

// 2c. Where a bound that was too low skipped surface, more sub-blocks are wanted: a skipped one
// whose points are not all of one sign (so every cell the surface crosses has all eight corners
// evaluated), and those holding a point on a block's face that is not evaluated in this block and
// whose sign the neighbouring block's copy contradicts (so both blocks see the same crossings on
// their shared face). Returns whether any was.
bool Extraction::wantMoreSubBlocks() {
    const std::size_t count = wantedSubs.size();
    const std::size_t chunks = chunkCount(count, 64);
    std::vector<char> added(chunks, 0);
    forEachChunk(count, chunks, [&](std::size_t chunk, std::size_t first, std::size_t end) {
        for (std::size_t slot = first; slot < end; ++slot) {
            const float* v = values.data() + slot * std::size_t(kPoints);
            std::uint64_t more = 0;
            for (std::uint64_t skipped = ~wantedSubs[slot]; skipped != 0; skipped &= skipped - 1) {
                const int s = std::countr_zero(skipped);
                const std::array<int, 3> lo = subCorner(s);
                bool seenInside = false, seenOutside = false;
                for (int k = lo[2]; k <= lo[2] + kSub; ++k)
                    for (int j = lo[1]; j <= lo[1] + kSub; ++j)
                        for (int i = lo[0]; i <= lo[0] + kSub; ++i) {
                            const float f = v[(k * kSide + j) * kSide + i];
                            if (std::isfinite(f)) (inside(f) ? seenInside : seenOutside) = true;
                        }
                if (seenInside && seenOutside) more |= std::uint64_t(1) << s;
            }
            const auto& b = kept[slot];
            const std::bitset<kPoints>& done = evaluatedPoints[slot];
            for (int axis = 0; axis < 3; ++axis)
                for (int side = 0; side < 2; ++side) {
                    const std::optional<std::size_t> next = neighbourBlock(b, axis, side);
                    if (!next) continue;
                    const std::int32_t other = blockSlot[*next];
                    if (other < 0) continue;
                    const float* w = values.data() + std::size_t(other) * std::size_t(kPoints);
                    const int u = (axis + 1) % 3, t = (axis + 2) % 3;
                    for (int j = 0; j < kSide; ++j)
                        for (int i = 0; i < kSide; ++i) {
                            int local[3];
                            local[axis] = side ? kBlock : 0;
                            local[u] = i;
                            local[t] = j;
                            const int p = local[0] * kStride[0] + local[1] * kStride[1] + local[2] * kStride[2];
                            if (done.test(std::size_t(p))) continue;
                            const int q = p + (side ? -kBlock : kBlock) * kStride[axis];
                            if (crosses(v[p], w[q])) more |= subsHolding(local[0], local[1], local[2]);
                        }
                }
            if (more & ~wantedSubs[slot]) {
                wantedSubs[slot] |= more;
                added[chunk] = 1;
            }
        }
    });
    return std::find(added.begin(), added.end(), 1) != added.end();
}

void Extraction::keepNeighboursAcrossCrossedFaces(std::size_t slot) {
    const std::array<int, 3> b = kept[slot];
    const float* v = values.data() + slot * std::size_t(kPoints);
    for (int axis = 0; axis < 3; ++axis)
        for (int side = 0; side < 2; ++side) {
            const std::optional<std::size_t> next = neighbourBlock(b, axis, side);
            if (!next || blockSlot[*next] >= 0) continue;
            const std::size_t index = *next;
            const int u = (axis + 1) % 3, w = (axis + 2) % 3;
            bool seenInside = false, seenOutside = false;
            for (int j = 0; j < kSide && !(seenInside && seenOutside); ++j)
                for (int i = 0; i < kSide; ++i) {
                    const float f = v[(side ? kBlock : 0) * kStride[axis] + i * kStride[u] + j * kStride[w]];
                    if (!std::isfinite(f)) continue;
                    (inside(f) ? seenInside : seenOutside) = true;
                }
            if (seenInside && seenOutside) {
                keep(index);
                ++stats.blocksGrown;
            }
        }
}

// 3. Edges with a sign change, block by block in slot order (so that a block's bits number them);
// chunks of blocks on several threads, joined in slot order.
void Extraction::findEdges() {
    blockEdges.assign(kept.size(), {});
    struct Found {
        std::vector<Edge> edges;
        std::vector<float> values;
    };
    const std::size_t chunks = chunkCount(kept.size(), 64);
    std::vector<Found> found(chunks);
    forEachChunk(kept.size(), chunks, [&](std::size_t chunk, std::size_t first, std::size_t end) {
        Found& out = found[chunk];
        for (std::size_t slot = first; slot < end; ++slot) {
            const auto& b = kept[slot];
            const float* v = values.data() + slot * std::size_t(kPoints);
            const bool last[3] = {b[0] == blocksPerAxis - 1, b[1] == blocksPerAxis - 1, b[2] == blocksPerAxis - 1};
            RankedBits<kEdgeSlots>& bits = blockEdges[slot];
            const std::bitset<kPoints>& evaluated = evaluatedPoints[slot];
            for (int k = 0; k < kSide; ++k)
                for (int j = 0; j < kSide; ++j)
                    for (int i = 0; i < kSide; ++i) {
                        const int p = (k * kSide + j) * kSide + i;
                        // A point no evaluated sub-block holds lies in skipped ones only, whose points
                        // have one sign (wantMoreSubBlocks): none of its edges crosses.
                        if (!evaluated.test(std::size_t(p))) continue;
                        const int local[3] = {i, j, k};
                        for (int axis = 0; axis < 3; ++axis) {
                            if (local[axis] == kBlock) continue;
                            const float f0 = v[p], f1 = v[p + kStride[axis]];
                            if (!crosses(f0, f1)) continue;
                            bits.set(3 * p + axis);
                            const bool owned = (i < kBlock || last[0]) && (j < kBlock || last[1]) && (k < kBlock || last[2]);
                            out.edges.push_back(
                                {b[0] * kBlock + i, b[1] * kBlock + j, b[2] * kBlock + k, std::int8_t(axis), inside(f0), owned});
                            out.values.insert(out.values.end(), {f0, f1});
                        }
                    }
        }
    });
    for (Found& part : found) {
        edges.insert(edges.end(), part.edges.begin(), part.edges.end());
        edgeValues.insert(edgeValues.end(), part.values.begin(), part.values.end());
    }
    std::uint32_t edgeCount = 0;
    for (RankedBits<kEdgeSlots>& bits : blockEdges) edgeCount = bits.number(edgeCount);
}

Expected<void> Extraction::placeCrossings() {
    auto edgeStart = [&](const Edge& e) { return glm::dvec3(grid.point(e.i, e.j, e.k)); };
    auto edgeVector = [&](const Edge& e) {
        glm::dvec3 d(0.0);
        d[e.axis] = grid.step[e.axis];
        return d;
    };
    // The crossing on each edge by false position with the Illinois rule (the field, not a linear
    // fit of its ends: near a box's edge the inside value follows another face): superlinear on
    // smooth and kinked fields alike; an edge stops when its crossing is known to 1e-4 of its length.
    crossings.assign(3 * edges.size(), 0.0f);
    {
        struct Bracket {
            double a = 0.0, b = 1.0, fa, fb, t;
            int side = 0;
        };
        std::vector<Bracket> brackets(edges.size());
        std::vector<std::uint32_t> active(edges.size());
        for (std::size_t e = 0; e < edges.size(); ++e) {
            brackets[e].fa = edgeValues[2 * e];
            brackets[e].fb = edgeValues[2 * e + 1];
            active[e] = std::uint32_t(e);
        }
        std::vector<float> guesses, guessValues;
        for (int iteration = 0; iteration < 8 && !active.empty(); ++iteration) {
            guesses.resize(3 * active.size());
            const std::size_t chunks = chunkCount(active.size(), 8192);
            forEachChunk(active.size(), chunks, [&](std::size_t, std::size_t first, std::size_t end) {
                for (std::size_t q = first; q < end; ++q) {
                    Bracket& r = brackets[active[q]];
                    r.t = (r.a * r.fb - r.b * r.fa) / (r.fb - r.fa);
                    if (!(r.t > r.a && r.t < r.b)) r.t = 0.5 * (r.a + r.b);
                    const glm::dvec3 p = edgeStart(edges[active[q]]) + r.t * edgeVector(edges[active[q]]);
                    guesses[3 * q] = float(p.x);
                    guesses[3 * q + 1] = float(p.y);
                    guesses[3 * q + 2] = float(p.z);
                }
            });
            if (auto ok = field.evaluate(guesses, guessValues, nullptr); !ok) return ok.error();
            stats.pointsEvaluated += guessValues.size();
            // Each chunk keeps its edges still open at its own start (in order), then the lists close up.
            std::vector<std::size_t> stillOpen(chunks);
            forEachChunk(active.size(), chunks, [&](std::size_t chunk, std::size_t first, std::size_t end) {
                std::size_t still = first;
                for (std::size_t q = first; q < end; ++q) {
                    Bracket& r = brackets[active[q]];
                    const double f = guessValues[q];
                    if (!std::isfinite(f)) continue;
                    if (inside(float(f)) == inside(float(r.fa))) {
                        r.a = r.t;
                        r.fa = f;
                        if (r.side == -1) r.fb *= 0.5;
                        r.side = -1;
                    } else {
                        r.b = r.t;
                        r.fb = f;
                        if (r.side == 1) r.fa *= 0.5;
                        r.side = 1;
                    }
                    // Done when t is known to 1e-4 of the edge: the bracket is that small, or |f| over the
                    // field's slope along the edge is (a small |f| alone misleads on an edge that grazes
                    // the surface, where the slope is small too).
                    const double slope = std::abs(r.fb - r.fa) / (r.b - r.a);
                    if (r.b - r.a > 1e-4 && std::abs(f) > 1e-4 * slope) active[still++] = active[q];
                }
                stillOpen[chunk] = still - first;
            });
            std::size_t still = 0;
            for (std::size_t chunk = 0; chunk < chunks; ++chunk) {
                const std::size_t first = active.size() * chunk / chunks;
                std::copy_n(active.begin() + std::ptrdiff_t(first), stillOpen[chunk], active.begin() + std::ptrdiff_t(still));
                still += stillOpen[chunk];
            }
            active.resize(still);
            if (progress.isCancelled()) return makeError("mesh: cancelled");
        }
        for (std::size_t e = 0; e < edges.size(); ++e) {
            const Bracket& r = brackets[e];
            // Never on a grid point itself: where the surface touches the grid at a point (f = 0
            // there, a torus's pole on a grid plane), the four cells around would otherwise put their
            // vertices within float rounding of each other and fold the mesh there.
            const double t = std::clamp(r.t, 1.0 / 1024.0, 1.0 - 1.0 / 1024.0);
            const glm::dvec3 p = edgeStart(edges[e]) + t * edgeVector(edges[e]);
            crossings[3 * e] = float(p.x);
            crossings[3 * e + 1] = float(p.y);
            crossings[3 * e + 2] = float(p.z);
        }
    }
    if (auto ok = field.evaluate(crossings, crossingValues, &normals, normalStep); !ok) return ok.error();
    stats.pointsEvaluated += crossingValues.size();
    return {};
}

// 4. Vertices: one per patch of surface in each cell. A cell's crossing edges are joined along
// its faces (an ambiguous face, with four crossings, is split by the sign of its bilinear
// centre, which both cells sharing it see alike), so two sheets through one cell get a vertex
// each and the mesh stays manifold. Each vertex is its patch's QEF minimiser, clamped into the cell.
void Extraction::placeVertices() {
    blockCells.assign(kept.size(), {});
    struct Placed { // one chunk's: its vertices numbered from 0, shifted when the chunks are joined
        std::vector<glm::vec3> vertices;
        std::vector<std::array<std::int32_t, 3>> vertexCell, jointCells;
        std::vector<CellRecord> records;
        std::uint64_t creasesOnFaces = 0, verticesBesideTheirCell = 0, clampedVertices = 0;
    };
    const std::size_t chunks = chunkCount(kept.size(), 32);
    std::vector<Placed> placed(chunks);
    forEachChunk(kept.size(), chunks, [&](std::size_t chunk, std::size_t first, std::size_t end) {
        Placed& out = placed[chunk];
        for (std::size_t slot = first; slot < end; ++slot) {
            const auto& b = kept[slot];
            const float* v = values.data() + slot * std::size_t(kPoints);
            const RankedBits<kEdgeSlots>& bits = blockEdges[slot];
            const std::uint64_t evaluated = evaluatedSubs[slot];
            for (int k = 0; k < kBlock && b[2] * kBlock + k < grid.n; ++k)
                for (int j = 0; j < kBlock && b[1] * kBlock + j < grid.n; ++j)
                    for (int i = 0; i < kBlock && b[0] * kBlock + i < grid.n; ++i) {
                        if (!(evaluated >> subIndex(i / kSub, j / kSub, k / kSub) & 1u)) continue; // one sign throughout
                        const int p = (k * kSide + j) * kSide + i;
                        float corner[8];
                        int signs = 0;
                        for (int c = 0; c < 8; ++c) {
                            corner[c] = v[p + (c & 1) * kStride[0] + (c >> 1 & 1) * kStride[1] + (c >> 2) * kStride[2]];
                            signs |= int(inside(corner[c])) << c;
                        }
                        if (signs == 0 || signs == 0xff) continue; // one side (NaN counts as outside, and crosses nothing)
                        int present = 0;
                        std::uint32_t global[12];
                        for (int l = 0; l < 12; ++l) {
                            if (!crosses(corner[tables.edgeCorner[l][0]], corner[tables.edgeCorner[l][1]])) continue;
                            present |= 1 << l;
                            const int* o = tables.edgeOffset[l];
                            global[l] = bits.rank(3 * (p + o[0] * kStride[0] + o[1] * kStride[1] + o[2] * kStride[2]) + l / 4);
                        }
                        if (present == 0) continue;
                        int parent[12];
                        for (int l = 0; l < 12; ++l) parent[l] = l;
                        auto find = [&](int x) {
                            while (parent[x] != x) x = parent[x] = parent[parent[x]];
                            return x;
                        };
                        auto join = [&](int a, int c) { parent[find(a)] = find(c); };
                        int ambiguous = 0, crossPaired = 0;
                        for (int face = 0; face < 6; ++face) {
                            const int* fe = tables.faceEdges[face];
                            int on[4], count = 0;
                            for (int q = 0; q < 4; ++q)
                                if (present >> fe[q] & 1) on[count++] = fe[q];
                            if (count == 4) {
                                const int* fc = tables.faceCorners[face];
                                const float c00 = corner[fc[0]];
                                const float centre = 0.25f * (c00 + corner[fc[1]] + corner[fc[2]] + corner[fc[3]]);
                                const int paired = inside(centre) == inside(c00) ? 0 : 1;
                                for (const auto& segment : kSegments[paired]) join(fe[segment[0]], fe[segment[1]]);
                                ambiguous |= 1 << face;
                                crossPaired |= paired << face;
                            } else {
                                for (int q = 1; q < count; ++q) join(on[0], on[q]);
                            }
                        }
                        const std::int32_t cell[3] = {b[0] * kBlock + i, b[1] * kBlock + j, b[2] * kBlock + k};
                        const glm::dvec3 lo = glm::dvec3(grid.point(cell[0], cell[1], cell[2]));
                        const glm::dvec3 hi = glm::dvec3(grid.point(cell[0] + 1, cell[1] + 1, cell[2] + 1));
                        CellRecord record{std::uint32_t(out.vertices.size()), 0, 0, std::uint8_t(crossPaired)};
                        for (int face = 0; face < 6; ++face)
                            if (ambiguous >> face & 1 && find(tables.faceEdges[face][0]) == find(tables.faceEdges[face][1]))
                                record.jointFaces |= std::uint8_t(1 << face);
                        if (record.jointFaces != 0) out.jointCells.push_back({cell[0], cell[1], cell[2]});
                        std::uint32_t patch = 0;
                        for (int root = 0; root < 12; ++root) {
                            if (!(present >> root & 1) || find(root) != root) continue;
                            glm::dvec3 points[13], patchNormals[13];
                            int count = 0;
                            for (int l = 0; l < 12; ++l) {
                                if (!(present >> l & 1) || find(l) != root) continue;
                                record.vertexOfEdge |= patch << (2 * l);
                                const std::size_t e = global[l];
                                const glm::dvec3 n(normals[3 * e], normals[3 * e + 1], normals[3 * e + 2]);
                                const double length = glm::length(n);
                                points[count] = glm::dvec3(crossings[3 * e], crossings[3 * e + 1], crossings[3 * e + 2]);
                                patchNormals[count++] = length > 0.0 && std::isfinite(length) ? n / length : glm::dvec3(0.0);
                            }
                            QefSolution qef = solveQef(points, patchNormals, count);
                            if (qef.freeCount > 0 && count < 13)
                                if (const auto crease = creaseOnUpperFace(points, patchNormals, count, qef, cell, hi)) {
                                    points[count] = crease->first;
                                    patchNormals[count++] = crease->second;
                                    qef = solveQef(points, patchNormals, count);
                                    ++out.creasesOnFaces;
                                }
                            const glm::dvec3 x =
                                placeVertex(qef, lo, hi, vertexMargin, out.verticesBesideTheirCell, out.clampedVertices);
                            out.vertices.push_back(glm::vec3(x));
                            out.vertexCell.push_back({cell[0], cell[1], cell[2]});
                            ++patch;
                        }
                        blockCells[slot].set((k * kBlock + j) * kBlock + i);
                        out.records.push_back(record);
                    }
        }
    });
    for (Placed& part : placed) {
        const auto base = std::uint32_t(mesh.vertices.size());
        for (CellRecord& record : part.records) record.firstVertex += base;
        mesh.vertices.insert(mesh.vertices.end(), part.vertices.begin(), part.vertices.end());
        vertexCell.insert(vertexCell.end(), part.vertexCell.begin(), part.vertexCell.end());
        jointCells.insert(jointCells.end(), part.jointCells.begin(), part.jointCells.end());
        cellRecords.insert(cellRecords.end(), part.records.begin(), part.records.end());
        stats.creasesOnFaces += part.creasesOnFaces;
        stats.verticesBesideTheirCell += part.verticesBesideTheirCell;
        stats.clampedVertices += part.clampedVertices;
    }
    std::uint32_t cellCount = 0;
    for (RankedBits<kCells>& bits : blockCells) cellCount = bits.number(cellCount);
    stats.activeCells = cellRecords.size();
}

// f at the eight corners of cell c (corner x + 2y + 4z); false outside the grid and in blocks
// skipped as empty.
bool Extraction::cellCorners(const std::int64_t c[3], float corner[8]) const {
    for (int a = 0; a < 3; ++a)
        if (c[a] < 0 || c[a] >= grid.n) return false;
    const std::int32_t slot = blockSlot[blockIndexOf(c)];
    if (slot < 0) return false;
    const float* v = values.data() + std::size_t(slot) * std::size_t(kPoints);
    int p = 0;
    for (int a = 0; a < 3; ++a) p += int(c[a] % kBlock) * kStride[a];
    for (int k = 0; k < 8; ++k) corner[k] = v[p + (k & 1) * kStride[0] + (k >> 1 & 1) * kStride[1] + (k >> 2) * kStride[2]];
    return true;
}

// A crease that lies exactly on a face between two cells (a hexagonal prism's corner on the plane
// x = 0) leaves each cell's crossings on one face only, and each cell's vertex on its own face, so
// the triangles between them cut the crease off (by a quarter cell). The crossings on that face's
// edges lie on the crease, their normals a mix of the two faces'; the QEF drops the direction that
// mix turns by. A patch with such a crossing on its upper face gets, through it, the plane of the
// cell above whose normal turns furthest from the face the mixed normal is nearest (further than
// the mixed one does): its vertex goes onto the crease, and the cell above keeps its flat vertex,
// whose triangles then lie in that face. Only the lower cell moves: both would put their vertices
// at one point. The crease must lie in the face, the patch's face must reach a tenth of a cell off
// it, and neither face may lie in the grid's plane (the Menger sponge's walls on grid planes are
// right as they are). Returns the crossing and the other face's normal.
std::optional<std::pair<glm::dvec3, glm::dvec3>> Extraction::creaseOnUpperFace(const glm::dvec3* points,
                                                                               const glm::dvec3* patchNormals, int count,
                                                                               const QefSolution& qef, const std::int32_t cell[3],
                                                                               const glm::dvec3& hi) const {
    constexpr double kFlat = 0.99619469809;   // cos 5 degrees: a normal this close is the same face's
    constexpr double kCrease = 0.93969262078; // cos 20 degrees: two faces turning further meet at a crease
    for (int i = 0; i < count; ++i) {
        // Only a normal the QEF dropped: it turns along a direction the solution left free (a right
        // angle's mixed normal, 45 degrees off, is kept, and the vertex is on the crease already).
        double dropped = 0.0;
        for (int k = 0; k < qef.freeCount; ++k)
            dropped = std::max(dropped, std::abs(glm::dot(patchNormals[i], qef.free[std::size_t(k)])));
        if (dropped < 0.2) continue;
        int own = -1; // the face this crossing's normal mixes with: the nearest other normal of the patch
        for (int j = 0; j < count; ++j) {
            const double turn = glm::dot(patchNormals[j], patchNormals[i]);
            if (turn <= kFlat && (own < 0 || turn > glm::dot(patchNormals[own], patchNormals[i]))) own = j;
        }
        if (own < 0) continue;
        const double mixed = glm::dot(patchNormals[i], patchNormals[own]);
        for (int a = 0; a < 3; ++a) {
            if (!(std::abs(points[i][a] - hi[a]) < 1e-4 * grid.step[a])) continue;
            std::int64_t above[3] = {cell[0], cell[1], cell[2]};
            ++above[a];
            std::optional<glm::dvec3> other;
            forEachCrossingOf(above, [&](std::uint32_t e) {
                glm::dvec3 n(normals[3 * e], normals[3 * e + 1], normals[3 * e + 2]);
                const double length = glm::length(n);
                if (!(length > 0.0) || !std::isfinite(length)) return;
                n /= length;
                const glm::dvec3 q(crossings[3 * e], crossings[3 * e + 1], crossings[3 * e + 2]);
                if (!(std::abs(glm::dot(n, points[i] - q)) < 1e-3 * grid.step[a])) return; // its plane misses the crossing
                if (!other || glm::dot(n, patchNormals[own]) < glm::dot(*other, patchNormals[own])) other = n;
            });
            if (!other) continue;
            const double turn = glm::dot(*other, patchNormals[own]);
            // The own face must reach well off the crease (a box whose edges lie on grid lines has only
            // mixed normals, each beside a crease: those cells keep their vertices).
            double reach = 0.0;
            for (int j = 0; j < count; ++j)
                if (glm::dot(patchNormals[j], patchNormals[own]) > kFlat)
                    reach = std::max(reach, std::abs(glm::dot(*other, points[j] - points[i])));
            // The crease must lie in the face (not cross it), and neither face in the grid's plane
            // itself (a face on a plane of the grid is met by crossings a 1024th of an edge off it,
            // and its cells are right as they are).
            const glm::dvec3 along = glm::cross(patchNormals[own], *other);
            const bool inTheFace = std::abs(along[a]) < 0.05 * glm::length(along);
            const bool faceInThePlane = std::abs((*other)[a]) > 0.95 || std::abs(patchNormals[own][a]) > 0.95;
            if (turn < kCrease && turn < mixed - 1e-3 && reach > 0.1 * grid.step[a] && inTheFace && !faceInThePlane)
                return std::pair{points[i], *other};
        }
    }
    return std::nullopt;
}

// The record of cell c; null when the cell was not meshed (outside the grid, in a skipped block,
// or with no crossing).
const CellRecord* Extraction::recordAt(const std::int64_t c[3]) const {
    for (int a = 0; a < 3; ++a)
        if (c[a] < 0 || c[a] >= grid.n) return nullptr;
    const std::int32_t slot = blockSlot[blockIndexOf(c)];
    if (slot < 0) return nullptr;
    const int local = int(((c[2] % kBlock) * kBlock + c[1] % kBlock) * kBlock + c[0] % kBlock);
    const RankedBits<kCells>& cells = blockCells[std::size_t(slot)];
    if (!cells.test(local)) return nullptr;
    return &cellRecords[cells.rank(local)];
}

// The index (into edges and crossings) of local edge l of meshed cell c.
std::uint32_t Extraction::crossingOf(const std::int64_t c[3], int l) const {
    const std::int32_t slot = blockSlot[blockIndexOf(c)];
    const int* o = tables.edgeOffset[l];
    int point = 0;
    for (int a = 0; a < 3; ++a) point += int(c[a] % kBlock + o[a]) * kStride[a];
    return blockEdges[std::size_t(slot)].rank(3 * point + l / 4);
}

// Calls visit(index) for each crossing on the twelve edges of cell c (none outside the grid or in
// a skipped block). Crossings are placed before any vertex is.
template <class Visit> void Extraction::forEachCrossingOf(const std::int64_t c[3], Visit&& visit) const {
    float corner[8];
    if (!cellCorners(c, corner)) return;
    for (int l = 0; l < 12; ++l)
        if (crosses(corner[tables.edgeCorner[l][0]], corner[tables.edgeCorner[l][1]])) visit(crossingOf(c, l));
}

// 4b. Manifold across ambiguous faces. When the patches on both sides of an ambiguous face each
// join the face's two segments (a tunnel thinner than a cell), the edge between their two vertices
// would be shared by the four quads of the face's four crossing edges. Each segment gets a vertex
// of its own on the face instead (the middle of its two crossings, projected onto the surface with
// the others), which connectQuads puts between the two cells' vertices: every edge then has two
// triangles and every vertex one fan.
void Extraction::splitJoinedFaces() {
    cellVertexCount = mesh.vertices.size();
    for (const auto& cell : jointCells) {
        const std::int64_t lower[3] = {cell[0], cell[1], cell[2]};
        const CellRecord* near = recordAt(lower);
        for (int w = 0; w < 3; ++w) {
            const int face = 2 * w + 1;
            if (!(near->jointFaces >> face & 1)) continue;
            std::int64_t upper[3] = {lower[0], lower[1], lower[2]};
            ++upper[w];
            const CellRecord* far = recordAt(upper);
            if (far == nullptr || !(far->jointFaces >> (2 * w) & 1)) continue;
            const int paired = near->crossPaired >> face & 1;
            for (int segment = 0; segment < 2; ++segment) {
                glm::vec3 middle(0.0f);
                for (int end = 0; end < 2; ++end) {
                    const std::uint32_t e = crossingOf(lower, tables.faceEdges[face][kSegments[paired][segment][end]]);
                    middle += 0.5f * glm::vec3(crossings[3 * e], crossings[3 * e + 1], crossings[3 * e + 2]);
                }
                faceVertices.emplace(faceKey(lower, w, segment), std::uint32_t(mesh.vertices.size()));
                mesh.vertices.push_back(middle);
                vertexCell.push_back(cell);
            }
            ++stats.splitFaces;
        }
    }
}

// The point of the box nearest to p on the plane f + g.(x - p) = 0 (the field's linear
// approximation at p): the Newton step, and where it leaves the box, the nearest point of the plane
// on the faces it crossed, found by holding those coordinates at the face and stepping along the
// rest of the gradient. A plain clamp would leave a vertex whose surface point lies just outside its
// cell (the top of a dome that barely enters it) at the face, off the surface by up to the dome's
// height; this puts it where the surface crosses that face (alongFace: it did). Falls back to the
// clamp where the step leaves by two or more faces at once, where the point on the face would
// leave the cell by another one, or where the rest of the gradient vanishes (the plane parallel to
// the face).
glm::vec3 stepOntoPlaneInBox(const glm::vec3& p, float f, const glm::vec3& g, const glm::vec3& lo, const glm::vec3& hi,
                             bool& alongFace) {
    alongFace = false;
    const float g2 = glm::dot(g, g);
    const glm::vec3 newton = p - g * (f / g2);
    const glm::bvec3 held = glm::lessThan(newton, lo) || glm::greaterThan(newton, hi);
    const int heldCount = int(held.x) + int(held.y) + int(held.z);
    if (heldCount == 0) return newton;
    // Held axes sit on the face they crossed; the free ones take the least step that makes the
    // linear field zero.
    glm::vec3 d(0.0f), free(0.0f);
    float rest = -f;
    for (int a = 0; a < 3; ++a) {
        if (held[a]) {
            d[a] = std::clamp(newton[a], lo[a], hi[a]) - p[a];
            rest -= g[a] * d[a];
        } else {
            free[a] = g[a];
        }
    }
    const float free2 = glm::dot(free, free);
    if (heldCount == 1 && free2 > 1e-6f * g2) {
        const glm::vec3 onFace = p + d + free * (rest / free2);
        bool inside = true;
        for (int a = 0; a < 3; ++a) inside = inside && (held[a] || (onFace[a] > lo[a] && onFace[a] < hi[a]));
        alongFace = inside;
        if (inside) return onFace;
    }
    return glm::clamp(newton, lo, hi);
}

// On curved surfaces the planes' minimiser lies off the surface by about h^2 times the
// curvature: two Newton steps along the gradient put each vertex on it (a vertex already on a
// sharp edge or corner has f = 0 and stays). Steps are kept within the vertex's cell (or, for a vertex
// placed beside its cell on a sharp edge, within the same margin).
Expected<void> Extraction::projectVertices() {
    // Every vertex takes two steps; the few whose second step ran into a face of their cell (the
    // surface point lies just beyond it) take two more along that face, evaluated alone.
    std::vector<std::uint32_t> moving(mesh.vertices.size());
    for (std::size_t vertex = 0; vertex < moving.size(); ++vertex) moving[vertex] = std::uint32_t(vertex);
    std::vector<float> positions, fieldValues, gradients;
    std::vector<std::uint8_t> onFace(mesh.vertices.size(), 0);
    for (int iteration = 0; iteration < 4 && !moving.empty(); ++iteration) {
        positions.resize(3 * moving.size());
        for (std::size_t i = 0; i < moving.size(); ++i)
            for (int a = 0; a < 3; ++a) positions[3 * i + std::size_t(a)] = mesh.vertices[moving[i]][a];
        if (auto ok = field.evaluate(positions, fieldValues, &gradients, normalStep); !ok) return ok.error();
        stats.pointsEvaluated += fieldValues.size();
        forEachChunk(moving.size(), chunkCount(moving.size(), 8192), [&](std::size_t, std::size_t first, std::size_t end) {
            for (std::size_t i = first; i < end; ++i) {
                const std::uint32_t vertex = moving[i];
                const float f = fieldValues[i];
                const glm::vec3 g(gradients[3 * i], gradients[3 * i + 1], gradients[3 * i + 2]);
                const float g2 = glm::dot(g, g);
                if (!std::isfinite(f) || !(g2 > 1e-12f) || !std::isfinite(g2)) continue;
                const auto& c = vertexCell[vertex];
                const glm::vec3 cellLo = grid.point(c[0], c[1], c[2]), cellHi = grid.point(c[0] + 1, c[1] + 1, c[2] + 1);
                // A vertex placed beside its cell (on a sharp edge) keeps the margin it was given.
                const bool beside = glm::any(glm::lessThan(mesh.vertices[vertex], cellLo)) ||
                                    glm::any(glm::greaterThan(mesh.vertices[vertex], cellHi));
                const glm::vec3 margin{beside ? float(vertexMargin) : 0.0f};
                // The first step is clamped plainly: stepping along a face at once would draw the cells'
                // vertices around a needle thinner than a cell onto one point of its axis.
                bool alongFace = false;
                mesh.vertices[vertex] =
                    iteration == 0 ? glm::clamp(mesh.vertices[vertex] - g * (f / g2), cellLo - margin, cellHi + margin)
                                   : stepOntoPlaneInBox(mesh.vertices[vertex], f, g, cellLo - margin, cellHi + margin, alongFace);
                onFace[vertex] = alongFace ? 1 : 0;
            }
        });
        if (iteration == 0) continue;
        std::erase_if(moving, [&](std::uint32_t vertex) { return onFace[vertex] == 0; });
    }
    return {};
}

// 5. A quad per sign-changing edge (from the block that owns it), wound so that it faces
// outward (towards f > 0).
Expected<void> Extraction::connectQuads() {
    const std::uint32_t firstFaceVertexIndex = std::uint32_t(cellVertexCount);
    const int offsets[4][2] = {{-1, -1}, {0, -1}, {0, 0}, {-1, 0}}; // the cells around an edge, in (u, v)
    const std::size_t chunks = chunkCount(edges.size(), 4096);
    std::vector<std::vector<std::uint32_t>> triangles(chunks); // each chunk's, joined in edge order
    struct Folded {
        std::size_t at; // its first triangle's first index in its chunk's triangles
        std::array<std::uint32_t, 4> quad;
        int apex; // the diagonal (apex, apex + 2) the shorter-diagonal rule chose
    };
    std::vector<std::vector<Folded>> folded(chunks);
    constexpr double kFold = 0.01;
    const double cellSize = std::min({grid.step.x, grid.step.y, grid.step.z});
    forEachChunk(edges.size(), chunks, [&](std::size_t chunk, std::size_t first, std::size_t end) {
        std::vector<std::uint32_t>& out = triangles[chunk];
        out.reserve(6 * (end - first));
        for (std::size_t index = first; index < end; ++index) {
            const Edge& edge = edges[index];
            if (!edge.owned) continue;
            const int u = (edge.axis + 1) % 3, v = (edge.axis + 2) % 3;
            std::int64_t cells[4][3];
            const CellRecord* records[4];
            int locals[4];
            std::uint32_t quad[4];
            bool complete = true;
            for (int q = 0; q < 4 && complete; ++q) {
                std::int64_t* c = cells[q];
                c[0] = edge.i;
                c[1] = edge.j;
                c[2] = edge.k;
                c[u] += offsets[q][0];
                c[v] += offsets[q][1];
                // The edge seen from this cell: at its +u side when the cell lies at -u, and so on.
                locals[q] = edge.axis * 4 + (-offsets[q][0]) + 2 * (-offsets[q][1]);
                records[q] = recordAt(c);
                complete = records[q] != nullptr;
                if (complete) quad[q] = records[q]->firstVertex + (records[q]->vertexOfEdge >> (2 * locals[q]) & 3u);
            }
            if (!complete) continue;
            // The polygon: the four cells' vertices, with a face vertex between two cells whose patches
            // both join an ambiguous face's segments (splitJoinedFaces).
            std::uint32_t polygon[8];
            int size = 0;
            for (int q = 0; q < 4; ++q) {
                polygon[size++] = quad[q];
                const int r = (q + 1) % 4;
                const int w = offsets[q][0] != offsets[r][0] ? u : v;
                const int lower = offsets[q][0] + offsets[q][1] < offsets[r][0] + offsets[r][1] ? q : r;
                const int upper = lower == q ? r : q;
                if (!(records[lower]->jointFaces >> (2 * w + 1) & 1) || !(records[upper]->jointFaces >> (2 * w) & 1)) continue;
                const int face = 2 * w + 1, paired = records[lower]->crossPaired >> face & 1;
                int segment = 1;
                for (int end = 0; end < 2; ++end)
                    if (tables.faceEdges[face][kSegments[paired][0][end]] == locals[lower]) segment = 0;
                const auto found = faceVertices.find(faceKey(cells[lower], w, segment));
                if (found == faceVertices.end()) continue;
                polygon[size++] = found->second;
            }
            // (u, v) counter-clockwise looking down +axis; the surface faces +axis when the edge starts inside.
            if (!edge.startInside) std::reverse(polygon, polygon + size);
            // A fan from one of the polygon's vertices. Without face vertices: the quad's shorter
            // diagonal. With them: never the diagonal between the two neighbours of a face vertex (the
            // edge that would gain a third triangle); every other diagonal is this polygon's alone.
            // Among the fans allowed, one with no triangle of zero area (vertices on one crease line),
            // then the one whose smallest triangle is largest.
            auto area = [&](std::uint32_t a, std::uint32_t b, std::uint32_t c) {
                const glm::dvec3 pa(mesh.vertices[a]), pb(mesh.vertices[b]), pc(mesh.vertices[c]);
                return glm::length(glm::cross(pb - pa, pc - pa));
            };
            auto smallest = [&](int apex) {
                double least = std::numeric_limits<double>::infinity();
                for (int k = 1; k + 1 < size; ++k)
                    least = std::min(least, area(polygon[apex], polygon[(apex + k) % size], polygon[(apex + k + 1) % size]));
                return least;
            };
            auto isFaceVertex = [&](int k) { return polygon[k] >= firstFaceVertexIndex; };
            auto allowed = [&](int apex) {
                for (int k = 2; k + 1 < size; ++k) { // the diagonals (apex, apex + k)
                    const int other = (apex + k) % size;
                    for (int between = 0; between < size; ++between)
                        if (isFaceVertex(between) && ((apex == (between + size - 1) % size && other == (between + 1) % size) ||
                                                      (other == (between + size - 1) % size && apex == (between + 1) % size)))
                            return false;
                }
                return true;
            };
            int apex = 0;
            if (size == 4) {
                const float d02 = glm::length(mesh.vertices[polygon[0]] - mesh.vertices[polygon[2]]);
                const float d13 = glm::length(mesh.vertices[polygon[1]] - mesh.vertices[polygon[3]]);
                apex = d02 <= d13 ? 0 : 1;
                if (!(smallest(apex) > 0.0) && smallest(1 - apex) > 0.0) apex = 1 - apex;
                // A quad folded by more than kFold of a cell (across a crease) is decided by the field
                // at its diagonals' middles, after this pass.
                const glm::dvec3 p0(mesh.vertices[polygon[0]]), p1(mesh.vertices[polygon[1]]), p2(mesh.vertices[polygon[2]]),
                    p3(mesh.vertices[polygon[3]]);
                const glm::dvec3 normal = glm::cross(p2 - p0, p3 - p1);
                const double length = glm::length(normal);
                if (length > 0.0 && std::abs(glm::dot(0.5 * (p0 + p2 - p1 - p3), normal)) > kFold * cellSize * length &&
                    smallest(0) > 0.0 && smallest(1) > 0.0)
                    folded[chunk].push_back({out.size(), {polygon[0], polygon[1], polygon[2], polygon[3]}, apex});
            } else {
                double best = -1.0;
                for (int k = 0; k < size; ++k)
                    if (allowed(k))
                        if (const double least = smallest(k); least > best) {
                            best = least;
                            apex = k;
                        }
            }
            for (int k = 1; k + 1 < size; ++k)
                out.insert(out.end(), {polygon[apex], polygon[(apex + k) % size], polygon[(apex + k + 1) % size]});
        }
    });
    // Each folded quad takes the diagonal whose middle lies nearer the surface (|f| smaller by a
    // tenth at least): the one along a crease rather than the one across it, which cuts the crease
    // off (or fills a groove) by up to the fold.
    std::vector<float> middles, f;
    for (const auto& part : folded)
        for (const Folded& q : part)
            for (int d = 0; d < 2; ++d) {
                const glm::vec3 m = 0.5f * (mesh.vertices[q.quad[std::size_t(d)]] + mesh.vertices[q.quad[std::size_t(d + 2)]]);
                middles.insert(middles.end(), {m.x, m.y, m.z});
            }
    if (auto ok = field.evaluate(middles, f, nullptr); !ok) return ok.error();
    stats.pointsEvaluated += f.size();
    std::size_t at = 0;
    for (std::size_t chunk = 0; chunk < chunks; ++chunk)
        for (const Folded& q : folded[chunk]) {
            const float along02 = std::abs(f[at]), along13 = std::abs(f[at + 1]);
            at += 2;
            if (!std::isfinite(along02) || !std::isfinite(along13)) continue;
            const int apex = along02 <= along13 ? 0 : 1;
            if (apex == q.apex || (apex == 0 ? along02 : along13) > 0.9f * (apex == 0 ? along13 : along02)) continue;
            std::uint32_t* t = triangles[chunk].data() + q.at;
            const std::uint32_t a = q.quad[std::size_t(apex)], b = q.quad[std::size_t(apex + 1)],
                                c = q.quad[std::size_t(apex + 2)], d = q.quad[std::size_t((apex + 3) % 4)];
            t[0] = a, t[1] = b, t[2] = c, t[3] = a, t[4] = c, t[5] = d;
            ++stats.foldedQuadsTurned;
        }
    std::size_t total = mesh.indices.size();
    for (const auto& part : triangles) total += part.size();
    mesh.indices.reserve(total);
    for (const auto& part : triangles) mesh.indices.insert(mesh.indices.end(), part.begin(), part.end());
    return {};
}

} // namespace

Expected<std::pair<Mesh, MeshStats>> extractMesh(const shaders::PreparedSdf& sdf, const MeshOptions& options,
                                                 const ProgressSink& progress) {
    if (options.resolution < 2 || options.resolution > 2048) return makeError("--resolution: must be 2..2048");
    for (int a = 0; a < 3; ++a)
        if (!(options.boundsMax[a] > options.boundsMin[a])) return makeError("--bounds: every maximum must exceed its minimum");
    return Extraction(sdf, options, progress).run();
}

std::uint64_t flipCollinearTriangles(Mesh& mesh) {
    const std::size_t vertexCount = mesh.vertices.size();
    // The corner of triangle t strictly between the other two when the three lie on one line, else -1.
    auto middleCorner = [&](std::size_t t) {
        const std::uint32_t* v = &mesh.indices[3 * t];
        if (v[0] == v[1] || v[1] == v[2] || v[0] == v[2] || std::max({v[0], v[1], v[2]}) >= vertexCount) return -1;
        const glm::dvec3 p[3] = {glm::dvec3(mesh.vertices[v[0]]), glm::dvec3(mesh.vertices[v[1]]),
                                 glm::dvec3(mesh.vertices[v[2]])};
        const glm::dvec3 n = glm::cross(p[1] - p[0], p[2] - p[0]);
        if (n.x != 0.0 || n.y != 0.0 || n.z != 0.0) return -1;
        for (int k = 0; k < 3; ++k) {
            const glm::dvec3 a = p[(k + 1) % 3], b = p[(k + 2) % 3], c = p[k];
            const double length2 = glm::dot(b - a, b - a), s = length2 > 0.0 ? glm::dot(c - a, b - a) / length2 : -1.0;
            if (s > 0.0 && s < 1.0 && c != a && c != b) return k;
        }
        return -1;
    };
    auto key = [](std::uint64_t a, std::uint64_t b) { return (a << 32) | b; };
    std::uint64_t flips = 0;
    for (int round = 0; round < 4; ++round) {
        const std::size_t triangles = mesh.triangleCount();
        const std::size_t chunks = chunkCount(triangles, 65536);
        std::vector<std::vector<std::pair<std::uint32_t, int>>> found(chunks); // (triangle, middle corner)
        forEachChunk(triangles, chunks, [&](std::size_t chunk, std::size_t first, std::size_t end) {
            for (std::size_t t = first; t < end; ++t)
                if (const int k = middleCorner(t); k >= 0) found[chunk].emplace_back(std::uint32_t(t), k);
        });
        std::vector<std::pair<std::uint32_t, int>> flat;
        for (const auto& part : found) flat.insert(flat.end(), part.begin(), part.end());
        if (flat.empty()) break;
        // One pass over the mesh: the triangle across each long edge (which runs it backwards), and
        // every neighbour of each middle vertex (a flip must not make an edge that exists).
        std::unordered_map<std::uint64_t, std::uint32_t> across;
        std::unordered_map<std::uint32_t, std::vector<std::uint32_t>> neighbours;
        for (const auto& [t, k] : flat) {
            const std::uint32_t* v = &mesh.indices[3 * std::size_t(t)];
            across.emplace(key(v[(k + 2) % 3], v[(k + 1) % 3]), std::uint32_t(-1));
            neighbours.emplace(v[k], std::vector<std::uint32_t>{});
        }
        for (std::size_t t = 0; t < triangles; ++t) {
            const std::uint32_t* v = &mesh.indices[3 * t];
            for (int e = 0; e < 3; ++e) {
                if (auto it = across.find(key(v[e], v[(e + 1) % 3])); it != across.end()) it->second = std::uint32_t(t);
                if (auto it = neighbours.find(v[e]); it != neighbours.end())
                    it->second.insert(it->second.end(), {v[(e + 1) % 3], v[(e + 2) % 3]});
            }
        }
        std::vector<bool> touched(triangles, false);
        std::uint64_t made = 0;
        for (const auto& [t, k] : flat) {
            // A triangle an earlier flip of this pass rewrote waits for the next pass.
            if (touched[t]) continue;
            std::uint32_t* v = &mesh.indices[3 * std::size_t(t)];
            const std::uint32_t a = v[(k + 1) % 3], b = v[(k + 2) % 3], c = v[k];
            const std::uint32_t other = across.at(key(b, a));
            if (other == std::uint32_t(-1) || other == t || touched[other]) continue;
            std::uint32_t* w = &mesh.indices[3 * std::size_t(other)];
            int at = 0; // w = (b, a, d) once rotated
            while (at < 3 && !(w[at] == b && w[(at + 1) % 3] == a)) ++at;
            if (at == 3) continue;
            const std::uint32_t d = w[(at + 2) % 3];
            const std::vector<std::uint32_t>& around = neighbours.at(c);                        // (c is always in the map)
            if (d == c || std::find(around.begin(), around.end(), d) != around.end()) continue; // c-d exists
            // (a, b, c) and (b, a, d) become (c, a, d) and (c, d, b): t' split at c, t gone.
            v[0] = c, v[1] = a, v[2] = d;
            w[0] = c, w[1] = d, w[2] = b;
            touched[t] = touched[other] = true;
            for (const auto& [from, to] : {std::pair{c, d}, std::pair{d, c}}) // the new edge, for later checks
                if (auto it = neighbours.find(from); it != neighbours.end()) it->second.push_back(to);
            ++made;
        }
        flips += made;
        if (made == 0) break;
    }
    return flips;
}

std::uint64_t countDegenerateTriangles(const Mesh& mesh) {
    const std::size_t triangles = mesh.indices.size() / 3, vertexCount = mesh.vertices.size();
    const std::size_t chunks = chunkCount(triangles, 65536);
    std::vector<std::uint64_t> degenerate(chunks, 0);
    forEachChunk(triangles, chunks, [&](std::size_t chunk, std::size_t first, std::size_t end) {
        for (std::size_t f = first; f < end; ++f) {
            const std::uint32_t v[3] = {mesh.indices[3 * f], mesh.indices[3 * f + 1], mesh.indices[3 * f + 2]};
            if (v[0] == v[1] || v[1] == v[2] || v[0] == v[2]) {
                ++degenerate[chunk];
            } else if (std::max({v[0], v[1], v[2]}) < vertexCount) {
                const glm::dvec3 p(mesh.vertices[v[0]]), q(mesh.vertices[v[1]]), r(mesh.vertices[v[2]]);
                const glm::dvec3 n = glm::cross(q - p, r - p);
                if (n.x == 0.0 && n.y == 0.0 && n.z == 0.0) ++degenerate[chunk];
            }
        }
    });
    std::uint64_t total = 0;
    for (std::uint64_t d : degenerate) total += d;
    return total;
}

Topology subdividedTopology(Topology coarse, std::uint64_t triangles, int levels) {
    for (int level = 0; level < levels; ++level) {
        coarse.edges = 2 * coarse.edges + 3 * triangles;
        triangles *= 4;
        coarse.boundaryEdges *= 2;
        coarse.nonManifoldEdges *= 2;
        coarse.misorientedEdges *= 2;
    }
    coarse.degenerateTriangles = 0;
    return coarse;
}

Topology checkTopology(const Mesh& mesh) {
    Topology t;
    const std::size_t triangles = mesh.indices.size() / 3, vertexCount = mesh.vertices.size();
    t.degenerateTriangles = countDegenerateTriangles(mesh);
    // Edges: each triangle's three, filed under their lower vertex as (higher vertex, whether the
    // triangle runs it downwards); a vertex's short list, sorted, has a run per undirected edge.
    std::uint32_t top = 0;
    for (std::uint32_t v : mesh.indices) top = std::max(top, v);
    const std::size_t lists = mesh.indices.empty() ? 0 : std::size_t(top) + 1;
    std::vector<std::uint32_t> begin(lists + 1, 0);
    auto forEachEdge = [&](auto&& visit) {
        for (std::size_t c = 0; c < 3 * triangles; ++c) {
            const std::uint32_t a = mesh.indices[c], b = mesh.indices[c - c % 3 + (c + 1) % 3];
            visit(std::min(a, b), (std::uint64_t(std::max(a, b)) << 1) | std::uint64_t(a > b));
        }
    };
    forEachEdge([&](std::uint32_t low, std::uint64_t) { ++begin[std::size_t(low) + 1]; });
    for (std::size_t v = 0; v < lists; ++v) begin[v + 1] += begin[v];
    std::vector<std::uint64_t> filed(3 * triangles);
    {
        std::vector<std::uint32_t> at(begin.begin(), begin.end() - 1);
        forEachEdge([&](std::uint32_t low, std::uint64_t key) { filed[at[low]++] = key; });
    }
    // Vertex manifoldness: the triangles around a vertex, joined where they share an edge through
    // it, form one fan. Union-find over each vertex's corners; its neighbours are few, so a short
    // list finds the corner that saw a neighbour first.
    std::vector<std::uint32_t> start(vertexCount + 1, 0);
    for (std::uint32_t v : mesh.indices)
        if (v < vertexCount) ++start[v + 1];
    for (std::size_t v = 0; v < vertexCount; ++v) start[v + 1] += start[v];
    std::vector<std::uint32_t> corners(mesh.indices.size()), fill(start.begin(), start.end() - 1);
    for (std::size_t c = 0; c < mesh.indices.size(); ++c)
        if (mesh.indices[c] < vertexCount) corners[fill[mesh.indices[c]]++] = std::uint32_t(c);

    const std::size_t chunks = chunkCount(std::max(lists, vertexCount), 16384);
    std::vector<Topology> parts(chunks);
    forEachChunk(std::max(lists, vertexCount), chunks, [&](std::size_t chunk, std::size_t first, std::size_t end) {
        Topology& part = parts[chunk];
        for (std::size_t v = first; v < std::min(end, lists); ++v) {
            const auto from = filed.begin() + begin[v], to = filed.begin() + begin[v + 1];
            std::sort(from, to);
            for (auto i = from, j = from; i != to; i = j) {
                while (j != to && *j >> 1 == *i >> 1) ++j;
                ++part.edges;
                if (j - i == 1) ++part.boundaryEdges;
                if (j - i > 2) ++part.nonManifoldEdges;
                // Orientation: an edge of two triangles is run once each way (its reverse belongs to
                // the neighbour); counted where both run it the same way.
                if (j - i == 2 && *i == *(i + 1)) ++part.misorientedEdges;
            }
        }
        std::vector<std::uint32_t> parent;
        std::vector<std::pair<std::uint32_t, std::uint32_t>> seen; // (neighbour vertex, the corner that saw it)
        for (std::size_t v = first; v < std::min(end, vertexCount); ++v) {
            const std::uint32_t n = start[v + 1] - start[v];
            if (n < 2) continue;
            parent.resize(n);
            for (std::uint32_t i = 0; i < n; ++i) parent[i] = i;
            auto find = [&](std::uint32_t x) {
                while (parent[x] != x) x = parent[x] = parent[parent[x]];
                return x;
            };
            seen.clear();
            std::uint32_t groups = n;
            for (std::uint32_t i = 0; i < n; ++i) {
                const std::size_t c = corners[start[v] + i], f = c - c % 3;
                for (int k = 1; k <= 2; ++k) {
                    const std::uint32_t other = mesh.indices[f + (c - f + std::size_t(k)) % 3];
                    const auto it = std::find_if(seen.begin(), seen.end(), [&](const auto& s) { return s.first == other; });
                    if (it == seen.end()) {
                        seen.emplace_back(other, i);
                        continue;
                    }
                    const std::uint32_t x = find(i), y = find(it->second);
                    if (x != y) {
                        parent[x] = y;
                        --groups;
                    }
                }
            }
            if (groups > 1) ++part.nonManifoldVertices;
        }
    });
    for (const Topology& part : parts) {
        t.edges += part.edges;
        t.boundaryEdges += part.boundaryEdges;
        t.nonManifoldEdges += part.nonManifoldEdges;
        t.misorientedEdges += part.misorientedEdges;
        t.nonManifoldVertices += part.nonManifoldVertices;
    }
    return t;
}

} // namespace sdfwb::meshing
