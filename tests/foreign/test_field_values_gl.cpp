// A whole shader's field where mainImage hands the march what the field reads (parameters after
// the point, globals it sets first) or where the distance is not the first thing the field returns:
// the field's value and gradient at points, through the samplers' points program.

#include <renderer/SampleCompute.h>
#include <sampling/Sampler.h>
#include <shaders/BuiltinShaders.h>
#include <shaders/SdfSource.h>

#include "ForeignTest.h"
#include "GlTestContext.h"

#include <glm/glm.hpp>
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>

#include <unistd.h>

using namespace sdfwb;
using sdfwb::testing::firstError;
using sdfwb::testing::kFolder;
using sdfwb::testing::prepare;
namespace fs = std::filesystem;

namespace {

class FieldParameters : public sdfwb::testing::GlTest {};

// The field's value at one point at `time`, through the samplers' points program; `slope` receives
// its gradient (six taps).
float fieldValueAt(const shaders::PreparedSdf& sdf, glm::vec3 p, float time, glm::vec3* slope = nullptr) {
    renderer::SampleCompute compute;
    EXPECT_FALSE(shaders::hasErrors(compute.build(sdf, *shaders::builtinPiece("analysis/points.glsl"))));
    sampling::SamplingJob job;
    job.count = 1;
    job.time = time;
    job.inputPoints = &p.x;
    // The parameters' defaults, as the commands resolve them (a host's inputs have no initializer).
    if (auto resolved = shaders::resolveParameters(sdf.parameters, {})) job.sdfParameters = resolved->settings;
    float position[3], distance = 0.0f, gradient[3];
    EXPECT_TRUE(sampling::sampleInto(compute, job, position, &distance, gradient, {}).hasValue());
    compute.releaseGl();
    if (slope) *slope = {gradient[0], gradient[1], gradient[2]};
    return distance;
}

// `text` opened as a user's file named `name` (in a folder of this process's own, removed after).
shaders::PreparedSdf prepareText(const std::string& name, const std::string& text) {
    const fs::path folder = fs::temp_directory_path() / ("sdfwb-field-values-" + std::to_string(::getpid()));
    fs::create_directories(folder);
    std::ofstream(folder / name) << text;
    shaders::PreparedSdf sdf = prepare(folder / name);
    fs::remove_all(folder);
    return sdf;
}

} // namespace

TEST_F(FieldParameters, ThoseMainImageComputesReachTheField) {
    shaders::PreparedSdf breathing = prepare(kFolder / "62_st_breathing_box_parameters.glsl");
    ASSERT_TRUE(breathing.ok()) << firstError(breathing);
    EXPECT_EQ(breathing.signature.arguments, ", grow, offset");
    EXPECT_NE(breathing.entryReason.find("with grow, offset as mainImage computes it"), std::string::npos)
        << breathing.entryReason;
    shaders::PreparedSdf plate = prepare(kFolder / "61_st_tilted_plate_parameter.glsl");
    ASSERT_TRUE(plate.ok()) << firstError(plate);
    EXPECT_EQ(plate.signature.arguments, ", tilt");
    auto valueAt = [](const shaders::PreparedSdf& sdf, glm::vec3 p, float time) { return fieldValueAt(sdf, p, time); };
    const float y1 = 0.1f + 0.15f * std::sin(1.7f);
    EXPECT_NEAR(valueAt(breathing, {0.6f, y1, 0.0f}, 1.0f), -0.2f, 1e-4f);
    EXPECT_NEAR(valueAt(breathing, {0.6f, y1, 0.0f}, 0.0f), 0.15f * std::sin(1.7f) - 0.2f, 1e-4f);
    EXPECT_NEAR(valueAt(plate, {0.0f, 0.47f, 0.0f}, 0.0f), -0.15f, 1e-4f);

    // A march whose parameter is computed inside the marching function cannot be traced: the file
    // then does not open, and the error says what to do.
    shaders::PreparedSdf inner = prepareText(
        "inner.glsl", "float field(vec3 p, vec2 r) { return length(p) - r.x; }\n"
                      "float march(vec3 ro, vec3 rd) {\n"
                      "    float t = 0.0;\n"
                      "    for (int i = 0; i < 64; i++) { vec2 r = vec2(0.5, float(i)); t += field(ro + rd * t, r); }\n"
                      "    return t;\n"
                      "}\n"
                      "void mainImage(out vec4 c, in vec2 u) { c = vec4(march(vec3(0.0, 0.0, -3.0), vec3(0.0, 0.0, 1.0))); }\n");
    EXPECT_FALSE(inner.ok());
    EXPECT_NE(firstError(inner).find("'r' is computed inside march"), std::string::npos) << firstError(inner);
}

// File-scope variables mainImage sets before the march (a radius from iTime, a rotation, a centre
// it adds to): the wrapper runs those statements first, once per invocation. The ball is centred at
// (0.6, 0, 0) after `p.xz *= spin` with radius 0.5 + 0.1 sin(t); without them radius, spin and ball
// would read 0 (0.6 at that centre), and run at every call the centre would move at every tap of the
// gradient. A glow the field only adds to and a tint set after the march are not the field's, and
// mainImage's `vec2 p` does not clash with the wrapper's point.
TEST_F(FieldParameters, GlobalsMainImageSetsBeforeTheMarchReachTheField) {
    shaders::PreparedSdf sdf = prepareText(
        "globals.glsl", "float radius;\nmat2 spin;\nvec3 tint;\nvec3 ball = vec3(0.3, 0.0, 0.0);\nfloat glow;\n"
                        "float map(vec3 p) { p.xz *= spin; glow += 0.01; return length(p - ball) - radius + 0.0 * tint.x; }\n"
                        "float march(vec3 ro, vec3 rd) {\n"
                        "    float t = 0.0;\n"
                        "    for (int i = 0; i < 100; i++) { float d = map(ro + rd * t); if (d < 0.001) break; t += d; }\n"
                        "    return t;\n"
                        "}\n"
                        "void setRadius() { radius = 0.5 + 0.1 * sin(iTime); }\n"
                        "void mainImage(out vec4 fragColor, in vec2 fragCoord) {\n"
                        "    vec2 p = (2.0 * fragCoord - iResolution.xy) / iResolution.y;\n"
                        "    p.x *= iResolution.x / iResolution.x;\n"
                        "    glow = 0.0;\n"
                        "    setRadius();\n"
                        "    ball.x += 0.3;\n"
                        "    float a = iTime * 0.3;\n"
                        "    spin = mat2(cos(a), sin(a), -sin(a), cos(a));\n"
                        "    float t = march(vec3(0.0, 0.0, -3.0), normalize(vec3(p, 1.5)));\n"
                        "    tint = vec3(t);\n"
                        "    fragColor = vec4(tint + glow, 1.0);\n"
                        "}\n");
    ASSERT_TRUE(sdf.ok()) << firstError(sdf);
    EXPECT_EQ(sdf.signature.entry, "map");
    EXPECT_NE(sdf.entryReason.find("after mainImage sets ball, radius, spin"), std::string::npos) << sdf.entryReason;
    EXPECT_EQ(sdf.entryReason.find("glow"), std::string::npos) << sdf.entryReason;
    EXPECT_TRUE(sdf.diagnostics.empty()) << "no value the field reads comes from the pixel: "
                                         << shaders::formatDiagnostic(sdf.diagnostics.front());
    EXPECT_NEAR(fieldValueAt(sdf, {0.6f, 0.0f, 0.0f}, 0.0f), -0.5f, 1e-5f);
    glm::vec3 slope(0.0f);
    EXPECT_NEAR(fieldValueAt(sdf, {1.2f, 0.0f, 0.0f}, 0.0f, &slope), 0.1f, 1e-5f);
    EXPECT_NEAR(slope.x, 1.0f, 1e-2f) << "the centre stays put between the gradient's taps";
    EXPECT_NEAR(glm::length(slope), 1.0f, 1e-2f);
    const float a = 0.3f, radius = 0.5f + 0.1f * std::sin(1.0f);
    const float moved = std::hypot(0.6f * std::cos(a) - 0.6f, 0.6f * std::sin(a)) - radius;
    EXPECT_NEAR(fieldValueAt(sdf, {0.6f, 0.0f, 0.0f}, 1.0f), moved, 1e-5f);
}

