// The composer: what goes into a shader, and what stays out.

#include <meshfield/MeshField.h>
#include <shaders/BuiltinShaders.h>
#include <shaders/GlslChecker.h>
#include <shaders/ShaderComposer.h>
#include <shaders/TracerComposer.h>

#include <gtest/gtest.h>

#include <regex>
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
        EXPECT_FALSE(hasErrors(diagnostics))
            << files.back() << ": " << (diagnostics.empty() ? "" : formatDiagnostic(diagnostics[0]));
    };
    auto vertex = composeBuiltinShader(Stage::Vertex, "tracer/fullscreen.vert", {});
    ASSERT_TRUE(vertex.hasValue());
    EXPECT_FALSE(hasErrors(checkWithGlslang(*vertex)));
    covered.insert("tracer/fullscreen.vert");
    auto tracerVertex = composeTracerVertex();
    ASSERT_TRUE(tracerVertex.hasValue());
    EXPECT_FALSE(hasErrors(checkWithGlslang(*tracerVertex)));
    covered.insert("tracer/trace.vert");
    for (const char* mode : {"normals", "gooch", "matcap", "curvature", "steps"}) {
        TracerFeatures features;
        features.shading = *parseShadingMode(mode);
        features.ambientOcclusion = true;
        features.overRelaxation = true;
        features.cuttingPlane = true;
        features.planeClipsSurface = true;
        features.planeLipschitzOverlay = true;
        features.markers = true;
        auto composed = composeTracer(sdf, features);
        ASSERT_TRUE(composed.hasValue());
        auto diagnostics = checkWithGlslang(*composed);
        EXPECT_FALSE(hasErrors(diagnostics)) << mode << ": " << (diagnostics.empty() ? "" : formatDiagnostic(diagnostics[0]));
        for (const char* file :
             {"tracer/trace_core.glsl", "tracer/ao.glsl", "tracer/plane.glsl", "tracer/markers.glsl", "tracer/trace_main.frag"})
            covered.insert(file);
        covered.insert(std::string("tracer/shading_") + mode + ".glsl");
    }
    // The march debugger's recorder, with plain and over-relaxed marching and the stats output.
    for (bool relaxed : {false, true}) {
        TracerFeatures features;
        features.probe = true;
        features.statsOutput = true;
        features.overRelaxation = relaxed;
        auto composed = composeTracer(sdf, features);
        ASSERT_TRUE(composed.hasValue());
        auto diagnostics = checkWithGlslang(*composed);
        EXPECT_FALSE(hasErrors(diagnostics)) << "probe: " << (diagnostics.empty() ? "" : formatDiagnostic(diagnostics[0]));
        covered.insert("tracer/probe.glsl");
    }
    for (const std::string& path : builtinShaderPaths())
        if (path.rfind("samplers/", 0) == 0 || path.rfind("analysis/", 0) == 0)
            check(Stage::Compute, {"sampling/bindings.glsl", "sampling/common.glsl", path, "sampling/sample.comp"});
    // The mesh deviation overlay: its vertex stage alone, its fragment stage with the SDF, and the
    // composite that lays its frame over the traced one.
    for (const char* file : {"overlay/mesh.vert"}) {
        auto stage = composeBuiltinShader(Stage::Vertex, file, {});
        ASSERT_TRUE(stage.hasValue());
        EXPECT_FALSE(hasErrors(checkWithGlslang(*stage))) << file;
        covered.insert(file);
    }
    // The composite and the point cloud's dots stand alone (no SDF).
    for (const char* file : {"overlay/composite.frag", "overlay/points.frag"}) {
        auto stage = composeBuiltinShader(Stage::Fragment, file, {});
        ASSERT_TRUE(stage.hasValue());
        EXPECT_FALSE(hasErrors(checkWithGlslang(*stage))) << file;
        covered.insert(file);
    }
    check(Stage::Fragment, {"overlay/mesh_deviation.frag"});
    {
        // Users' code in the overlay too: the G3D dialect (Point3, saturate, the host's noise
        // texture, scene time) composed with the deviation stage.
        PreparedSdf g3d = prepare("float sdf(Point3 X) {\n"
                                  "    float n = texelFetch(g3d_uniformRandom, ivec2(0), 0).r;\n"
                                  "    return length(X) - 0.5 + 0.01 * saturate(n) * sin(g3d_SceneTime);\n"
                                  "}\n");
        ASSERT_FALSE(hasErrors(g3d.diagnostics));
        auto piece = builtinPiece("overlay/mesh_deviation.frag");
        ASSERT_TRUE(piece.hasValue());
        auto diagnostics = checkWithGlslang(composeSdfShader(g3d, Stage::Fragment, {*piece}, {}));
        EXPECT_FALSE(hasErrors(diagnostics)) << (diagnostics.empty() ? "" : formatDiagnostic(diagnostics[0]));
    }
    {
        // A whole Shadertoy shader's own picture: its mainImage, called by the picture stage.
        PreparedSdf shadertoy =
            prepare("float map(vec3 p) { return length(p) - 0.5; }\n"
                    "void mainImage(out vec4 c, in vec2 f) { c = vec4(f / iResolution.xy, map(vec3(iTime)), 1.0); }\n");
        ASSERT_TRUE(shadertoy.shadertoyMainImage);
        auto piece = builtinPiece("shadertoy/picture.frag");
        ASSERT_TRUE(piece.hasValue());
        auto diagnostics = checkWithGlslang(composeSdfShader(shadertoy, Stage::Fragment, {*piece}, {}));
        EXPECT_FALSE(hasErrors(diagnostics)) << (diagnostics.empty() ? "" : formatDiagnostic(diagnostics[0]));
        covered.insert("shadertoy/picture.frag");
    }
    {
        // A triangle mesh as the SDF (one triangle is enough for the text): its traversal composed
        // with each sign method, in the tracer's fragment stage and the samplers' compute stage.
        sdfwb::meshfield::TriangleMesh triangle{{glm::vec3(0.0f), glm::vec3(1.0f, 0.0f, 0.0f), glm::vec3(0.0f, 1.0f, 0.0f)},
                                                {0, 1, 2}};
        for (sdfwb::meshfield::SignMethod sign : {sdfwb::meshfield::SignMethod::Winding, sdfwb::meshfield::SignMethod::Parity,
                                                  sdfwb::meshfield::SignMethod::Pseudonormal}) {
            sdfwb::meshfield::MeshFieldOptions options;
            options.sign = sign;
            auto field = sdfwb::meshfield::makeMeshField(triangle, "triangle.obj", options);
            ASSERT_TRUE(field.hasValue());
            PreparedSdf mesh = prepareMeshSdf(*field, "triangle.obj");
            ASSERT_FALSE(hasErrors(mesh.diagnostics)) << formatDiagnostic(mesh.diagnostics[0]);
            auto traced = composeTracer(mesh, TracerFeatures{});
            ASSERT_TRUE(traced.hasValue());
            auto diagnostics = checkWithGlslang(*traced);
            EXPECT_FALSE(hasErrors(diagnostics))
                << sdfwb::meshfield::signName(sign) << ": " << (diagnostics.empty() ? "" : formatDiagnostic(diagnostics[0]));
            std::vector<ShaderPiece> pieces;
            for (const char* file :
                 {"sampling/bindings.glsl", "sampling/common.glsl", "analysis/points.glsl", "sampling/sample.comp"})
                pieces.push_back(*builtinPiece(file));
            diagnostics = checkWithGlslang(composeSdfShader(mesh, Stage::Compute, pieces, {}));
            EXPECT_FALSE(hasErrors(diagnostics))
                << sdfwb::meshfield::signName(sign) << ": " << (diagnostics.empty() ? "" : formatDiagnostic(diagnostics[0]));
        }
        covered.insert("mesh/mesh_field.glsl");
    }
    // The compat prelude is composed when an SDF needs it (tested above); everything else must be
    // reached by one of the stages here, so a new built-in file cannot go unchecked.
    covered.insert("prelude/g3d_compat.glsl");
    for (const std::string& path : builtinShaderPaths())
        EXPECT_TRUE(covered.count(path)) << path << " is not compiled by any test";
}

