// Tracing a mesh: every pixel shaded with its face's normal, and the mesh walk drawing what the sphere
// tracer draws.
#include "MeshSdfTesting.h"

namespace sdfwb::meshsdftest {
namespace {

// The picture's path (the box proxy, normals shading) on a mesh's field, against each pixel's ray
// met with the triangles here in double precision: the shaded normal is the face's. Two llvmpipe
// faults drew wrong pixels here: lines along every edge of the proxy box (its helper lanes spun
// through the walks and spent the invocation's loop budget) and blocks on large flat faces (each
// leaf triangle cost a loop iteration, so long marches ran out of budget).
TEST_F(MeshSdfTest, TheTracerShadesEveryPixelOfAMeshWithItsFacesNormal) {
    const auto mesh = testing::torusMesh(0.6f, 0.3f, 64, 32); // 4096 triangles
    auto field = meshfield::makeMeshField(mesh, "torus.obj", {});
    ASSERT_TRUE(field.hasValue());
    renderer::SdfRenderer sdfRenderer;
    const auto diagnostics = sdfRenderer.setSdf(shaders::prepareMeshSdf(*field, "torus.obj"));
    ASSERT_FALSE(shaders::hasErrors(diagnostics)) << (diagnostics.empty() ? "" : shaders::formatDiagnostic(diagnostics[0]));
    values::Camera camera;
    camera.position = {1.2f, -1.5f, 1.8f}; // the proxy's hidden edges cross the ring
    constexpr int kW = 192, kH = 144;
    renderer::OffscreenRenderer offscreen;
    const renderer::Image image = offscreen.render(sdfRenderer, kW, kH, camera, 0.0f);
    // The compute tracer's walk draws the same pixels (issue 49).
    values::TraceSettings trace;
    trace.tracer = values::TraceSettings::Tracer::Compute;
    ASSERT_FALSE(shaders::hasErrors(sdfRenderer.setTrace(trace)));
    EXPECT_TRUE(sdfRenderer.computeTracer());
    const renderer::Image computed = offscreen.render(sdfRenderer, kW, kH, camera, 0.0f);
    sdfRenderer.releaseGl();
    ASSERT_EQ(image.width, kW);
    ASSERT_EQ(computed.rgba.size(), image.rgba.size());
    std::size_t tracersDiffer = 0;
    for (std::size_t i = 0; i < image.rgba.size(); i += 4)
        tracersDiffer += !std::equal(&image.rgba[i], &image.rgba[i] + 3, &computed.rgba[i]);
    std::printf("torus mesh: %zu of %d pixels differ between the fragment and the compute tracer\n", tracersDiffer, kW * kH);
    EXPECT_LE(tracersDiffer, std::size_t(kW * kH / 1000));
    const dvec3 origin(camera.position);
    std::size_t compared = 0, wrongNormals = 0, misses = 0, worstX = 0, worstY = 0;
    double worst = 0.0;
    for (int y = 0; y < kH; ++y)
        for (int x = 0; x < kW; ++x) {
            const dvec3 d = testing::pixelRay(camera, x, y, kW, kH);
            double nearest = std::numeric_limits<double>::infinity();
            dvec3 normal(0.0);
            for (std::size_t t = 0; t < mesh.indices.size(); t += 3) { // Moller-Trumbore
                const dvec3 a(mesh.vertices[mesh.indices[t]]), b(mesh.vertices[mesh.indices[t + 1]]),
                    c(mesh.vertices[mesh.indices[t + 2]]);
                const dvec3 e1 = b - a, e2 = c - a, h = glm::cross(d, e2);
                const double det = glm::dot(e1, h);
                if (std::abs(det) < 1e-14) continue;
                const dvec3 o = origin - a, q = glm::cross(o, e1);
                const double u = glm::dot(o, h) / det, v = glm::dot(d, q) / det, hit = glm::dot(e2, q) / det;
                if (u < 0.0 || v < 0.0 || u + v > 1.0 || hit <= 0.0 || hit >= nearest) continue;
                nearest = hit;
                normal = glm::normalize(glm::cross(e1, e2));
            }
            // Grazing rays may miss or blend faces at the silhouette: only rays meeting a face at
            // more than ~17 degrees count.
            if (!std::isfinite(nearest) || std::abs(glm::dot(normal, d)) < 0.3) continue;
            ++compared;
            const std::uint8_t* rgba = image.pixel(x, y);
            const dvec3 shaded = dvec3(rgba[0], rgba[1], rgba[2]) / 255.0 * 2.0 - 1.0;
            if (glm::length(shaded) < 0.5) { // the background (0.16 grey) or black
                ++misses;
                continue;
            }
            // Central differences blend neighbouring faces (7.5 degrees apart at most) near edges.
            const double degrees = std::acos(std::clamp(glm::dot(glm::normalize(shaded), normal), -1.0, 1.0)) * 180.0 / M_PI;
            if (degrees > 15.0) ++wrongNormals;
            if (degrees > worst) worst = degrees, worstX = std::size_t(x), worstY = std::size_t(y);
        }
    std::printf("torus mesh, %dx%d: %zu pixels compared, %zu misses, %zu normals over 15 degrees off (worst %.1f at %zu,%zu)\n",
                kW, kH, compared, misses, wrongNormals, worst, worstX, worstY);
    EXPECT_GT(compared, std::size_t(kW * kH / 8));
    EXPECT_EQ(misses, 0u);
    EXPECT_EQ(wrongNormals, 0u);
}

// The picture of a mesh's own field is drawn by one walk of its hierarchy a pixel
// (SDFWB_MESH_RAYCAST, trace_core.glsl) where the sphere tracer evaluates the whole field at every
// step (SDFWB_MESH_TRACE=march draws that): the two pictures agree pixel by pixel, without and
// with the cutting plane shown and clipping the shape, where the walk reads the plane's field from
// the texture the CPU engine fills once per plane and the march evaluates it at every pixel. The
// march debugger's program and the step heat map still march.
TEST_F(MeshSdfTest, TheMeshWalkDrawsWhatTheSphereTracerDraws) {
    const auto mesh = testing::torusMesh(0.6f, 0.3f, 64, 32);
    auto field = meshfield::makeMeshField(mesh, "torus.obj", {});
    ASSERT_TRUE(field.hasValue());
    const shaders::PreparedSdf prepared = shaders::prepareMeshSdf(*field, "torus.obj");
    values::Camera camera;
    camera.position = {1.2f, -1.5f, 1.8f};
    constexpr int kW = 160, kH = 120;
    renderer::OffscreenRenderer offscreen;
    // No plane; the plane with the camera on its cut side (the plane's colours over the whole
    // cross-section); with the camera on the kept side (the shape in front of the plane).
    auto draw = [&](bool walk, int plane, shaders::ShadingMode mode, std::string& fragment) {
        if (walk)
            unsetenv("SDFWB_MESH_TRACE");
        else
            setenv("SDFWB_MESH_TRACE", "march", 1);
        renderer::SdfRenderer sdfRenderer;
        values::ShadingSettings shading;
        shading.mode = mode;
        (void)sdfRenderer.setShading(shading);
        if (plane) {
            values::CuttingPlane cut;
            cut.enabled = true;
            cut.normal = plane == 1 ? glm::vec3(0.3f, -0.2f, 1.0f) : glm::vec3(-0.3f, 0.2f, -1.0f);
            cut.offset = plane == 1 ? 0.05f : -0.05f;
            (void)sdfRenderer.setPlane(cut);
        }
        const auto diagnostics = sdfRenderer.setSdf(prepared);
        EXPECT_FALSE(shaders::hasErrors(diagnostics));
        fragment = sdfRenderer.fragmentSource();
        renderer::Image image = offscreen.render(sdfRenderer, kW, kH, camera, 0.0f);
        sdfRenderer.releaseGl();
        unsetenv("SDFWB_MESH_TRACE");
        return image;
    };
    for (const int plane : {0, 1, 2}) {
        std::string walkSource, marchSource;
        const renderer::Image walked = draw(true, plane, shaders::ShadingMode::Normals, walkSource);
        const renderer::Image marched = draw(false, plane, shaders::ShadingMode::Normals, marchSource);
        EXPECT_NE(walkSource.find("#define SDFWB_MESH_RAYCAST"), std::string::npos);
        EXPECT_EQ(marchSource.find("#define SDFWB_MESH_RAYCAST"), std::string::npos);
        EXPECT_EQ(walkSource.find("#define SDFWB_PLANE_FIELD") != std::string::npos, plane != 0);
        ASSERT_EQ(walked.rgba.size(), marched.rgba.size());
        // The march counts a ray passing within its hit tolerance (half a pixel's footprint) of
        // the surface as a hit: its silhouettes are up to a pixel wider. A pixel only one picture
        // shows the shape in must lie next to one both show it in; where both do, the colours agree.
        auto background = [](const std::uint8_t* rgba) {
            return std::abs(rgba[0] - 41) <= 1 && std::abs(rgba[1] - 43) <= 1 && std::abs(rgba[2] - 48) <= 1;
        };
        auto bothShow = [&](int x, int y) {
            return x >= 0 && y >= 0 && x < kW && y < kH && !background(walked.pixel(x, y)) && !background(marched.pixel(x, y));
        };
        auto colourDistance = [](const std::uint8_t* a, const std::uint8_t* b) {
            int worst = 0;
            for (int c = 0; c < 3; ++c) worst = std::max(worst, std::abs(int(a[c]) - int(b[c])));
            return worst;
        };
        std::size_t differ = 0, shape = 0, rim = 0, strayHits = 0;
        for (int y = 0; y < kH; ++y)
            for (int x = 0; x < kW; ++x) {
                const std::uint8_t *a = walked.pixel(x, y), *b = marched.pixel(x, y);
                if (!background(a)) ++shape;
                if (background(a) != background(b)) {
                    ++rim;
                    if (!(bothShow(x - 1, y) || bothShow(x + 1, y) || bothShow(x, y - 1) || bothShow(x, y + 1))) ++strayHits;
                    continue;
                }
                if (colourDistance(a, b) <= 40) continue;
                // Against the plane the march's wider silhouette covers plane pixels.
                bool edge = false;
                for (const auto& [dx, dy] : {std::pair{-1, 0}, std::pair{1, 0}, std::pair{0, -1}, std::pair{0, 1}})
                    if (x + dx >= 0 && y + dy >= 0 && x + dx < kW && y + dy < kH)
                        edge = edge || colourDistance(a, walked.pixel(x + dx, y + dy)) > 40;
                ++(edge ? rim : differ);
            }
        std::printf("torus mesh%s, %dx%d: %zu pixels show the shape; %zu on a silhouette differ (%zu show the shape in "
                    "one picture only and lie beside no pixel where both do); %zu others differ by more than 40 of 255\n",
                    plane == 0   ? ""
                    : plane == 1 ? ", the plane in front"
                                 : ", the plane behind",
                    kW, kH, shape, rim, strayHits, differ);
        EXPECT_EQ(strayHits, 0u);
        EXPECT_LT(rim, shape / 20);
        EXPECT_GT(shape, std::size_t(kW * kH / 10));
        EXPECT_LT(differ, std::size_t(kW * kH / 200)); // edges between faces, where the march's taps blend them
    }
    std::string heatMap;
    (void)draw(true, 0, shaders::ShadingMode::Steps, heatMap);
    EXPECT_EQ(heatMap.find("#define SDFWB_MESH_RAYCAST"), std::string::npos);
}

} // namespace
} // namespace sdfwb::meshsdftest