// mainImage's statements before the march inside a preprocessor option's `#else` (Otavio Good's
// iceberg: `#ifdef NON_REALTIME_HQ_RENDER ... #else localTime = iGlobalTime; RayTrace(...)
// #endif`): the prelude ends inside the `#else`, and the wrapper closes it. The branch taken is the
// `#else`'s, as in the shader: the radius is 0.5, not the option's 0.25.
TEST_F(FieldParameters, APreludeEndingInsideAnOptionsElseRunsThatBranch) {
    shaders::PreparedSdf sdf =
        prepareText("option.glsl", "float radius;\n"
                                   "float map(vec3 p) { return length(p) - radius; }\n"
                                   "vec3 render(vec2 uv) {\n"
                                   "    float t = 0.0;\n"
                                   "    for (int i = 0; i < 100; i++) { float d = map(vec3(uv, -3.0) + vec3(0, 0, 1) * t); "
                                   "if (d < 0.001) break; t += d; }\n"
                                   "    return vec3(t);\n"
                                   "}\n"
                                   "void mainImage(out vec4 fragColor, in vec2 fragCoord) {\n"
                                   "#ifdef HIGH_QUALITY\n"
                                   "    radius = 0.25;\n"
                                   "    vec3 c = render(fragCoord / iResolution.xy);\n"
                                   "#else\n"
                                   "    radius = 0.5;\n"
                                   "    vec3 c = render(fragCoord / iResolution.xy);\n"
                                   "#endif\n"
                                   "    fragColor = vec4(c, 1.0);\n"
                                   "}\n");
    ASSERT_TRUE(sdf.ok()) << firstError(sdf);
    EXPECT_EQ(sdf.signature.entry, "map");
    EXPECT_NE(sdf.entryReason.find("after mainImage sets radius"), std::string::npos) << sdf.entryReason;
    EXPECT_NEAR(fieldValueAt(sdf, {0.0f, 0.0f, 0.0f}, 0.0f), -0.5f, 1e-5f);
}

// dr2's scenes: mainImage sets dstFar, then ShowScene sets the tower's radius before it marches the
// solid and then the glass, and draws the nearer. Both globals are set first (mainImage's
// statements, then ShowScene's in a block), and the field is the union of the two marches'.
TEST_F(FieldParameters, TwoPrimaryMarchesAreUnitedAfterMainImageAndTheSceneSetTheirGlobals) {
    shaders::PreparedSdf sdf = prepareText(
        "scene.glsl",
        "float dstFar, twRad;\n"
        "float ObjDf(vec3 p) { return min(dstFar, length(p) - twRad); }\n"
        "float TransObjDf(vec3 p) { return min(dstFar, length(p - vec3(1.0, 0.0, 0.0)) - 0.25); }\n"
        "float ObjRay(vec3 ro, vec3 rd) {\n"
        "    float t = 0.0;\n"
        "    for (int j = 0; j < 120; j++) { float d = ObjDf(ro + t * rd); t += d; if (d < 0.001 || t > dstFar) break; }\n"
        "    return t;\n"
        "}\n"
        "float TransObjRay(vec3 ro, vec3 rd) {\n"
        "    float t = 0.0;\n"
        "    for (int j = 0; j < 120; j++) { float d = TransObjDf(ro + t * rd); t += d; if (d < 0.001 || t > dstFar) break; }\n"
        "    return t;\n"
        "}\n"
        "vec3 ShowScene(vec3 ro, vec3 rd) {\n"
        "    twRad = 0.5;\n"
        "    float dstObj = ObjRay(ro, rd);\n"
        "    float dstTrans = TransObjRay(ro, rd);\n"
        "    return vec3(min(dstObj, dstTrans) / dstFar);\n"
        "}\n"
        "void mainImage(out vec4 fragColor, in vec2 fragCoord) {\n"
        "    vec2 uv = (2.0 * fragCoord - iResolution.xy) / iResolution.y;\n"
        "    dstFar = 100.0;\n"
        "    fragColor = vec4(ShowScene(vec3(0.0, 0.0, -5.0), normalize(vec3(uv, 2.0))), 1.0);\n"
        "}\n");
    ASSERT_TRUE(sdf.ok()) << firstError(sdf);
    EXPECT_EQ(sdf.signature.entry, "ObjDf");
    EXPECT_NE(sdf.entryReason.find("the union of ObjDf"), std::string::npos) << sdf.entryReason;
    EXPECT_NE(sdf.entryReason.find("after mainImage and ShowScene set dstFar, twRad"), std::string::npos) << sdf.entryReason;
    EXPECT_NEAR(fieldValueAt(sdf, {0.0f, 0.0f, 0.0f}, 0.0f), -0.5f, 1e-5f);
    EXPECT_NEAR(fieldValueAt(sdf, {1.0f, 0.0f, 0.0f}, 0.0f), -0.25f, 1e-5f);
    EXPECT_NEAR(fieldValueAt(sdf, {3.0f, 0.0f, 0.0f}, 0.0f), 1.75f, 1e-5f);
}

