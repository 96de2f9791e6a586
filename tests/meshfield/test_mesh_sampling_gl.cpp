// Sampling a mesh: the marching samplers give the field or a reported bad row, surface and near draw
// points on the mesh by area, the audit flags where an open mesh's sign is a guess, and the plane over
// a mesh is clean along its primitives' edges.
#include "MeshSdfTesting.h"

namespace sdfwb::meshsdftest {
namespace {

TEST_F(MeshSdfTest, MarchingSamplersGiveTheFieldOrAReportedBadRowNeverAWrongValue) {
    // Over text of its own (here the mesh's field written out by hand, so not the generated text),
    // the near sampler marches to the surface, evaluating the field many times in one shader
    // invocation; on llvmpipe the walks can run out of its loop budget. A walk that does returns
    // NaN (a bad row), so every finite row must be the field's value at its position.
    const meshfield::TriangleMesh mesh = testing::torusMesh(0.6f, 0.25f, 48, 16);
    auto field = meshfield::makeMeshField(mesh, "torus.obj", {});
    ASSERT_TRUE(field.hasValue());
    renderer::SampleCompute compute;
    auto sampler = sampling::findSampler("near", {});
    ASSERT_TRUE(sampler.hasValue());
    auto diagnostics =
        compute.build(shaders::prepareMeshSdf(*field, "torus.obj", "float sdf(vec3 p) { return sdfwb_meshSdf(p); }\n"), *sampler);
    ASSERT_FALSE(shaders::hasErrors(diagnostics));
    sampling::SamplingJob job;
    job.count = 2000;
    job.seed = 3;
    std::vector<float> positions(3 * job.count), distances(job.count), gradients(3 * job.count);
    auto report = sampling::sampleInto(compute, job, positions.data(), distances.data(), gradients.data(), {});
    ASSERT_TRUE(report.hasValue()) << report.error().message;
    compute.releaseGl();
    std::uint64_t finite = 0;
    std::uint64_t nan = 0;
    double worst = 0.0;
    for (std::size_t i = 0; i < job.count; ++i) {
        if (!std::isfinite(distances[i]) || !std::isfinite(gradients[3 * i]) || !std::isfinite(gradients[3 * i + 1]) ||
            !std::isfinite(gradients[3 * i + 2])) {
            ++nan;
            continue;
        }
        ++finite;
        const dvec3 p(positions[3 * i], positions[3 * i + 1], positions[3 * i + 2]);
        worst = std::max(worst, std::abs(double(distances[i]) - (*field)->signedDistance(p)));
    }
    EXPECT_EQ(report->badRows, nan) << "every row with a NaN value or gradient is counted as bad";
    EXPECT_GE(finite, job.count / 2) << "most rows are the field's (a test every NaN row would pass proves nothing)";
    EXPECT_LT(worst, 1e-5) << "a finite row differs from the float64 field";
    std::printf("near on a 1536-triangle torus: %llu finite rows within %.2e of the float64 field, %llu rows with a cut walk "
                "(NaN, bad rows)\n",
                (unsigned long long)finite, worst, (unsigned long long)nan);
}

// On a mesh's own field, surface and near draw their points on the triangles (uniform by area)
// instead of marching: no bad rows on llvmpipe, |f| at float precision on the surface, the near
// offsets' standard deviation as asked. Uniform by area shows on a torus: the outer half
// (x^2 + y^2 > R^2) holds 1/2 + r/(pi R) of its area. Text that changes the field (an offset
// shell) keeps the marching samplers: its surface rows lie 0.05 off the mesh.
TEST_F(MeshSdfTest, SurfaceAndNearDrawPointsOnTheMeshItselfByArea) {
    const meshfield::TriangleMesh mesh = testing::torusMesh(0.6f, 0.25f, 96, 32);
    auto field = meshfield::makeMeshField(mesh, "torus.obj", {});
    ASSERT_TRUE(field.hasValue());
    auto sample = [&](const char* pattern, const std::string& text, std::vector<float>& positions,
                      std::vector<float>& distances) {
        renderer::SampleCompute compute;
        auto sampler = sampling::findSampler(pattern, {});
        EXPECT_TRUE(sampler.hasValue());
        auto diagnostics = compute.build(shaders::prepareMeshSdf(*field, "torus.obj", text), *sampler);
        EXPECT_FALSE(shaders::hasErrors(diagnostics));
        sampling::SamplingJob job;
        job.count = 4000;
        job.seed = 5;
        positions.assign(3 * job.count, 0.0f);
        distances.assign(job.count, 0.0f);
        std::vector<float> gradients(3 * job.count);
        auto report = sampling::sampleInto(compute, job, positions.data(), distances.data(), gradients.data(), {});
        compute.releaseGl();
        EXPECT_TRUE(report.hasValue());
        return report.hasValue() ? report->badRows : job.count;
    };
    std::vector<float> positions, distances;
    EXPECT_EQ(sample("surface", "", positions, distances), 0u);
    double worst = 0.0;
    std::size_t outer = 0;
    for (std::size_t i = 0; i < distances.size(); ++i) {
        worst = std::max(worst, double(std::abs(distances[i])));
        const double x = positions[3 * i], y = positions[3 * i + 1];
        outer += x * x + y * y > 0.36 ? 1u : 0u;
    }
    EXPECT_LT(worst, 1e-5) << "surface rows lie on the zero set";
    const double share = double(outer) / double(distances.size()), expected = 0.5 + 0.25 / (3.14159265 * 0.6);
    EXPECT_NEAR(share, expected, 0.025) << "points uniform by area";

    EXPECT_EQ(sample("near", "", positions, distances), 0u);
    double sum = 0.0, squares = 0.0;
    for (float d : distances) {
        sum += d;
        squares += double(d) * d;
    }
    const double mean = sum / double(distances.size()), deviation = std::sqrt(squares / double(distances.size()) - mean * mean);
    EXPECT_NEAR(deviation, 0.005, 0.0004) << "near's default offset: a Gaussian of deviation 0.005";
    EXPECT_NEAR(mean, 0.0, 0.0004);

    const std::uint64_t bad = sample("surface", "float sdf(vec3 p) { return sdfwb_meshSdf(p) - 0.05; }\n", positions, distances);
    std::size_t checked = 0;
    for (std::size_t i = 0; i < distances.size(); ++i) {
        if (!std::isfinite(distances[i])) continue;
        ++checked;
        const dvec3 p(positions[3 * i], positions[3 * i + 1], positions[3 * i + 2]);
        EXPECT_NEAR((*field)->signedDistance(p), 0.05, 1e-3) << "row " << i;
        if (HasFailure()) break;
    }
    EXPECT_GE(checked, distances.size() / 2) << "most rows are on the shell (a cut walk's NaN row is bad, not checked)";
    std::printf("surface over an offset shell: %zu rows on the shell, %llu bad rows (llvmpipe's loop budget)\n", checked,
                (unsigned long long)bad);
}

TEST_F(MeshSdfTest, TheAuditFlagsWhereAnOpenMeshsSignIsAGuess) {
    // A cube of side 1.2 (two triangles a side, counter-clockwise from outside), and the same cube
    // without its top: around the hole the winding number passes through 1/2 away from any surface.
    meshfield::TriangleMesh closed;
    for (int k = 0; k < 8; ++k) closed.vertices.emplace_back(k & 4 ? 0.6f : -0.6f, k & 2 ? 0.6f : -0.6f, k & 1 ? 0.6f : -0.6f);
    const std::uint32_t sides[6][6] = {{0, 1, 3, 0, 3, 2}, {4, 6, 7, 4, 7, 5}, {0, 4, 5, 0, 5, 1},
                                       {2, 3, 7, 2, 7, 6}, {0, 2, 6, 0, 6, 4}, {1, 5, 7, 1, 7, 3}};
    meshfield::TriangleMesh open = closed;
    for (int side = 0; side < 6; ++side) {
        closed.indices.insert(closed.indices.end(), sides[side], sides[side] + 6);
        if (side != 5) open.indices.insert(open.indices.end(), sides[side], sides[side] + 6); // side 5: +z
    }
    ASSERT_LT(open.triangleCount(), closed.triangleCount());
    sampling::AuditOptions options;
    options.samples = 500;
    options.convergence = false;
    const std::array<const meshfield::TriangleMesh*, 2> meshes{&closed, &open};
    for (const meshfield::TriangleMesh* mesh : meshes) {
        auto field = meshfield::makeMeshField(*mesh, mesh == &closed ? "closed.obj" : "open.obj", {});
        ASSERT_TRUE(field.hasValue());
        auto report = sampling::auditField(shaders::prepareMeshSdf(*field, (*field)->name), options, {});
        ASSERT_TRUE(report.hasValue()) << report.error().message;
        const values::AuditFlag* flag = values::findFlag(report->flags, values::Finding::SignUncertain);
        if (mesh == &closed) {
            EXPECT_EQ(flag, nullptr) << report->reason;
            continue;
        }
        ASSERT_NE(flag, nullptr) << report->reason;
        EXPECT_GE(flag->count, 10u);
        EXPECT_NEAR(flag->share, double(flag->count) / 500.0, 1e-12);
        EXPECT_FALSE(flag->examples.empty());
        for (const glm::vec3& p : flag->examples) {
            const double w = (*field)->winding(dvec3(p));
            EXPECT_LT(std::abs(w - 0.5), sampling::kSignUncertainBand) << "an example's winding number is " << w;
        }
        EXPECT_NE(report->reason.find("sign-uncertain"), std::string::npos) << report->reason;
        std::printf("open cube: %s\n", flag->evidence.c_str());
    }
}

// The cutting plane over a mesh's field, seen from above through the proxy: inside the torus's
// section, away from the zero contour, every pixel is the solid inside colour. The plane draws its
// lines with screen-space derivatives, which read the helper lanes that mesh_field.glsl leaves
// unevaluated; when the plane took fwidth of those values, black lines ran along the proxy's edges.
TEST_F(MeshSdfTest, ThePlaneOverAMeshIsCleanAlongThePrimitivesEdges) {
    const auto mesh = testing::torusMesh(0.6f, 0.3f, 64, 32);
    auto field = meshfield::makeMeshField(mesh, "torus.obj", {});
    ASSERT_TRUE(field.hasValue());
    renderer::SdfRenderer sdfRenderer;
    values::CuttingPlane plane;
    plane.enabled = true;
    plane.lipschitzOverlay = false;
    ASSERT_TRUE(sdfRenderer.setPlane(plane).empty());
    const auto diagnostics = sdfRenderer.setSdf(shaders::prepareMeshSdf(*field, "torus.obj"));
    ASSERT_FALSE(shaders::hasErrors(diagnostics)) << (diagnostics.empty() ? "" : shaders::formatDiagnostic(diagnostics[0]));
    values::Camera camera;
    camera.position = {0.3f, -0.4f, 2.6f}; // above the plane z = 0, a little off its axis
    constexpr int kW = 160, kH = 120;
    renderer::OffscreenRenderer offscreen;
    const renderer::Image image = offscreen.render(sdfRenderer, kW, kH, camera, 0.0f);
    sdfRenderer.releaseGl();
    const dvec3 origin(camera.position);
    std::size_t inside = 0, marked = 0;
    for (int y = 0; y < kH; ++y)
        for (int x = 0; x < kW; ++x) {
            const dvec3 d = testing::pixelRay(camera, x, y, kW, kH);
            const dvec3 p = origin + (-origin.z / d.z) * d; // on z = 0
            // Deep inside the section: more than 4 pixels (about 0.03) from its rim.
            if (testing::torusDistance(p, 0.6, 0.3) > -0.06 || testing::bruteDistance(mesh, p) < 0.05) continue;
            ++inside;
            const std::uint8_t* rgba = image.pixel(x, y);
            const int expected[3] = {237, 140, 46}; // vec3(0.93, 0.55, 0.18)
            if (std::abs(rgba[0] - expected[0]) > 3 || std::abs(rgba[1] - expected[1]) > 3 || std::abs(rgba[2] - expected[2]) > 3)
                ++marked;
        }
    std::printf("torus mesh on the plane, %dx%d: %zu pixels inside the section, %zu not the inside colour\n", kW, kH, inside,
                marked);
    EXPECT_GT(inside, std::size_t(1000));
    EXPECT_EQ(marked, 0u);
}

} // namespace
} // namespace sdfwb::meshsdftest
