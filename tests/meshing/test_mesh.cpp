// Dual contouring against the exact field: sharp corners and straight edges on a box (what
// marching cubes cannot keep), the error's order of convergence on a sphere, closed dataset shapes
// come out watertight, skipping empty blocks loses nothing, and files read back the same.
#include <meshing/Mesh.h>

#include "GlTestContext.h"
#include "common/SourceSdfs.h"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include <cmath>
#include <filesystem>
#include <unistd.h>

using namespace sdfwb;

namespace {

class MeshTest : public sdfwb::testing::GlTest {
protected:
    static shaders::PreparedSdf source(const std::string& text) {
        shaders::IncludeOptions options;
        auto sdf = shaders::prepareSdf(text, "<test>", {}, options);
        EXPECT_TRUE(sdf.ok());
        return sdf;
    }
    static meshing::Mesh extract(const shaders::PreparedSdf& sdf, int resolution, float lipschitz = 1.0f) {
        meshing::MeshOptions options;
        options.resolution = resolution;
        options.lipschitz = lipschitz;
        auto mesh = meshing::extractMesh(sdf, options, {});
        EXPECT_TRUE(mesh) << (mesh ? "" : mesh.error().message);
        return mesh ? mesh->first : meshing::Mesh{};
    }
};

const char* kBox =
    "float sdf(vec3 p) { vec3 q = abs(p) - vec3(0.5); return length(max(q, 0.0)) + min(max(q.x, max(q.y, q.z)), 0.0); }";
const char* kSphere = "float sdf(vec3 p) { return length(p) - 0.6; }";

// Distance from p to the segment ab.
float segmentDistance(glm::vec3 p, glm::vec3 a, glm::vec3 b) {
    const float t = std::clamp(glm::dot(p - a, b - a) / glm::dot(b - a, b - a), 0.0f, 1.0f);
    return glm::length(p - (a + t * (b - a)));
}

} // namespace

TEST_F(MeshTest, ABoxKeepsItsCornersAndStraightEdges) {
    const meshing::Mesh mesh = extract(source(kBox), 64);
    ASSERT_GT(mesh.triangleCount(), 1000u);
    for (int corner = 0; corner < 8; ++corner) {
        const glm::vec3 c((corner & 1) ? 0.5f : -0.5f, (corner & 2) ? 0.5f : -0.5f, (corner & 4) ? 0.5f : -0.5f);
        float nearest = 1e9f;
        for (const glm::vec3& v : mesh.vertices) nearest = std::min(nearest, glm::length(v - c));
        EXPECT_LT(nearest, 1e-3f) << "corner " << c.x << "," << c.y << "," << c.z;
    }
    // Every vertex of a cell an edge passes through lies on that edge: marching cubes would cut it
    // at about half a cell (0.016 here).
    int edgeVertices = 0;
    for (const glm::vec3& v : mesh.vertices) {
        const glm::vec3 a = glm::abs(v);
        int onFaces = (a.x > 0.5f - 0.02f) + (a.y > 0.5f - 0.02f) + (a.z > 0.5f - 0.02f);
        if (onFaces < 2) continue;
        ++edgeVertices;
        // The nearest of the 12 edges.
        float best = 1e9f;
        for (int axis = 0; axis < 3; ++axis)
            for (int s = 0; s < 4; ++s) {
                glm::vec3 from(0.0f), to(0.0f);
                const int u = (axis + 1) % 3, w = (axis + 2) % 3;
                from[axis] = -0.5f;
                to[axis] = 0.5f;
                from[u] = to[u] = (s & 1) ? 0.5f : -0.5f;
                from[w] = to[w] = (s & 2) ? 0.5f : -0.5f;
                best = std::min(best, segmentDistance(v, from, to));
            }
        EXPECT_LT(best, 1e-3f) << v.x << "," << v.y << "," << v.z;
    }
    EXPECT_GT(edgeVertices, 12 * 30) << "a vertex per cell along each edge (32 cells each)";
    const meshing::Topology topology = meshing::checkTopology(mesh);
    EXPECT_TRUE(topology.watertight()) << topology.boundaryEdges << " boundary, " << topology.nonManifoldEdges << " non-manifold";
    // Outward winding: the signed volume is the box's.
    double volume = 0.0;
    for (std::size_t f = 0; f < mesh.triangleCount(); ++f)
        volume += glm::dot(mesh.vertices[mesh.indices[3 * f]],
                           glm::cross(mesh.vertices[mesh.indices[3 * f + 1]], mesh.vertices[mesh.indices[3 * f + 2]])) /
                  6.0;
    EXPECT_NEAR(volume, 1.0, 1e-3);
}