TEST(BuiltinShaders, UnknownNameIsAnError) {
    auto missing = builtinShader("no/such.frag");
    ASSERT_FALSE(missing.hasValue());
    EXPECT_NE(missing.error().message.find("no/such.frag"), std::string::npos);
}

// Issue 14, point 2: any entry point.
TEST(EntryPoint, ShadertoyMapWithMaterialIsFoundAndItsDistanceUsed) {
    PreparedSdf sdf = prepare("#define PI 3.14159\n#define normal(p) calcNormal(p)\n"
                              "vec2 map(vec3 p) { return vec2(length(p) - 0.5, 1.0); }\n"
                              "vec3 calcNormal(vec3 p) { return normalize(p); }\n");
    ASSERT_TRUE(sdf.ok()) << sdf.diagnostics.front().message;
    EXPECT_EQ(sdf.signature.entry, "map");
    EXPECT_EQ(sdf.signature.returnType, "vec2");
    EXPECT_EQ(sdf.entrySource, EntrySource::Convention);
    EXPECT_EQ(sdf.macros, (std::vector<std::string>{"PI", "normal"}));
    const std::string wrapper = entryWrapper(sdf);
    EXPECT_NE(wrapper.find("float sdfwb_sdf(vec3 p) { return map(p).x; }"), std::string::npos) << wrapper;
    EXPECT_NE(wrapper.find("#undef PI\n#undef normal\n"), std::string::npos) << wrapper;
    // With the macros gone, the tracer's own code (a local `normal`, ...) compiles after them.
    for (ShadingMode mode : {ShadingMode::Normals, ShadingMode::Gooch, ShadingMode::Curvature}) {
        TracerFeatures features;
        features.shading = mode;
        features.ambientOcclusion = true;
        auto composed = composeTracer(sdf, features);
        ASSERT_TRUE(composed.hasValue());
        auto diagnostics = checkWithGlslang(*composed);
        EXPECT_FALSE(hasErrors(diagnostics)) << (diagnostics.empty() ? "" : diagnostics.front().message);
    }
}

