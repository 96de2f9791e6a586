// The composer: what goes into a shader, and what stays out.

#include <shaders/BuiltinShaders.h>
#include <shaders/GlslChecker.h>
#include <shaders/ShaderComposer.h>
#include <shaders/TracerComposer.h>

#include <gtest/gtest.h>

#include <set>

using namespace sdfwb::shaders;

namespace {

PreparedSdf prepare(const std::string& text) { return prepareSdf(text, "<test>", {}, IncludeOptions{}); }

} // namespace

TEST(Composer, PlainSdfGetsNoCompatPreludeAndNoTime) {
    PreparedSdf sdf = prepare("float sdf(vec3 p) { return length(p) - 0.5; }\n");
    ASSERT_TRUE(sdf.ok());
    auto composed = composeTracer(sdf, TracerFeatures{});
    ASSERT_TRUE(composed.hasValue());
    EXPECT_EQ(composed->text.rfind("#version 430 core\n", 0), 0u);
    EXPECT_EQ(composed->text.find("g3d"), std::string::npos);
    EXPECT_EQ(composed->text.find("#define SDFWB_USES_TIME"), std::string::npos);
    EXPECT_NE(composed->text.find("#define SDFWB_SHADING_NORMALS 1"), std::string::npos);
    EXPECT_FALSE(hasErrors(checkWithGlslang(*composed)));
}

TEST(Composer, G3dFileGetsOnlyWhatItUses) {
    PreparedSdf sdf = prepare("float sdf(Point3 X) { return length(X) - 0.5 * pi; }\n");
    ASSERT_TRUE(sdf.ok());
    auto composed = composeTracer(sdf, TracerFeatures{});
    ASSERT_TRUE(composed.hasValue());
    EXPECT_NE(composed->text.find("#define SDFWB_COMPAT_pi 1"), std::string::npos);
    EXPECT_NE(composed->text.find("#define SDFWB_COMPAT_Point3 1"), std::string::npos);
    EXPECT_EQ(composed->text.find("#define SDFWB_COMPAT_saturate"), std::string::npos);
    auto diagnostics = checkWithGlslang(*composed);
    EXPECT_FALSE(hasErrors(diagnostics)) << (diagnostics.empty() ? "" : formatDiagnostic(diagnostics[0]));
}

TEST(Composer, AnimatedSdfIsCalledWithTime) {
    PreparedSdf sdf = prepare("float sdf(vec3 p, float t) { return length(p) - 0.5 + 0.1 * sin(t); }\n");
    ASSERT_TRUE(sdf.signature.animated);
    auto composed = composeTracer(sdf, TracerFeatures{});
    ASSERT_TRUE(composed.hasValue());
    EXPECT_NE(composed->text.find("#define SDFWB_ANIMATED 1"), std::string::npos);
    EXPECT_FALSE(hasErrors(checkWithGlslang(*composed)));
}

TEST(Composer, FeaturesThatAreOffAreNotInTheSource) {
    PreparedSdf sdf = prepare("float sdf(vec3 p) { return length(p) - 0.5; }\n");
    TracerFeatures plain;
    auto bare = composeTracer(sdf, plain);
    ASSERT_TRUE(bare.hasValue());
    EXPECT_EQ(bare->text.find("sdfwb_ambientOcclusion(vec3"), std::string::npos) << "AO off: no AO function";
    EXPECT_EQ(bare->text.find("sdfwb_matcap"), std::string::npos) << "normals mode: no matcap sampler";
    EXPECT_EQ(bare->text.find("#define SDFWB_OVERRELAX"), std::string::npos);
    EXPECT_EQ(bare->text.find("#define SDFWB_USES_TIME"), std::string::npos) << "static SDF: time is compiled out";
    // The one call site in trace_main.frag sits in an #ifdef SDFWB_PLANE block; the plane's
    // functions and uniforms are not composed at all.
    EXPECT_EQ(bare->text.find("vec3 sdfwb_planeColor("), std::string::npos) << "no plane: none of the plane's code";
    EXPECT_EQ(bare->text.find("uniform vec3 sdfwb_planeNormal"), std::string::npos);
    EXPECT_EQ(bare->text.find("#define SDFWB_PLANE"), std::string::npos);
    EXPECT_EQ(bare->text.find("sdfwb:tracer/plane.glsl"), std::string::npos);
    TracerFeatures rich;
    rich.shading = ShadingMode::Matcap;
    rich.ambientOcclusion = true;
    rich.overRelaxation = true;
    rich.cuttingPlane = true;
    rich.planeClipsSurface = true;
    rich.planeLipschitzOverlay = true;
    auto full = composeTracer(sdf, rich);
    ASSERT_TRUE(full.hasValue());
    EXPECT_NE(full->text.find("float sdfwb_ambientOcclusion(vec3"), std::string::npos);
    EXPECT_NE(full->text.find("uniform sampler2D sdfwb_matcap"), std::string::npos);
    EXPECT_NE(full->text.find("#define SDFWB_OVERRELAX 1"), std::string::npos);
    EXPECT_NE(full->text.find("vec3 sdfwb_planeColor(vec3 p)"), std::string::npos);
    EXPECT_NE(full->text.find("#define SDFWB_PLANE_CLIP 1"), std::string::npos);
    EXPECT_FALSE(hasErrors(checkWithGlslang(*full)));
}

