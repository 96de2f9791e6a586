// The error of a mesh against the exact field, on meshes whose error is known exactly: an inscribed
// icosphere's sag, an offset icosphere, an exact box, concentric spheres and an offset slab, very
// large triangles, and the edge measures that find and grade creases.
#include "MeshTesting.h"

using namespace sdfwb;
using namespace sdfwb::meshtest;

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

TEST_F(MeshTest, TheErrorOfAnInscribedIcosphereIsItsSag) {
    // Vertices on the sphere, flat faces inside it: a point p of a face is 0.6 - |p| from the
    // sphere, most at the foot of the perpendicular from the centre (the face's circumcentre, inside
    // each of these acute faces), 0.6 - (the plane's distance from the centre): the sag.
    const shaders::PreparedSdf sphere = source(kSphere);
    const meshing::Mesh mesh = icosphere(3, 0.6);
    ASSERT_EQ(mesh.triangleCount(), 1280u);
    ASSERT_TRUE(closedAndOutward(mesh));
    // The sag, and the mean and deviation of 0.6 - |p| over the faces by area (each face split
    // into kSplit^2 triangles, |p| at their centroids).
    double sag = 0.0, area = 0.0, integral = 0.0, squares = 0.0;
    constexpr int kSplit = 64;
    for (std::size_t t = 0; t < mesh.triangleCount(); ++t) {
        const glm::dvec3 a = corner(mesh, t, 0), b = corner(mesh, t, 1), c = corner(mesh, t, 2);
        const glm::dvec3 normal = glm::normalize(glm::cross(b - a, c - a));
        const glm::dvec3 foot = glm::dot(normal, a) * normal;
        for (const auto& [p, q, r] : {std::tuple(a, b, c), std::tuple(b, c, a), std::tuple(c, a, b)})
            ASSERT_GE(glm::dot(glm::cross(q - p, foot - p), normal), 0.0) << "face " << t << ": the foot lies outside";
        sag = std::max(sag, 0.6 - glm::dot(normal, a));
        const double faceArea = 0.5 * glm::length(glm::cross(b - a, c - a)), piece = faceArea / (kSplit * kSplit);
        area += faceArea;
        const glm::dvec3 du = (b - a) / double(kSplit), dv = (c - a) / double(kSplit);
        for (int i = 0; i < kSplit; ++i)
            for (int j = 0; i + j < kSplit; ++j) {
                const glm::dvec3 o = a + double(i) * du + double(j) * dv;
                // The triangle (o, o + du, o + dv), and the one beyond its long edge when in the face.
                for (int half = 0; half < (i + j < kSplit - 1 ? 2 : 1); ++half) {
                    const double d = 0.6 - glm::length(o + double(half + 1) * (du + dv) / 3.0);
                    integral += piece * d;
                    squares += piece * d * d;
                }
            }
    }
    const double mean = integral / area, deviation = std::sqrt(squares / area - mean * mean);
    ASSERT_NEAR(sag, 2.717e-3, 1e-6); // 1 - cos of the largest face's angular circumradius, times 0.6

    meshing::ErrorOptions options; // 100000 points each way
    auto error = meshing::measureError(sphere, mesh, options);
    ASSERT_TRUE(error) << error.error().message;
    const double vertices = double(mesh.vertices.size()), points = double(options.meshPoints);
    ASSERT_EQ(error->meshPoints, mesh.vertices.size() + options.meshPoints) << "every vertex, then the points on the faces";
    ASSERT_EQ(error->surfacePoints, options.surfacePoints);
    // Mesh -> surface: never beyond the sag; the points nearest the circumcentres come within
    // 1e-5 of it (measured 6.6e-7). The mean is the faces' mean (the vertices add zeros), within
    // five standard errors of the sampling (7.5e-6; measured 2.2e-6 off).
    EXPECT_LE(error->meshToSurfaceMax, sag + 1e-6);
    EXPECT_GE(error->meshToSurfaceMax, sag - 1e-5);
    EXPECT_NEAR(error->meshToSurfaceMean, mean * points / (vertices + points),
                5.0 * deviation / std::sqrt(points) * points / (vertices + points));
    // Surface -> mesh: the same gap seen from the sphere, plus up to 1e-5 as the surface sampler
    // stops its rays where |f| < 1e-5 (measured: the sag + 6.1e-6; the mean 4.1e-6 above).
    EXPECT_LE(error->surfaceToMeshMax, sag + 1.1e-5);
    EXPECT_GE(error->surfaceToMeshMax, sag - 1e-5);
    EXPECT_NEAR(error->surfaceToMeshMean, mean, 1e-5 + 5.0 * deviation / std::sqrt(points));
    EXPECT_NEAR(error->hausdorff, sag, 1e-5);
}

