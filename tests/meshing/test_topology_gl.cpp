// Topology: every dataset shape and closed foreign file meshes edge- and vertex-manifold, tunnels
// thinner than a cell keep every edge to two triangles, pinched vertices and turned faces are
// counted, and self-intersections are found where a mesh passes through itself.
#include "MeshTesting.h"

using namespace sdfwb;
using namespace sdfwb::meshtest;

// Every dataset shape and every closed foreign file (Shadertoy, IQ, hg_sdf and G3D styles), as
// paths from the source root. Left out: the three foreign files whose field is NaN over half of
// space (their `expect:` line flags nan), where the surface ends at the NaN region.
std::vector<std::string> manifoldCorpus() {
    const std::filesystem::path root(SDFWB_SOURCE_DIR);
    std::vector<std::string> files;
    for (const auto& folder : std::filesystem::directory_iterator(root / "dataset"))
        if (folder.is_directory() && folder.path().filename() != "lib")
            for (const auto& file : std::filesystem::directory_iterator(folder.path()))
                if (file.path().extension() == ".glsl") files.push_back(std::filesystem::relative(file.path(), root).string());
    const std::size_t datasetShapes = files.size();
    std::size_t nanFiles = 0;
    for (const auto& file : std::filesystem::directory_iterator(root / "tests" / "foreign")) {
        if (file.path().extension() != ".glsl") continue;
        std::ifstream in(file.path());
        const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
        const std::size_t expect = text.find("// expect:");
        if (expect != std::string::npos &&
            text.substr(expect, text.find('\n', expect) - expect).find("nan") != std::string::npos) {
            ++nanFiles;
            continue;
        }
        files.push_back(std::filesystem::relative(file.path(), root).string());
    }
    EXPECT_EQ(datasetShapes, 78u);
    EXPECT_EQ(nanFiles, 3u);
    EXPECT_GE(files.size() - datasetShapes, 45u);
    std::sort(files.begin(), files.end());
    return files;
}

// Issue 33, point 1, on the path `sdfwb --batch mesh` takes by default (issue 48, point 4): the
// Lipschitz bound estimated from the block centres, blocks without surface skipped. Every file
// meshes watertight, edge- and vertex-manifold and consistently oriented, with no triangle of zero
// area, at `resolution` cells.
void expectManifoldOnTheDefaultPath(int resolution) {
    for (const std::string& file : manifoldCorpus()) {
        meshing::MeshOptions options;
        options.resolution = resolution;
        options.estimateLipschitz = true; // what the CLI does without --lipschitz or --audit
        auto extracted = meshing::extractMesh(sdfwb::testing::loadSourceSdf(file), options, {});
        ASSERT_TRUE(extracted) << file << ": " << extracted.error().message;
        const meshing::Mesh& mesh = extracted->first;
        ASSERT_GT(mesh.triangleCount(), 100u) << file;
        const meshing::Topology topology = meshing::checkTopology(mesh);
        EXPECT_TRUE(topology.manifold()) << file << " at " << resolution << ": " << topology.boundaryEdges << " boundary edges, "
                                         << topology.nonManifoldEdges << " non-manifold edges, " << topology.nonManifoldVertices
                                         << " non-manifold vertices, " << topology.misorientedEdges << " misoriented edges";
        EXPECT_TRUE(closedAndOutward(mesh)) << file << " at " << resolution;
    }
}

TEST_F(MeshTest, EveryDatasetShapeAndClosedForeignFileMeshesManifold) { expectManifoldOnTheDefaultPath(64); }

TEST_F(MeshTest, EveryDatasetShapeAndClosedForeignFileMeshesManifoldAt256) { expectManifoldOnTheDefaultPath(256); }