// A field with a parameter after the point, and a centre mainImage moves (`ball.x += 0.3;`) before
// it calls the march: mainImage's statements run once per invocation on this path too, so the
// centre stays put between the gradient's taps. The ball, centred at (0.6, 0, 0) with radius
// 0.4 + 0.1 k.x and k.x = 1, reads -0.5 at its centre and has a unit gradient along x beside it; run at
// every call, the centre would move 0.3 at every tap.
TEST_F(FieldParameters, MainImagesStatementsRunOnceWhenTheFieldHasParameters) {
    shaders::PreparedSdf sdf =
        prepareText("once.glsl", "vec3 ball = vec3(0.3, 0.0, 0.0);\n"
                                 "float field(vec3 p, vec2 k) { return length(p - ball) - 0.4 - 0.1 * k.x; }\n"
                                 "float march(vec3 ro, vec3 rd, vec2 k) {\n"
                                 "    float t = 0.0;\n"
                                 "    for (int i = 0; i < 100; i++) {\n"
                                 "        float d = field(ro + rd * t, k);\n"
                                 "        if (d < 0.001) break;\n"
                                 "        t += d;\n"
                                 "    }\n"
                                 "    return t;\n"
                                 "}\n"
                                 "void mainImage(out vec4 fragColor, in vec2 fragCoord) {\n"
                                 "    vec2 p = (2.0 * fragCoord - iResolution.xy) / iResolution.y;\n"
                                 "    ball.x += 0.3;\n"
                                 "    vec2 k = vec2(1.0 + 0.0 * iTime, 0.0);\n"
                                 "    fragColor = vec4(march(vec3(0.0, 0.0, -3.0), normalize(vec3(p, 1.5)), k));\n"
                                 "}\n");
    ASSERT_TRUE(sdf.ok()) << firstError(sdf);
    EXPECT_EQ(sdf.signature.arguments, ", k");
    EXPECT_NEAR(fieldValueAt(sdf, {0.6f, 0.0f, 0.0f}, 0.0f), -0.5f, 1e-5f);
    glm::vec3 slope(0.0f);
    EXPECT_NEAR(fieldValueAt(sdf, {1.2f, 0.0f, 0.0f}, 0.0f, &slope), 0.1f, 1e-5f);
    EXPECT_NEAR(slope.x, 1.0f, 1e-2f) << "the centre stays put between the gradient's taps";
}

// A vector field whose distance is not its x: `vec4 sdScene(vec3 p)` returning (colour, distance),
// its march stepping by `.w` (a public atom shader's form), and a vec2 (material, distance) read
// into a float first. The field is the component the march steps by, not the colour's red.
TEST_F(FieldParameters, AVectorsDistanceIsTheComponentTheMarchStepsBy) {
    auto shader = [](const std::string& name, const std::string& field, const std::string& loop) {
        return prepareText(name, field +
                                     "float march(vec3 ro, vec3 rd) {\n    float t = 0.0;\n"
                                     "    for (int i = 0; i < 100; i++) {\n" +
                                     loop +
                                     "    }\n    return t;\n}\nvoid mainImage(out vec4 c, in vec2 u) {\n"
                                     "    c = vec4(march(vec3(0.0, 0.0, -3.0), vec3(0.0, 0.0, 1.0)));\n}\n");
    };
    const shaders::PreparedSdf colour =
        shader("colour.glsl", "vec4 sdScene(vec3 p) { return vec4(0.9, 0.2, 0.1, length(p) - 0.5); }\n",
               "        vec4 ds = sdScene(ro + rd * t);\n        if (ds.w < 0.001) break;\n        t += ds.w;\n");
    const shaders::PreparedSdf material =
        shader("material.glsl", "vec2 scene(vec3 p) { return vec2(3.0, length(p) - 0.25); }\n",
               "        vec2 h = scene(ro + rd * t);\n        float d = h.y;\n        if (d < 0.001) break;\n        t += d;\n");
    const shaders::PreparedSdf first =
        shader("first.glsl", "vec2 scene(vec3 p) { return vec2(length(p) - 0.25, 3.0); }\n",
               "        vec2 h = scene(ro + rd * t);\n        if (h.y > 2.0 && h.x < 0.001) break;\n        t += h.x;\n");
    ASSERT_TRUE(colour.ok()) << firstError(colour);
    ASSERT_TRUE(material.ok()) << firstError(material);
    ASSERT_TRUE(first.ok()) << firstError(first);
    EXPECT_EQ(colour.signature.member, "w");
    EXPECT_EQ(material.signature.member, "y");
    EXPECT_EQ(first.signature.member, "") << "a step by .x keeps the x, whatever else the loop reads";
    EXPECT_NEAR(fieldValueAt(colour, {0.0f, 0.0f, 0.0f}, 0.0f), -0.5f, 1e-5f);
    EXPECT_NEAR(fieldValueAt(colour, {1.0f, 0.0f, 0.0f}, 0.0f), 0.5f, 1e-5f);
    EXPECT_NEAR(fieldValueAt(material, {1.0f, 0.0f, 0.0f}, 0.0f), 0.75f, 1e-5f);
    EXPECT_NEAR(fieldValueAt(first, {1.0f, 0.0f, 0.0f}, 0.0f), 0.75f, 1e-5f);
}