TEST_F(MeshTest, AnIcosphereOffTheSurfaceIsItsOffsetAway) {
    // Vertices on the sphere of radius 0.62, graded against the one of radius 0.6: the vertices are
    // 0.02 off, the faces' points 0.02 less the sag (here 1.1e-5, every face within 1.1e-5 of the
    // circumscribed sphere).
    const shaders::PreparedSdf sphere = source(kSphere);
    const meshing::Mesh mesh = icosphere(7, 0.62);
    ASSERT_TRUE(closedAndOutward(mesh));
    const double sag = largestSag(mesh, 0.62);
    ASSERT_LT(sag, 1.2e-5);
    meshing::ErrorOptions options;
    auto error = meshing::measureError(sphere, mesh, options);
    ASSERT_TRUE(error) << error.error().message;
    // Mesh -> surface: 0.02 at the vertices (measured 4e-8 off), the mean between 0.02 less the sag
    // and 0.02 (measured 0.02 - 2.7e-6).
    EXPECT_NEAR(error->meshToSurfaceMax, 0.02, 1e-6);
    EXPECT_NEAR(error->meshToSurfaceMean, 0.02, 1e-5);
    EXPECT_GE(error->meshToSurfaceMean, 0.02 - sag - 1e-6);
    EXPECT_LE(error->meshToSurfaceMean, 0.02 + 1e-6);
    // Surface -> mesh: the same, less up to 1e-5 as the surface sampler's points stop where
    // |f| < 1e-5, outside the sphere (measured: the maximum 0.02 - 8.6e-7, the mean 0.02 - 1.27e-5,
    // the mean sag 7.0e-6 plus the points' mean 5.7e-6 outside).
    EXPECT_GE(error->surfaceToMeshMax, 0.02 - sag - 1e-5);
    EXPECT_LE(error->surfaceToMeshMax, 0.02 + 1e-6);
    EXPECT_GE(error->surfaceToMeshMean, 0.02 - sag - 1e-5);
    EXPECT_LE(error->surfaceToMeshMean, 0.02 + 1e-6);
    EXPECT_NEAR(error->hausdorff, 0.02, 1e-6);
}

TEST_F(MeshTest, AnExactBoxMeshHasNoError) {
    // A cube's 12 triangles under an irrational rotation, against that rotated cube's exact field.
    const meshing::Mesh mesh = boxMesh(kTilt, glm::dvec3(0.5));
    ASSERT_EQ(mesh.triangleCount(), 12u);
    ASSERT_TRUE(closedAndOutward(mesh));
    EXPECT_NEAR(signedVolume(mesh), 1.0, 1e-6);
    meshing::ErrorOptions options;
    auto error = meshing::measureError(source(rotatedBoxSource(kTilt, glm::dvec3(0.5))), mesh, options);
    ASSERT_TRUE(error) << error.error().message;
    // Float rounding on the faces (measured 1.2e-7 at most); from the surface, the sampler's
    // tolerance (points stop where |f| < 1e-5) and float rounding (measured 1.0034e-5, mean 5.7e-6).
    EXPECT_LT(error->meshToSurfaceMax, 1e-6);
    EXPECT_LT(error->meshToSurfaceMean, 1e-7);
    EXPECT_LT(error->surfaceToMeshMax, 1.1e-5);
    EXPECT_LT(error->surfaceToMeshMean, 1e-5);
    EXPECT_LT(error->hausdorff, 1.1e-5);
    // The same mesh against the unrotated cube is far off (measured 0.178).
    auto unrotated = meshing::measureError(source(kBox), mesh, options);
    ASSERT_TRUE(unrotated) << unrotated.error().message;
    EXPECT_GT(unrotated->hausdorff, 0.1f);
}