TEST(EntryPoint, RequestedMetadataAndTimeDependentEntries) {
    // Requested by name, with time: animated, the wrapper passes sdfwb_time.
    PreparedSdf timed =
        prepareSdf("float shape(in vec3 q, float t) { return length(q) - 0.4 - 0.1 * sin(t); }\n", "<test>", {}, {}, "shape");
    ASSERT_TRUE(timed.ok());
    EXPECT_TRUE(timed.signature.animated);
    EXPECT_TRUE(timed.usesTime());
    EXPECT_EQ(timed.entrySource, EntrySource::Requested);
    EXPECT_NE(entryWrapper(timed).find("shape(p, sdfwb_time)"), std::string::npos);
    auto composed = composeTracer(timed, TracerFeatures{});
    ASSERT_TRUE(composed.hasValue());
    EXPECT_NE(composed->text.find("uniform float sdfwb_time;"), std::string::npos);
    EXPECT_FALSE(hasErrors(checkWithGlslang(*composed)));

    // From the metadata block; it wins over a plain sdf() in the same file.
    PreparedSdf fromMetadata =
        prepare("/* sdfwb\nname: Two\ncategory: Misc\ntype: exact\nanimated: no\nauthor: a\nlicense: CC0-1.0\n"
                "entry: scene\n*/\nvec4 scene(vec3 p) { return vec4(length(p) - 0.5); }\n"
                "float sdf(vec3 p) { return 1.0; }\n");
    ASSERT_TRUE(fromMetadata.ok());
    EXPECT_EQ(fromMetadata.signature.entry, "scene");
    EXPECT_EQ(fromMetadata.signature.returnType, "vec4");
    EXPECT_EQ(fromMetadata.entrySource, EntrySource::Metadata);

    // Shadertoy's undeclared iTime makes a file time-dependent; a declared one does not.
    PreparedSdf shadertoy = prepare("float map(vec3 p) { return length(p) - 0.5 + 0.1 * sin(iTime); }\n");
    ASSERT_TRUE(shadertoy.ok());
    EXPECT_TRUE(shadertoy.usesTime());
    EXPECT_FALSE(shadertoy.signature.animated);
    EXPECT_FALSE(prepare("uniform float iTime;\nfloat map(vec3 p) { return length(p) - 0.5 + 0.1 * sin(iTime); }\n").usesTime());
}