// One loop stepping by two functions together (`dist = min(torusSDF(p, ...), planeSDF(p, ...));
// t += dist;`, a public torus-over-a-floor shader's form) in a function mainImage calls with the
// torus's size and the floor's height, under the same names as its own locals: the field is the
// loop's step (their union), not one of them, and the parameters are what mainImage passes. With
// zeros for them the ring's tube would read 0, not -0.2.
TEST_F(FieldParameters, FunctionsOneLoopStepsByTogetherAreTheField) {
    const shaders::PreparedSdf sdf = prepareText(
        "union.glsl", "float torusSDF(vec3 p, vec2 t, float angle) {\n"
                      "    p.xz = mat2(cos(angle), -sin(angle), sin(angle), cos(angle)) * p.xz;\n"
                      "    vec2 q = vec2(length(p.xz) - t.x, p.y);\n    return length(q) - t.y;\n}\n"
                      "float planeSDF(vec3 p, float height) { return p.y - height; }\n"
                      "float raymarch(vec3 ro, vec3 rd, vec2 torusParams, float planeHeight, float angle) {\n"
                      "    float t = 0.0;\n"
                      "    for (int i = 0; i < 100; ++i) {\n"
                      "        vec3 p = ro + rd * t;\n"
                      "        float distTorus = torusSDF(p, torusParams, angle);\n"
                      "        float distPlane = planeSDF(p, planeHeight);\n"
                      "        float dist = min(distTorus, distPlane);\n"
                      "        if (dist < 0.001) return t;\n"
                      "        t += dist;\n"
                      "        if (t > 20.0) break;\n"
                      "    }\n    return -1.0;\n}\n"
                      "void mainImage(out vec4 fragColor, in vec2 fragCoord) {\n"
                      "    vec2 uv = (fragCoord - 0.5 * iResolution.xy) / iResolution.y;\n"
                      "    float angle = iTime * 0.5;\n"
                      "    vec2 torusParams = vec2(0.6, 0.2);\n"
                      "    float planeHeight = -0.5;\n"
                      "    float t = raymarch(vec3(0.0, 0.0, 3.0), normalize(vec3(uv, -1.0)), torusParams, planeHeight, angle);\n"
                      "    fragColor = vec4(vec3(t > 0.0 ? 1.0 : 0.0), 1.0);\n}\n");
    ASSERT_TRUE(sdf.ok()) << firstError(sdf);
    EXPECT_EQ(sdf.signature.entry, "raymarch");
    EXPECT_FALSE(sdf.signature.inlineBody.empty());
    EXPECT_TRUE(sdf.entryCandidates.empty());
    EXPECT_NE(sdf.entryReason.find("it steps by torusSDF and planeSDF together"), std::string::npos) << sdf.entryReason;
    EXPECT_NE(sdf.entryReason.find("with ro, rd, torusParams, planeHeight, angle as mainImage computes it"), std::string::npos)
        << sdf.entryReason;
    EXPECT_NEAR(fieldValueAt(sdf, {0.6f, 0.0f, 0.0f}, 0.0f), -0.2f, 1e-5f) << "inside the tube";
    EXPECT_NEAR(fieldValueAt(sdf, {0.0f, -0.7f, 0.0f}, 0.0f), -0.2f, 1e-5f) << "under the floor";
    EXPECT_NEAR(fieldValueAt(sdf, {0.0f, 0.5f, 0.0f}, 0.0f), std::sqrt(0.36f + 0.25f) - 0.2f, 1e-5f) << "above the ring";

    // A loop whose text the wrapper cannot run (a public shader reflecting its rays off the box: the
    // point moves by `ro = ro + rd * min(dbox, dsphere)` in one branch of an if): the function of a
    // point that calls both, which its normals are taken from, is their union.
    const shaders::PreparedSdf reflecting = prepareText(
        "reflect.glsl", "float sphere(vec3 p) { return length(p - vec3(0.0, 0.4, 0.0)) - 0.3; }\n"
                        "float box(vec3 p) { vec3 q = abs(p + vec3(0.0, 0.5, 0.0)) - vec3(0.4); "
                        "return length(max(q, 0.0)) + min(max(q.x, max(q.y, q.z)), 0.0); }\n"
                        "float df(vec3 p) { float d1 = sphere(p); float d2 = box(p); return min(d1, d2); }\n"
                        "vec3 calNormal(vec3 p) { vec2 e = vec2(1e-4, 0.0); return normalize(vec3(df(p + e.xyy) - df(p - "
                        "e.xyy), df(p + e.yxy) - df(p - e.yxy), df(p + e.yyx) - df(p - e.yyx))); }\n"
                        "void mainImage(out vec4 fragColor, in vec2 fragCoord) {\n"
                        "    vec3 ro = vec3(0.0, 0.0, 3.0), rd = normalize(vec3(fragCoord / iResolution.xy - 0.5, -1.0));\n"
                        "    vec3 col = vec3(0.3);\n    int refNum = 0;\n"
                        "    for (int i = 0; i < 128; i++) {\n"
                        "        float dbox = refNum == 0 ? box(ro) : 2000.0;\n"
                        "        float dsphere = sphere(ro);\n"
                        "        if (abs(dbox) < 1e-4) { rd = reflect(rd, calNormal(ro)); refNum = 1; continue; }\n"
                        "        if (abs(dsphere) < 1e-4) { col = calNormal(ro); break; }\n"
                        "        if (refNum == 0) { ro = ro + rd * min(dbox, dsphere); } else { ro = ro + rd * dsphere; }\n"
                        "    }\n    fragColor = vec4(col, 1.0);\n}\n");
    ASSERT_TRUE(reflecting.ok()) << firstError(reflecting);
    EXPECT_EQ(reflecting.signature.entry, "df");
    EXPECT_NE(reflecting.entryReason.find("df (it calls box and sphere, which the march at line"), std::string::npos)
        << reflecting.entryReason;
    EXPECT_NEAR(fieldValueAt(reflecting, {0.0f, 0.4f, 0.0f}, 0.0f), -0.3f, 1e-5f) << "the sphere's centre";
    EXPECT_NEAR(fieldValueAt(reflecting, {0.0f, -0.5f, 0.0f}, 0.0f), -0.4f, 1e-5f) << "the box's centre";
}