// Where a tunnel is thinner than a cell, the patches on both sides of an ambiguous face join its
// two segments; the edge between their vertices would be shared by four triangles. A vertex per
// segment on the face keeps every edge to two: the Menger sponge (a tunnel in every cell at 64)
// and IQ's Menger sponge in Shadertoy style.
TEST_F(MeshTest, TunnelsThinnerThanACellKeepEveryEdgeToTwoTriangles) {
    for (const char* file : {"dataset/Fractal/MengerSponge.glsl", "tests/foreign/11_menger_iq.glsl"}) {
        meshing::MeshOptions options;
        options.resolution = 64;
        options.lipschitz = 1.0f;
        auto result = meshing::extractMesh(sdfwb::testing::loadSourceSdf(file), options, {});
        ASSERT_TRUE(result) << result.error().message;
        const auto& [mesh, stats] = *result;
        EXPECT_GT(stats.splitFaces, 100u) << file;
        const meshing::Topology topology = meshing::checkTopology(mesh);
        EXPECT_EQ(topology.nonManifoldEdges, 0u) << file;
        EXPECT_TRUE(topology.manifold()) << file;
        EXPECT_TRUE(closedAndOutward(mesh)) << file;
    }
}

// Issue 33, point 1: the topology report tells a manifold mesh from one pinched at a vertex or with
// a face turned over, both watertight by their edges alone.
TEST_F(MeshTest, TheTopologyCountsPinchedVerticesAndTurnedFaces) {
    const meshing::Mesh cube = boxMesh(kTilt, glm::dvec3(0.3));
    const meshing::Topology whole = meshing::checkTopology(cube);
    EXPECT_TRUE(whole.manifold());
    EXPECT_EQ(whole.edges, 18u);
    // Two cubes touching at one corner: cube corner 7 (+,+,+) is the other's corner 0 (-,-,-).
    meshing::Mesh pinched = boxMesh(glm::dmat3(1.0), glm::dvec3(0.3));
    const meshing::Mesh other = boxMesh(glm::dmat3(1.0), glm::dvec3(0.3));
    const std::uint32_t base = std::uint32_t(pinched.vertices.size());
    for (const glm::vec3& v : other.vertices) pinched.vertices.push_back(v + glm::vec3(0.6f));
    for (std::uint32_t i : other.indices) pinched.indices.push_back(i == 0 ? 7u : base + i);
    const meshing::Topology touching = meshing::checkTopology(pinched);
    EXPECT_TRUE(touching.watertight());
    EXPECT_EQ(touching.nonManifoldVertices, 1u);
    EXPECT_EQ(touching.misorientedEdges, 0u);
    EXPECT_FALSE(touching.manifold());
    // One triangle turned over: its three edges run the same way as their neighbours'.
    meshing::Mesh turned = cube;
    std::swap(turned.indices[1], turned.indices[2]);
    const meshing::Topology flipped = meshing::checkTopology(turned);
    EXPECT_TRUE(flipped.watertight());
    EXPECT_EQ(flipped.misorientedEdges, 3u);
    EXPECT_EQ(flipped.nonManifoldVertices, 0u);
    EXPECT_FALSE(flipped.manifold());
}

// Issue 33, point 1: self-intersections are counted. Two icospheres of radius 0.6 whose centres
// are 0.5 apart cross along a circle; 2 apart, or one alone, or a mesh of the sphere's field, they
// do not.
TEST_F(MeshTest, SelfIntersectionsAreCountedWhereAMeshPassesThroughItself) {
    auto merged = [](meshing::Mesh a, const meshing::Mesh& b, glm::vec3 shift) {
        const std::uint32_t base = std::uint32_t(a.vertices.size());
        for (const glm::vec3& v : b.vertices) a.vertices.push_back(v + shift);
        for (std::uint32_t i : b.indices) a.indices.push_back(base + i);
        return a;
    };
    const meshing::Mesh ball = icosphere(3, 0.6);
    EXPECT_EQ(meshing::countSelfIntersections(ball), 0u);
    const std::uint64_t crossing = meshing::countSelfIntersections(merged(ball, ball, {0.5f, 0.0f, 0.0f}));
    // The circle where they cross (radius sqrt(0.36 - 0.0625) = 0.545) passes through roughly
    // 2 pi 0.545 / (edge ~0.075) ~ 45 triangles of each: each meets one or two of the other's.
    EXPECT_GT(crossing, 40u);
    EXPECT_LT(crossing, 400u);
    EXPECT_EQ(meshing::countSelfIntersections(merged(ball, ball, {2.0f, 0.0f, 0.0f})), 0u);
    EXPECT_EQ(meshing::countSelfIntersections(extract(source(kSphere), 48)), 0u);
    EXPECT_EQ(meshing::countSelfIntersections(extract(source(kBox), 48)), 0u) << "sharp edges and corners do not fold";
}
