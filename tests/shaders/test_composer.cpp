// The composer: what goes into a shader, and what stays out.

#include <shaders/BuiltinShaders.h>
#include <shaders/GlslChecker.h>
#include <shaders/ShaderComposer.h>

#include <gtest/gtest.h>

using namespace sdfwb::shaders;

namespace {

PreparedSdf prepare(const std::string& text) { return prepareSdf(text, "<test>", {}, IncludeOptions{}); }

} // namespace

TEST(Composer, PlainSdfGetsNoCompatPreludeAndNoTime) {
    PreparedSdf sdf = prepare("float sdf(vec3 p) { return length(p) - 0.5; }\n");
    ASSERT_TRUE(sdf.ok());
    auto composed = composeSdfShader(sdf, Stage::Fragment, "tracer/trace.frag", {{"SDFWB_SHADING_NORMALS", "1"}});
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
    auto composed = composeSdfShader(sdf, Stage::Fragment, "tracer/trace.frag", {});
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
    auto composed = composeSdfShader(sdf, Stage::Fragment, "tracer/trace.frag", {});
    ASSERT_TRUE(composed.hasValue());
    EXPECT_NE(composed->text.find("#define SDFWB_ANIMATED 1"), std::string::npos);
    EXPECT_FALSE(hasErrors(checkWithGlslang(*composed)));
}

TEST(Composer, EqualFeatureSetsGiveEqualText) {
    PreparedSdf sdf = prepare("float sdf(vec3 p) { return length(p) - 0.5; }\n");
    auto a = composeSdfShader(sdf, Stage::Fragment, "tracer/trace.frag", {{"B", "1"}, {"A", "2"}});
    auto b = composeSdfShader(sdf, Stage::Fragment, "tracer/trace.frag", {{"A", "2"}, {"B", "1"}});
    ASSERT_TRUE(a.hasValue() && b.hasValue());
    EXPECT_EQ(a->text, b->text);
}

TEST(BuiltinShaders, EveryEmbeddedStageCompilesWithGlslang) {
    PreparedSdf sdf = prepare("float sdf(vec3 p) { return length(p) - 0.5; }\n");
    auto paths = builtinShaderPaths();
    ASSERT_FALSE(paths.empty());
    for (const std::string& path : paths) {
        if (path.rfind("prelude/", 0) == 0) continue;
        Stage stage = path.ends_with(".vert") ? Stage::Vertex : path.ends_with(".comp") ? Stage::Compute : Stage::Fragment;
        auto composed = stage == Stage::Vertex ? composeBuiltinShader(stage, path, {}) : composeSdfShader(sdf, stage, path, {});
        ASSERT_TRUE(composed.hasValue()) << path;
        auto diagnostics = checkWithGlslang(*composed);
        EXPECT_FALSE(hasErrors(diagnostics)) << path << ": " << (diagnostics.empty() ? "" : formatDiagnostic(diagnostics[0]));
    }
}

TEST(BuiltinShaders, UnknownNameIsAnError) {
    auto missing = builtinShader("no/such.frag");
    ASSERT_FALSE(missing.hasValue());
    EXPECT_NE(missing.error().message.find("no/such.frag"), std::string::npos);
}
