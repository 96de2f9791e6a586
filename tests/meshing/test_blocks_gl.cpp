// Blocks a Lipschitz bound proves empty are skipped and lose nothing: the same triangles with and
// without skipping, a bound too low loses no connected surface, the estimated bound follows the
// field's slope, and every thread count gives the same mesh.
#include "MeshTesting.h"

using namespace sdfwb;
using namespace sdfwb::meshtest;

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
    // The same triangles, wound alike, at bitwise the same positions: a kept block's points,
    // crossings and vertices are computed from the same coordinates either way.
    const auto a = canonicalTriangles(skipped->first), b = canonicalTriangles(all->first);
    std::size_t differ = 0, first = a.size();
    float largest = 0.0f;
    for (std::size_t t = 0; t < a.size(); ++t) {
        if (std::memcmp(a[t].data(), b[t].data(), sizeof a[t]) == 0) continue;
        if (differ++ == 0) first = t;
        for (std::size_t k = 0; k < 9; ++k) largest = std::max(largest, std::abs(a[t][k] - b[t][k]));
    }
    EXPECT_EQ(differ, 0u) << "triangles differ, the first at sorted position " << first << ", by up to " << largest;
}

namespace {

// The components of a mesh's triangles (triangles sharing a vertex index are in one), each
// triangle's label.
std::vector<std::size_t> triangleComponents(const meshing::Mesh& mesh) {
    std::vector<std::size_t> parent(mesh.vertices.size());
    std::iota(parent.begin(), parent.end(), std::size_t(0));
    auto find = [&](std::size_t v) {
        while (parent[v] != v) v = parent[v] = parent[parent[v]];
        return v;
    };
    for (std::size_t i = 0; i + 2 < mesh.indices.size(); i += 3)
        for (std::size_t k = 1; k < 3; ++k) parent[find(mesh.indices[i + k])] = find(mesh.indices[i]);
    std::vector<std::size_t> label(mesh.triangleCount());
    for (std::size_t t = 0; t < label.size(); ++t) label[t] = find(mesh.indices[3 * t]);
    return label;
}

} // namespace

// A bound far too low skips blocks and sub-blocks the surface passes through; the surface is
// followed from the evaluated points across the crossings they show, so every piece of surface
// connected to one the bound kept comes out whole. The torus is one piece and comes out whole; the
// Menger sponge at 64 cells is a main piece and 368 crumbs a few cells wide: its mesh is the full
// mesh less whole crumbs (none cut), with the main piece whole.
TEST_F(MeshTest, ABoundTooLowLosesNoConnectedSurface) {
    for (const char* file : {"dataset/Geometry/Torus.glsl", "dataset/Fractal/MengerSponge.glsl"}) {
        const shaders::PreparedSdf sdf = sdfwb::testing::loadSourceSdf(file);
        meshing::MeshOptions options;
        options.resolution = 64;
        options.lipschitz = 0.1f; // the fields' true bound is 1
        auto low = meshing::extractMesh(sdf, options, {});
        options.lipschitz = 0.0f;
        auto all = meshing::extractMesh(sdf, options, {});
        ASSERT_TRUE(low && all) << file;
        EXPECT_GT(low->second.blocksGrown, 10u) << file;
        EXPECT_LT(low->second.blocksKept, all->second.blocksKept) << file << ": the empty blocks stay skipped";
        const auto lowTriangles = canonicalTriangles(low->first);
        if (std::string(file).find("Torus") != std::string::npos) {
            EXPECT_EQ(lowTriangles, canonicalTriangles(all->first)) << file;
            continue;
        }
        // Per component of the full mesh: how many of its triangles the low bound's mesh has.
        const std::vector<std::size_t> label = triangleComponents(all->first);
        std::map<std::size_t, std::pair<std::size_t, std::size_t>> kept; // label: (found, total)
        std::size_t found = 0;
        for (std::size_t t = 0; t < label.size(); ++t) {
            meshing::Mesh one;
            for (int k = 0; k < 3; ++k) one.vertices.push_back(all->first.vertices[all->first.indices[3 * t + std::size_t(k)]]);
            one.indices = {0, 1, 2};
            const bool in = std::binary_search(lowTriangles.begin(), lowTriangles.end(), canonicalTriangles(one)[0]);
            found += in;
            kept[label[t]].first += in;
            ++kept[label[t]].second;
        }
        EXPECT_EQ(found, lowTriangles.size()) << file << ": a triangle the full mesh does not have";
        std::size_t largest = 0, cut = 0, lost = 0;
        for (const auto& [component, counts] : kept) {
            largest = std::max(largest, counts.second);
            cut += counts.first != 0 && counts.first != counts.second;
            lost += counts.first == 0;
        }
        EXPECT_GT(kept.size(), 300u) << file;
        EXPECT_EQ(cut, 0u) << file << ": a piece of surface came out in part";
        EXPECT_LT(lost, kept.size() / 10) << file;
        for (const auto& [component, counts] : kept)
            if (counts.second == largest) { EXPECT_EQ(counts.first, largest) << file << ": the main piece"; }
        EXPECT_GT(largest, label.size() / 2) << file;
    }
}