// `float map(vec3 p, float s)` has the form of a field of the point and the time, but in a whole
// shader its march says what the float is. Where mainImage marches it itself with a local it sets
// before the loop (`float s = 0.25 + 0.1 * cos(iTime);`), that local, traced: 0.35 at time 0, not
// the time (0). Where the value comes through functions sdfwb cannot trace (IQ's Apollonian hands
// mainImage's `anim` to render, and render to trace), the file does not open: the time would make
// s 0 and the field NaN; the error says how to give a value.
TEST_F(FieldParameters, AFloatAfterThePointIsWhatTheMarchPassesNotTheTime) {
    const std::string field = "float map(vec3 p, float s) { return length(p) - s; }\n";
    const shaders::PreparedSdf own = prepareText(
        "own.glsl", field + "void mainImage(out vec4 fragColor, in vec2 fragCoord) {\n"
                            "    float s = 0.25 + 0.1 * cos(iTime);\n"
                            "    vec3 ro = vec3(0.0, 0.0, 3.0), rd = normalize(vec3(fragCoord / iResolution.y - 0.5, -1.0));\n"
                            "    float t = 0.0;\n"
                            "    for (int i = 0; i < 64; i++) { float d = map(ro + rd * t, s); if (d < 0.001) break; t += d; }\n"
                            "    fragColor = vec4(t);\n}\n");
    ASSERT_TRUE(own.ok()) << firstError(own);
    EXPECT_EQ(own.signature.entry, "map");
    EXPECT_FALSE(own.signature.animated);
    EXPECT_NE(own.entryReason.find("with s as mainImage computes it"), std::string::npos) << own.entryReason;
    EXPECT_NEAR(fieldValueAt(own, {0.0f, 0.0f, 0.0f}, 0.0f), -0.35f, 1e-5f);
    // A point moved by `p = p + rd * d` (no inline field reads it) and a file-scope constant: the
    // constant (a public repeated-boxes shader's `df(rayPos, size)`).
    const shaders::PreparedSdf constant =
        prepareText("constant.glsl", field + "const float size = 0.4;\n"
                                             "void mainImage(out vec4 fragColor, in vec2 fragCoord) {\n"
                                             "    vec3 rayDir = normalize(vec3(fragCoord / iResolution.y - 0.5, -1.0));\n"
                                             "    vec3 rayPos = vec3(0.0, 0.0, 3.0);\n"
                                             "    for (int i = 0; i < 100; i++) {\n"
                                             "        float dist = map(rayPos, size);\n"
                                             "        if (dist < 0.001) break;\n"
                                             "        rayPos = rayPos + rayDir * dist;\n"
                                             "    }\n    fragColor = vec4(rayPos, 1.0);\n}\n");
    ASSERT_TRUE(constant.ok()) << firstError(constant);
    EXPECT_EQ(constant.signature.entry, "map");
    EXPECT_NEAR(fieldValueAt(constant, {0.0f, 0.0f, 0.0f}, 0.0f), -0.4f, 1e-5f);

    // IQ's Apollonian: mainImage computes `anim` once, hands it to render in its anti-aliasing loops,
    // render to trace and trace to map. The wrapper runs mainImage's code up to that call.
    const std::string marcher =
        "float trace(vec3 ro, vec3 rd, float s) {\n"
        "    float t = 0.0;\n"
        "    for (int i = 0; i < 64; i++) { float h = map(ro + rd * t, s); if (h < 0.001) break; t += h; }\n"
        "    return t;\n}\n"
        "vec3 render(vec3 ro, vec3 rd, float anim) { return vec3(trace(ro, rd, anim)); }\n";
    const shaders::PreparedSdf through =
        prepareText("through.glsl", field + marcher +
                                        "#define AA 2\n"
                                        "void mainImage(out vec4 fragColor, in vec2 fragCoord) {\n"
                                        "    float anim = 1.1 + 0.5 * smoothstep(-0.3, 0.3, cos(0.1 * iTime));\n"
                                        "    vec3 tot = vec3(0.0);\n"
                                        "    #if AA>1\n    for (int jj = 0; jj < AA; jj++)\n    for (int ii = 0; ii < AA; ii++)\n"
                                        "    #else\n    int ii = 1, jj = 1;\n    #endif\n"
                                        "    {\n        vec2 q = fragCoord + vec2(float(ii), float(jj)) / float(AA);\n"
                                        "        vec3 rd = normalize(vec3(q / iResolution.y - 0.5, -1.0));\n"
                                        "        tot += render(vec3(0.0, 0.0, 3.0), rd, anim);\n    }\n"
                                        "    fragColor = vec4(tot / float(AA * AA), 1.0);\n}\n");
    ASSERT_TRUE(through.ok()) << firstError(through);
    EXPECT_EQ(through.signature.entry, "map");
    EXPECT_NE(through.entryReason.find("with s as mainImage computes it"), std::string::npos) << through.entryReason;
    EXPECT_NEAR(fieldValueAt(through, {0.0f, 0.0f, 0.0f}, 0.0f), -1.6f, 1e-5f);       // cos(0) = 1: anim = 1.6
    EXPECT_NEAR(fieldValueAt(through, {0.0f, 0.0f, 0.0f}, 15.70796f), -1.35f, 1e-4f); // cos(pi / 2) = 0: 1.35
    // One call further (mainImage -> image -> render -> trace): no value, and the error says what to write.
    const shaders::PreparedSdf deeper =
        prepareText("deeper.glsl", field + marcher +
                                       "vec3 image(vec2 uv, float anim) { return render(vec3(0.0, 0.0, 3.0), normalize(vec3(uv, "
                                       "-1.0)), anim); }\n"
                                       "void mainImage(out vec4 fragColor, in vec2 fragCoord) {\n"
                                       "    float anim = 1.1 + 0.5 * smoothstep(-0.3, 0.3, cos(0.1 * iTime));\n"
                                       "    fragColor = vec4(image(fragCoord / iResolution.y - 0.5, anim), 1.0);\n}\n");
    EXPECT_FALSE(deeper.ok());
    EXPECT_NE(firstError(deeper).find("trace's 's' is anim where render calls it"), std::string::npos) << firstError(deeper);
    EXPECT_NE(firstError(deeper).find("add `float sdf(vec3 p) { return map(p, ...); }`"), std::string::npos)
        << firstError(deeper);
    // The same untraceable march of a field whose float is named as the time: read as the time.
    std::string timed = "float map(vec3 p, float time) { return length(p) - 0.2 - 0.1 * sin(time); }\n" +
                        deeper.source.map.files.front().text.substr(field.size());
    const shaders::PreparedSdf named = prepareText("timed.glsl", timed);
    ASSERT_TRUE(named.ok()) << firstError(named);
    EXPECT_TRUE(named.signature.animated);
    EXPECT_NEAR(fieldValueAt(named, {0.0f, 0.0f, 0.0f}, 1.0f), -0.2f - 0.1f * std::sin(1.0f), 1e-5f);
}

TEST_F(FieldParameters, AStructParameterMainImageDoesNotGiveIsItsMembersZeros) {
    // A heightfield's march in a function whose ray is a struct (a public snow-terrain shader's
    // `float castRay(ray r, float tmin, float tmax)`), called from render, not at mainImage's top:
    // the point is given, the ray's members are zeros (`ray(vec3(0), vec3(0))`, not `ray(0)`).
    const shaders::PreparedSdf terrain = prepareText(
        "terrain.glsl", "struct ray { vec3 origin; vec3 direction; };\n"
                        "float terrainH(vec2 xz) { return 0.25 * sin(xz.x); }\n"
                        "float castRay(ray r, float tmin, float tmax) {\n"
                        "    float t = tmin;\n"
                        "    for (int i = 0; i < 128; i++) {\n"
                        "        vec3 pos = r.origin + r.direction * t;\n"
                        "        float h = pos.y - terrainH(pos.xz);\n"
                        "        if (abs(h) < 0.0015 * t || t > tmax) break;\n"
                        "        t += 0.5 * h;\n"
                        "    }\n    return t;\n}\n"
                        "vec3 render(vec3 ro, vec3 rd) { ray r = ray(ro, rd); return vec3(castRay(r, 0.01, 50.0)); }\n"
                        "void mainImage(out vec4 fragColor, in vec2 fragCoord) {\n"
                        "    vec3 rd = normalize(vec3(fragCoord / iResolution.y - 0.5, -1.0));\n"
                        "    if (fragCoord.x > 1.0) fragColor = vec4(render(vec3(0.0, 1.0, 3.0), rd), 1.0);\n}\n");
    ASSERT_TRUE(terrain.ok()) << firstError(terrain);
    EXPECT_EQ(terrain.signature.entry, "castRay");
    // An inline field is the march's step: half the height above the terrain here.
    EXPECT_NEAR(fieldValueAt(terrain, {1.0f, 0.5f, 0.0f}, 0.0f), 0.5f * (0.5f - 0.25f * std::sin(1.0f)), 1e-5f);
}

TEST_F(FieldParameters, AnOldShadertoysIGlobalTimeIsTheTime) {
    // Shadertoy's time was iGlobalTime until 2017; shaders downloaded then use it undeclared, and
    // ports of then declare it.
    const std::string shader = "float map(vec3 p) { return length(p) - 0.5 - 0.2 * sin(iGlobalTime); }\n"
                               "void mainImage(out vec4 fragColor, in vec2 fragCoord) {\n"
                               "    float t = iGlobalTime * 0.5;\n"
                               "    vec3 ro = vec3(3.0 * sin(t), 0.0, 3.0 * cos(t)), rd = -normalize(ro);\n"
                               "    float d = 0.0;\n"
                               "    for (int i = 0; i < 64; i++) d += map(ro + rd * d);\n"
                               "    fragColor = vec4(d);\n}\n";
    for (const std::string& text : {shader, "uniform float iGlobalTime;\n" + shader}) {
        const shaders::PreparedSdf old = prepareText("old.glsl", text);
        ASSERT_TRUE(old.ok()) << firstError(old);
        EXPECT_EQ(old.host, "an old Shadertoy shader");
        EXPECT_EQ(old.signature.entry, "map");
        EXPECT_NEAR(fieldValueAt(old, {0.0f, 0.0f, 0.0f}, 1.0f), -0.5f - 0.2f * std::sin(1.0f), 1e-5f);
        EXPECT_NEAR(fieldValueAt(old, {0.0f, 0.0f, 0.0f}, 2.0f), -0.5f - 0.2f * std::sin(2.0f), 1e-5f);
    }
}

