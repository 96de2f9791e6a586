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

// The GLSL field's sign lattice: on a closed mesh the points that paths clear of the surface join
// share one winding number, computed once; on an open one each point has its own. Either way every
// point's value is within the hierarchy's 1/4 of its own walk's, on the same side of 1/2, and the
// header says what follows. The mesh is two closed shells, a torus and a smaller torus through
// its tube (where both enclose a point its winding number is 2).
TEST(MeshQueryCpu, TheSignLatticeSharesAClosedMeshsWindingNumbersAcrossClearPathsAndKeepsEverySide) {
    TriangleMesh closed = testing::torusMesh(0.6f, 0.25f, 48, 16);
    const TriangleMesh inner = testing::torusMesh(0.15f, 0.08f, 24, 12);
    for (const glm::vec3& v : inner.vertices) closed.vertices.push_back(v + glm::vec3(0.0f, 0.5f, 0.0f));
    const std::uint32_t base = std::uint32_t(closed.vertices.size() - inner.vertices.size());
    for (std::uint32_t i : inner.indices) closed.indices.push_back(base + i);
    TriangleMesh open = closed;
    open.indices.erase(open.indices.begin(), open.indices.begin() + 6);
    for (const auto& [name, mesh] : {std::pair{"closed", closed}, std::pair{"open", open}}) {
        auto query = meshQuery(makeField(mesh, SignMethod::Winding));
        const int level = 4;
        const std::vector<float> lattice = query->signLattice(level);
        ASSERT_GE(lattice.size(), 8u);
        const std::size_t side = std::size_t(lattice[4]), points = side * side * side;
        ASSERT_EQ(side, 17u);
        EXPECT_EQ(lattice[6], std::string(name) == "open" ? 1.0f : 0.0f) << name << ": boundary slopes follow";
        int wrongSide = 0, inside = 0, bitEqual = 0;
        double worst = 0.0;
        for (std::size_t j = 0; j < points; ++j) {
            const glm::vec3 q = glm::vec3(lattice[0], lattice[1], lattice[2]) +
                                glm::vec3(float(j % side), float((j / side) % side), float(j / (side * side))) * lattice[3];
            const double own = query->winding(dvec3(q));
            const float stored = lattice[8 + j];
            worst = std::max(worst, std::abs(double(stored) - own));
            wrongSide += (stored > 0.5f) != (own > 0.5) ? 1 : 0;
            inside += stored > 0.5f ? 1 : 0;
            bitEqual += stored == float(own) ? 1 : 0;
        }
        std::printf("%s: %d of %zu lattice points inside, %d equal to their own walk bit for bit, largest difference %.2e\n",
                    name, inside, points, bitEqual, worst);
        EXPECT_EQ(wrongSide, 0) << name;
        EXPECT_LT(worst, 0.25) << name;
        EXPECT_GT(inside, 0) << name;
        if (std::string(name) == "open") {
            EXPECT_EQ(bitEqual, int(points)) << "an open mesh's points each get their own walk";
        } else {
            EXPECT_LT(bitEqual, int(points)) << "a closed mesh's points share their sets' values";
        }
    }
}

// Points within a few triangle sizes of the surface, where no lattice point fits inside the empty
// ball around a row: random points on random triangles, moved off along random directions by
// 1e-5 to 3e-2, and some exactly on corners and edges' midpoints moved by 1e-6.
std::vector<float> pointsNearTheSurface(const TriangleMesh& mesh, std::size_t n, unsigned seed) {
    std::mt19937 random(seed);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    std::normal_distribution<double> g(0.0, 1.0);
    const std::size_t triangles = mesh.indices.size() / 3;
    std::vector<float> points;
    for (std::size_t i = 0; i < n; ++i) {
        const std::size_t t = std::size_t(u(random) * double(triangles)) % triangles;
        const dvec3 a(mesh.vertices[mesh.indices[3 * t]]), b(mesh.vertices[mesh.indices[3 * t + 1]]),
            c(mesh.vertices[mesh.indices[3 * t + 2]]);
        double x = u(random), y = u(random);
        if (x + y > 1.0) x = 1.0 - x, y = 1.0 - y;
        dvec3 on = a + x * (b - a) + y * (c - a);
        if (i % 8 == 0) on = a;             // a corner
        if (i % 8 == 1) on = (a + b) * 0.5; // an edge
        const dvec3 direction = glm::normalize(dvec3(g(random), g(random), g(random)));
        const double offset = i % 8 < 2 ? 1e-6 : std::pow(10.0, -5.0 + 3.5 * u(random));
        const dvec3 p = on + direction * offset;
        points.insert(points.end(), {float(p.x), float(p.y), float(p.z)});
    }
    return points;
}

TEST(MeshQueryCpu, RowsNearTheSurfaceTakeTheirSignFromALatticePointAndTheTrianglesBetween) {
    const TriangleMesh torus = testing::torusMesh(0.6f, 0.25f, 48, 16);
    TriangleMesh holed = torus;
    holed.indices.erase(holed.indices.begin(), holed.indices.begin() + 6);
    struct Case {
        const char* name;
        TriangleMesh mesh;
        double crossedShare; // the least share of rows that must cross (see below)
    };
    // On a closed, oriented mesh every row off the surface can cross; on an open one, those far
    // enough from the open boundary: most with one hole, fewer with 5 % of the faces gone, next to
    // none with 10 % flipped (every flipped face's rim is open boundary), where the walk decides.
    const Case cases[] = {{"closed", torus, 0.9},
                          {"one quad missing", holed, 0.9},
                          {"5% removed", testing::damaged(torus, testing::Damage::RemoveFivePercent), 0.3},
                          {"10% flipped", testing::damaged(torus, testing::Damage::FlipTenPercent), 0.0},
                          {"shell duplicated", testing::damaged(torus, testing::Damage::DuplicateShell), 0.9}};
    for (const Case& c : cases) {
        auto field = makeField(c.mesh, SignMethod::Winding);
        auto query = std::make_unique<MeshQuery>(*field);
        const std::vector<float> points = pointsNearTheSurface(c.mesh, 20000, 21);
        const std::size_t n = points.size() / 3;
        std::vector<float> values(n);
        QueryCounters counters;
        query->evaluate({points.data(), 3, values.data(), 1, nullptr, 3}, n, {}, 0, &counters);
        int differ = 0, compared = 0;
        for (std::size_t i = 0; i < n; ++i) {
            const dvec3 p(points[3 * i], points[3 * i + 1], points[3 * i + 2]);
            const double w = query->winding(p);
            // The walk's own sign where it is clear of 1/2 (the hierarchy's approximation): the
            // sign the rows must have.
            if (std::abs(values[i]) < 1e-7f || std::abs(w - 0.5) < 0.1) continue;
            ++compared;
            if ((values[i] < 0.0f) != (w > 0.5)) ++differ;
        }
        std::printf("%-16s %d rows compared, %d differ from the walk; signs: %llu cached, %llu crossed (%.1f nodes a segment)\n",
                    c.name, compared, differ, (unsigned long long)counters.cachedSigns, (unsigned long long)counters.crossedSigns,
                    double(counters.segmentNodes) / double(std::max<std::uint64_t>(1, counters.crossedSigns)));
        EXPECT_EQ(differ, 0) << c.name;
        EXPECT_GT(compared, int(n) * 9 / 10) << c.name;
        EXPECT_GE(double(counters.crossedSigns), c.crossedShare * double(n)) << c.name;
    }
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
