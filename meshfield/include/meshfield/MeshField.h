#pragma once
// A triangle mesh as a signed distance field: the mesh read through assimp, optionally normalised,
// a bounding volume hierarchy over its triangles, and the sign from one of three methods. The same
// hierarchy is uploaded to the GPU (shaders/mesh/mesh_field.glsl traverses it), so every sampler,
// the tracer, the plane, the audit and the mesher run on the mesh as on any SDF. The CPU queries
// here run in double precision: they are the reference the GPU field is tested against.
//
// Conventions: the distance is to the nearest point of any triangle; negative inside. "Inside" is
//   winding       the generalized winding number (Jacobson et al. 2013) is above 1/2, evaluated
//                 hierarchically (Barill et al. 2018: far clusters as dipoles); open seams, holes,
//                 flipped faces and overlapping parts keep the sign a person expects
//   parity        an odd number of crossings along a ray, the majority of three rays (the classic
//                 test: right on closed meshes, wrong behind holes)
//   pseudonormal  the angle-weighted pseudonormal of the nearest feature (Baerentzen and Aanaes
//                 2005) points away from the query (exact on closed, consistently oriented meshes)

#include <core/Expected.h>

#include <glm/vec3.hpp>

#include <array>
#include <cstdint>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

namespace sdfwb::meshfield {

enum class SignMethod { Winding, Parity, Pseudonormal };
enum class Normalization { None, UnitCube, UnitSphere };

const char* signName(SignMethod method);             // "winding", "parity", "pseudonormal"
const char* normalizationName(Normalization method); // "none", "unit-cube", "unit-sphere"
Expected<SignMethod> parseSign(const std::string& text);
Expected<Normalization> parseNormalization(const std::string& text);

// sdfwb's one triangle mesh: what files give, what a mesh SDF is built from, and what meshing
// makes (meshing::Mesh is this type).
struct TriangleMesh {
    std::vector<glm::vec3> vertices;
    std::vector<std::uint32_t> indices; // three per triangle (meshing's: counter-clockwise seen from outside, f > 0)
    std::size_t triangleCount() const { return indices.size() / 3; }
};

// The file extensions read as meshes (lower case, with the dot): .obj .ply .stl .off .glb .gltf
// .fbx .dae .3ds.
bool isMeshPath(const std::filesystem::path& path);

// Any format assimp reads, triangulated; equal positions are merged so shared edges share indices.
// Errors name the file.
Expected<TriangleMesh> readTriangleMesh(const std::filesystem::path& path);

struct Box {
    glm::dvec3 lo{0.0};
    glm::dvec3 hi{0.0};
    // Inside [-1, 1]^3, the box sdfwb samples and traces by default.
    bool insideUnitBox() const {
        return lo.x >= -1.0 && lo.y >= -1.0 && lo.z >= -1.0 && hi.x <= 1.0 && hi.y <= 1.0 && hi.z <= 1.0;
    }
};

struct MeshFieldOptions {
    SignMethod sign = SignMethod::Winding;
    Normalization normalize = Normalization::None;
    // Winding numbers: a cluster farther than beta times its radius counts as one dipole.
    double beta = 2.0;
};

// Options from their names ("winding", "unit-cube"; empty: the default). The error says which:
// "sign: expected ..." or "normalize: expected ...".
Expected<MeshFieldOptions> parseMeshFieldOptions(const std::string& sign, const std::string& normalize);

// Triangles a leaf holds at most.
inline constexpr std::uint32_t kMaxLeafTriangles = 4;

// One BVH node as the GPU reads it: 28 floats (seven vec4).
//   [0..2] box min, [3] first triangle (leaf) or left child (inner; right = left + 1), as bits
//   [4..6] box max, [7] triangle count (0: inner node), as bits
//   [8..10] area-weighted centroid c of its triangles, [11] radius of a ball around c holding them
//   [12..14] sum of area times unit normal of its triangles (the dipole), [15] unused
//   [16..26] the second moment M = sum of area * n (x - c)^T over its triangles (x: a triangle's
//   centroid; exact, since n is constant on a triangle), row i at [16 + 4i .. 18 + 4i]; [19], [23],
//   [27] unused. Far clusters add the dipole's term and M's (Barill et al. 2018, second order).
inline constexpr int kNodeFloats = 28;
// The same hierarchy with four children a node (a binary node's children, or where a child is a
// leaf, that leaf), for walks that test a node's children's boxes at once (the CPU engine, and the
// GPU's nearest walk): 32 floats (eight vec4) a node, node 0 the root.
//   [0..3] the four children's box min x, [4..7] min y, [8..11] min z, [12..23] box max x, y, z
//   [24..27] each child as bits: an inner node's index (count 0) or a leaf's first triangle slot
//   [28..31] each child's triangle count as bits (0: an inner node)
// An empty slot has the box +inf..-inf, child 0 and count 0.
inline constexpr int kWideNodeFloats = 32;
// One triangle: three vec4 (corners, w unused), in leaf order.
inline constexpr int kTriangleFloats = 12;
// Pseudonormals of one triangle (only for SignMethod::Pseudonormal): face, edges ab bc ca,
// vertices a b c, each a vec4 (w unused).
inline constexpr int kPseudonormalFloats = 28;

struct MeshField {
    std::string name;  // the file's name, for messages
    TriangleMesh mesh; // in field coordinates (after the normalisation)
    MeshFieldOptions options;
    Box originalBounds;                 // of the file's vertices
    Box bounds;                         // in field coordinates
    std::array<double, 16> transform{}; // file -> field coordinates, column-major 4x4
    std::size_t boundaryEdges = 0;      // edges used by one triangle (0: closed)
    std::size_t nonManifoldEdges = 0;   // edges used by more than two
    double readSeconds = 0.0;
    double buildSeconds = 0.0;
    std::size_t depth = 0;     // of the hierarchy
    std::size_t wideDepth = 0; // inner nodes on the longest path from the root of the four-wide one