TEST_F(FieldParameters, AnIsfShadersInputsHaveTheirDefaultsAndTimeIsTheTime) {
    // An ISF generator (VDMX, Resolume): its INPUTS are uniforms the host sets, its DEFAULTs what
    // sdfwb sets when nothing else is given; TIME is the scene time.
    const shaders::PreparedSdf isf = prepareText(
        "ball.fs", "/*{\n  \"ISFVSN\": \"2\",\n  \"INPUTS\": [\n"
                   "    { \"NAME\": \"radius\", \"TYPE\": \"float\", \"DEFAULT\": 0.6, \"MIN\": 0.1, \"MAX\": 1.0 },\n"
                   "    { \"NAME\": \"offset\", \"TYPE\": \"point2D\", \"DEFAULT\": [0.25, 0.0] }\n"
                   "  ]\n}*/\n"
                   "float map(vec3 p) { return length(p - vec3(offset, 0.0)) - radius - 0.1 * sin(TIME); }\n"
                   "void main() {\n"
                   "    vec3 rd = normalize(vec3((2.0 * gl_FragCoord.xy - RENDERSIZE) / RENDERSIZE.y, -1.5));\n"
                   "    float t = 0.0;\n"
                   "    for (int i = 0; i < 64; i++) t += map(vec3(0.0, 0.0, 3.0) + rd * t);\n"
                   "    gl_FragColor = vec4(vec3(t * 0.1), 1.0);\n}\n");
    ASSERT_TRUE(isf.ok()) << firstError(isf);
    EXPECT_EQ(isf.host, "ISF");
    EXPECT_NEAR(fieldValueAt(isf, {0.25f, 0.0f, 0.0f}, 0.0f), -0.6f, 1e-5f);
    EXPECT_NEAR(fieldValueAt(isf, {0.25f, 0.0f, 0.0f}, 1.0f), -0.6f - 0.1f * std::sin(1.0f), 1e-5f);
}

TEST_F(FieldParameters, TheVscodeExtensionsUniformsHaveTheirDefaultsAlsoWhenDeclaredInAFunction) {
    // The VS Code Shader Toy extension: `#iUniform` values are what sdfwb sets when nothing else is
    // given, one declared inside the field too; iGlobalTime is the scene time.
    const shaders::PreparedSdf ball =
        prepareText("ball.glsl", "#iChannel0 \"file://noise.png\"\n"
                                 "#iUniform float radius = 0.6 in { 0.1, 1.0 }\n"
                                 "#iUniform vec2 offset = vec2(0.25, 0.0)\n"
                                 "float map(vec3 p) {\n"
                                 "    #iUniform float wobble = 0.1 in { 0.0, 1.0 } step 0.01\n"
                                 "    return length(p - vec3(offset, 0.0)) - radius - wobble * sin(iGlobalTime);\n"
                                 "}\n"
                                 "void mainImage(out vec4 fragColor, in vec2 fragCoord) {\n"
                                 "    vec3 rd = normalize(vec3((2.0 * fragCoord - iResolution.xy) / iResolution.y, -1.5));\n"
                                 "    float t = 0.0;\n"
                                 "    for (int i = 0; i < 64; i++) t += map(vec3(0.0, 0.0, 3.0) + rd * t);\n"
                                 "    fragColor = vec4(vec3(t * 0.1), 1.0);\n}\n");
    ASSERT_TRUE(ball.ok()) << firstError(ball);
    EXPECT_EQ(ball.host, "the VS Code Shader Toy extension");
    EXPECT_NEAR(fieldValueAt(ball, {0.25f, 0.0f, 0.0f}, 0.0f), -0.6f, 1e-5f);
    EXPECT_NEAR(fieldValueAt(ball, {0.25f, 0.0f, 0.0f}, 1.0f), -0.6f - 0.1f * std::sin(1.0f), 1e-5f);
}

TEST_F(FieldParameters, ASynesthesiaScenesControlsHaveTheirSceneJsonDefaults) {
    // main.glsl in its .synScene folder: the field reads a slider and an xy pad scene.json declares,
    // and Synesthesia's TIME, which is the scene time.
    const fs::path folder = fs::temp_directory_path() / ("sdfwb-synscene-gl-" + std::to_string(::getpid())) / "b.synScene";
    fs::create_directories(folder);
    std::ofstream(folder / "main.glsl")
        << "float ball(vec3 p) { return length(p - vec3(centre, 0.0)) - size - 0.1 * sin(TIME); }\n"
           "vec4 renderMain() {\n"
           "    vec3 rd = normalize(vec3(_uvc, 1.0));\n"
           "    float t = 0.0;\n"
           "    for (int i = 0; i < 64; i++) t += ball(vec3(0.0, 0.0, -3.0) + rd * t);\n"
           "    return vec4(vec3(t * 0.1), 1.0);\n}\n";
    std::ofstream(folder / "scene.json") << "{ \"CONTROLS\": [ { \"NAME\": \"size\", \"TYPE\": \"slider\", \"DEFAULT\": 0.6 },\n"
                                            "  { \"NAME\": \"centre\", \"TYPE\": \"xy\", \"DEFAULT\": [0.25, 0] } ] }\n";
    const shaders::PreparedSdf scene = prepare(folder / "main.glsl");
    fs::remove_all(folder.parent_path());
    ASSERT_TRUE(scene.ok()) << firstError(scene);
    EXPECT_EQ(scene.host, "Synesthesia");
    EXPECT_NEAR(fieldValueAt(scene, {0.25f, 0.0f, 0.0f}, 0.0f), -0.6f, 1e-5f);
    EXPECT_NEAR(fieldValueAt(scene, {0.25f, 0.0f, 0.0f}, 1.0f), -0.6f - 0.1f * std::sin(1.0f), 1e-5f);
}