namespace {

// Two squares covering [-2, 2]^2 at z = -height and z = +height, facing away from each other (wider
// than the bounds, as the surface sampler's points may lie a little beyond them).
meshing::Mesh slabMesh(float height) {
    meshing::Mesh mesh;
    for (float z : {-height, height})
        for (int c = 0; c < 4; ++c) mesh.vertices.push_back({(c == 1 || c == 2) ? 2.0f : -2.0f, c >= 2 ? 2.0f : -2.0f, z});
    mesh.indices = {0, 2, 1, 0, 3, 2, 4, 5, 6, 4, 6, 7};
    return mesh;
}

// The cube of half-size 0.5 with its four edges along z cut off by 45-degree faces `c` wide along x
// and y: an octagonal prism, counter-clockwise seen from outside.
meshing::Mesh chamferedPrism(float c) {
    const float h = 0.5f;
    const glm::vec2 octagon[8] = {{h - c, -h}, {h, -h + c}, {h, h - c},   {h - c, h},
                                  {-h + c, h}, {-h, h - c}, {-h, -h + c}, {-h + c, -h}};
    meshing::Mesh mesh;
    for (float z : {-h, h})
        for (const glm::vec2& p : octagon) mesh.vertices.push_back({p.x, p.y, z});
    for (std::uint32_t k = 1; k + 1 < 8; ++k) {
        mesh.indices.insert(mesh.indices.end(), {8, 8 + k, 8 + k + 1}); // top, seen from +z
        mesh.indices.insert(mesh.indices.end(), {0, k + 1, k});         // bottom, seen from -z
    }
    for (std::uint32_t k = 0; k < 8; ++k) {
        const std::uint32_t next = (k + 1) % 8;
        mesh.indices.insert(mesh.indices.end(), {k, next, 8 + next, k, 8 + next, 8 + k});
    }
    return mesh;
}

} // namespace

// The grader's nearest-triangle search keeps triangles far larger than the rest (a projection
// across a thin wall, a broken mesh's spike) out of its k-d tree, where their size would widen
// every search to the whole mesh, and measures them at every query. The concentric spheres below
// plus one huge triangle in the plane z = 0.6, touching the graded sphere's top: surface points
// near the top are nearer to it than to the ball (completeness below 0.02 there), and no point is
// farther from the mesh than from the ball alone.
TEST_F(MeshTest, TheEvaluationMeasuresTrianglesFarLargerThanTheRest) {
    meshing::Mesh mesh = icosphere(7, 0.62);
    const auto first = std::uint32_t(mesh.vertices.size());
    for (const glm::vec3& v : {glm::vec3(-2.0f, -2.0f, 0.6f), glm::vec3(2.0f, -2.0f, 0.6f), glm::vec3(0.0f, 2.5f, 0.6f)})
        mesh.vertices.push_back(v);
    mesh.indices.insert(mesh.indices.end(), {first, first + 1, first + 2});
    meshing::EvalOptions options;
    options.occupancyResolution = 0;
    auto e = meshing::evaluateMesh(source(kSphere), mesh, options);
    ASSERT_TRUE(e) << e.error().message;
    EXPECT_LE(e->completenessMax, 0.02 + 1e-6) << "a surface point's nearest triangle was missed";
    EXPECT_LT(e->completenessMean, 0.02 - 1e-4) << "the huge triangle is measured";
    EXPECT_NEAR(e->completenessMax, 0.02, 1.2e-5) << "the sphere's bottom is 0.02 from the ball";
}