TEST(EntryPoint, MissingWrongAndReservedEntriesAreNamed) {
    PreparedSdf missing = prepareSdf("float map(vec3 p) { return length(p); }\n", "<test>", {}, {}, "shape");
    ASSERT_FALSE(missing.ok());
    EXPECT_NE(missing.diagnostics.back().message.find("entry point 'shape' not found"), std::string::npos)
        << missing.diagnostics.back().message;
    PreparedSdf wrongType = prepareSdf("float shape(vec2 p) { return length(p); }\n", "<test>", {}, {}, "shape");
    ASSERT_FALSE(wrongType.ok());
    EXPECT_EQ(wrongType.diagnostics.back().line, 1);
    EXPECT_NE(wrongType.diagnostics.back().message.find("found `float shape(vec2 p)`"), std::string::npos);
    for (const char* reserved : {"main", "sdfwb_sdf", "SDFWB_x", "gl_Position", "1abc", "a-b"}) {
        PreparedSdf refused = prepareSdf("float sdf(vec3 p) { return length(p); }\n", "<test>", {}, {}, reserved);
        EXPECT_FALSE(refused.ok()) << reserved;
    }
    PreparedSdf none = prepare("float shape(vec3 p) { return length(p); }\n");
    ASSERT_FALSE(none.ok());
    EXPECT_NE(none.diagnostics.back().message.find("--entry"), std::string::npos) << "the message says how to name the entry";
}

// Issue 14, point 1: every name the workbench's own GLSL declares at file scope carries the
// reserved prefix, so no user name can clash with it. (The compat prelude declares the G3D
// dialect's names on purpose, and only those a file uses without defining; samplers define
// samplePosition, which common.glsl renames to sdfwb_samplePosition.)
TEST(BuiltinShaders, EveryNameTheWorkbenchDeclaresIsPrefixed) {
    const std::regex declaration(
        R"((?:^|\n)(?:#\s*define\s+(\w+)|(?:uniform|const|out|in)\s+\w+\s+(\w+)|struct\s+(\w+)|(?:\w+)\s+(\w+)\s*\([^)]*\)\s*\{))");
    const std::regex buffer(R"(buffer\s+(\w+)\s*\{\s*\w+\s+(\w+)\s*\[)");
    int names = 0;
    for (const std::string& path : builtinShaderPaths()) {
        if (path.rfind("prelude/", 0) == 0) continue;
        const std::string text = stripComments(*builtinShader(path));
        auto checkName = [&](const std::string& name) {
            ++names;
            if (name == "main" || name == "samplePosition") return;
            EXPECT_TRUE(name.rfind("sdfwb_", 0) == 0 || name.rfind("SDFWB_", 0) == 0) << path << ": '" << name << "'";
        };
        for (auto it = std::sregex_iterator(text.begin(), text.end(), declaration); it != std::sregex_iterator(); ++it)
            for (int group = 1; group <= 4; ++group)
                if ((*it)[group].matched) checkName((*it)[group].str());
        for (auto it = std::sregex_iterator(text.begin(), text.end(), buffer); it != std::sregex_iterator(); ++it) {
            checkName((*it)[1].str());
            checkName((*it)[2].str());
        }
    }
    EXPECT_GT(names, 80) << "the pattern stopped finding declarations";
}