TEST_F(FieldParameters, AVariableDeclaredWithoutAValueIsZeroAsInWebGl) {
    // Golfed WebGL code (twigl, Shadertoy) counts on zero: `float r, i; vec3 q; r += 0.5;`. Desktop GL
    // leaves such a variable undefined; sdfwb writes WebGL's zero into the declaration.
    const shaders::PreparedSdf golfed =
        prepareText("golfed.glsl", "float sdf(vec3 p) {\n"
                                   "    float r, i; vec3 q; mat2 m;\n"
                                   "    for (float j; j < 2.; j++) for (; i++ < 4.;) r += 0.125;\n"
                                   "    q.x += 0.25 + m[0][0];\n"
                                   "    return length(p - q) - r;\n}\n");
    ASSERT_TRUE(golfed.ok()) << firstError(golfed);
    EXPECT_NEAR(fieldValueAt(golfed, {0.25f, 0.0f, 0.0f}, 0.0f), -0.5f, 1e-6f);
    EXPECT_NEAR(fieldValueAt(golfed, {0.25f, 1.0f, 0.0f}, 0.0f), 0.5f, 1e-6f);
    // An array too, whatever its size is written with: a sum over one starts at zero.
    const shaders::PreparedSdf summed = prepareText("summed.glsl", "#define N 3\n"
                                                                   "float sdf(vec3 p) {\n"
                                                                   "    float r[N]; vec2 o[2];\n"
                                                                   "    for (int j = 0; j < N; j++) r[j] += 0.25;\n"
                                                                   "    o[1].x += 0.5;\n"
                                                                   "    return length(p) - r[0] - r[2] - o[1].x - o[0].y;\n}\n");
    ASSERT_TRUE(summed.ok()) << firstError(summed);
    EXPECT_NEAR(fieldValueAt(summed, {2.0f, 0.0f, 0.0f}, 0.0f), 1.0f, 1e-6f);
}

TEST_F(FieldParameters, FragmentariumWebsRotationTakesRadiansAndItsPrimitivesMeasure) {
    // FragmentariumWeb's rotationMatrix(axis, angle): radians, any axis length, M * (1,0,0) turned to
    // (0,-1,0) by a quarter turn about z (the transpose of the right-handed turn, as its matrix is written).
    const shaders::PreparedSdf web = prepareText(
        "web.frag", "#include \"common-primitives.frag\"\n"
                    "float DE(vec3 p) {\n"
                    "  vec3 q = rotationMatrix(vec3(0.0, 0.0, 2.0), radians(90.0)) * p;\n"
                    "  return min(sdSphere(q - vec3(0.0, -1.0, 0.0), 0.25), sdBox(q - vec3(0.0, 0.0, 5.0), vec3(0.5)));\n"
                    "}\n");
    ASSERT_TRUE(web.ok()) << firstError(web);
    EXPECT_NEAR(fieldValueAt(web, {1.0f, 0.0f, 0.0f}, 0.0f), -0.25f, 1e-5f);
    EXPECT_NEAR(fieldValueAt(web, {-1.0f, 0.0f, 0.0f}, 0.0f), 1.75f, 1e-5f);
    EXPECT_NEAR(fieldValueAt(web, {0.0f, 0.0f, 6.0f}, 0.0f), 0.5f, 1e-5f);
}

TEST_F(FieldParameters, ANameLaterGlslTookKeepsItsValue) {
    // `float smooth` and a function named `sample` (GLSL 1.10 and WebGL 1 code), renamed where compiled.
    const shaders::PreparedSdf old =
        prepareText("old.glsl", "float sample(float smooth) { return smooth * 0.5; }\n"
                                "float sdf(vec3 p) { float shared = sample(1.0); return length(p) - shared; }\n");
    ASSERT_TRUE(old.ok()) << firstError(old);
    EXPECT_NEAR(fieldValueAt(old, {2.0f, 0.0f, 0.0f}, 0.0f), 1.5f, 1e-6f);
}

TEST_F(FieldParameters, GlobalsAFunctionWithoutParametersSetsBeforeItMarchesReachTheField) {
    // Synesthesia's style (mainImage, or renderMain, calls `vec3 render3D()`, which sets the globals
    // the field reads and then marches): that function's statements before its march run first.
    shaders::PreparedSdf sdf = prepareText(
        "render3d.glsl", "float radius;\nmat2 spin;\n"
                         "float map(vec3 p) { p.xz *= spin; return length(p - vec3(0.6, 0.0, 0.0)) - radius; }\n"
                         "float march(vec3 ro, vec3 rd) {\n"
                         "    float t = 0.0;\n"
                         "    for (int i = 0; i < 100; i++) { float d = map(ro + rd * t); if (d < 0.001) break; t += d; }\n"
                         "    return t;\n"
                         "}\n"
                         "vec3 render3D() {\n"
                         "    float T = iTime, a = 0.3 * T;\n"
                         "    vec2 p = (2.0 * gl_FragCoord.xy - iResolution.xy) / iResolution.y;\n"
                         "    radius = 0.5 + 0.1 * sin(T);\n"
                         "    spin = mat2(cos(a), sin(a), -sin(a), cos(a));\n"
                         "    float t = march(vec3(0.0, 0.0, -3.0), normalize(vec3(p, 1.5)));\n"
                         "    return vec3(t * 0.1);\n"
                         "}\n"
                         "void mainImage(out vec4 fragColor, in vec2 fragCoord) {\n"
                         "    if (iResolution.x > 0.0) fragColor = vec4(render3D(), 1.0);\n"
                         "}\n");
    ASSERT_TRUE(sdf.ok()) << firstError(sdf);
    EXPECT_EQ(sdf.signature.entry, "map");
    EXPECT_NE(sdf.entryReason.find("after render3D sets radius, spin"), std::string::npos) << sdf.entryReason;
    EXPECT_NEAR(fieldValueAt(sdf, {0.6f, 0.0f, 0.0f}, 0.0f), -0.5f, 1e-5f);
    const float a = 0.3f, radius = 0.5f + 0.1f * std::sin(1.0f);
    const float moved = std::hypot(0.6f * std::cos(a) - 0.6f, 0.6f * std::sin(a)) - radius;
    EXPECT_NEAR(fieldValueAt(sdf, {0.6f, 0.0f, 0.0f}, 1.0f), moved, 1e-5f);
}

