#pragma once
// Meshes of an SDF's zero set: extraction by dual contouring on the GPU-evaluated field (sharp
// edges and corners kept through a QEF per cell), topology checks, the error of any mesh against
// the exact field (both ways, with the time it took), and mesh files through assimp.
// Extraction and error need a current GL 4.3 context on the calling thread.

#include <core/Expected.h>
#include <core/Progress.h>
#include <shaders/Parameters.h>
#include <shaders/SdfSource.h>

#include <glm/vec3.hpp>

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace sdfwb::meshing {

struct Mesh {
    std::vector<glm::vec3> vertices;
    std::vector<std::uint32_t> indices; // three per triangle, counter-clockwise seen from outside (f > 0)
    std::size_t triangleCount() const { return indices.size() / 3; }
};

struct MeshOptions {
    int resolution = 128; // cells along each axis of the bounds
    glm::vec3 boundsMin{-1.0f};
    glm::vec3 boundsMax{1.0f};
    float time = 0.0f;
    std::vector<shaders::ParameterSetting> parameters;
    // A bound on |grad f|: a block of cells whose centre has |f| > lipschitz * (half its diagonal)
    // holds no surface and is skipped. 0 evaluates every cell.
    float lipschitz = 1.0f;
};

struct MeshStats {
    std::uint64_t blocks = 0, blocksKept = 0; // blocks of 8^3 cells, and those that may hold surface
    std::uint64_t pointsEvaluated = 0;        // field evaluations on the GPU (grid, crossings, centres)
    std::uint64_t activeCells = 0;            // cells the surface crosses (one vertex each)
    std::uint64_t clampedVertices = 0;        // QEF minimisers outside their cell, clamped into it
    double seconds = 0.0;
};

Expected<std::pair<Mesh, MeshStats>> extractMesh(const shaders::PreparedSdf& sdf, const MeshOptions& options,
                                                 const ProgressSink& progress);

struct Topology {
    std::uint64_t edges = 0;
    std::uint64_t boundaryEdges = 0;    // used by one triangle: a hole (or the bounds cut the shape)
    std::uint64_t nonManifoldEdges = 0; // used by three or more triangles
    std::uint64_t degenerateTriangles = 0;
    bool watertight() const { return boundaryEdges == 0 && nonManifoldEdges == 0; }
};

// Counts by shared vertex index (the writers keep indices; readers should merge equal positions).
Topology checkTopology(const Mesh& mesh);

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
};

struct MeshError {
    float meshToSurfaceMean = 0.0f, meshToSurfaceMax = 0.0f;
    float surfaceToMeshMean = 0.0f, surfaceToMeshMax = 0.0f;
    float hausdorff = 0.0f; // the larger of the two maxima
    std::uint64_t meshPoints = 0, surfacePoints = 0;
    double seconds = 0.0;
};

Expected<MeshError> measureError(const shaders::PreparedSdf& sdf, const Mesh& mesh, const ErrorOptions& options);

// .ply (binary), .obj, .stl (binary) or .glb, by the extension; written to a temporary file
// beside the target and renamed into place. `comment` goes where the format has room (PLY).
bool canWriteMesh(const std::filesystem::path& path);
Expected<void> writeMesh(const std::filesystem::path& path, const Mesh& mesh);
// Any format assimp reads; equal positions are merged so shared edges share indices.
Expected<Mesh> readMesh(const std::filesystem::path& path);

} // namespace sdfwb::meshing