TEST_F(MeshTest, TheSphereErrorFallsAtSecondOrder) {
    const shaders::PreparedSdf sphere = source(kSphere);
    std::vector<float> hausdorff;
    for (int resolution : {16, 32, 64}) {
        const meshing::Mesh mesh = extract(sphere, resolution);
        meshing::ErrorOptions options;
        options.meshPoints = options.surfacePoints = 50000;
        auto error = meshing::measureError(sphere, mesh, options);
        ASSERT_TRUE(error) << error.error().message;
        EXPECT_EQ(error->surfacePoints, 50000u);
        hausdorff.push_back(error->hausdorff);
    }
    // Chords of a circle of radius R over a cell h sag by h^2 / (8R): halving h quarters it.
    EXPECT_GT(hausdorff[0] / hausdorff[1], 3.0f) << hausdorff[0] << " -> " << hausdorff[1];
    EXPECT_GT(hausdorff[1] / hausdorff[2], 3.0f) << hausdorff[1] << " -> " << hausdorff[2];
    EXPECT_LT(hausdorff[2], 2e-3f);
}

TEST_F(MeshTest, ClosedDatasetShapesAreWatertight) {
    for (const char* file :
         {"dataset/Geometry/Torus.glsl", "dataset/Geometry/Capsule.glsl", "dataset/Geometry/Link.glsl",
          "dataset/Geometry/TrefoilKnot.glsl", "dataset/Geometry/Octahedron.glsl", "dataset/Geometry/Cone.glsl"}) {
        const meshing::Mesh mesh = extract(sdfwb::testing::loadSourceSdf(file), 64);
        ASSERT_GT(mesh.triangleCount(), 100u) << file;
        const meshing::Topology topology = meshing::checkTopology(mesh);
        EXPECT_EQ(topology.boundaryEdges, 0u) << file;
        EXPECT_EQ(topology.nonManifoldEdges, 0u) << file;
    }
}

TEST_F(MeshTest, TwoSheetsInOneCellGetAVertexEach) {
    // The mug's wall is thinner than a cell at 128: one vertex per cell made ~100 edges shared by
    // four triangles; a vertex per patch of surface keeps every edge to two.
    const meshing::Mesh mesh = extract(sdfwb::testing::loadSourceSdf("dataset/Manufactured/Mug.glsl"), 128);
    const meshing::Topology topology = meshing::checkTopology(mesh);
    EXPECT_EQ(topology.nonManifoldEdges, 0u);
    EXPECT_EQ(topology.boundaryEdges, 0u);
}

TEST_F(MeshTest, SkippingEmptyBlocksLosesNothing) {
    const shaders::PreparedSdf torus = sdfwb::testing::loadSourceSdf("dataset/Geometry/Torus.glsl");
    meshing::MeshOptions options;
    options.resolution = 96;
    auto skipped = meshing::extractMesh(torus, options, {});
    options.lipschitz = 0.0f; // evaluate every block
    auto all = meshing::extractMesh(torus, options, {});
    ASSERT_TRUE(skipped && all);
    EXPECT_LT(skipped->second.blocksKept, skipped->second.blocks / 2) << "most of the box is empty";
    EXPECT_EQ(all->second.blocksKept, all->second.blocks);
    EXPECT_LT(skipped->second.pointsEvaluated, all->second.pointsEvaluated / 2);
    ASSERT_EQ(skipped->first.vertices.size(), all->first.vertices.size());
    ASSERT_EQ(skipped->first.indices.size(), all->first.indices.size());
}

