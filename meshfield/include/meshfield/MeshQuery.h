#pragma once
// The native CPU engine for a mesh's own field: the same field as shaders/mesh/mesh_field.glsl
// (nearest triangle through the hierarchy, then the sign by the field's method), evaluated in
// double precision on every core, with the exact gradient from the closest point. sdfwb uses it
// instead of the GLSL field where the GL device runs on the CPU anyway (Mesa's llvmpipe), since
// there one nearest walk and one sign walk a row in C++ beat eight-lane divergent shader loops.
//
// Thread safety: a MeshQuery is immutable after construction except for its sign cache, which is
// filled lock-free and holds only values that are pure functions of the mesh, and the GLSL field's
// sign lattices, each built once under a lock; any number of threads may query one MeshQuery at
// once, and results never depend on the order or the threads.

#include <meshfield/MeshField.h>

#include <glm/vec3.hpp>

#include <array>
#include <atomic>
#include <cstdint>
#include <memory>
#include <mutex>
#include <vector>

namespace sdfwb::meshfield {

// Where a call's rows live: row i's position at positions[i * positionStride] (x y z), its value at
// distances[i * distanceStride] and, when gradients is not null, its gradient at
// gradients[i * gradientStride]. Strides are in floats (3, 1, 3 for separate arrays; 7 for the
// interleaved x y z distance gx gy gz rows).
struct RowView {
    const float* positions = nullptr;
    std::size_t positionStride = 3;
    float* distances = nullptr;
    std::size_t distanceStride = 1;
    float* gradients = nullptr;
    std::size_t gradientStride = 3;
};

// How a gradient is computed: exact from the closest point ((p - c) / |p - c| times the sign; the
// face's unit normal on the surface), or six-tap central differences of the float field with the
// given step (what the GLSL samplers write when a step is asked for).
struct GradientMode {
    bool exact = true;
    float step = 1e-3f;
};

// Counters of one evaluate() call (for benchmarks: they do not depend on the machine).
struct QueryCounters {
    std::uint64_t nearestNodes = 0; // nodes whose children's boxes a nearest walk tested
    std::uint64_t windingNodes = 0; // nodes the winding walks opened or took as dipoles
    std::uint64_t cachedSigns = 0;  // rows whose sign came from the sign cache
    std::uint64_t crossedSigns = 0; // rows whose sign came from a lattice point and the triangles between
    std::uint64_t segmentNodes = 0; // nodes those segments' walks tested
};

class MeshQuery {
public:
    static constexpr std::uint32_t kNoSeed = 0xffffffffu;
    // Builds the CPU layout (inner nodes holding both children's boxes) from `field`'s hierarchy.
    // `field` must outlive the query (meshQuery() keeps it alive).
    explicit MeshQuery(const MeshField& field);
    ~MeshQuery();
    MeshQuery(const MeshQuery&) = delete;
    MeshQuery& operator=(const MeshQuery&) = delete;

    const MeshField& field() const { return m_field; }

    // Squared distance to the nearest triangle, which triangle (leaf order), its feature (as in
    // closestPointOnTriangle) and the closest point. `visits` (optional) counts nodes tested.
    // `seed` (optional): a triangle slot whose distance bounds the walk from the start (a
    // neighbour's nearest); the answer is the same with or without it (among equally near
    // triangles the lowest slot wins).
    double nearest(const glm::dvec3& p, std::uint32_t& slot, int& feature, glm::dvec3& closest, std::uint64_t* visits = nullptr,
                   std::uint32_t seed = kNoSeed) const;
    // The hierarchical winding number (the field's beta), as MeshField::winding.
    double winding(const glm::dvec3& p, std::uint64_t* visits = nullptr) const;
    // Inside by the field's sign method; `distance` (the nearest distance) lets the winding sign
    // come from the sign cache where a bound on the winding number's change proves it (see the .cpp).
    bool inside(const glm::dvec3& p, double distance, std::uint32_t slot, int feature, const glm::dvec3& closest,
                QueryCounters* counters = nullptr) const;
    // The signed distance, and its gradient when `gradient` is not null.
    double signedDistance(const glm::dvec3& p, glm::dvec3* gradient, QueryCounters* counters = nullptr) const;

    // Fills rows [0, count): the float value (NaN where the position is not finite) and the
    // gradient by `mode`. Uses `threads` threads (0: every core, or SDFWB_MESH_THREADS).
    // Returns the rows with a NaN or infinity among the values written (positions included).
    std::uint64_t evaluate(const RowView& rows, std::size_t count, const GradientMode& mode, unsigned threads = 0,
                           QueryCounters* counters = nullptr) const;

