// The mesh field's CPU side: the hierarchy finds the same nearest triangle as a brute-force scan,
// hierarchical winding numbers match the exact sum, every sign method is right on a closed mesh,
// winding numbers keep the sign on broken meshes, the normalisations are what they say, and bad
// meshes are refused with messages naming them.
#include "TestMeshes.h"

#include <meshfield/MeshField.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <random>
#include <unistd.h>

namespace sdfwb::meshfield {
namespace {

using glm::dvec3;
namespace fs = std::filesystem;

constexpr float kR = 0.6f;
constexpr float kr = 0.25f;

std::shared_ptr<const MeshField> field(const TriangleMesh& mesh, SignMethod sign = SignMethod::Winding,
                                       Normalization normalize = Normalization::None) {
    MeshFieldOptions options;
    options.sign = sign;
    options.normalize = normalize;
    auto made = makeMeshField(mesh, "torus", options);
    EXPECT_TRUE(made.hasValue()) << (made ? "" : made.error().message);
    return made ? *made : nullptr;
}

std::vector<dvec3> randomPoints(std::size_t count, double extent, unsigned seed) {
    std::mt19937 random(seed);
    std::uniform_real_distribution<double> u(-extent, extent);
    std::vector<dvec3> points(count);
    for (dvec3& p : points) p = dvec3(u(random), u(random), u(random));
    return points;
}

TEST(MeshFieldCpu, TheHierarchyFindsTheNearestTriangleABruteForceScanFinds) {
    const TriangleMesh mesh = testing::torusMesh(kR, kr, 64, 24);
    ASSERT_EQ(mesh.triangleCount(), 3072u);
    auto f = field(mesh);
    ASSERT_TRUE(f);
    EXPECT_EQ(f->boundaryEdges, 0u);
    EXPECT_EQ(f->nonManifoldEdges, 0u);
    EXPECT_GT(f->depth, 5u);
    EXPECT_LE(f->depth, 60u);
    double worst = 0.0;
    auto points = randomPoints(1500, 1.2, 1);
    // and points right at the surface, where the nearest triangle changes fastest
    for (int k = 0; k < 500; ++k) {
        const dvec3 v(mesh.vertices[std::size_t(k * 7) % mesh.vertices.size()]);
        points.push_back(v + dvec3(1e-4 * (k % 3), -2e-4 * (k % 5), 3e-5 * (k % 7)));
    }
    for (const dvec3& p : points) worst = std::max(worst, std::abs(f->distance(p) - testing::bruteDistance(mesh, p)));
    EXPECT_LT(worst, 1e-12) << "the hierarchy's nearest distance differs from the brute-force scan";
}

// The four-wide hierarchy (what the CPU engine and the GPU's nearest walk read): every triangle
// slot in exactly one leaf, each child's box holding its triangles (or its children's boxes), and
// no path from the root longer than wideDepth inner nodes (mesh_field.glsl sizes its stack by it).
TEST(MeshFieldCpu, TheFourWideHierarchyHoldsEveryTriangleOnceInsideItsBoxes) {
    const TriangleMesh torus = testing::torusMesh(kR, kr, 64, 24);
    for (const TriangleMesh& mesh : {torus, testing::damaged(torus, testing::Damage::RemoveFivePercent)}) {
        auto f = makeMeshField(mesh, "torus.obj", {});
        ASSERT_TRUE(f.hasValue());
        const MeshField& field = **f;
        const std::size_t slots = field.triangles.size() / kTriangleFloats;
        std::vector<int> seen(slots, 0);
        auto bits = [](float v) { return std::bit_cast<std::uint32_t>(v); };
        std::size_t deepest = 0;
        // (node, depth), and the box the node's children must lie in.
        struct Visit {
            std::uint32_t node;
            std::size_t depth;
            float lo[3], hi[3];
        };
        const float inf = std::numeric_limits<float>::infinity();
        std::vector<Visit> stack = {{0, 1, {-inf, -inf, -inf}, {inf, inf, inf}}};
        while (!stack.empty()) {
            const Visit v = stack.back();
            stack.pop_back();
            deepest = std::max(deepest, v.depth);
            const float* n = field.wideNodes.data() + std::size_t(v.node) * kWideNodeFloats;
            for (int k = 0; k < 4; ++k) {
                const std::uint32_t child = bits(n[24 + k]), count = bits(n[28 + k]);
                const float lo[3] = {n[k], n[4 + k], n[8 + k]}, hi[3] = {n[12 + k], n[16 + k], n[20 + k]};
                if (count == 0 && child == 0) { // an empty slot: an empty box
                    EXPECT_GT(lo[0], hi[0]);
                    continue;
                }
                for (int a = 0; a < 3; ++a) {
                    EXPECT_GE(lo[a], v.lo[a]);
                    EXPECT_LE(hi[a], v.hi[a]);
                }
                if (count == 0) {
                    stack.push_back({child, v.depth + 1, {lo[0], lo[1], lo[2]}, {hi[0], hi[1], hi[2]}});
                    continue;
                }
                EXPECT_LE(count, kMaxLeafTriangles);
                for (std::uint32_t s = child; s < child + count && s < slots; ++s) {
                    ++seen[s];
                    for (int corner = 0; corner < 3; ++corner)
                        for (int a = 0; a < 3; ++a) {
                            const float x = field.triangles[s * kTriangleFloats + std::size_t(corner * 4 + a)];
                            EXPECT_TRUE(x >= lo[a] && x <= hi[a]) << "slot " << s;
                        }
                }
            }
        }
        EXPECT_EQ(std::count(seen.begin(), seen.end(), 1), std::ptrdiff_t(slots));
        EXPECT_EQ(deepest, field.wideDepth);
        EXPECT_LE(field.wideDepth, field.depth / 2 + 1); // two binary levels a step
    }
}

TEST(MeshFieldCpu, HierarchicalWindingNumbersMatchTheExactSum) {
    const TriangleMesh mesh = testing::torusMesh(kR, kr, 64, 24);
    auto f = field(mesh);
    ASSERT_TRUE(f);
    double worst = 0.0;
    int inside = 0;
    for (const dvec3& p : randomPoints(2000, 1.2, 2)) {
        const double exact = f->windingExact(p);
        const double fast = f->winding(p);
        worst = std::max(worst, std::abs(exact - fast));
        if (testing::torusDistance(p, kR, kr) < -0.01) {
            ++inside;
            EXPECT_NEAR(exact, 1.0, 1e-9);
        } else if (testing::torusDistance(p, kR, kr) > 0.01) {
            EXPECT_NEAR(exact, 0.0, 1e-9);
        }
    }
    EXPECT_GT(inside, 50);
    // Beta 2, second order (Barill et al.): 0.032 at worst here (first order alone: 0.068, with the
    // tight cluster radii the hierarchy now has); only points whose winding number is within that of
    // 1/2 (the ambiguous band of open meshes) can change sign.
    EXPECT_LT(worst, 0.05);
    std::printf("winding numbers: hierarchical vs exact, largest difference %.2e over 2000 points\n", worst);
}

TEST(MeshFieldCpu, EverySignMethodIsRightOnAClosedMesh) {
    const TriangleMesh mesh = testing::torusMesh(kR, kr, 64, 24);
    for (SignMethod sign : {SignMethod::Winding, SignMethod::Parity, SignMethod::Pseudonormal}) {
        auto f = field(mesh, sign);
        ASSERT_TRUE(f);
        int wrong = 0;
        int counted = 0;
        for (const dvec3& p : randomPoints(3000, 1.1, 3)) {
            const double exact = testing::torusDistance(p, kR, kr);
            if (std::abs(exact) < 0.01) continue; // within the polygon's chord error of the smooth torus
            ++counted;
            if (f->inside(p) != (exact < 0.0)) ++wrong;
        }
        EXPECT_GT(counted, 2500);
        EXPECT_EQ(wrong, 0) << signName(sign);
    }
}

TEST(MeshFieldCpu, WindingNumbersKeepTheSignOfBrokenMeshes) {
    const TriangleMesh closed = testing::torusMesh(kR, kr, 64, 24);
    auto reference = field(closed, SignMethod::Pseudonormal);
    ASSERT_TRUE(reference);
    const dvec3 extent = reference->bounds.hi - reference->bounds.lo;
    const double diagonal = glm::length(extent);
    std::vector<dvec3> points;
    std::vector<char> truth;
    for (const dvec3& p : randomPoints(6000, 1.1, 4)) {
        if (reference->distance(p) < 0.01 * diagonal) continue;
        points.push_back(p);
        truth.push_back(reference->inside(p));
    }
    ASSERT_GT(points.size(), 4000u);
    for (testing::Damage damage : {testing::Damage::RemoveOnePercent, testing::Damage::RemoveFivePercent,
                                   testing::Damage::FlipTenPercent, testing::Damage::DuplicateShell}) {
        const TriangleMesh broken = testing::damaged(closed, damage);
        for (SignMethod sign : {SignMethod::Winding, SignMethod::Parity, SignMethod::Pseudonormal}) {
            auto f = field(broken, sign);
            ASSERT_TRUE(f);
            std::size_t agree = 0;
            for (std::size_t i = 0; i < points.size(); ++i) agree += f->inside(points[i]) == bool(truth[i]);
            const double share = double(agree) / double(points.size());
            std::printf("%-22s %-12s agrees with the closed mesh at %6.2f %% of %zu points\n", testing::damageName(damage),
                        signName(sign), 100.0 * share, points.size());
            if (sign == SignMethod::Winding) EXPECT_GE(share, 0.995) << testing::damageName(damage);
        }
    }
}

TEST(MeshFieldCpu, NormalisationsScaleIntoTheStatedShapeAndRecordTheTransform) {
    TriangleMesh mesh = testing::torusMesh(kR, kr, 32, 12);
    for (glm::vec3& v : mesh.vertices) v = v * 3.0f + glm::vec3(5.0f, -2.0f, 1.0f);
    auto cube = field(mesh, SignMethod::Winding, Normalization::UnitCube);
    ASSERT_TRUE(cube);
    const dvec3 e = cube->bounds.hi - cube->bounds.lo;
    EXPECT_NEAR(std::max({e.x, e.y, e.z}), 2.0, 1e-5);
    EXPECT_NEAR(cube->bounds.lo.x + cube->bounds.hi.x, 0.0, 1e-5);
    EXPECT_NEAR(cube->bounds.lo.z + cube->bounds.hi.z, 0.0, 1e-5);
    EXPECT_NEAR(cube->originalBounds.lo.x, 5.0 - 3.0 * (kR + kr), 1e-4);
    // The transform takes a file vertex to its field vertex.
    const auto& m = cube->transform;
    const glm::vec3 v = mesh.vertices[17];
    const dvec3 mapped(m[0] * v.x + m[4] * v.y + m[8] * v.z + m[12], m[1] * v.x + m[5] * v.y + m[9] * v.z + m[13],
                       m[2] * v.x + m[6] * v.y + m[10] * v.z + m[14]);
    EXPECT_LT(glm::length(mapped - dvec3(cube->mesh.vertices[17])), 1e-5);

    auto sphere = field(mesh, SignMethod::Winding, Normalization::UnitSphere);
    ASSERT_TRUE(sphere);
    double farthest = 0.0;
    for (const glm::vec3& w : sphere->mesh.vertices) farthest = std::max(farthest, glm::length(dvec3(w)));
    EXPECT_NEAR(farthest, 1.0, 1e-5);
    auto none = field(mesh);
    EXPECT_EQ(none->transform[0], 1.0);
    EXPECT_EQ(none->transform[12], 0.0);
    EXPECT_EQ(none->mesh.vertices[3], mesh.vertices[3]);
}

TEST(MeshFieldCpu, FilesAreReadThroughAssimpAndCached) {
    const fs::path folder = fs::temp_directory_path() / ("sdfwb_meshfield_" + std::to_string(::getpid()));
    fs::create_directories(folder);
    const TriangleMesh mesh = testing::torusMesh(kR, kr, 16, 8);
    testing::writeObj(folder / "torus.obj", mesh);
    {
        std::ofstream off(folder / "torus.off");
        off << "OFF\n" << mesh.vertices.size() << ' ' << mesh.triangleCount() << " 0\n";
        for (const glm::vec3& v : mesh.vertices) off << v.x << ' ' << v.y << ' ' << v.z << '\n';
        for (std::size_t t = 0; t < mesh.indices.size(); t += 3)
            off << "3 " << mesh.indices[t] << ' ' << mesh.indices[t + 1] << ' ' << mesh.indices[t + 2] << '\n';
    }
    for (const char* name : {"torus.obj", "torus.off"}) {
        EXPECT_TRUE(isMeshPath(folder / name));
        auto loaded = loadMeshField(folder / name, {});
        ASSERT_TRUE(loaded.hasValue()) << loaded.error().message;
        EXPECT_EQ((*loaded)->mesh.triangleCount(), mesh.triangleCount()) << name;
        EXPECT_EQ((*loaded)->boundaryEdges, 0u) << name;
        auto again = loadMeshField(folder / name, {});
        ASSERT_TRUE(again.hasValue());
        EXPECT_EQ(again->get(), loaded->get()) << "the same file and options give the cached field";
        MeshFieldOptions parity;
        parity.sign = SignMethod::Parity;
        auto other = loadMeshField(folder / name, parity);
        ASSERT_TRUE(other.hasValue());
        EXPECT_NE(other->get(), loaded->get());
    }
    EXPECT_FALSE(isMeshPath("shape.glsl"));
    EXPECT_TRUE(isMeshPath("SHAPE.STL"));
    auto missing = loadMeshField(folder / "missing.obj", {});
    ASSERT_FALSE(missing.hasValue());
    EXPECT_NE(missing.error().message.find("missing.obj"), std::string::npos) << missing.error().message;
    {
        std::ofstream bad(folder / "bad.obj");
        bad << "this is not a mesh\n";
    }
    auto bad = loadMeshField(folder / "bad.obj", {});
    ASSERT_FALSE(bad.hasValue());
    EXPECT_NE(bad.error().message.find("bad.obj"), std::string::npos) << bad.error().message;
    fs::remove_all(folder);
}

TEST(MeshFieldCpu, BadMeshesAreRefusedByName) {
    TriangleMesh empty;
    auto e = makeMeshField(empty, "empty.obj", {});
    ASSERT_FALSE(e.hasValue());
    EXPECT_NE(e.error().message.find("empty.obj"), std::string::npos);
    TriangleMesh outOfRange{{glm::vec3(0.0f), glm::vec3(1.0f, 0.0f, 0.0f), glm::vec3(0.0f, 1.0f, 0.0f)}, {0, 1, 5}};
    auto r = makeMeshField(outOfRange, "range.obj", {});
    ASSERT_FALSE(r.hasValue());
    EXPECT_NE(r.error().message.find("vertex 5"), std::string::npos) << r.error().message;
    TriangleMesh nan{{glm::vec3(0.0f), glm::vec3(std::nanf(""), 0.0f, 0.0f), glm::vec3(0.0f, 1.0f, 0.0f)}, {0, 1, 2}};
    EXPECT_FALSE(makeMeshField(nan, "nan.obj", {}).hasValue());
    // One triangle and a degenerate one (all corners in a line) still answer finite distances.
    TriangleMesh sliver{{glm::vec3(0.0f), glm::vec3(1.0f, 0.0f, 0.0f), glm::vec3(2.0f, 0.0f, 0.0f), glm::vec3(0.0f, 1.0f, 0.0f)},
                        {0, 1, 2, 0, 1, 3}};
    auto s = makeMeshField(sliver, "sliver.obj", {});
    ASSERT_TRUE(s.hasValue());
    EXPECT_NEAR((*s)->distance(dvec3(1.5, -1.0, 0.0)), 1.0, 1e-12);
    EXPECT_NEAR((*s)->distance(dvec3(0.25, 0.25, 2.0)), 2.0, 1e-12);
    EXPECT_FALSE(parseSign("inside").hasValue());
    EXPECT_FALSE(parseNormalization("unit").hasValue());
    EXPECT_EQ(*parseNormalization("unit-sphere"), Normalization::UnitSphere);
}

// Two parallel sheets, each a fine grid of triangles, far apart: the hierarchy must cut between
// them (the binned split once priced every cut across empty bins at infinity, so it cut only
// along the sheets and 1 % of a subdivided bunny's leaves spanned front and back), and its
// clusters' radii must not grow with depth (a 1.1 M-triangle bunny's root ball had radius 3.8
// around a shape of half-diagonal 1.6), or winding walks open nearly every node.
TEST(MeshFieldCpu, TheHierarchySeparatesDistantSheetsAndKeepsItsBallsTight) {
    TriangleMesh mesh;
    constexpr int kGrid = 48;
    for (int sheet = 0; sheet < 2; ++sheet) {
        const auto base = std::uint32_t(mesh.vertices.size());
        for (int j = 0; j <= kGrid; ++j)
            for (int i = 0; i <= kGrid; ++i)
                mesh.vertices.emplace_back(-0.5f + float(i) / kGrid, -0.5f + float(j) / kGrid, sheet ? 0.6f : -0.6f);
        for (int j = 0; j < kGrid; ++j)
            for (int i = 0; i < kGrid; ++i) {
                const std::uint32_t a = base + std::uint32_t(j * (kGrid + 1) + i), b = a + 1, c = a + kGrid + 1, d = c + 1;
                mesh.indices.insert(mesh.indices.end(), {a, b, d, a, d, c});
            }
    }
    auto f = field(mesh);
    ASSERT_TRUE(f);
    const std::size_t nodes = f->nodes.size() / kNodeFloats;
    std::size_t leaves = 0;
    double widest = 0.0;
    for (std::size_t i = 0; i < nodes; ++i) {
        const float* n = f->nodes.data() + i * kNodeFloats;
        std::uint32_t count = 0;
        std::memcpy(&count, &n[7], sizeof count);
        if (count == 0) continue;
        ++leaves;
        widest = std::max(widest, double(n[6] - n[2])); // a leaf's extent across the sheets
    }
    EXPECT_GT(leaves, std::size_t(1000));
    EXPECT_LT(widest, 1e-6) << "a leaf holds triangles of both sheets";
    // The root's ball: at most the box's half-diagonal from the area-weighted centre (the origin).
    const double halfDiagonal = std::sqrt(0.5 * 0.5 * 2 + 0.6 * 0.6);
    EXPECT_LE(double(f->nodes[11]), halfDiagonal * 1.0001);
    std::printf("two sheets: %zu leaves, widest across the sheets %.2g, root radius %.4f (half-diagonal %.4f)\n", leaves, widest,
                double(f->nodes[11]), halfDiagonal);
}

// PLY is read by our own reader: assimp 5.2 skipped every whitespace byte after a binary PLY's
// header, so a file whose first data byte was 0x0a (here: the first vertex's x, 1.0000012f, whose
// lowest byte is 0x0a) was read out of step and crashed its post-processing (one mesh in ~40 from
// sdfwb.mesh or meshio). ASCII and big-endian files, polygons (fans), extra properties and any
// scalar types are read; broken files are refused by name, never crashed on.
TEST(MeshFieldCpu, PlyFilesAreReadWhateverTheirFirstDataByte) {
    const fs::path folder = fs::temp_directory_path() / ("sdfwb_ply_" + std::to_string(::getpid()));
    fs::create_directories(folder);
    float first;
    const std::uint32_t bits = 0x3f80000au;
    std::memcpy(&first, &bits, 4);
    const float corners[4][3] = {{first, 0.0f, 0.0f}, {0.0f, 1.0f, 0.0f}, {0.0f, 0.0f, 1.0f}, {0.0f, 0.0f, 0.0f}};
    const int faces[4][3] = {{0, 1, 2}, {0, 3, 1}, {0, 2, 3}, {1, 3, 2}};
    auto binary = [&](const fs::path& path, bool bigEndian) {
        std::ofstream out(path, std::ios::binary);
        out << "ply\nformat " << (bigEndian ? "binary_big_endian" : "binary_little_endian")
            << " 1.0\ncomment a tetrahedron\nelement vertex 4\nproperty float x\nproperty float y\nproperty float z\n"
               "property uchar red\nelement face 4\nproperty list uchar int vertex_indices\nend_header\n";
        auto put = [&](const void* value, int size) {
            char bytes[8];
            std::memcpy(bytes, value, std::size_t(size));
            if (bigEndian) std::reverse(bytes, bytes + size);
            out.write(bytes, size);
        };
        for (const auto& c : corners) {
            for (float v : c) put(&v, 4);
            const unsigned char red = 200;
            put(&red, 1);
        }
        for (const auto& f : faces) {
            const unsigned char three = 3;
            put(&three, 1);
            for (int i : f) put(&i, 4);
        }
    };
    binary(folder / "little.ply", false);
    binary(folder / "big.ply", true);
    {
        std::ofstream ascii(folder / "ascii.ply");
        ascii << "ply\nformat ascii 1.0\nelement vertex 5\nproperty double x\nproperty double y\nproperty double z\n"
                 "property float nx\nelement face 2\nproperty list uchar uint vertex_index\nend_header\n"
                 "0 0 0 1\n1 0 0 1\n1 1 0 1\n0 1 0 1\n0.5 0.5 1 1\n4 0 1 2 3\n3 0 1 4\n";
    }
    for (const char* name : {"little.ply", "big.ply"}) {
        auto mesh = readTriangleMesh(folder / name);
        ASSERT_TRUE(mesh.hasValue()) << name << ": " << mesh.error().message;
        EXPECT_EQ(mesh->triangleCount(), 4u) << name;
        ASSERT_EQ(mesh->vertices.size(), 4u) << name;
        EXPECT_EQ(mesh->vertices[0].x, first) << name;
        EXPECT_EQ(mesh->vertices[2].z, 1.0f) << name;
        EXPECT_EQ(std::vector<std::uint32_t>(mesh->indices.begin(), mesh->indices.begin() + 3),
                  (std::vector<std::uint32_t>{0, 1, 2}))
            << name;
    }
    auto ascii = readTriangleMesh(folder / "ascii.ply");
    ASSERT_TRUE(ascii.hasValue()) << ascii.error().message;
    EXPECT_EQ(ascii->triangleCount(), 3u) << "a quad as two triangles and a triangle";
    EXPECT_EQ(ascii->vertices.size(), 5u);
    EXPECT_EQ(ascii->vertices[4], glm::vec3(0.5f, 0.5f, 1.0f));
    // Broken files: a face naming a missing vertex, data cut short, a header that is not PLY's.
    auto refused = [&](const std::string& name, const std::string& text, const std::string& expected) {
        {
            std::ofstream out(folder / name, std::ios::binary);
            out << text;
        }
        auto mesh = readTriangleMesh(folder / name);
        ASSERT_FALSE(mesh.hasValue()) << name;
        EXPECT_NE(mesh.error().message.find(name), std::string::npos) << mesh.error().message;
        EXPECT_NE(mesh.error().message.find(expected), std::string::npos) << mesh.error().message;
    };
    const std::string head = "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
                             "element face 1\nproperty list uchar int vertex_indices\nend_header\n0 0 0\n1 0 0\n0 1 0\n";
    refused("missing_vertex.ply", head + "3 0 1 7\n", "names vertex 7 of 3");
    refused("short.ply", head + "3 0 1\n", "ends early");
    refused("not_ply.ply", "solid nothing\n", "not a PLY file");
    refused("bad_type.ply", "ply\nformat ascii 1.0\nelement vertex 1\nproperty quaternion x\nend_header\n",
            ":4: unknown property type");
    fs::remove_all(folder);
}

} // namespace
} // namespace sdfwb::meshfield
