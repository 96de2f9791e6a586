// The native CPU engine (meshfield::MeshQuery) against the double-precision reference it must
// equal: the same nearest distance, the same sign for every method, the sign cache used only where
// it is exact (closed, consistently oriented meshes) and never changing a sign, the exact gradient
// against central differences away from the medial axis, and rows bit-identical for every thread
// count.
#include "TestMeshes.h"

#include <meshfield/MeshField.h>
#include <meshfield/MeshQuery.h>

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <memory>
#include <random>

namespace sdfwb::meshfield {
namespace {

using glm::dvec3;

std::vector<float> randomPoints(std::size_t n, unsigned seed, float reach = 1.2f) {
    std::mt19937 random(seed);
    std::uniform_real_distribution<float> u(-reach, reach);
    std::vector<float> points(3 * n);
    for (float& x : points) x = u(random);
    return points;
}

std::shared_ptr<const MeshField> makeField(const TriangleMesh& mesh, SignMethod sign) {
    MeshFieldOptions options;
    options.sign = sign;
    auto field = makeMeshField(mesh, "mesh.obj", options);
    EXPECT_TRUE(field.hasValue());
    return *field;
}

TEST(MeshQueryCpu, TheEngineEqualsTheDoubleReferenceForEverySignMethodAndMesh) {
    const TriangleMesh torus = testing::torusMesh(0.6f, 0.25f, 48, 16);
    struct Case {
        const char* name;
        TriangleMesh mesh;
    };
    const Case cases[] = {{"closed", torus},
                          {"5% removed", testing::damaged(torus, testing::Damage::RemoveFivePercent)},
                          {"10% flipped", testing::damaged(torus, testing::Damage::FlipTenPercent)},
                          {"shell duplicated", testing::damaged(torus, testing::Damage::DuplicateShell)}};
    const std::vector<float> points = randomPoints(6000, 3);
    const std::size_t n = points.size() / 3;
    for (const Case& c : cases)
        for (SignMethod sign : {SignMethod::Winding, SignMethod::Parity, SignMethod::Pseudonormal}) {
            auto field = makeField(c.mesh, sign);
            auto query = meshQuery(field);
            std::vector<float> values(n);
            QueryCounters counters;
            query->evaluate({points.data(), 3, values.data(), 1, nullptr, 3}, n, {}, 0, &counters);
            double worst = 0.0;
            int wrongSign = 0;
            for (std::size_t i = 0; i < n; ++i) {
                const dvec3 p(points[3 * i], points[3 * i + 1], points[3 * i + 2]);
                const double distance = field->distance(p);
                worst = std::max(worst, std::abs(std::abs(double(values[i])) - distance));
                if (distance > 1e-4 && (values[i] < 0.0f) != field->inside(p)) ++wrongSign;
            }
            std::printf("%-16s %-12s largest |d| difference %.2e, signs differing %d of %zu, cached signs %llu\n", c.name,
                        signName(sign), worst, wrongSign, n, (unsigned long long)counters.cachedSigns);
            EXPECT_LE(worst, 1e-7) << c.name << ' ' << signName(sign); // the float rounding of the value
            EXPECT_EQ(wrongSign, 0) << c.name << ' ' << signName(sign);
            // The sign cache serves the winding sign only; on a closed, oriented mesh (a duplicated
            // shell is two) it serves most rows, elsewhere where its bound allows.
            if (sign != SignMethod::Winding)
                EXPECT_EQ(counters.cachedSigns, 0u) << c.name << ' ' << signName(sign);
            else if (std::string(c.name) == "closed" || std::string(c.name) == "shell duplicated")
                EXPECT_GT(counters.cachedSigns, n / 2) << c.name;
        }
}

TEST(MeshQueryCpu, TheSignCacheServesAnOpenMeshWhereItsBoundHoldsAndNeverChangesASign) {
    // A torus with one quad missing: a hole whose rim (4 short edges) bounds how fast the winding
    // number can change away from it.
    TriangleMesh mesh = testing::torusMesh(0.6f, 0.25f, 48, 16);
    mesh.indices.erase(mesh.indices.begin(), mesh.indices.begin() + 6);
    auto field = makeField(mesh, SignMethod::Winding);
    auto query = meshQuery(field);
    const std::vector<float> points = randomPoints(20000, 13);
    const std::size_t n = points.size() / 3;
    std::vector<float> values(n);
    QueryCounters counters;
    query->evaluate({points.data(), 3, values.data(), 1, nullptr, 3}, n, {}, 0, &counters);
    int differ = 0;
    for (std::size_t i = 0; i < n; ++i) {
        const dvec3 p(points[3 * i], points[3 * i + 1], points[3 * i + 2]);
        if (std::abs(values[i]) > 1e-5f && (values[i] < 0.0f) != (query->winding(p) > 0.5)) ++differ;
    }
    std::printf("open torus: %llu of %zu signs from the cache, %d differ from the walk\n",
                (unsigned long long)counters.cachedSigns, n, differ);
    EXPECT_GT(counters.cachedSigns, n / 2);
    EXPECT_EQ(differ, 0);
}

TEST(MeshQueryCpu, EveryThreadCountWritesTheSameRowsBitForBit) {
    auto field = makeField(testing::torusMesh(0.6f, 0.25f, 64, 24), SignMethod::Winding);
    const std::vector<float> points = randomPoints(20000, 5);
    const std::size_t n = points.size() / 3;
    std::vector<float> reference;
    for (unsigned threads : {1u, 2u, 3u, 8u}) {
        // A new query each time: the sign cache fills in a different order on every run.
        auto query = std::make_unique<MeshQuery>(*field);
        std::vector<float> rows(7 * n);
        for (std::size_t i = 0; i < n; ++i)
            std::copy(points.begin() + long(3 * i), points.begin() + long(3 * i + 3), rows.begin() + long(7 * i));
        const std::uint64_t bad = query->evaluate({rows.data(), 7, rows.data() + 3, 7, rows.data() + 4, 7}, n, {}, threads);
        EXPECT_EQ(bad, 0u);
        if (reference.empty())
            reference = rows;
        else
            EXPECT_EQ(0, std::memcmp(rows.data(), reference.data(), rows.size() * sizeof(float))) << threads << " threads";
    }
}

TEST(MeshQueryCpu, TheExactGradientIsTheFieldsSlopeAwayFromTheMedialAxisAndUnitEverywhere) {
    auto field = makeField(testing::torusMesh(0.6f, 0.25f, 96, 32), SignMethod::Winding);
    auto query = meshQuery(field);
    const std::vector<float> points = randomPoints(4000, 9);
    const std::size_t n = points.size() / 3;
    std::vector<float> values(n), exact(3 * n);
    ASSERT_EQ(query->evaluate({points.data(), 3, values.data(), 1, exact.data(), 3}, n, {true, 1e-3f}), 0u);
    // Central differences of the double field with a small step are its slope wherever the field is
    // smooth over the stencil: their length is then 1 to rounding. A stencil across a kink (the
    // medial axis, which a polygon's concave edges bring close to the surface) is shorter: skipped.
    const double h = 1e-6;
    int compared = 0;
    int disagree = 0;
    for (std::size_t i = 0; i < n; ++i) {
        const dvec3 p(points[3 * i], points[3 * i + 1], points[3 * i + 2]);
        const dvec3 e(exact[3 * i], exact[3 * i + 1], exact[3 * i + 2]);
        EXPECT_NEAR(glm::length(e), 1.0, 1e-6) << "row " << i;
        dvec3 t;
        for (int a = 0; a < 3; ++a) {
            dvec3 step(0.0);
            step[a] = h;
            t[a] = (query->signedDistance(p + step, nullptr) - query->signedDistance(p - step, nullptr)) / (2.0 * h);
        }
        if (std::abs(glm::length(t) - 1.0) > 1e-6 || std::abs(values[i]) < 1e-4f) continue;
        ++compared;
        if (glm::length(e - t) > 1e-4) ++disagree;
    }
    std::printf("exact gradient against central differences (double, h 1e-6): %d of %d smooth rows differ by more than 1e-4\n",
                disagree, compared);
    EXPECT_GT(compared, int(n) * 9 / 10);
    EXPECT_EQ(disagree, 0);
}

TEST(MeshQueryCpu, RowsWithoutAFinitePositionAreNaNAndCounted) {
    auto query = meshQuery(makeField(testing::torusMesh(0.6f, 0.25f, 24, 8), SignMethod::Winding));
    std::vector<float> points = {0.6f, 0.0f, 0.0f, NAN, 0.0f, 0.0f, 0.0f, INFINITY, 0.0f};
    std::vector<float> values(3), gradients(9);
    EXPECT_EQ(query->evaluate({points.data(), 3, values.data(), 1, gradients.data(), 3}, 3, {}), 2u);
    EXPECT_LT(values[0], 0.0f);
    EXPECT_TRUE(std::isnan(values[1]) && std::isnan(values[2]) && std::isnan(gradients[3]) && std::isnan(gradients[8]));
}

TEST(MeshQueryCpu, TheEngineFollowsTheDriverUnlessTheEnvironmentSaysOtherwise) {
    unsetenv("SDFWB_MESH_ENGINE");
    EXPECT_EQ(chooseMeshEngine("llvmpipe (LLVM 15.0.6, 256 bits)"), MeshEngine::Cpu);
    EXPECT_EQ(chooseMeshEngine("NVIDIA H100 80GB HBM3/PCIe/SSE2"), MeshEngine::Gpu);
    setenv("SDFWB_MESH_ENGINE", "gpu", 1);
    EXPECT_EQ(chooseMeshEngine("llvmpipe (LLVM 15.0.6, 256 bits)"), MeshEngine::Gpu);
    setenv("SDFWB_MESH_ENGINE", "cpu", 1);
    EXPECT_EQ(chooseMeshEngine("NVIDIA H100 80GB HBM3/PCIe/SSE2"), MeshEngine::Cpu);
    unsetenv("SDFWB_MESH_ENGINE");
}

} // namespace
} // namespace sdfwb::meshfield
