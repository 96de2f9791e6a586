// Refinement: a smooth shape's error quartered with the topology kept, creases kept, and the
// reported topology holding on tunnels.
#include "MeshTesting.h"

using namespace sdfwb;
using namespace sdfwb::meshtest;

// refine: each level cuts every triangle into four and puts the new vertices on the surface, so on
// a smooth shape the error falls as if the resolution doubled, and the topology the mesher reports
// for the fine mesh without checking it (subdividedTopology) is what a check of it finds.
TEST_F(MeshTest, RefinementQuartersASmoothShapesErrorAndKeepsItsTopology) {
    for (const char* file : {"dataset/Geometry/Torus.glsl", "dataset/Geometry/Sphere.glsl"}) {
        const shaders::PreparedSdf sdf = sdfwb::testing::loadSourceSdf(file);
        std::vector<float> hausdorff;
        std::size_t coarseTriangles = 0;
        for (int refine : {0, 1, 2}) {
            meshing::MeshOptions options;
            options.resolution = 24;
            options.refine = refine;
            auto result = meshing::extractMesh(sdf, options, {});
            ASSERT_TRUE(result) << result.error().message;
            const auto& [mesh, stats] = *result;
            if (refine == 0) coarseTriangles = mesh.triangleCount();
            EXPECT_EQ(mesh.triangleCount(), coarseTriangles << (2 * refine)) << file;
            EXPECT_TRUE(closedAndOutward(mesh)) << file << " refine " << refine;
            EXPECT_EQ(stats.midpointsKept, 0u) << file;
            EXPECT_LT(largestVertexDistance(sdf, mesh), 1e-5f) << file << " refine " << refine;
            EXPECT_EQ(stats.topology.has_value(), refine > 0);
            if (stats.topology) {
                expectSameTopology(*stats.topology, meshing::checkTopology(mesh), std::string(file) + " refined");
                EXPECT_TRUE(stats.topology->manifold());
            }
            meshing::ErrorOptions errorOptions;
            errorOptions.meshPoints = errorOptions.surfacePoints = 50000;
            auto error = meshing::measureError(sdf, mesh, errorOptions);
            ASSERT_TRUE(error) << error.error().message;
            hausdorff.push_back(error->hausdorff);
        }
        EXPECT_GT(hausdorff[0] / hausdorff[1], 3.0f) << file << ": " << hausdorff[0] << " -> " << hausdorff[1];
        EXPECT_GT(hausdorff[1] / hausdorff[2], 3.0f) << file << ": " << hausdorff[1] << " -> " << hausdorff[2];
    }
}

// Refining a creased shape keeps its corners and flat faces (a midpoint on a face has f = 0 and
// stays), and the topology reported without a check matches one where faces were split
// (the Menger sponge's tunnels thinner than a cell).
TEST_F(MeshTest, RefinementKeepsCreasesAndTheReportedTopologyHoldsOnTunnels) {
    const shaders::PreparedSdf box = source(rotatedBoxSource(kTilt, glm::dvec3(0.5)));
    std::vector<float> hausdorff;
    for (int refine : {0, 1}) {
        meshing::MeshOptions options;
        options.resolution = 32;
        options.refine = refine;
        auto result = meshing::extractMesh(box, options, {});
        ASSERT_TRUE(result) << result.error().message;
        EXPECT_TRUE(closedAndOutward(result->first));
        meshing::ErrorOptions errorOptions;
        errorOptions.meshPoints = errorOptions.surfacePoints = 50000;
        auto error = meshing::measureError(box, result->first, errorOptions);
        ASSERT_TRUE(error) << error.error().message;
        hausdorff.push_back(error->hausdorff);
    }
    EXPECT_LT(hausdorff[1], 1.05f * hausdorff[0] + 1e-6f) << hausdorff[0] << " -> " << hausdorff[1];
    // More triangles than the limit: a message naming the counts, not an allocation that fails.
    meshing::MeshOptions tooFine;
    tooFine.resolution = 32;
    tooFine.refine = 4;
    tooFine.refineTriangleLimit = 100000;
    auto refused = meshing::extractMesh(box, tooFine, {});
    ASSERT_FALSE(refused);
    EXPECT_NE(refused.error().message.find("refine 4 would cut the"), std::string::npos) << refused.error().message;
    for (const char* file : {"dataset/Fractal/MengerSponge.glsl", "tests/foreign/42_hg_mercury_arcade.glsl"}) {
        meshing::MeshOptions options;
        options.resolution = 64;
        options.refine = 1;
        auto result = meshing::extractMesh(sdfwb::testing::loadSourceSdf(file), options, {});
        ASSERT_TRUE(result) << result.error().message;
        ASSERT_TRUE(result->second.topology.has_value());
        expectSameTopology(*result->second.topology, meshing::checkTopology(result->first), file);
        EXPECT_TRUE(closedAndOutward(result->first)) << file;
    }
}