TEST_F(MeshTest, FilesReadBackTheSameTriangles) {
    const meshing::Mesh mesh = extract(source(kSphere), 24);
    const std::filesystem::path folder =
        std::filesystem::temp_directory_path() / ("sdfwb-mesh-test-" + std::to_string(::getpid()));
    std::filesystem::create_directories(folder);
    for (const char* name : {"m.ply", "m.obj", "m.stl", "m.glb"}) {
        ASSERT_TRUE(meshing::writeMesh(folder / name, mesh)) << name;
        auto back = meshing::readMesh(folder / name);
        ASSERT_TRUE(back) << name << ": " << back.error().message;
        EXPECT_EQ(back->triangleCount(), mesh.triangleCount()) << name;
        EXPECT_EQ(back->vertices.size(), mesh.vertices.size()) << name << " (equal positions merged)";
        EXPECT_TRUE(meshing::checkTopology(*back).watertight()) << name;
    }
    auto bad = meshing::writeMesh(folder / "m.xyz", mesh);
    ASSERT_FALSE(bad);
    EXPECT_NE(bad.error().message.find("unsupported mesh type"), std::string::npos);
    EXPECT_FALSE(meshing::readMesh(folder / "missing.ply"));
    std::filesystem::remove_all(folder);
}

TEST_F(MeshTest, EvaluationFiguresMatchTheGeometry) {
    // Our own sphere mesh against its field: near perfect.
    const shaders::PreparedSdf sphere = source(kSphere);
    const meshing::Mesh mesh = extract(sphere, 64);
    meshing::EvalOptions options;
    options.points = 50000;
    auto own = meshing::evaluateMesh(sphere, mesh, options);
    ASSERT_TRUE(own) << own.error().message;
    EXPECT_LT(own->chamferL1, 5e-4f); // chords of a radius-0.6 sphere over 1/32 cells
    EXPECT_FLOAT_EQ(own->fscore, 1.0f);
    EXPECT_GT(own->normalConsistency, 0.999f);
    ASSERT_TRUE(own->iou);
    EXPECT_GT(*own->iou, 0.99f);
    EXPECT_TRUE(own->closed);
    // The same mesh against a sphere 0.05 larger: every distance is 0.05 both ways, the IoU the
    // volume ratio (0.6 / 0.65)^3 = 0.7865, nothing within tau = 0.01 and everything within 0.1.
    const shaders::PreparedSdf larger = source("float sdf(vec3 p) { return length(p) - 0.65; }");
    auto off = meshing::evaluateMesh(larger, mesh, options);
    ASSERT_TRUE(off) << off.error().message;
    EXPECT_NEAR(off->accuracyMean, 0.05f, 1e-3f);
    EXPECT_NEAR(off->completenessMean, 0.05f, 1e-3f);
    EXPECT_NEAR(off->chamferL1, 0.05f, 1e-3f);
    EXPECT_NEAR(off->chamferL2, 0.0025f, 1e-4f);
    EXPECT_NEAR(off->hausdorff, 0.05f, 2e-3f);
    EXPECT_NEAR(*off->iou, 0.7865f, 0.01f);
    EXPECT_EQ(off->fscore, 0.0f);
    options.tau = 0.1f;
    auto loose = meshing::evaluateMesh(larger, mesh, options);
    ASSERT_TRUE(loose);
    EXPECT_FLOAT_EQ(loose->fscore, 1.0f);
    EXPECT_GT(loose->normalConsistency, 0.999f) << "concentric spheres have parallel normals";
}