    // What the GPU reads (see kNodeFloats ...).
    std::vector<float> nodes;
    std::vector<float> wideNodes;
    std::vector<float> triangles;
    std::vector<float> pseudonormals;
    bool closed() const { return boundaryEdges == 0 && nonManifoldEdges == 0; }
    std::size_t gpuBytes() const {
        return (nodes.size() + wideNodes.size() + triangles.size() + pseudonormals.size()) * sizeof(float);
    }

    // Unsigned distance to the mesh (BVH, double precision).
    double distance(const glm::dvec3& p) const;
    // The generalized winding number, hierarchical (beta from the options) or exact (every triangle).
    double winding(const glm::dvec3& p) const;
    double windingExact(const glm::dvec3& p) const;
    // Inside by the options' sign method.
    bool inside(const glm::dvec3& p) const;
    double signedDistance(const glm::dvec3& p) const { return inside(p) ? -distance(p) : distance(p); }

    // The SDF text a mesh file stands for: a comment naming the mesh, and `float sdf(vec3 p)`
    // returning the field (shaders/mesh/mesh_field.glsl provides it).
    std::string glslSource() const;
    // Where the field came from, for every output's metadata: a JSON object with file, triangles,
    // closed, sign, normalize, transform (16 numbers, column-major) and bounds (the file's min xyz,
    // max xyz).
    std::string provenanceJson() const;
    // One line: triangles, closed or not, bounds, sign, normalisation, build time and memory.
    std::string summary() const;
};

// Reads, normalises and builds (the transform maps the file's coordinates into the field's).
Expected<std::shared_ptr<const MeshField>> makeMeshField(TriangleMesh mesh, const std::string& name,
                                                         const MeshFieldOptions& options);
// The same from a file; a process-wide cache returns the same field for the same file (path,
// size and modification time) and options.
Expected<std::shared_ptr<const MeshField>> loadMeshField(const std::filesystem::path& path, const MeshFieldOptions& options);

// Closest point of triangle abc to p (double precision), and the feature it lies on:
// 0 the face, 1..3 the vertices a b c, 4..6 the edges ab bc ca.
glm::dvec3 closestPointOnTriangle(const glm::dvec3& p, const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c,
                                  int* feature = nullptr);
// Signed solid angle of triangle abc seen from p (positive when p is behind its counter-clockwise face).
double solidAngle(const glm::dvec3& p, const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c);

} // namespace sdfwb::meshfield