TEST(Composer, EqualFeatureSetsGiveEqualText) {
    PreparedSdf sdf = prepare("float sdf(vec3 p) { return length(p) - 0.5; }\n");
    auto a = composeSdfShader(sdf, Stage::Fragment, "tracer/trace_core.glsl", {{"B", "1"}, {"A", "2"}});
    auto b = composeSdfShader(sdf, Stage::Fragment, "tracer/trace_core.glsl", {{"A", "2"}, {"B", "1"}});
    ASSERT_TRUE(a.hasValue() && b.hasValue());
    EXPECT_EQ(a->text, b->text);
}

TEST(BuiltinShaders, EveryEmbeddedFileCompilesWithGlslangInItsStage) {
    PreparedSdf sdf = prepare("float sdf(vec3 p) { return length(p) - 0.5; }\n");
    std::set<std::string> covered;
    auto check = [&](Stage stage, const std::vector<std::string>& files) {
        std::vector<ShaderPiece> pieces;
        for (const std::string& file : files) {
            auto piece = builtinPiece(file);
            ASSERT_TRUE(piece.hasValue()) << file;
            pieces.push_back(*piece);
            covered.insert(file);
        }
        ComposedShader composed = composeSdfShader(sdf, stage, pieces, {});
        auto diagnostics = checkWithGlslang(composed);
        EXPECT_FALSE(hasErrors(diagnostics)) << files.back() << ": " << (diagnostics.empty() ? "" : formatDiagnostic(diagnostics[0]));
    };
    auto vertex = composeBuiltinShader(Stage::Vertex, "tracer/fullscreen.vert", {});
    ASSERT_TRUE(vertex.hasValue());
    EXPECT_FALSE(hasErrors(checkWithGlslang(*vertex)));
    covered.insert("tracer/fullscreen.vert");
    for (const char* mode : {"normals", "gooch", "matcap", "curvature", "steps"}) {
        TracerFeatures features;
        features.shading = *parseShadingMode(mode);
        features.ambientOcclusion = true;
        features.overRelaxation = true;
        features.cuttingPlane = true;
        features.planeClipsSurface = true;
        features.planeLipschitzOverlay = true;
        auto composed = composeTracer(sdf, features);
        ASSERT_TRUE(composed.hasValue());
        auto diagnostics = checkWithGlslang(*composed);
        EXPECT_FALSE(hasErrors(diagnostics)) << mode << ": " << (diagnostics.empty() ? "" : formatDiagnostic(diagnostics[0]));
        for (const char* file : {"tracer/trace_core.glsl", "tracer/ao.glsl", "tracer/plane.glsl", "tracer/trace_main.frag"}) covered.insert(file);
        covered.insert(std::string("tracer/shading_") + mode + ".glsl");
    }
    for (const std::string& path : builtinShaderPaths())
        if (path.rfind("samplers/", 0) == 0 || path.rfind("analysis/", 0) == 0)
            check(Stage::Compute, {"sampling/bindings.glsl", "sampling/common.glsl", path, "sampling/sample.comp"});
    // The compat prelude is composed when an SDF needs it (tested above); everything else must be
    // reached by one of the stages here, so a new built-in file cannot go unchecked.
    covered.insert("prelude/g3d_compat.glsl");
    for (const std::string& path : builtinShaderPaths()) EXPECT_TRUE(covered.count(path)) << path << " is not compiled by any test";
}

TEST(BuiltinShaders, UnknownNameIsAnError) {
    auto missing = builtinShader("no/such.frag");
    ASSERT_FALSE(missing.hasValue());
    EXPECT_NE(missing.error().message.find("no/such.frag"), std::string::npos);
}
