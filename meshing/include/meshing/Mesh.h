#pragma once
// Meshes of an SDF's zero set: extraction by dual contouring on the GPU-evaluated field (sharp
// edges and corners kept through a QEF per cell), topology checks, the error of any mesh against
// the exact field (both ways, with the time it took), and mesh files through assimp.
// Extraction and error need a current GL 4.3 context on the calling thread.

#include <core/Expected.h>
#include <core/Progress.h>
#include <meshfield/MeshField.h>
#include <shaders/Parameters.h>
#include <shaders/SdfSource.h>

#include <glm/vec3.hpp>

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace sdfwb::meshing {

// The one triangle mesh type (meshfield::TriangleMesh): a mesh read from a file and a mesh made
// here are the same value.
using Mesh = meshfield::TriangleMesh;

struct MeshOptions {
    int resolution = 128; // cells along each axis of the bounds
    glm::vec3 boundsMin{-1.0f};
    glm::vec3 boundsMax{1.0f};
    float time = 0.0f;
    std::vector<shaders::ParameterSetting> parameters;
    // A bound on |grad f|: a block of cells whose centre has |f| > lipschitz * (half its diagonal)
    // holds no surface and is skipped. 0 evaluates every cell.
    float lipschitz = 1.0f;
    // Ignore `lipschitz` and estimate the bound from the block centres themselves: 1.25 x the
    // steepest |grad f| there or quotient between neighbouring centres, at least 1. Either way a
    // skipped block is evaluated after all when the surface crosses its face with a kept block.
    bool estimateLipschitz = false;
    // After extraction, cut every triangle into four this many times, each new vertex (an edge's
    // midpoint) stepped onto the surface by the exact field: on a smooth surface each level quarters
    // the error for four times the triangles, about what doubling the resolution gives, at a
    // fraction of its cost. Creases stay where the grid put them; features smaller than the coarse
    // grid's cells stay missed. 0: none.
    int refine = 0;
    // The most triangles refinement may make (4^refine times the coarse mesh's): beyond it the
    // extraction fails with a message rather than run out of memory or of 32-bit indices.
    std::uint64_t refineTriangleLimit = std::uint64_t(1) << 27;
};

struct Topology {
    std::uint64_t edges = 0;
    std::uint64_t boundaryEdges = 0;       // used by one triangle: a hole
    std::uint64_t nonManifoldEdges = 0;    // used by three or more triangles
    std::uint64_t degenerateTriangles = 0; // a vertex repeated, or zero area (three points on one line)
    // Vertices whose triangles do not form one fan (two sheets meeting at a point: a pinch), and
    // edges that two triangles run the same way (neighbours facing opposite ways).
    std::uint64_t nonManifoldVertices = 0;
    std::uint64_t misorientedEdges = 0;
    bool watertight() const { return boundaryEdges == 0 && nonManifoldEdges == 0; }
    // Watertight, every vertex a single fan, every edge run once each way.
    bool manifold() const { return watertight() && nonManifoldVertices == 0 && misorientedEdges == 0; }
};

struct MeshStats {
    std::uint64_t blocks = 0, blocksKept = 0;  // blocks of 8^3 cells, and those that may hold surface
    std::uint64_t blocksGrown = 0;             // of those, skipped by the bound but crossed at a face with a kept block
    float lipschitzUsed = 0.0f;                // the bound the blocks were skipped by (given or estimated)
    std::uint64_t pointsEvaluated = 0;         // field evaluations on the GPU (grid, crossings, centres)
    std::uint64_t activeCells = 0;             // cells the surface crosses (one vertex each)
    std::uint64_t clampedVertices = 0;         // QEF minimisers outside their cell, clamped into it
    std::uint64_t verticesBesideTheirCell = 0; // on a sharp edge that passes beside the cell, at most half a cell out
    std::uint64_t creasesOnFaces = 0;          // flat patches moved onto a crease lying on their upper face
    std::uint64_t collinearFlips = 0;          // zero-area triangles removed by an edge flip (flipCollinearTriangles)
    std::uint64_t foldedQuadsTurned = 0;       // folded quads given the diagonal whose middle lies nearer the surface
    std::uint64_t splitFaces = 0;              // ambiguous faces both of whose cells join its two segments: a vertex per segment
    std::uint64_t midpointsKept = 0;           // refinement midpoints left off the surface (no step a quarter edge or shorter)
    // With refine > 0: the refined mesh's topology, from the coarse mesh's check (subdividedTopology)
    // and a count of the fine mesh's degenerate triangles. Absent without refinement: checkTopology.
    std::optional<Topology> topology;
    // Grid points inside the shape but outside the bounds (half a cell beyond them): the shape
    // leaves the bounds and the mesh is closed by flat caps there. 0: the shape lies inside.
    std::uint64_t boundsCutPoints = 0;
    double seconds = 0.0;
    std::vector<std::pair<std::string, double>> phaseSeconds; // each step's wall time, in order
};

// The box extractMesh() cuts the field by: the bounds grown by half a cell on every side.
std::pair<glm::vec3, glm::vec3> cutBox(const MeshOptions& options);

Expected<std::pair<Mesh, MeshStats>> extractMesh(const shaders::PreparedSdf& sdf, const MeshOptions& options,
                                                 const ProgressSink& progress);

// Counts by shared vertex index (the writers keep indices; readers should merge equal positions).
Topology checkTopology(const Mesh& mesh);
// Triangles with a vertex repeated or zero area (three points on one line): checkTopology's
// degenerateTriangles alone.
std::uint64_t countDegenerateTriangles(const Mesh& mesh);
// The topology of a mesh of `triangles` triangles with topology `coarse` after each triangle is cut
// into four at its edges' midpoints `levels` times (MeshOptions::refine), without looking at it:
// the cut doubles every edge and adds three inside each triangle; a new vertex lies on one coarse
// edge, so it joins no fans that were apart, and a boundary, non-manifold or misoriented edge
// becomes two of the same. Degenerate triangles are geometry, not topology: 0 here, count them on
// the fine mesh (countDegenerateTriangles).
Topology subdividedTopology(Topology coarse, std::uint64_t triangles, int levels);

// Triangles of zero area whose three vertices lie on one line, the middle one strictly between the
// others (a crease's vertices in a row; seen on a GPU driver, not on llvmpipe): each is removed by
// flipping its long edge with the triangle across it, which splits that triangle at the middle
// vertex. Topology and orientation are kept; a flip that would duplicate an edge is not made.
// Returns the flips made. Triangles with two vertices at one position are left to the welding.
std::uint64_t flipCollinearTriangles(Mesh& mesh);

// Pairs of triangles that share no vertex and cross (an edge of one passes through the other):
// where a mesh passes through itself. Triangles that only touch a neighbour at a shared vertex or
// edge do not count. A uniform grid of the triangles' boxes: about two seconds per million triangles on 2 cores.
std::uint64_t countSelfIntersections(const Mesh& mesh);

// The mesh against the exact field, both ways:
//   mesh -> surface: |f| at every vertex and at points spread on the faces by area (for an exact
//                    field |f| is the distance to the surface; for a conservative one a lower bound);
//   surface -> mesh: points on the zero set (the surface sampler) to the nearest triangle (a k-d
//                    tree over triangle centres, then exact point-triangle distances).
struct ErrorOptions {
    std::uint64_t meshPoints = 100000;
    std::uint64_t surfacePoints = 100000;
    std::uint64_t seed = 0;
    float time = 0.0f;
    std::vector<shaders::ParameterSetting> parameters;
    // False for a field the audit did not find exact: |f| then underestimates the distance, and
    // mesh -> surface uses |f| / |grad f| (one Newton step to the zero set) instead.
    bool fieldIsExact = true;
    // The box the mesher cut the field by (cutBox()), when the shape leaves the bounds: the error is
    // then against the cut field, whose surface includes the flat caps, and only surface points
    // inside the box count.
    std::optional<std::pair<glm::vec3, glm::vec3>> cut;
};

struct MeshError {
    float meshToSurfaceMean = 0.0f, meshToSurfaceMax = 0.0f;
    std::string meshToSurfaceMethod; // |f|, or |f| / |grad f| for a field that is not exact
    float surfaceToMeshMean = 0.0f, surfaceToMeshMax = 0.0f;
    float hausdorff = 0.0f; // the larger of the two maxima
    std::uint64_t meshPoints = 0, surfacePoints = 0;
    double seconds = 0.0;
};

Expected<MeshError> measureError(const shaders::PreparedSdf& sdf, const Mesh& mesh, const ErrorOptions& options);

// Any mesh graded against the exact field (a reconstruction, another tool's mesh). Conventions:
//   accuracy      points spread on the mesh by area -> |f| there (the distance to the surface for
//                 an exact field; a lower bound for a conservative one);
//   completeness  points on the exact surface (the surface sampler) -> the nearest triangle;
//   chamfer_l1    (mean accuracy + mean completeness) / 2, distances not squared;
//   chamfer_l2    (mean accuracy^2 + mean completeness^2) / 2, squared distances;
//   normal consistency: the mean |cos| between the mesh's face normal and the field's gradient,
//                 averaged over both point sets;
//   F-score at tau: 2PR / (P + R), P = share of mesh points within tau, R = share of surface points;
//   Hausdorff: the larger of the two maxima; IoU: occupancy of the field (f < 0) against the mesh's
//   (parity of ray crossings, meaningful for closed meshes) at the centres of an n^3 grid;
//   edges:        the same accuracy, completeness, Chamfer-L1, F-score and Hausdorff over the points
//                 of both sets that lie near a crease of the exact field: where its normal turns by
//                 more than edgeAngleDegrees between the point and one of 8 points edgeRadius away
//                 around it in its tangent plane. A mesher that rounds or cuts sharp edges scores
//                 worse here than over the whole surface, where the creases' share is small.
// No normalisation: distances are in the SDF's units (the default bounds are [-1,1]^3).
struct EvalOptions {
    std::uint64_t points = 100000; // each way
    float tau = 0.01f;
    int occupancyResolution = 128; // 0: no IoU
    float edgeRadius = 0.02f;      // 0: no edge measure
    float edgeAngleDegrees = 30.0f;
    glm::vec3 boundsMin{-1.0f};
    glm::vec3 boundsMax{1.0f};
    std::uint64_t seed = 0;
    float time = 0.0f;
    std::vector<shaders::ParameterSetting> parameters;
};

// The measures over the points near creases (see EvalOptions).
struct EdgeEvaluation {
    float accuracyMean = 0.0f, completenessMean = 0.0f, chamferL1 = 0.0f;
    float precision = 0.0f, recall = 0.0f, fscore = 0.0f, hausdorff = 0.0f;
    std::uint64_t meshPoints = 0, surfacePoints = 0; // of each set, those near a crease
};

struct MeshEvaluation {
    float accuracyMean = 0.0f, accuracyMax = 0.0f;
    float completenessMean = 0.0f, completenessMax = 0.0f;
    float chamferL1 = 0.0f, chamferL2 = 0.0f;
    float normalConsistency = 0.0f;
    float tau = 0.0f, precision = 0.0f, recall = 0.0f, fscore = 0.0f;
    float hausdorff = 0.0f;
    std::optional<float> iou;
    std::optional<EdgeEvaluation> edges; // none when no surface point lies near a crease
    bool closed = false;                 // no boundary edges (the IoU's parity test assumes it)
    std::uint64_t meshPoints = 0, surfacePoints = 0, occupancyPoints = 0;
    double seconds = 0.0;
};

Expected<MeshEvaluation> evaluateMesh(const shaders::PreparedSdf& sdf, const Mesh& mesh, const EvalOptions& options);

// .ply (binary), .obj, .stl (binary) or .glb, by the extension; written to a temporary file
// beside the target and renamed into place.
bool canWriteMesh(const std::filesystem::path& path);
// `comments` (one line each) go into a PLY's header and an OBJ's first lines; STL and glTF
// files have no place for them.
Expected<void> writeMesh(const std::filesystem::path& path, const Mesh& mesh, const std::vector<std::string>& comments = {});
// Any format assimp reads; equal positions are merged so shared edges share indices.
Expected<Mesh> readMesh(const std::filesystem::path& path);

} // namespace sdfwb::meshing