TEST_F(FieldParameters, GlobalsAFunctionWithParametersSetsFromOtherValuesReachTheField) {
    // The magic lamp's style: `vec3 render(vec3 ro, vec3 rd)` sets the rotation the field reads,
    // computes its background from the ray, then marches. The ray is not the field's: its statements
    // run first with the ray zero. A global computed from the ray would be the pixel's, and is not run.
    const std::string common = "mat2 spin;\nvec3 centre;\n"
                               "float map(vec3 p) { p.xz *= spin; return length(p - centre) - 0.5; }\n"
                               "vec3 render(vec3 ro, vec3 rd) {\n"
                               "    float a = 0.3 * iTime;\n"
                               "    spin = mat2(cos(a), sin(a), -sin(a), cos(a));\n"
                               "    vec3 sky = 0.5 + 0.5 * rd;\n"
                               "    vec3 seen = ro * 0.0;\n"
                               "    CENTRE\n"
                               "    for (float t = 0.0; t < 8.0;) { float d = map(ro + rd * t); if (d < 0.001) break; t += d; }\n"
                               "    return sky;\n"
                               "}\n"
                               "void mainImage(out vec4 fragColor, in vec2 fragCoord) {\n"
                               "    vec2 uv = (2.0 * fragCoord - iResolution.xy) / iResolution.y;\n"
                               "    fragColor = vec4(render(vec3(0.0, 0.0, -3.0), normalize(vec3(uv, 1.5))), 1.0);\n"
                               "}\n";
    auto with = [&](const std::string& centre) {
        std::string text = common;
        text.replace(text.find("CENTRE"), 6, centre);
        return prepareText("render.glsl", text);
    };
    const shaders::PreparedSdf fixed = with("centre = vec3(0.6, 0.0, 0.0);");
    ASSERT_TRUE(fixed.ok()) << firstError(fixed);
    EXPECT_EQ(fixed.signature.entry, "map");
    EXPECT_NE(fixed.entryReason.find("after render sets centre, spin"), std::string::npos) << fixed.entryReason;
    EXPECT_NEAR(fieldValueAt(fixed, {0.6f, 0.0f, 0.0f}, 0.0f), -0.5f, 1e-5f);
    const float a = 0.3f, moved = std::hypot(0.6f * std::cos(a) - 0.6f, 0.6f * std::sin(a)) - 0.5f;
    EXPECT_NEAR(fieldValueAt(fixed, {0.6f, 0.0f, 0.0f}, 1.0f), moved, 1e-5f);
    const shaders::PreparedSdf fromRay = with("centre = seen + vec3(0.6, 0.0, 0.0);");
    ASSERT_TRUE(fromRay.ok()) << firstError(fromRay);
    EXPECT_EQ(fromRay.entryReason.find("after render sets"), std::string::npos) << fromRay.entryReason;
}

TEST_F(FieldParameters, AnInlineFieldsPointCopiedInItsOwnDeclarationIsThePointGiven) {
    // Golfed style: `vec3 A = p + q * k, b = A;` sets the point and copies it in one declaration; the
    // field works on the copy. Given a point, the copy is of that point, not of the camera's.
    const shaders::PreparedSdf sdf = prepareText("copied.glsl", "void mainImage(out vec4 G, in vec2 I) {\n"
                                                                "  vec2 J = (I - .5 * iResolution.xy) / iResolution.y;\n"
                                                                "  vec3 p = vec3(0., 0., -3.), q = normalize(vec3(J, 1.));\n"
                                                                "  float k = 0.;\n"
                                                                "  for (int c = 0; c < 64; c++) {\n"
                                                                "    vec3 A = p + q * k, b = A;\n"
                                                                "    b.x -= .25;\n"
                                                                "    float a = length(b) - .5;\n"
                                                                "    if (abs(a) < .0015 || k > 16.) break;\n"
                                                                "    k += a;\n"
                                                                "  }\n"
                                                                "  G = vec4(k * .1);\n"
                                                                "}\n");
    ASSERT_TRUE(sdf.ok()) << firstError(sdf);
    EXPECT_NEAR(fieldValueAt(sdf, {0.25f, 0.0f, 0.0f}, 0.0f), -0.5f, 1e-5f);
    EXPECT_NEAR(fieldValueAt(sdf, {1.25f, 0.0f, 0.0f}, 0.0f), 0.5f, 1e-5f);
}

TEST_F(FieldParameters, AFieldWhosePointIsDeclaredOutReadsThePointGiven) {
    // `float DE(out vec3 p)` passing p on to `fold(out vec3 z)`, both read before written: written on
    // a driver where an out parameter holds the caller's value (GLSL leaves it undefined; llvmpipe
    // read a constant field). Composed inout, every out parameter of the file.
    const shaders::PreparedSdf sdf = prepareText(
        "outpoint.glsl", "float fold(out vec3 z) { z = abs(z); return length(z - vec3(0.5, 0.0, 0.0)) - 0.25; }\n"
                         "float DE(out vec3 p) { p.x += 0.0; return fold(p); }\n"
                         "void mainImage(out vec4 fragColor, in vec2 fragCoord) {\n"
                         "    vec3 rd = normalize(vec3((fragCoord - 0.5 * iResolution.xy) / iResolution.y, 1.5));\n"
                         "    float t = 0.0;\n"
                         "    for (int i = 0; i < 64; i++) { vec3 p = vec3(0.0, 0.0, -3.0) + rd * t; float d = DE(p);\n"
                         "        if (d < 0.001) break; t += d; }\n"
                         "    fragColor = vec4(t * 0.1);\n"
                         "}\n");
    ASSERT_TRUE(sdf.ok()) << firstError(sdf);
    EXPECT_EQ(sdf.signature.entry, "DE");
    EXPECT_TRUE(sdf.signature.pointOut);
    EXPECT_NEAR(fieldValueAt(sdf, {0.5f, 0.0f, 0.0f}, 0.0f), -0.25f, 1e-5f);
    EXPECT_NEAR(fieldValueAt(sdf, {-0.5f, 0.0f, 0.0f}, 0.0f), -0.25f, 1e-5f);
    EXPECT_NEAR(fieldValueAt(sdf, {1.5f, 0.0f, 0.0f}, 0.0f), 0.75f, 1e-5f);
}

TEST_F(FieldParameters, GlobalsMainImageSetsBeforeTheLoopThatHoldsTheCallReachTheField) {
    // dr2's form: mainImage sets the globals, then calls the scene in an antialiasing loop.
    const shaders::PreparedSdf sdf = prepareText(
        "aa.glsl",
        "float dstFar, radius;\n"
        "float ObjDf(vec3 p) { return min(dstFar, length(p) - radius); }\n"
        "vec3 ShowScene(vec3 ro, vec3 rd) {\n"
        "  float t = 0.;\n"
        "  for (int j = 0; j < 64; j ++) { float d = ObjDf(ro + t * rd); if (d < 0.001 || t > dstFar) break; t += d; }\n"
        "  return vec3(t);\n"
        "}\n"
        "void mainImage(out vec4 fragColor, in vec2 fragCoord) {\n"
        "  vec2 uv = 2. * fragCoord / iResolution.xy - 1.;\n"
        "  vec3 col = vec3(0.);\n"
        "  dstFar = 200.;\n"
        "  radius = 0.5 + 0.1 * sin(iTime);\n"
        "  for (float a = 0.; a < 3.; a ++)\n"
        "    col += ShowScene(vec3(0., 0., -3.), normalize(vec3(uv + 0.001 * a, 1.5))) / 3.;\n"
        "  fragColor = vec4(col, 1.);\n"
        "}\n");
    ASSERT_TRUE(sdf.ok()) << firstError(sdf);
    EXPECT_EQ(sdf.signature.entry, "ObjDf");
    EXPECT_NE(sdf.entryReason.find("after mainImage sets dstFar, radius"), std::string::npos) << sdf.entryReason;
    EXPECT_NEAR(fieldValueAt(sdf, {2.0f, 0.0f, 0.0f}, 0.0f), 1.5f, 1e-5f);
    EXPECT_NEAR(fieldValueAt(sdf, {2.0f, 0.0f, 0.0f}, 1.0f), 1.5f - 0.1f * std::sin(1.0f), 1e-5f);
}