// Issue 32, point 1: a whole Shadertoy shader as pasted (`#version 300 es`, precision lines, an
// ES extension, undeclared inputs, texture2D, derivatives in mainImage, its own ray caster)
// compiles unmodified in the tracer's fragment stage and in the sampler's compute stage, where
// derivatives do not exist; mainImage is never called.
TEST(Composer, WholeShadertoyShaderCompilesInEveryStage) {
    const std::string text =
        "#version 300 es\n"
        "#extension GL_OES_standard_derivatives : enable\n"
        "precision highp float;\nprecision highp int;\n"
        "vec2 map(in vec3 pos) {\n"
        "  float n = texture(iChannel0, pos.xz).x + texture2DLod(iChannel3, pos.xy, 0.0).y;\n"
        "  return vec2(length(pos) - 0.5 + 0.001 * n + 0.01 * sin(iTime), 1.0);\n}\n"
        "float castRay(vec3 ro, vec3 rd) { float t = 0.0;\n"
        "  for (int i = 0; i < 64; i++) { float h = map(ro + t * rd).x; if (h < 1e-4) break; t += h; }\n"
        "  return t; }\n"
        "void mainImage(out vec4 fragColor, in vec2 fragCoord) {\n"
        "  vec2 p = (2.0 * fragCoord - iResolution.xy) / iResolution.y + iMouse.xy / iResolution.xy;\n"
        "  float t = castRay(vec3(0.0, 0.0, 3.0), normalize(vec3(p, -2.0)));\n"
        "  vec3 col = texture2D(iChannel1, p).rgb * fwidth(p.x) + dFdx(p.y) + dFdy(t) + float(iFrame) * iTimeDelta;\n"
        "  fragColor = vec4(col + iDate.xyz * 0.0 + iChannelTime[0] + iChannelResolution[2] + iFrameRate + iSampleRate, 1.0);\n"
        "}\n";
    PreparedSdf sdf = prepare(text);
    ASSERT_TRUE(sdf.ok());
    EXPECT_EQ(sdf.signature.entry, "map");
    EXPECT_TRUE(sdf.source.extensions.empty()) << "an ES extension is part of core GLSL 4.30";
    auto tracer = composeTracer(sdf, TracerFeatures{});
    ASSERT_TRUE(tracer.hasValue());
    EXPECT_EQ(tracer->text.rfind("#version 430 core\n", 0), 0u);
    EXPECT_EQ(tracer->text.find("#version 300"), std::string::npos);
    EXPECT_EQ(tracer->text.find("#define SDFWB_COMPAT_fwidth"), std::string::npos) << "fragment shaders have derivatives";
    auto diagnostics = checkWithGlslang(*tracer);
    EXPECT_FALSE(hasErrors(diagnostics)) << (diagnostics.empty() ? "" : formatDiagnostic(diagnostics[0]));
    auto sampler = builtinPiece("samplers/rand.glsl");
    auto common = builtinPiece("sampling/common.glsl");
    auto bindings = builtinPiece("sampling/bindings.glsl");
    auto main = builtinPiece("sampling/sample.comp");
    ASSERT_TRUE(sampler.hasValue() && common.hasValue() && bindings.hasValue() && main.hasValue());
    ComposedShader compute = composeSdfShader(sdf, Stage::Compute, {*bindings, *common, *sampler, *main}, {});
    EXPECT_NE(compute.text.find("#define SDFWB_COMPAT_fwidth 1"), std::string::npos);
    diagnostics = checkWithGlslang(compute);
    EXPECT_FALSE(hasErrors(diagnostics)) << (diagnostics.empty() ? "" : formatDiagnostic(diagnostics[0]));

    // A desktop extension the code asks for is kept, ahead of every other line but #version.
    PreparedSdf withExtension =
        prepare("#extension GL_ARB_gpu_shader_fp64 : enable\nfloat sdf(vec3 p) { return length(p) - 0.5; }\n");
    auto composed = composeTracer(withExtension, TracerFeatures{});
    ASSERT_TRUE(composed.hasValue());
    EXPECT_EQ(composed->text.rfind("#version 430 core\n#extension GL_ARB_gpu_shader_fp64 : enable\n", 0), 0u);
    EXPECT_FALSE(hasErrors(checkWithGlslang(*composed)));
}