    // The sign cache's level of 2^level + 1 points a side (level 2 .. 7) for the GLSL field
    // (shaders/mesh/mesh_field.glsl reads it after the hierarchy): a header of eight floats (the
    // lattice's first point x y z, its step, its points a side, the open boundary's length, 1 when
    // boundary slopes follow, 1 when seeds follow), then every point's winding number (x fastest),
    // then, on an open mesh, every point's boundary slope over the ball of half a cell's diagonal
    // (boundarySlope, rounded up; +inf where the ball reaches the boundary): the crossing sign's
    // bound; then every point's nearest triangle slot (as float bits): a row's nearest walk starts
    // bounded by its nearest lattice point's triangle. Filled on `threads` threads (0: every core);
    // only the header, with 0 points a side, when the sign is not winding numbers. Built once a
    // level and kept (a GPU program binds it at every build: each sdfwb.evaluate call).
    std::vector<float> signLattice(int level, unsigned threads = 0) const;

    // Bytes the CPU layout and the sign cache take.
    std::size_t bytes() const;

private:
    struct Node;
    float floatField(const glm::vec3& p) const;
    // signedDistance walking from `seed` (kNoSeed: none); leaves the nearest triangle's slot there.
    double seededDistance(const glm::dvec3& p, glm::dvec3* gradient, QueryCounters* counters, std::uint32_t& seed) const;
    bool parityInside(const glm::dvec3& p) const;
    bool cachedWindingInside(const glm::dvec3& p, double distance, bool& fromCache, QueryCounters* counters) const;
    // The sign cache's level `level` point nearest p (clamped to the lattice) in `q`; its index in
    // the level. And the winding number at cache slot `slot` (point q), computed on first use.
    std::size_t nearestLatticePoint(const glm::dvec3& p, int level, glm::dvec3& q) const;
    std::vector<float> buildSignLattice(int level, unsigned threads) const;
    float latticeWinding(std::size_t slot, const glm::dvec3& q, std::uint64_t* visits) const;
    // The winding sign from the nearest lattice point of the crossing level and the triangles the
    // segment between them crosses; false when that cannot decide (see the .cpp).
    bool crossedWindingInside(const glm::dvec3& p, bool& inside, QueryCounters* counters) const;
    // The oriented crossings of segment q -> p (w(p) - w(q) on the surface's account); false when
    // a crossing lies too near an edge, a corner or an end to be counted with certainty.
    bool segmentCrossings(const glm::dvec3& q, const glm::dvec3& p, int& net, std::uint64_t* visits) const;
    // Bounds |grad w| over the ball of radius `reach` (a crossing level's half cell diagonal) around
    // lattice point q (the open boundary's Biot-Savart field); infinity where the boundary comes
    // that close.
    double boundarySlope(const glm::dvec3& q, double reach) const;

    const MeshField& m_field;
    std::vector<Node> m_nodes;     // inner nodes; m_nodes[0] is the root (a leaf root has a one-child node)
    std::vector<double> m_corners; // 9 doubles per triangle slot, leaf order
    double m_scale = 0.0;          // the largest coordinate of the bounds (float rounding's scale)
    // The sign cache (winding sign): lattices over the bounds, each point's winding number once
    // computed (NaN: not yet).
    bool m_useCache = false;
    double m_boundaryLength = 0.0; // of the mesh as an oriented chain (0: closed and oriented)
    glm::dvec3 m_cacheLo{0.0};
    double m_cacheStep = 0.0;
    int m_cacheSide = 0;
    mutable std::unique_ptr<std::atomic<float>[]> m_cache;
    // Each crossing level's points' boundary slopes (NaN: not yet; open meshes only); the open
    // boundary as edges (a, b, |net use|).
    struct BoundaryEdge {
        glm::dvec3 a, b;
        double weight;
    };
    std::vector<BoundaryEdge> m_boundary;
    mutable std::unique_ptr<std::atomic<float>[]> m_slopes[2];
    // signLattice's arrays, each level's once built (levels 2 .. 7).
    mutable std::mutex m_latticeMutex;
    mutable std::array<std::vector<float>, 8> m_lattices;
};

// Rows [0, count) of `xyz` (row i's x y z at xyz[i * stride]) in Morton order, 10 bits an axis
// over the cube of side `side` from `lo` (clamped to it; NaN as its low end): each entry is the
// row's code << 32 | i, sorted, stable. Neighbours in the order are neighbours in space.
std::vector<std::uint64_t> mortonOrder(const float* xyz, std::size_t stride, std::size_t count, const glm::dvec3& lo,
                                       double side);
// The cube the engine orders rows and caches signs over: 1.5 times the bounds' largest side, about
// their centre. Returns its low corner and sets `side`.
glm::dvec3 mortonBoxCorner(const MeshField& field, double& side);

// The query for `field`, built once per field (a process-wide cache holding it as long as the
// field lives).
std::shared_ptr<const MeshQuery> meshQuery(const std::shared_ptr<const MeshField>& field);

// Which engine evaluates a mesh's own field: SDFWB_MESH_ENGINE=cpu|gpu|auto (auto, the default:
// the CPU engine when the GL renderer's name says it runs on the CPU, "llvmpipe" or "softpipe").
enum class MeshEngine { Cpu, Gpu };
MeshEngine chooseMeshEngine(const std::string& glRenderer);
const char* meshEngineName(MeshEngine engine); // "cpu", "gpu"

} // namespace sdfwb::meshfield