// Issue 33, point 2: evaluateMesh against answers known exactly, at the 1e-5 level.
// Concentric spheres: an icosphere with its vertices on the sphere of radius 0.62 (every face within
// its sag, 1.2e-5, of that sphere) graded against the sphere of radius 0.6. An offset slab: two
// squares at z = +-0.32 graded against |z| - 0.3, where every distance both ways is exactly 0.02.
TEST_F(MeshTest, TheEvaluationOfConcentricSpheresAndAnOffsetSlabIsExact) {
    const meshing::Mesh ball = icosphere(7, 0.62);
    const double sag = largestSag(ball, 0.62);
    ASSERT_LT(sag, 1.2e-5);
    meshing::EvalOptions options; // 100000 points each way, tau 0.01
    auto spheres = meshing::evaluateMesh(source(kSphere), ball, options);
    ASSERT_TRUE(spheres) << spheres.error().message;
    // Mesh points: 0.02 less up to the sag. Surface points: the same, less up to 1e-5 where the
    // surface sampler stops its rays (|f| < 1e-5), plus float rounding.
    EXPECT_LE(spheres->accuracyMax, 0.02 + 1e-6);
    EXPECT_GE(spheres->accuracyMean, 0.02 - sag - 1e-6);
    EXPECT_LE(spheres->accuracyMean, 0.02 + 1e-6);
    EXPECT_GE(spheres->completenessMean, 0.02 - sag - 1e-5);
    EXPECT_LE(spheres->completenessMax, 0.02 + 1e-6);
    EXPECT_NEAR(spheres->chamferL1, 0.02, 1.2e-5);
    EXPECT_NEAR(spheres->chamferL2, 0.0004, 2 * 0.02 * 1.2e-5);
    EXPECT_NEAR(spheres->hausdorff, 0.02, 1.2e-5);
    EXPECT_GT(spheres->normalConsistency, 1.0f - 1e-5f) << "concentric spheres have parallel normals";
    EXPECT_EQ(spheres->fscore, 0.0f) << "every distance is over tau = 0.01";
    EXPECT_FALSE(spheres->edges) << "a sphere has no crease";
    // IoU: the grid centres inside radius 0.6 against those inside the mesh, the ball of radius 0.62
    // less its sag; a centre in that sliver could go either way.
    const int n = options.occupancyResolution;
    std::uint64_t field = 0, meshInside = 0, either = 0;
    for (int k = 0; k < n; ++k)
        for (int j = 0; j < n; ++j)
            for (int i = 0; i < n; ++i) {
                const double r = glm::length(-1.0 + (glm::dvec3(i, j, k) + 0.5) * (2.0 / n));
                field += r < 0.6;
                meshInside += r < 0.62 - sag;
                either += r >= 0.62 - sag && r < 0.62;
            }
    ASSERT_TRUE(spheres->iou);
    EXPECT_GE(*spheres->iou, double(field) / double(meshInside + either) - 1e-6);
    EXPECT_LE(*spheres->iou, double(field) / double(meshInside) + 1e-6);

    auto slab = meshing::evaluateMesh(source("float sdf(vec3 p) { return abs(p.z) - 0.3; }"), slabMesh(0.32f), options);
    ASSERT_TRUE(slab) << slab.error().message;
    EXPECT_NEAR(slab->accuracyMean, 0.02, 1e-6);
    EXPECT_NEAR(slab->accuracyMax, 0.02, 1e-6);
    EXPECT_NEAR(slab->completenessMean, 0.02, 1e-5);
    EXPECT_NEAR(slab->completenessMax, 0.02, 1e-5);
    EXPECT_NEAR(slab->chamferL1, 0.02, 1e-5);
    EXPECT_NEAR(slab->chamferL2, 0.0004, 4e-7);
    EXPECT_NEAR(slab->hausdorff, 0.02, 1e-5);
    EXPECT_GT(slab->normalConsistency, 1.0f - 1e-6f);
    EXPECT_EQ(slab->fscore, 0.0f);
    EXPECT_FALSE(slab->edges);
    EXPECT_FALSE(slab->closed);
    // Inside the field: centres with |z| < 0.3; inside the squares by ray parity: |z| < 0.32.
    std::uint64_t slabField = 0, slabMeshInside = 0;
    for (int k = 0; k < n; ++k) {
        const double z = std::abs(-1.0 + (k + 0.5) * (2.0 / n));
        slabField += z < 0.3;
        slabMeshInside += z < 0.32;
    }
    ASSERT_TRUE(slab->iou);
    EXPECT_NEAR(*slab->iou, double(slabField) / double(slabMeshInside), 1e-6);
    options.tau = 0.0201f;
    auto loose = meshing::evaluateMesh(source("float sdf(vec3 p) { return abs(p.z) - 0.3; }"), slabMesh(0.32f), options);
    ASSERT_TRUE(loose);
    EXPECT_EQ(loose->fscore, 1.0f) << "every distance is under tau = 0.0201";
}