// Inside a kept block only the sub-blocks of 2^3 cells that the bound cannot prove empty are
// evaluated (the others' points take their centre's value), and the mesh is the one from every
// grid point, bit for bit: on a creased dataset shape and two foreign files (hg_sdf's chamfered
// arcade, IQ's primitives) with the bound estimated, as the command line does. Fewer points are
// evaluated in all than the kept blocks' grid points alone.
TEST_F(MeshTest, SkippedSubBlocksChangeNoTriangle) {
    for (const char* file :
         {"dataset/Manufactured/Anvil.glsl", "tests/foreign/42_hg_mercury_arcade.glsl", "tests/foreign/01_iq_primitives.glsl"}) {
        const shaders::PreparedSdf sdf = sdfwb::testing::loadSourceSdf(file);
        meshing::MeshOptions options;
        options.resolution = 128;
        options.estimateLipschitz = true;
        auto skipped = meshing::extractMesh(sdf, options, {});
        options.estimateLipschitz = false;
        options.lipschitz = 0.0f;
        auto all = meshing::extractMesh(sdf, options, {});
        ASSERT_TRUE(skipped && all) << file;
        ASSERT_GT(skipped->first.triangleCount(), 10000u) << file;
        EXPECT_LT(skipped->second.pointsEvaluated, skipped->second.blocksKept * 729u) << file;
        EXPECT_EQ(canonicalTriangles(skipped->first), canonicalTriangles(all->first)) << file;
    }
}

// With the bound estimated from the block centres, an exact field's bound is 1.25 (the gradient is
// 1 everywhere), a field steeper by 3 gets a bound near 3.75, and the mesh is the unskipped one.
TEST_F(MeshTest, TheEstimatedBoundFollowsTheFieldsSlope) {
    for (const auto& [text, slope] :
         {std::pair{kSphere, 1.0f}, std::pair{"float sdf(vec3 p) { return 3.0 * (length(p) - 0.6); }", 3.0f}}) {
        const shaders::PreparedSdf sdf = source(text);
        meshing::MeshOptions options;
        options.resolution = 64;
        options.estimateLipschitz = true;
        auto estimated = meshing::extractMesh(sdf, options, {});
        options.estimateLipschitz = false;
        options.lipschitz = 0.0f;
        auto all = meshing::extractMesh(sdf, options, {});
        ASSERT_TRUE(estimated && all);
        EXPECT_NEAR(estimated->second.lipschitzUsed, 1.25f * slope, 0.01f * slope) << text;
        EXPECT_LT(estimated->second.blocksKept, all->second.blocksKept / 2) << text;
        EXPECT_EQ(estimated->second.blocksGrown, 0u) << text;
        EXPECT_EQ(canonicalTriangles(estimated->first), canonicalTriangles(all->first)) << text;
    }
}

// The CPU steps run in chunks on every core and are joined in order: one thread and five give the
// same vertices and triangles, bit for bit, in the same order (a creased, a split-face and a
// smooth shape), and the same counts.
TEST_F(MeshTest, EveryThreadCountGivesTheSameMesh) {
    const char* saved = std::getenv("SDFWB_THREADS");
    const std::string restore = saved ? saved : "";
    for (const char* file :
         {"dataset/Fractal/MengerSponge.glsl", "dataset/Geometry/Torus.glsl", "dataset/Manufactured/Anvil.glsl"}) {
        const shaders::PreparedSdf sdf = sdfwb::testing::loadSourceSdf(file);
        meshing::MeshOptions options;
        options.resolution = 96;
        options.estimateLipschitz = true;
        ::setenv("SDFWB_THREADS", "1", 1);
        auto one = meshing::extractMesh(sdf, options, {});
        ::setenv("SDFWB_THREADS", "5", 1);
        auto five = meshing::extractMesh(sdf, options, {});
        ASSERT_TRUE(one && five) << file;
        ASSERT_GT(one->first.indices.size(), 1000u) << file;
        EXPECT_EQ(one->first.indices, five->first.indices) << file;
        ASSERT_EQ(one->first.vertices.size(), five->first.vertices.size()) << file;
        EXPECT_EQ(
            std::memcmp(one->first.vertices.data(), five->first.vertices.data(), one->first.vertices.size() * sizeof(glm::vec3)),
            0)
            << file;
        EXPECT_EQ(one->second.activeCells, five->second.activeCells) << file;
        EXPECT_EQ(one->second.clampedVertices, five->second.clampedVertices) << file;
        EXPECT_EQ(one->second.creasesOnFaces, five->second.creasesOnFaces) << file;
        EXPECT_EQ(meshing::checkTopology(one->first).misorientedEdges, 0u) << file;
    }
    if (saved)
        ::setenv("SDFWB_THREADS", restore.c_str(), 1);
    else
        ::unsetenv("SDFWB_THREADS");
}
