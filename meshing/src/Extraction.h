#pragma once
// Dual contouring's extraction (DualContouring.cpp runs it; ExtractionBlocks.cpp chooses and
// evaluates the blocks, ExtractionVertices.cpp places and projects the vertices): the grid, the
// block layout, the cube's tables and the state one extraction hands from step to step.

#include <meshing/Mesh.h>

#include "PointEvaluator.h"
#include "Qef.h"

#include <glm/vec3.hpp>

#include <array>
#include <bit>
#include <bitset>
#include <cmath>
#include <cstdint>
#include <optional>
#include <unordered_map>
#include <utility>
#include <vector>

namespace sdfwb::meshing::detail {

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
inline const CubeTables& cube() {
    static const CubeTables tables;
    return tables;
}

inline bool inside(float f) { return f < 0.0f; }
inline bool crosses(float f0, float f1) { return std::isfinite(f0) && std::isfinite(f1) && inside(f0) != inside(f1); }

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

} // namespace sdfwb::meshing::detail