// Issue 33, point 2: the edge measures. A point is near a crease when the field's normal turns by
// over 30 degrees between it and one of 8 points 0.02 away around it. On a cube of side 1 that is
// a point within 0.02 cos(a) of an edge, where a (at most 22.5 degrees) is the angle between the
// edge's normal in the face and the nearest of the 8 directions: between 1 - (1 - 0.04 cos 22.5)^2
// = 7.26 % and 1 - 0.96^2 = 7.84 % of each face. The cube's own mesh, rotated off the grid, scores
// perfectly there. A prism whose four edges along z are cut by 45-degree faces 0.05 wide misses
// them: the surface's points on those edges are 0.05 / sqrt 2 from the cut, and the measures near
// creases are far worse than over the whole surface, where the creases' share is small.
TEST_F(MeshTest, TheEdgeMeasuresFindTheCreasesAndGradeThem) {
    meshing::EvalOptions options;
    options.tau = 0.001f;
    const shaders::PreparedSdf box = source(rotatedBoxSource(kTilt, glm::dvec3(0.5)));
    auto exact = meshing::evaluateMesh(box, boxMesh(kTilt, glm::dvec3(0.5)), options);
    ASSERT_TRUE(exact) << exact.error().message;
    ASSERT_TRUE(exact->edges);
    const double share = double(exact->edges->surfacePoints) / double(exact->surfacePoints);
    const double noise = 5.0 * std::sqrt(0.075 * 0.925 / double(exact->surfacePoints));
    EXPECT_GE(share, 1.0 - std::pow(1.0 - 0.04 * std::cos(3.14159265 / 8.0), 2.0) - noise);
    EXPECT_LE(share, 1.0 - 0.96 * 0.96 + noise);
    const double meshShare = double(exact->edges->meshPoints) / double(exact->meshPoints);
    EXPECT_NEAR(meshShare, share, 2.0 * noise) << "the mesh is the surface";
    EXPECT_EQ(exact->edges->fscore, 1.0f);
    EXPECT_LT(exact->edges->hausdorff, 1.1e-5f);
    EXPECT_LT(exact->edges->chamferL1, 1e-5f);

    const float c = 0.05f;
    const shaders::PreparedSdf cube = source(kBox);
    options.tau = 0.01f;
    auto cut = meshing::evaluateMesh(cube, chamferedPrism(c), options);
    ASSERT_TRUE(cut) << cut.error().message;
    ASSERT_TRUE(cut->edges);
    // The farthest surface points are those on the cut edges, 0.05 / sqrt 2 = 0.03536 from the cut.
    EXPECT_NEAR(cut->edges->hausdorff, c / std::sqrt(2.0f), 2e-4f);
    EXPECT_NEAR(cut->hausdorff, c / std::sqrt(2.0f), 2e-4f);
    // The 4 cut edges of 12 lose every point within 0.02 of them (their distance is at least
    // (0.05 - 0.02) / sqrt 2 = 0.021 > tau): a third of the surface's crease points.
    EXPECT_GT(cut->fscore, 0.9f) << "over the whole surface the cuts are a small share";
    EXPECT_LT(cut->edges->recall, 0.7f);
    EXPECT_GT(cut->edges->recall, 0.55f);
    EXPECT_LT(cut->edges->fscore, 0.75f);
    EXPECT_GT(cut->edges->chamferL1, 5.0f * cut->chamferL1);

    meshing::EvalOptions none = options;
    none.edgeRadius = 0.0f;
    auto without = meshing::evaluateMesh(cube, chamferedPrism(c), none);
    ASSERT_TRUE(without);
    EXPECT_FALSE(without->edges) << "edge radius 0 turns the measure off";
    none.edgeAngleDegrees = 180.0f;
    EXPECT_FALSE(meshing::evaluateMesh(cube, chamferedPrism(c), none));
}
