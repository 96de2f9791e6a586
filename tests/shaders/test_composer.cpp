// The composer: what goes into a shader, and what stays out.

#include <meshfield/MeshField.h>
#include <shaders/BuiltinShaders.h>
#include <shaders/GlslChecker.h>
#include <shaders/ShaderComposer.h>
#include <shaders/TracerComposer.h>

#include <gtest/gtest.h>

#include <algorithm>
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
        for (const char* file : {"common/geometry.glsl", "tracer/trace_core.glsl", "tracer/ao.glsl", "tracer/plane.glsl",
                                 "tracer/markers.glsl", "tracer/trace_main.frag"})
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
        if (path.rfind("samplers/", 0) == 0 || path.rfind("analysis/", 0) == 0) {
            auto sampler = builtinPiece(path);
            ASSERT_TRUE(sampler.hasValue()) << path;
            auto pieces = samplingStagePieces(*sampler);
            ASSERT_TRUE(pieces.hasValue()) << path;
            std::vector<std::string> files;
            for (const ShaderPiece& piece : *pieces) files.push_back(piece.name.substr(std::string("sdfwb:").size()));
            check(Stage::Compute, files);
        }
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
            auto pieces = samplingStagePieces(*builtinPiece("analysis/points.glsl"));
            ASSERT_TRUE(pieces.hasValue());
            diagnostics = checkWithGlslang(composeSdfShader(mesh, Stage::Compute, *pieces, {}));
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
    auto pieces = samplingStagePieces(*builtinPiece("samplers/rand.glsl"));
    ASSERT_TRUE(pieces.hasValue());
    ComposedShader compute = composeSdfShader(sdf, Stage::Compute, *pieces, {});
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

namespace {

// A whole shader in the common Shadertoy layout around `fieldCode` (which defines the functions
// named) and a march loop `march`, with an AO loop and a glow loop over other functions.
std::string wholeShader(const std::string& fieldCode, const std::string& march) {
    return fieldCode +
           "float occluder(vec3 p) { return length(p) - 0.3; }\n"
           "float glowField(vec3 p) { return length(p - vec3(0.2)) - 0.1; }\n"
           "float calcAO(vec3 pos, vec3 nor) {\n"
           "    float occ = 0.0;\n"
           "    for (int i = 0; i < 5; i++) { float h = 0.01 + 0.12 * float(i) / 4.0; occ += (h - occluder(pos + h * nor)); }\n"
           "    return clamp(1.0 - 3.0 * occ, 0.0, 1.0);\n"
           "}\n"
           "float glow(vec3 ro, vec3 rd) {\n"
           "    float g = 0.0, s = 0.0;\n"
           "    for (int i = 0; i < 32; i++) { g += 0.01 / (0.01 + abs(glowField(ro + rd * s))); s += 0.05; }\n"
           "    return g;\n"
           "}\n"
           "float castRay(vec3 ro, vec3 rd) {\n" +
           march +
           "}\n"
           "void mainImage(out vec4 fragColor, in vec2 fragCoord) {\n"
           "    vec2 uv = (2.0 * fragCoord - iResolution.xy) / iResolution.y;\n"
           "    vec3 ro = vec3(0.0, 0.0, 3.0), rd = normalize(vec3(uv, -2.0));\n"
           "    float t = castRay(ro, rd);\n"
           "    fragColor = vec4(vec3(calcAO(ro + t * rd, vec3(0.0, 1.0, 0.0)) + glow(ro, rd)), 1.0);\n"
           "}\n";
}

} // namespace

// Issue 47, point 1: a whole shader's field is the function its own march steps by, whatever its
// name: by t (`t += h`), by the point (`p += rd * d`), by a vec2's .x; not a function only an AO
// loop or a glow loop (whose accumulator the point does not depend on) calls.
TEST(EntryPoint, AWholeShadersFieldIsTheFunctionItsMarchStepsBy) {
    struct Case {
        const char* field;
        const char* march;
        const char* entry;
        float threshold; // the constant the march stops at (0: none)
    };
    const Case cases[] = {
        {"float Map(vec3 p) { return length(p) - 0.5; }\n",
         "    float t = 0.0;\n    for (int i = 0; i < 128; i++) {\n        float h = Map(ro + rd * t);\n"
         "        if (h < 0.001) break;\n        t += h;\n    }\n    return t;\n",
         "Map", 0.001f},
        {"float GetDist(vec3 p) { return length(p) - 0.5; }\n",
         "    float dO = 0.0;\n    for (int i = 0; i < 100; i++) {\n        vec3 p = ro + rd * dO;\n"
         "        float dS = GetDist(p);\n        dO += dS;\n        if (dO > 100.0 || dS < 0.01) break;\n    }\n"
         "    return dO;\n",
         "GetDist", 0.01f},
        {"vec2 sceneDist(vec3 p) { return vec2(length(p) - 0.5, 1.0); }\n",
         "    vec3 p = ro;\n    for (int i = 0; i < 90; i++) {\n        vec2 res = sceneDist(p);\n"
         "        p += rd * res.x;\n    }\n    return length(p - ro);\n",
         "sceneDist", 0.0f},
        {"float field(vec3 p) { return length(p) - 0.5; }\n",
         "    float t = 0.1;\n    for (float h = 1.0; t < 20.0 && h > 1e-3; t += h) h = field(ro + rd * t);\n    return t;\n",
         "field", 1e-3f},
    };
    for (const Case& c : cases) {
        const std::string text = wholeShader(c.field, c.march);
        PreparedSdf sdf = prepare(text);
        ASSERT_TRUE(sdf.ok()) << c.entry << ": " << (sdf.diagnostics.empty() ? "" : formatDiagnostic(sdf.diagnostics.front()));
        EXPECT_EQ(sdf.signature.entry, c.entry);
        EXPECT_EQ(sdf.entrySource, EntrySource::March);
        // The reason names the call's line in the file.
        const std::size_t call = text.find(std::string(c.entry) + "(", text.find("float castRay"));
        const int line = 1 + int(std::count(text.begin(), text.begin() + std::ptrdiff_t(call), '\n'));
        EXPECT_EQ(sdf.entryReason, std::string(c.entry) + " (called by the march at line " + std::to_string(line) + ")");
        EXPECT_EQ(sdf.marchThreshold, c.threshold) << c.entry;
        auto tracer = composeTracer(sdf, TracerFeatures{});
        ASSERT_TRUE(tracer.hasValue());
        EXPECT_FALSE(hasErrors(checkWithGlslang(*tracer))) << c.entry;
    }

    // The march steps by a constant: no field is found (the AO and glow functions are not one).
    PreparedSdf none =
        prepare(wholeShader("", "    float t = 0.0;\n    for (int i = 0; i < 10; i++) t += 0.1;\n    return t;\n"));
    EXPECT_FALSE(none.ok());
    EXPECT_NE(none.diagnostics.back().message.find("no SDF here"), std::string::npos) << none.diagnostics.back().message;

    // A conventional name the march does not step by loses to the one it does.
    PreparedSdf preferred =
        prepare(wholeShader("float map(vec3 p) { return 1.0; }\nfloat Map(vec3 p) { return length(p) - 0.5; }\n",
                            "    float t = 0.0;\n    for (int i = 0; i < 64; i++) t += Map(ro + rd * t);\n"
                            "    return t + map(ro);\n"));
    ASSERT_TRUE(preferred.ok());
    EXPECT_EQ(preferred.signature.entry, "Map");
}

// The constant a march stops at (an unsigned field's surface: --level): through a macro, a const,
// abs() and a component; the first loop's, not a shadow loop's; none where it is not one constant
// (a relative threshold, with an escape test `d > 20.0` beside it that is no hit).
TEST(EntryPoint, TheConstantAWholeShadersMarchStopsAtIsRead) {
    struct Case {
        const char* field;
        const char* march;
        float threshold;
    };
    const Case cases[] = {
        {"#define SURF_DIST .02\nfloat GetDist(vec3 p) { return abs(length(p) - 0.5); }\n",
         "    float dO = 0.0;\n    for (int i = 0; i < 100; i++) {\n        float dS = GetDist(ro + rd * dO);\n"
         "        dO += dS;\n        if (dO > 100.0 || dS < SURF_DIST) break;\n    }\n    return dO;\n",
         0.02f},
        {"const float EPS = 0.0005;\nvec2 map(vec3 p) { return vec2(abs(length(p) - 0.5), 2.0); }\n",
         "    float t = 0.0;\n    for (int i = 0; i < 100; i++) {\n        vec2 h = map(ro + rd * t);\n"
         "        if (abs(h.x) < EPS) break;\n        t += h.x;\n    }\n"
         "    float s = 0.1;\n    for (int i = 0; i < 20; i++) { float e = map(ro + rd * s).x; if (e < 1e-5) break; s += e; }\n"
         "    return t + s;\n",
         0.0005f},
        {"float map(vec3 p) { return abs(length(p) - 0.5); }\n",
         "    float t = 0.0;\n    for (int i = 0; i < 100; i++) {\n        float d = map(ro + rd * t);\n"
         "        if (d < 0.001 * t || d > 20.0) break;\n        t += d;\n    }\n    return t;\n",
         0.0f},
        // Marches that write their field inline: a distance along the ray, and the point itself.
        {"",
         "    float t = 0.0;\n    for (int i = 0; i < 100; i++) {\n        vec3 p = ro + rd * t;\n"
         "        float d = abs(length(p) - 0.5);\n        if (d < 0.002) break;\n        t += d;\n    }\n    return t;\n",
         0.002f},
        {"",
         "    vec3 p = ro;\n    for (int i = 0; i < 100; i++) {\n        float d = abs(length(p) - 0.5);\n"
         "        if (d < 3e-3) break;\n        p += rd * d;\n    }\n    return length(p - ro);\n",
         0.003f},
    };
    for (const Case& c : cases) {
        const std::string text = wholeShader(c.field, c.march);
        PreparedSdf sdf = prepare(text);
        ASSERT_TRUE(sdf.ok()) << c.march;
        EXPECT_EQ(sdf.marchThreshold, c.threshold) << c.march;
        if (c.threshold > 0.0f) {
            // The comparison is on the line of the first loop's break.
            const std::size_t exit = text.find("break", text.find("float castRay"));
            EXPECT_EQ(sdf.marchThresholdLine, 1 + int(std::count(text.begin(), text.begin() + std::ptrdiff_t(exit), '\n')))
                << c.march;
        }
    }
}

// Two functions marched equally often (a scene and its reflection): an error naming both, and
// both offered; a conventional name among them breaks the tie.
TEST(EntryPoint, TwoEquallyMarchedFunctionsAreUnitedOrNamedAndOffered) {
    const std::string marches = "    float t = 0.0, s = 0.0;\n"
                                "    for (int i = 0; i < 64; i++) t += Solid(ro + rd * t);\n"
                                "    for (int i = 0; i < 64; i++) s += Water(ro + rd * s);\n"
                                "    return min(t, s);\n";
    // Functions of the point alone: the scene the shader draws is their union.
    std::string unitedMarches = marches;
    unitedMarches.replace(unitedMarches.find("Water(ro + rd * s)"), 18, "Water(ro + rd * s).x");
    PreparedSdf united = prepare(wholeShader("float Solid(vec3 p) { return length(p) - 0.5; }\n"
                                             "vec2 Water(vec3 p) { return vec2(p.y + 0.4, 2.0); }\n",
                                             unitedMarches));
    ASSERT_TRUE(united.ok()) << united.diagnostics.back().message;
    EXPECT_EQ(united.signature.entry, "Solid");
    EXPECT_EQ(united.signature.unionWith, (std::vector<std::pair<std::string, std::string>>{{"Water", ".x"}}));
    EXPECT_NE(united.entryReason.find("the union of Solid (called by the march at line"), std::string::npos)
        << united.entryReason;
    EXPECT_NE(united.entryReason.find("; and Water (called by the march at line"), std::string::npos) << united.entryReason;
    auto tracer = composeTracer(united, TracerFeatures{});
    ASSERT_TRUE(tracer.hasValue());
    EXPECT_NE(tracer->text.find("return min(Solid(p), Water(p).x);"), std::string::npos);
    EXPECT_FALSE(hasErrors(checkWithGlslang(*tracer)));
    // One with an out parameter (a material written through it): no union, a tie to choose from.
    std::string withOut = marches;
    withOut.replace(withOut.find("s += Water(ro + rd * s)"), 23, "s += Water(ro + rd * s, id)");
    withOut = "    float id = 0.0;\n" + withOut;
    PreparedSdf tied = prepare(wholeShader("float Solid(vec3 p) { return length(p) - 0.5; }\n"
                                           "float Water(vec3 p, out float id) { id = 1.0; return p.y + 0.4; }\n",
                                           withOut));
    ASSERT_FALSE(tied.ok());
    EXPECT_EQ(tied.entryCandidates, (std::vector<std::string>{"Solid", "Water"}));
    const std::string& message = tied.diagnostics.back().message;
    EXPECT_NE(message.find("Solid (called by the march at line"), std::string::npos) << message;
    EXPECT_NE(message.find("Water (called by the march at line"), std::string::npos) << message;
    EXPECT_NE(message.find("--entry NAME"), std::string::npos) << message;
    // Named, either opens.
    PreparedSdf named = prepareSdf(wholeShader("float Solid(vec3 p) { return length(p) - 0.5; }\n"
                                               "float Water(vec3 p, out float id) { id = 1.0; return p.y + 0.4; }\n",
                                               withOut),
                                   "<test>", {}, IncludeOptions{}, "Water");
    EXPECT_TRUE(named.ok());
    EXPECT_EQ(named.entrySource, EntrySource::Requested);

    std::string withMap = marches;
    withMap.replace(withMap.find("Solid"), 5, "map");
    PreparedSdf conventional = prepare(wholeShader("float map(vec3 p) { return length(p) - 0.5; }\n"
                                                   "float Water(vec3 p) { return p.y + 0.4; }\n",
                                                   withMap));
    ASSERT_TRUE(conventional.ok());
    EXPECT_EQ(conventional.signature.entry, "map");
    EXPECT_EQ(conventional.entrySource, EntrySource::March);
}

// A glass shader (mrange's "self reflect" on Shadertoy): the primary ray marches the solid, and each
// refracted ray marches the inside, once each. The primary ray's march is nearer mainImage in its
// calls: that field is the scene, and the reason names the other. Its size, a global mainImage sets
// before it calls render(), is set first for the field too.
TEST(EntryPoint, ATieIsBrokenByThePrimaryRaysMarch) {
    const std::string text =
        "float g_r;\nfloat outside(vec3 p) { return length(p) - g_r; }\n"
        "float inside(vec3 p) { return 0.45 - length(p); }\n"
        "float marchInside(vec3 ro, vec3 rd) {\n"
        "    float t = 0.0;\n"
        "    for (int i = 0; i < 64; i++) { float d = inside(ro + rd * t); if (d < 0.001) break; t += d; }\n"
        "    return t;\n}\n"
        "vec3 refracted(vec3 p, vec3 rd) { return vec3(marchInside(p, refract(rd, normalize(p), 0.7))); }\n"
        "vec3 render(vec3 ro, vec3 rd) {\n"
        "    float t = 0.0;\n"
        "    for (int i = 0; i < 64; i++) { float d = outside(ro + rd * t); if (d < 0.001) break; t += d; }\n"
        "    return refracted(ro + rd * t, rd);\n}\n"
        "void mainImage(out vec4 c, in vec2 f) {\n"
        "    vec3 rd = normalize(vec3((f - 0.5 * iResolution.xy) / iResolution.y, -2.0));\n"
        "    g_r = 0.5 + 0.1 * sin(iTime);\n"
        "    c = vec4(render(vec3(0.0, 0.0, 3.0), rd), 1.0);\n}\n";
    PreparedSdf glass = prepare(text);
    ASSERT_TRUE(glass.ok()) << glass.diagnostics.back().message;
    EXPECT_EQ(glass.signature.entry, "outside");
    EXPECT_EQ(glass.entrySource, EntrySource::March);
    EXPECT_TRUE(glass.entryCandidates.empty());
    EXPECT_NE(glass.entryReason.find("inside (line 6) is marched as often, deeper in mainImage's calls"), std::string::npos)
        << glass.entryReason;
    EXPECT_NE(glass.entryReason.find("after mainImage sets g_r"), std::string::npos) << glass.entryReason;
    EXPECT_NE(glass.signature.prelude.find("g_r = 0.5 + 0.1 * sin(iTime);"), std::string::npos) << glass.signature.prelude;
}

// Two marches as near mainImage as each other, where the second runs only where the first one's
// result lets it: a glass's refraction inside `if (hit.x > 0.)` (a glslify-bundled icosahedron on
// GitHub), or a second pass in the `else` of a test on a colour the first pass decided (Twenkid's
// Hackafe logo). The first is the scene; a second march that runs whatever the first found is
// primary too, and the scene their union (TwoEquallyMarchedFunctionsAreUnitedOrNamedAndOffered).
TEST(EntryPoint, AMarchThatRunsOnlyAfterTheFirstOnesHitIsASecondaryRay) {
    const std::string fields =
        "vec2 glass(vec3 p) { return vec2(length(p) - 0.6, 1.0); }\n"
        "vec2 solid(vec3 p) { return vec2(length(p) - 0.3, 2.0); }\n"
        "vec2 castGlass(vec3 ro, vec3 rd) {\n"
        "    float t = 0.0;\n"
        "    for (int i = 0; i < 64; i++) { vec2 h = glass(ro + rd * t); if (h.x < 0.001) return vec2(t, h.y); t += h.x; }\n"
        "    return vec2(-1.0);\n}\n"
        "vec2 castSolid(vec3 ro, vec3 rd) {\n"
        "    float t = 0.0;\n"
        "    for (int i = 0; i < 64; i++) { vec2 h = solid(ro + rd * t); if (h.x < 0.001) return vec2(t, h.y); t += h.x; }\n"
        "    return vec2(-1.0);\n}\n";
    const std::string refraction =
        fields + "void mainImage(out vec4 c, in vec2 f) {\n"
                 "    vec3 ro = vec3(0.0, 0.0, 3.0), rd = normalize(vec3((f - 0.5 * iResolution.xy) / iResolution.y, -2.0));\n"
                 "    vec2 hit = castGlass(ro, rd);\n"
                 "    c = vec4(0.0);\n"
                 "    if (hit.x > 0.0) {\n"
                 "        vec3 pos = ro + rd * hit.x, ref = refract(rd, normalize(pos), 0.9);\n"
                 "        vec2 inner = castSolid(pos + ref * 0.1, ref);\n"
                 "        c = vec4(inner, 0.0, 1.0);\n"
                 "    }\n}\n";
    PreparedSdf glass = prepare(refraction);
    ASSERT_TRUE(glass.ok()) << glass.diagnostics.back().message;
    EXPECT_EQ(glass.signature.entry, "glass");
    EXPECT_NE(glass.entryReason.find("solid (line 10, run only where glass's march lets it)"), std::string::npos)
        << glass.entryReason;
    // The second pass in the else of a test on what the first decided through a branch.
    const std::string passes =
        fields + "void mainImage(out vec4 c, in vec2 f) {\n"
                 "    vec3 ro = vec3(0.0, 0.0, 3.0), rd = normalize(vec3((f - 0.5 * iResolution.xy) / iResolution.y, -2.0));\n"
                 "    vec2 first = castGlass(ro, rd);\n"
                 "    int m;\n"
                 "    if (first.x > 0.0) { m = 0; } else { m = 1; }\n"
                 "    vec3 colour = vec3(0.2);\n"
                 "    if (m == 1) colour = vec3(0.0);\n"
                 "    else { vec2 second = castSolid(ro, rd); colour += second.y; }\n"
                 "    c = vec4(colour, 1.0);\n}\n";
    PreparedSdf twoPass = prepare(passes);
    ASSERT_TRUE(twoPass.ok()) << twoPass.diagnostics.back().message;
    EXPECT_EQ(twoPass.signature.entry, "glass");
    // A test on what the first march did not compute leaves both primary rays: their union.
    std::string unrelated = passes;
    unrelated.replace(unrelated.find("if (m == 1)"), 11, "if (f.x > 9.)");
    PreparedSdf both = prepare(unrelated);
    ASSERT_TRUE(both.ok()) << both.diagnostics.back().message;
    EXPECT_EQ(both.signature.entry, "glass");
    EXPECT_EQ(both.signature.unionWith, (std::vector<std::pair<std::string, std::string>>{{"solid", ".x"}}));
    // dr2's smoke: the second march's function is handed what the first found (`SmokeCol(ro, rd,
    // dstObj)`, through a value computed from it), and runs in no branch. A value changed by the
    // first's result only after the call (`ro += rd * hit.x` below it) hands it nothing: both primary.
    const std::string smoke =
        fields + "vec4 smokeCol(vec3 ro, vec3 rd, float far) {\n"
                 "    float t = 0.0;\n"
                 "    for (int i = 0; i < 64; i++) { float h = solid(ro + rd * t).x; if (h < 0.001) break; t += h; }\n"
                 "    return vec4(t < far ? 1.0 : 0.0);\n}\n"
                 "void mainImage(out vec4 c, in vec2 f) {\n"
                 "    vec3 ro = vec3(0.0, 0.0, 3.0), rd = normalize(vec3((f - 0.5 * iResolution.xy) / iResolution.y, -2.0));\n"
                 "    vec2 hit = castGlass(ro, rd);\n"
                 "    float dstObj = hit.x < 0.0 ? 50.0 : hit.x;\n"
                 "    c = smokeCol(ro, rd, dstObj);\n"
                 "}\n";
    PreparedSdf given = prepare(smoke);
    ASSERT_TRUE(given.ok()) << given.diagnostics.back().message;
    EXPECT_EQ(given.signature.entry, "glass");
    EXPECT_NE(given.entryReason.find("solid (line 15, run only given what glass's march found)"), std::string::npos)
        << given.entryReason;
    std::string later = smoke;
    later.replace(later.find("    c = smokeCol(ro, rd, dstObj);\n"), 34,
                  "    c = smokeCol(ro, rd, 50.0);\n    ro += rd * hit.x;\n");
    PreparedSdf primaries = prepare(later);
    ASSERT_TRUE(primaries.ok()) << primaries.diagnostics.back().message;
    EXPECT_EQ(primaries.signature.unionWith, (std::vector<std::pair<std::string, std::string>>{{"solid", ".x"}}));
}

// Xafer's SDF platform (a RetroArch port): a Ray struct marched by `map(ray.pos, factor)` with a
// factor computed at each step, a shadow marched by the overload `map(p)`, and a refraction loop
// that reads `getMaterial(ray.pos)` and bends the ray with it (`ray.dir = refract(ray.dir, n,
// mat.refr)`, then fixed steps along it). The field is map, by its point-only overload; the
// material bends the ray but steps no march.
TEST(EntryPoint, AMaterialThatBendsTheRayStepsNoMarchAndAPointOnlyOverloadIsTheField) {
    const std::string text =
        "struct Ray { vec3 pos, dir; float near, dist; };\n"
        "struct Material { vec3 color; float refr; float opacity; };\n"
        "float map(vec3 p, float factor) { return length(p) - 0.5 + 0.0 * factor; }\n"
        "float map(vec3 p) { return map(p, 0.0); }\n"
        "Material getMaterial(vec3 p) { Material m; m.color = p; m.refr = 0.8; m.opacity = 0.7; return m; }\n"
        "Ray march(Ray ray) {\n"
        "    for (int i = 0; i < 64; i++) {\n"
        "        ray.near = map(ray.pos, sqrt(ray.dist) * 0.01);\n"
        "        if (ray.near < 0.001) break;\n"
        "        float n = ray.near * 0.9; ray.pos += ray.dir * n; ray.dist += n;\n"
        "    }\n"
        "    return ray;\n}\n"
        "float shadow(vec3 p, vec3 dir) {\n"
        "    float dist = 0.0;\n"
        "    for (int i = 0; i < 32; i++) { float near = map(p); if (near < 0.001) break; float n = abs(near * 0.1); "
        "p += n * dir; dist += n; }\n"
        "    return dist;\n}\n"
        "vec3 refraction(Ray ray) {\n"
        "    float intensity = 1.0, total = 0.0;\n"
        "    Material mat = getMaterial(ray.pos);\n"
        "    for (int i = 0; i < 4; i++) {\n"
        "        ray.dir = refract(ray.dir, normalize(ray.pos), mat.refr);\n"
        "        ray.pos += ray.dir * 0.002;\n"
        "        ray = march(ray);\n"
        "        mat = getMaterial(ray.pos);\n"
        "        total += intensity; intensity *= 1.0 - mat.opacity;\n"
        "    }\n"
        "    return vec3(total) + shadow(ray.pos, vec3(0, 1, 0));\n}\n"
        "void mainImage(out vec4 c, in vec2 f) {\n"
        "    Ray ray; ray.pos = vec3(0.0, 0.0, -3.0); ray.dir = normalize(vec3(f / iResolution.xy - 0.5, 1.0));\n"
        "    ray.near = 1.0; ray.dist = 0.0;\n"
        "    c = vec4(refraction(ray), 1.0);\n}\n";
    PreparedSdf sdf = prepare(text);
    ASSERT_TRUE(sdf.ok()) << sdf.diagnostics.back().message;
    EXPECT_EQ(sdf.signature.entry, "map");
    EXPECT_EQ(sdf.entrySource, EntrySource::March);
    EXPECT_EQ(sdf.entryReason.find("map (called by the march at line"), 0u) << sdf.entryReason;
    EXPECT_FALSE(sdf.signature.animated) << "the overload of the point alone";
}

// A loop that steps by two calls of one function with other values (yuanlin2008's shadertoy
// repository: a plane and two spheres, `sdSphere(pos, centre, radius)` twice, in a Ray-struct march
// function): the scene is the loop's inline field, not the first sphere. The same call twice
// (`scene(p)` to step and `sign(scene(p))` to go on inside, blackle's x-ray) is one field.
TEST(EntryPoint, ALoopSteppingByTwoCallsOfOneFunctionIsItsInlineField) {
    const std::string text =
        "struct Ray { vec3 ori; vec3 dir; };\n"
        "float sdSphere(vec3 p, vec3 c, float r) { return length(p - c) - r; }\n"
        "float rayMarch(in Ray ray) {\n"
        "    float dist = 0.0;\n"
        "    for (int i = 0; i < 100; i++) {\n"
        "        vec3 pos = ray.ori + ray.dir * dist;\n"
        "        float d0 = pos.y;\n"
        "        float d1 = sdSphere(pos, vec3(0, 0, 0), 1.0);\n"
        "        float d2 = sdSphere(pos, vec3(0.5, 0, 1), 0.5);\n"
        "        float d = min(d0, min(d1, d2));\n"
        "        if (abs(d) < 0.0001) break;\n"
        "        dist += d;\n"
        "    }\n"
        "    return dist;\n}\n"
        "void mainImage(out vec4 c, in vec2 f) {\n"
        "    Ray ray = Ray(vec3(2, 1, 0), normalize(vec3((f - 0.5 * iResolution.xy) / iResolution.y, -1.0)));\n"
        "    c = vec4(vec3(rayMarch(ray) * 0.1), 1.0);\n}\n";
    PreparedSdf sdf = prepare(text);
    ASSERT_TRUE(sdf.ok()) << sdf.diagnostics.back().message;
    EXPECT_EQ(sdf.signature.entry, "rayMarch");
    EXPECT_FALSE(sdf.signature.inlineBody.empty());
    EXPECT_NE(sdf.entryReason.find("its march at line 5 writes the field inline"), std::string::npos) << sdf.entryReason;
    auto tracer = composeTracer(sdf, TracerFeatures{});
    ASSERT_TRUE(tracer.hasValue());
    EXPECT_FALSE(hasErrors(checkWithGlslang(*tracer)));
    std::string once = text;
    once.replace(once.find("sdSphere(pos, vec3(0.5, 0, 1), 0.5)"), 35, "sign(sdSphere(pos, vec3(0, 0, 0), 1.0))");
    PreparedSdf same = prepare(once);
    ASSERT_TRUE(same.ok()) << same.diagnostics.back().message;
    EXPECT_TRUE(same.signature.inlineBody.empty());
    EXPECT_EQ(same.entryReason.find("sdSphere (called by the march at line 8)"), 0u) << same.entryReason;
}

// A terrain that reuses its distance's variable for the clouds after the step (David Hoskins'
// "Alps": `h = Map(p); ... t += clamp(.5 * h, ...); h = MapClouds(p);`): the clouds' value is
// overwritten before the step reads h again, so the march steps by Map alone. Where nothing
// overwrites it first, both step the loop together, as before.
TEST(EntryPoint, AValueOverwrittenBeforeTheStepReadsItDoesNotStepTheMarch) {
    auto shader = [](const std::string& top) {
        return "float Map(vec3 p) { return p.y + 0.5 - 0.1 * sin(3.0 * p.x); }\n"
               "float MapClouds(vec3 p) { return length(p - vec3(0.0, 8.0, 0.0)) - 3.0; }\n"
               "void mainImage(out vec4 c, in vec2 f) {\n"
               "    vec3 ro = vec3(0.0, 0.0, -3.0), rd = normalize(vec3((f - 0.5 * iResolution.xy) / iResolution.y, 1.5));\n"
               "    float t = 0.0, h = 0.0, glow = 0.0;\n"
               "    vec3 p = ro;\n"
               "    for (int j = 0; j < 100; j++) {\n"
               "        p = ro + t * rd;\n" +
               top +
               "        if (h < 0.01) break;\n"
               "        t += clamp(0.5 * h, 0.002, 20.0) + t * 0.004;\n"
               "        h = MapClouds(p);\n"
               "        glow += max(-h, 0.0);\n"
               "    }\n"
               "    c = vec4(t, glow, 0.0, 1.0);\n}\n";
    };
    PreparedSdf terrain = prepare(shader("        h = Map(p);\n"));
    ASSERT_TRUE(terrain.ok()) << terrain.diagnostics.back().message;
    EXPECT_EQ(terrain.signature.entry, "Map");
    EXPECT_EQ(terrain.entrySource, EntrySource::March);
    PreparedSdf conditional = prepare(shader("        if (j == 0) h = Map(p); else h = min(h, Map(p));\n"));
    ASSERT_TRUE(conditional.ok()) << conditional.diagnostics.back().message;
    EXPECT_NE(conditional.entryReason.find("together"), std::string::npos) << conditional.entryReason;
}

// A size-coded march that keeps no float for its distance: the point grows by the direction times
// the field (`p += r * .1 * min(...)`, Chromaney's Glorb Tunnel): the product's float factor, the
// last of `a * b * c`, is the field, and the body runs up to the step.
TEST(EntryPoint, AFieldWrittenInThePointsStepIsThatStepsFactor) {
    const std::string text = "void mainImage(out vec4 o, vec2 c) {\n"
                             "    vec3 p = vec3(0.0, 0.0, -3.0), r = normalize(vec3(c / iResolution.xy - 0.5, 1.0));\n"
                             "    for (int i = 0; i < 99; i++) {\n"
                             "        vec3 q = p;\n"
                             "        q.xz *= mat2(0.8, 0.6, -0.6, 0.8);\n"
                             "        p += r * .5 * min(length(q) - .5, q.y + 1.);\n"
                             "    }\n"
                             "    o = vec4(p, 1.0);\n}\n";
    PreparedSdf sdf = prepare(text);
    ASSERT_TRUE(sdf.ok()) << sdf.diagnostics.back().message;
    EXPECT_EQ(sdf.signature.entry, "mainImage");
    EXPECT_NE(sdf.entryReason.find("writes the field inline: min(length(q) - .5, q.y + 1.)"), std::string::npos)
        << sdf.entryReason;
    EXPECT_NE(sdf.signature.inlineBody.find("return float(min(length(q) - .5, q.y + 1.));"), std::string::npos)
        << sdf.signature.inlineBody;
}

// A march over several balls that returns the hit's colour from inside its loop over them (a raycast
// that marches the point itself by the nearest ball's distance): that return would leave the field
// with a vec4, so it goes like the march's own exits, and the loop over the balls is the field's
// minimum. The composed tracer compiles; before, the driver rejected the entry wrapper.
TEST(EntryPoint, AReturnInsideALoopNestedInTheMarchLeavesTheField) {
    const std::string text =
        "vec3 centres[3] = vec3[3](vec3(-0.5, 0.0, 0.0), vec3(0.5, 0.0, 0.0), vec3(0.0, 0.5, 0.0));\n"
        "float ball(vec3 p, int i) { return distance(p, centres[i]) - 0.3; }\n"
        "vec4 raycast(vec3 pos, vec3 dir) {\n"
        "    float total = 0.0;\n"
        "    for (int n = 0; n < 100; n++) {\n"
        "        float len = 100.0;\n"
        "        for (int s = 0; s < 3; s++) {\n"
        "            float d = ball(pos, s);\n"
        "            if (d < 0.001) return vec4(float(s) / 3.0, total * 0.1, 0.0, 1.0);\n"
        "            if (d < len) len = d;\n"
        "        }\n"
        "        total += len;\n"
        "        pos += dir * len;\n"
        "    }\n"
        "    return vec4(0.0);\n}\n"
        "void mainImage(out vec4 c, in vec2 f) {\n"
        "    c = raycast(vec3(0.0, 0.0, -3.0), normalize(vec3((f - 0.5 * iResolution.xy) / iResolution.y, 1.5)));\n"
        "}\n";
    PreparedSdf sdf = prepare(text);
    ASSERT_TRUE(sdf.ok()) << sdf.diagnostics.back().message;
    EXPECT_EQ(sdf.signature.entry, "raycast");
    EXPECT_EQ(sdf.signature.inlineBody.find("return vec4"), std::string::npos) << sdf.signature.inlineBody;
    auto composed = composeTracer(sdf, TracerFeatures{});
    ASSERT_TRUE(composed.hasValue());
    EXPECT_FALSE(hasErrors(checkWithGlslang(*composed)));
}

// A march in the `#else` of a preprocessor option (`#if NAIVE_RAYMARCHING` fixed steps `#else` a
// sphere tracer `#endif`, with NAIVE_RAYMARCHING 0): the branches before the one holding the march
// are left out of the code run before it, and so are the directives still open at the loop.
TEST(EntryPoint, AMarchInAPreprocessorOptionsElseOpens) {
    const std::string text =
        "#define NAIVE 0\n"
        "float ball(vec3 p) { return length(p) - 0.5; }\n"
        "vec4 raycast(vec3 pos, vec3 dir) {\n"
        "    float total = 0.0;\n"
        "#if NAIVE\n"
        "    for (float t = 0.0; t < 10.0; t += 0.1) if (ball(pos + dir * t) < 0.1) return vec4(t);\n"
        "#else\n"
        "#ifdef SHOW_STEPS\n"
        "    total = 1.0;\n"
        "#endif\n"
        "    for (int n = 0; n < 100; n++) {\n"
        "        float len = length(pos) - 0.5;\n"
        "        total += len;\n"
        "        pos += dir * len;\n"
        "    }\n"
        "#endif\n"
        "    return vec4(total);\n}\n"
        "void mainImage(out vec4 c, in vec2 f) {\n"
        "    c = raycast(vec3(0.0, 0.0, -3.0), normalize(vec3((f - 0.5 * iResolution.xy) / iResolution.y, 1.5)));\n"
        "}\n";
    PreparedSdf sdf = prepare(text);
    ASSERT_TRUE(sdf.ok()) << sdf.diagnostics.back().message;
    EXPECT_EQ(sdf.signature.entry, "raycast") << sdf.entryReason;
    EXPECT_NE(sdf.signature.inlineBody.find("#ifdef SHOW_STEPS"), std::string::npos) << sdf.signature.inlineBody;
    EXPECT_EQ(sdf.signature.inlineBody.find("#if NAIVE"), std::string::npos) << sdf.signature.inlineBody;
    auto composed = composeTracer(sdf, TracerFeatures{});
    ASSERT_TRUE(composed.hasValue());
    EXPECT_FALSE(hasErrors(checkWithGlslang(*composed)));
}

// A field with an out parameter and a flag (a tea cup scene on Shadertoy: `map(pt, mat,
// includeDielectrics)`), marched by castRay, which render calls, not mainImage: the flag is the
// constant render passes for the primary ray, the out parameter a local of the wrapper's. A flag
// render computes per pixel cannot be traced, and the reason says so.
TEST(EntryPoint, AnOutParameterIsALocalAndAConstantFromTheNearestCallerIsTraced) {
    auto shader = [](const std::string& flag) {
        return "struct Material { float id; };\n"
               "float map(in vec3 p, out Material mat, in bool withGlass) {\n"
               "    mat.id = 1.0; float d = length(p) - 0.5;\n"
               "    return withGlass ? min(d, length(p - vec3(0.6, 0.0, 0.0)) - 0.2) : d;\n}\n"
               "float castRay(vec3 ro, vec3 rd, out Material mat, bool withGlass) {\n"
               "    float t = 0.0;\n"
               "    for (int i = 0; i < 64; i++) { float h = map(ro + rd * t, mat, withGlass); if (h < 0.001) break; t += h; }\n"
               "    return t;\n}\n"
               "vec3 render(vec3 ro, vec3 rd) { Material mat; float t = castRay(ro, rd, mat, " +
               flag +
               "); return vec3(t * mat.id); }\n"
               "void mainImage(out vec4 c, in vec2 f) {\n"
               "    vec3 rd = normalize(vec3((f - 0.5 * iResolution.xy) / iResolution.y, -2.0));\n"
               "    c = vec4(render(vec3(0.0, 0.0, 3.0), rd), 1.0);\n}\n";
    };
    PreparedSdf cup = prepare(shader("true"));
    ASSERT_TRUE(cup.ok()) << cup.diagnostics.back().message;
    EXPECT_EQ(cup.signature.entry, "map");
    EXPECT_NE(cup.entryReason.find("with mat, withGlass as render computes it"), std::string::npos) << cup.entryReason;
    ASSERT_EQ(cup.signature.traced.size(), 2u);
    EXPECT_EQ(cup.signature.traced[0].value, "true");
    EXPECT_EQ(cup.signature.traced[1].type, "Material");
    EXPECT_TRUE(cup.signature.traced[1].value.empty());
    const std::vector<ShaderPiece> stage{{"<test main>", "void main() { float d = sdfwb_sdf(vec3(0.6, 0.0, 0.0)); }\n"}};
    const std::vector<Diagnostic> found = checkWithGlslang(composeSdfShader(cup, Stage::Fragment, stage, {}));
    EXPECT_TRUE(found.empty()) << formatDiagnostic(found.front());

    PreparedSdf perPixel = prepare(shader("rd.y > 0.0"));
    EXPECT_FALSE(perPixel.ok());
    EXPECT_NE(perPixel.entryReason.find("castRay's 'withGlass' is rd.y > 0.0 where render calls it, not a constant"),
              std::string::npos)
        << perPixel.entryReason;
}

// Issue 47, point 2: a macro whose body names itself wraps the input; the input is still provided
// (for time, as a uniform the renderer sets) and the composed shader compiles. A macro that
// replaces the name outright still declares it.
TEST(CompatNeeds, AMacroThatWrapsAnInputStillGetsTheInput) {
    PreparedSdf wrapped = prepare("const float mx = 1.6;\n#define iTime (iTime - 25. + mx)\n"
                                  "#define iResolution (iResolution * 0.5)\n"
                                  "float map(vec3 p) { return length(p) - 0.5 + 0.1 * sin(iTime) + 0.0 * iResolution.x; }\n");
    ASSERT_TRUE(wrapped.ok());
    EXPECT_TRUE(wrapped.usesTime());
    for (const char* name : {"iTime", "iResolution"}) {
        EXPECT_NE(std::find(wrapped.compat.symbols.begin(), wrapped.compat.symbols.end(), name), wrapped.compat.symbols.end())
            << name;
        EXPECT_NE(std::find(wrapped.compat.wrapped.begin(), wrapped.compat.wrapped.end(), name), wrapped.compat.wrapped.end())
            << name;
    }
    auto tracer = composeTracer(wrapped, TracerFeatures{});
    ASSERT_TRUE(tracer.hasValue());
    EXPECT_NE(tracer->text.find("uniform float iTime;"), std::string::npos);
    auto diagnostics = checkWithGlslang(*tracer);
    EXPECT_FALSE(hasErrors(diagnostics)) << (diagnostics.empty() ? "" : formatDiagnostic(diagnostics[0]));

    PreparedSdf replaced = prepare("#define iTime 2.0\nfloat map(vec3 p) { return length(p) - 0.5 + 0.1 * sin(iTime); }\n");
    ASSERT_TRUE(replaced.ok());
    EXPECT_TRUE(replaced.compat.symbols.empty());
}

// Issue 47, point 3: every declarator of a file-scope declaration declares its name; a name in an
// initializer's arguments, a function's or a local declaration does not.
TEST(CompatNeeds, EveryDeclaratorOfAFileScopeListDeclaresItsName) {
    auto needs = [](const std::string& text) { return prepare(text).compat.symbols; };
    const std::string use = "float map(vec3 p) { return length(p) - 0.5 + 0.0 * pi; }\n";
    EXPECT_TRUE(needs("float det = .005, maxdist = 50., pi = 3.1416;\n" + use).empty());
    EXPECT_TRUE(needs("const float EPS = 1e-3,\n    FAR = 40.0,\n    pi = 3.1416;\n" + use).empty());
    EXPECT_TRUE(needs("float a, pi;\n" + use).empty());
    EXPECT_EQ(needs("const vec3 v = vec3(1.0, pi, 2.0);\n" + use), (std::vector<std::string>{"pi"}));
    EXPECT_EQ(needs("float g(float a, float b) { float c, pi = 1.0; return a + pi; }\n" + use), (std::vector<std::string>{"pi"}));
    PreparedSdf listed = prepare("float det = .005, maxdist = 50., pi = 3.1416;\n" + use);
    auto tracer = composeTracer(listed, TracerFeatures{});
    ASSERT_TRUE(tracer.hasValue());
    EXPECT_FALSE(hasErrors(checkWithGlslang(*tracer)));
}

// Issue 47, points 4 and 5: mainImage's helpers read gl_FragCoord and call texture() with a bias;
// outside the fragment stage the composer renames them (the origin; the level-0 lookup), so the
// sampler's compute stage compiles; the fragment stage keeps them.
TEST(CompatNeeds, FragmentOnlyBuiltinsInHelpersCompileInTheComputeStage) {
    PreparedSdf sdf = prepare("float hash12(vec2 p) { return fract(sin(dot(p, vec2(12.9898, 78.233))) * 43758.5453); }\n"
                              "float dither() { return hash12(gl_FragCoord.xy) / 255.0; }\n"
                              "vec3 sky(vec3 rd) { return texture(iChannel0, rd.xy * .5 + .5, -100.).rgb\n"
                              "    + texture(iChannel0, vec2(rd.x, (rd.y)), 4.0).rgb + texture(iChannel0, rd.xy).rgb; }\n"
                              "float map(vec3 p) { return length(p) - 0.5; }\n"
                              "void mainImage(out vec4 c, in vec2 f) { c = vec4(sky(vec3(f, 1.0)) + dither(), 1.0); }\n");
    ASSERT_TRUE(sdf.ok());
    auto pieces = samplingStagePieces(*builtinPiece("samplers/rand.glsl"));
    ASSERT_TRUE(pieces.hasValue());
    ComposedShader compute = composeSdfShader(sdf, Stage::Compute, *pieces, {});
    EXPECT_EQ(compute.text.find("gl_FragCoord.xy"), std::string::npos);
    EXPECT_NE(compute.text.find("hash12(sdfwb_FragCoord.xy)"), std::string::npos);
    EXPECT_NE(compute.text.find("sdfwb_textureBias(iChannel0, rd.xy * .5 + .5, -100.)"), std::string::npos);
    EXPECT_NE(compute.text.find("sdfwb_textureBias(iChannel0, vec2(rd.x, (rd.y)), 4.0)"), std::string::npos);
    EXPECT_NE(compute.text.find("+ texture(iChannel0, rd.xy)"), std::string::npos) << "the two-argument form stays";
    auto diagnostics = checkWithGlslang(compute);
    EXPECT_FALSE(hasErrors(diagnostics)) << (diagnostics.empty() ? "" : formatDiagnostic(diagnostics[0]));
    auto tracer = composeTracer(sdf, TracerFeatures{});
    ASSERT_TRUE(tracer.hasValue());
    EXPECT_NE(tracer->text.find("hash12(gl_FragCoord.xy)"), std::string::npos);
    EXPECT_NE(tracer->text.find("texture(iChannel0, rd.xy * .5 + .5, -100.)"), std::string::npos);
    EXPECT_FALSE(hasErrors(checkWithGlslang(*tracer)));
}

// Real shaders' fields come in more forms than `float map(vec3)`: a struct (the march's member is
// the distance, else the struct's first float), out parameters (the wrapper passes locals), and
// helpers named like GLSL's deprecated noise1..4 (renamed: glslang refuses them at 4.30). A vec3
// a reflection loop grows the point by (calcNormal) is not a field.
TEST(EntryPoint, AVec3FieldWhoseXTheMarchStepsByIsTheEntry) {
    // evilryu's style: `vec3 f(vec3 p)` returns (distance, orbit trap, 0); the march reads only .x.
    const std::string field = "vec3 f(vec3 p) { float d = length(p) - 0.5; return vec3(d, length(p), 0.0); }\n"
                              "vec3 nor(vec3 p) { vec2 e = vec2(1e-3, 0.0);\n"
                              "    return normalize(vec3(f(p + e.xyy).x - f(p - e.xyy).x, f(p + e.yxy).x - f(p - e.yxy).x,\n"
                              "                          f(p + e.yyx).x - f(p - e.yyx).x)); }\n";
    PreparedSdf held = prepare(wholeShader(field, "    float t = 0.0;\n    vec3 c;\n    for (int i = 0; i < 64; i++) {\n"
                                                  "        c = f(ro + rd * t);\n        if (c.x < 1e-3) break;\n"
                                                  "        t += c.x;\n    }\n    return t;\n"));
    ASSERT_TRUE(held.ok()) << (held.diagnostics.empty() ? "" : formatDiagnostic(held.diagnostics.front()));
    EXPECT_EQ(held.signature.entry, "f");
    EXPECT_EQ(held.signature.returnType, "vec3");
    auto tracer = composeTracer(held, TracerFeatures{});
    ASSERT_TRUE(tracer.hasValue());
    EXPECT_FALSE(hasErrors(checkWithGlslang(*tracer)));
    // Read through the call itself.
    PreparedSdf direct = prepare(wholeShader(field, "    float t = 0.0;\n    for (int i = 0; i < 64; i++) {\n"
                                                    "        float d = f(ro + rd * t).x;\n        if (d < 1e-3) break;\n"
                                                    "        t += d;\n    }\n    return t;\n"));
    ASSERT_TRUE(direct.ok()) << (direct.diagnostics.empty() ? "" : formatDiagnostic(direct.diagnostics.front()));
    EXPECT_EQ(direct.signature.entry, "f");
    // A vec3 the loop reads in more than its x (a normal, a colour) is not a field.
    PreparedSdf normal = prepare(
        wholeShader("vec3 bend(vec3 p) { return vec3(p.x, p.y + 0.1, p.z); }\n",
                    "    float t = 0.0;\n    vec3 q = ro;\n    for (int i = 0; i < 64; i++) {\n        vec3 b = bend(q);\n"
                    "        q += rd * 0.01 * b.x + rd * 0.01 * b.y;\n    }\n    return t;\n"));
    EXPECT_FALSE(normal.ok()) << "a vec3 read in x and y is not taken for a distance";
    // A tunnel's path (totetmatt's cable tunnel): the loop moves the point by the whole vec3 and
    // reads its x elsewhere; the distance is written inline after it, and that is the field.
    PreparedSdf tunnel =
        prepare(wholeShader("vec3 path(vec3 p) { return vec3(sin(p.z * 0.1), cos(p.z * 0.1), 0.0); }\n",
                            "    float g = 0.0, e;\n    for (int i = 0; i < 64; i++) {\n        vec3 p = ro + rd * g;\n"
                            "        p -= path(p);\n        float h = length(p.xy) - 0.5 - 0.1 * path(p).x;\n"
                            "        g += e = max(0.001, h);\n    }\n    return g;\n"));
    EXPECT_NE(tunnel.signature.entry, "path") << "a path the point is moved by is not a field";
}

// A field with a parameter after the point that mainImage computes and hands to the march in a call
// written one argument to a line (glslang places the call at its last line).
TEST(EntryPoint, ParametersMainImageComputesAreTracedAndThosePerPixelWarned) {
    auto shader = [](const std::string& second, const std::string& secondValue) {
        return "float field(vec3 p, " + second +
               ") { return length(p) - 0.5 - 0.1 * k.x; }\n"
               "float march(vec3 ro, vec3 rd, " +
               second +
               ") {\n"
               "    float t = 0.0;\n"
               "    for (int i = 0; i < 64; i++) { float d = field(ro + rd * t, k); if (d < 1e-3) break; t += d; }\n"
               "    return t;\n"
               "}\n"
               "void mainImage(out vec4 fragColor, in vec2 fragCoord) {\n"
               "    vec2 uv = (fragCoord - 0.5 * iResolution.xy) / iResolution.y;\n"
               "    vec3 dir = normalize(vec3(uv, 1.0));\n"
               "    float grow = 0.5 + 0.5 * sin(iTime);\n"
               "    float t = march(vec3(0.0, 0.0, -3.0),\n"
               "                    dir,\n"
               "                    " +
               secondValue +
               ");\n"
               "    fragColor = vec4(vec3(t), 1.0);\n"
               "}\n";
    };
    PreparedSdf timed = prepare(shader("vec2 k", "vec2(grow)"));
    ASSERT_TRUE(timed.ok()) << (timed.diagnostics.empty() ? "" : formatDiagnostic(timed.diagnostics.front()));
    EXPECT_EQ(timed.signature.entry, "field");
    EXPECT_EQ(timed.signature.arguments, ", k");
    EXPECT_TRUE(timed.diagnostics.empty()) << "a value of time alone is the field's own: "
                                           << formatDiagnostic(timed.diagnostics.front());
    auto tracer = composeTracer(timed, TracerFeatures{});
    ASSERT_TRUE(tracer.hasValue());
    EXPECT_FALSE(hasErrors(checkWithGlslang(*tracer)));

    // The same parameter computed from the pixel (through uv and dir): opens, with a warning at the march.
    PreparedSdf pixel = prepare(shader("vec3 k", "dir"));
    ASSERT_TRUE(pixel.ok()) << (pixel.diagnostics.empty() ? "" : formatDiagnostic(pixel.diagnostics.front()));
    EXPECT_EQ(pixel.signature.entry, "field");
    ASSERT_EQ(pixel.diagnostics.size(), 1u);
    EXPECT_EQ(pixel.diagnostics[0].severity, Severity::Warning);
    EXPECT_EQ(pixel.diagnostics[0].line, 4);
    EXPECT_NE(pixel.diagnostics[0].message.find("field reads 'k', which mainImage computes for each pixel"), std::string::npos)
        << pixel.diagnostics[0].message;

    // mainImage that marches itself: the statements before its loop set what the field reads.
    PreparedSdf own = prepare("float radius;\nfloat map(vec3 p) { return length(p) - radius; }\n"
                              "void mainImage(out vec4 c, in vec2 u) {\n"
                              "    radius = 0.5 + 0.1 * sin(iTime);\n"
                              "    float t = 0.0;\n"
                              "    for (int i = 0; i < 64; i++) {\n"
                              "        float d = map(vec3(0.0, 0.0, -3.0) + vec3(0.0, 0.0, 1.0) * t);\n"
                              "        if (d < 1e-3) break;\n"
                              "        t += d;\n"
                              "    }\n"
                              "    c = vec4(t);\n"
                              "}\n");
    ASSERT_TRUE(own.ok()) << (own.diagnostics.empty() ? "" : formatDiagnostic(own.diagnostics.front()));
    EXPECT_NE(own.entryReason.find("after mainImage sets radius"), std::string::npos) << own.entryReason;
    EXPECT_NE(entryWrapper(own).find("radius = 0.5 + 0.1 * sin(iTime);"), std::string::npos) << entryWrapper(own);
}

// File-scope variables mainImage sets before the march: named on the entry line, run once in a
// block of their own; one computed from the pixel (a ray direction) is warned about, a swizzle of
// the pixel's uv in an earlier statement does not make every later `.x` the pixel's.
TEST(EntryPoint, GlobalsMainImageSetsFirstAndThoseFromThePixel) {
    auto shader = [](const std::string& field, const std::string& sets) {
        return "float radius;\nvec3 dir;\nfloat map(vec3 p) { return " + field +
               "; }\n"
               "float march(vec3 ro, vec3 rd) {\n"
               "    float t = 0.0;\n"
               "    for (int i = 0; i < 64; i++) { float d = map(ro + rd * t); if (d < 1e-3) break; t += d; }\n"
               "    return t;\n"
               "}\n"
               "void mainImage(out vec4 fragColor, in vec2 p) {\n"
               "    vec2 uv = (p - 0.5 * iResolution.xy) / iResolution.y;\n"
               "    uv.x *= 1.5;\n" +
               sets +
               "    float t = march(vec3(0.0, 0.0, -3.0), normalize(vec3(uv, 1.0)));\n"
               "    fragColor = vec4(vec3(t), 1.0);\n"
               "}\n";
    };
    PreparedSdf mouse = prepare(shader("length(p) - radius", "    radius = 0.5 + 0.1 * iMouse.x;\n"));
    ASSERT_TRUE(mouse.ok()) << (mouse.diagnostics.empty() ? "" : formatDiagnostic(mouse.diagnostics.front()));
    EXPECT_NE(mouse.entryReason.find("after mainImage sets radius"), std::string::npos) << mouse.entryReason;
    EXPECT_TRUE(mouse.diagnostics.empty()) << formatDiagnostic(mouse.diagnostics.front());
    const std::string wrapper = entryWrapper(mouse);
    EXPECT_NE(wrapper.find("if (!sdfwb_preludeRun) { sdfwb_preludeRun = true;"), std::string::npos) << wrapper;
    auto tracer = composeTracer(mouse, TracerFeatures{});
    ASSERT_TRUE(tracer.hasValue());
    EXPECT_FALSE(hasErrors(checkWithGlslang(*tracer))) << "mainImage's `p` is the pixel; the wrapper's point is its own";

    PreparedSdf pixel = prepare(shader("length(p) - 0.5 + 0.1 * dir.x", "    dir = normalize(vec3(uv, 1.0));\n"));
    ASSERT_TRUE(pixel.ok()) << (pixel.diagnostics.empty() ? "" : formatDiagnostic(pixel.diagnostics.front()));
    ASSERT_EQ(pixel.diagnostics.size(), 1u);
    EXPECT_NE(pixel.diagnostics[0].message.find("map reads 'dir', which mainImage computes for each pixel"), std::string::npos)
        << pixel.diagnostics[0].message;
}

TEST(EntryPoint, StructReturnsOutParametersAndNoiseNamedHelpers) {
    const std::string structField = "struct Hit { float id; float dist; };\n"
                                    "Hit scene(vec3 p) { Hit h; h.id = 1.0; h.dist = length(p) - 0.5; return h; }\n";
    PreparedSdf hit = prepare(wholeShader(structField, "    float t = 0.0;\n    for (int i = 0; i < 64; i++) {\n"
                                                       "        Hit h = scene(ro + rd * t);\n        if (h.dist < 1e-3) break;\n"
                                                       "        t += h.dist;\n    }\n    return t;\n"));
    ASSERT_TRUE(hit.ok()) << (hit.diagnostics.empty() ? "" : formatDiagnostic(hit.diagnostics.front()));
    EXPECT_EQ(hit.signature.entry, "scene");
    EXPECT_EQ(hit.signature.member, "dist") << "the member the march steps by, not the first float";
    EXPECT_NE(entryWrapper(hit).find("return scene(p).dist;"), std::string::npos) << entryWrapper(hit);
    auto tracer = composeTracer(hit, TracerFeatures{});
    ASSERT_TRUE(tracer.hasValue());
    EXPECT_FALSE(hasErrors(checkWithGlslang(*tracer)));
    // By name (no march to read), the struct's first float member.
    PreparedSdf named = prepare("struct Res { float d; int mat; };\nRes map(vec3 p) { Res r; r.d = length(p) - 0.5; r.mat = 1; "
                                "return r; }\n");
    ASSERT_TRUE(named.ok());
    EXPECT_EQ(named.signature.member, "d");

    PreparedSdf withOut = prepare("struct Material { vec3 albedo; float rough; };\n"
                                  "float sdf(in vec3 pt, out Material mat, inout float glow) { mat.albedo = vec3(1.0); "
                                  "mat.rough = 0.5; glow += 0.1; return length(pt) - 0.5; }\n");
    ASSERT_TRUE(withOut.ok()) << (withOut.diagnostics.empty() ? "" : formatDiagnostic(withOut.diagnostics.front()));
    EXPECT_EQ(withOut.signature.outParameters, (std::vector<std::string>{"Material", "float"}));
    EXPECT_NE(entryWrapper(withOut).find("Material sdfwb_out0; float sdfwb_out1; return sdf(p, sdfwb_out0, sdfwb_out1);"),
              std::string::npos)
        << entryWrapper(withOut);
    tracer = composeTracer(withOut, TracerFeatures{});
    ASSERT_TRUE(tracer.hasValue());
    EXPECT_FALSE(hasErrors(checkWithGlslang(*tracer)));

    PreparedSdf noise = prepare("float noise2(vec2 p) { return fract(sin(dot(p, vec2(12.9, 78.2))) * 43758.5); }\n"
                                "float map(vec3 p) { return length(p) - 0.5 + 0.01 * noise2(p.xz); }\n");
    ASSERT_TRUE(noise.ok());
    EXPECT_EQ(noise.compat.renamed, (std::vector<std::string>{"noise2"}));
    tracer = composeTracer(noise, TracerFeatures{});
    ASSERT_TRUE(tracer.hasValue());
    EXPECT_NE(tracer->text.find("float sdfwb_noise2(vec2 p)"), std::string::npos);
    auto diagnostics = checkWithGlslang(*tracer);
    EXPECT_FALSE(hasErrors(diagnostics)) << (diagnostics.empty() ? "" : formatDiagnostic(diagnostics[0]));

    // calcNormal grows the point in a reflection loop; the field is found by name (no march loop).
    PreparedSdf reflection = prepare(wholeShader(
        "float map(vec3 p) { return length(p) - 0.5; }\n"
        "vec3 calcNormal(vec3 p) { return normalize(p); }\n",
        "    vec3 p = ro;\n    for (int i = 0; i < 3; i++) { vec3 n = calcNormal(p); p += n * 0.01; }\n    return p.x;\n"));
    ASSERT_TRUE(reflection.ok());
    EXPECT_EQ(reflection.signature.entry, "map");
    EXPECT_EQ(reflection.entrySource, EntrySource::Convention);
}

// The Metropolis chain is written once (sampling/metropolis_chain.glsl) and composed for the
// samplers that call it: both built-in metropolis samplers, and a user's sampler that defines its
// own target the same way; no other sampler compiles it.
TEST(SamplingStage, ComposesTheMetropolisChainForTheSamplersThatCallIt) {
    auto names = [](const std::vector<ShaderPiece>& pieces) {
        std::vector<std::string> list;
        for (const ShaderPiece& piece : pieces) list.push_back(piece.name);
        return list;
    };
    const std::string chain = "sdfwb:sampling/metropolis_chain.glsl";
    for (const char* file : {"samplers/metropolis.glsl", "samplers/metropolis_curvature.glsl"}) {
        auto pieces = samplingStagePieces(*builtinPiece(file));
        ASSERT_TRUE(pieces.hasValue()) << file;
        const auto list = names(*pieces);
        const auto at = std::find(list.begin(), list.end(), chain);
        ASSERT_NE(at, list.end()) << file;
        EXPECT_EQ(*(at + 1), std::string("sdfwb:") + file) << "the chain comes right before its sampler";
    }
    for (const char* file : {"samplers/rand.glsl", "samplers/near.glsl", "analysis/points.glsl"}) {
        auto pieces = samplingStagePieces(*builtinPiece(file));
        ASSERT_TRUE(pieces.hasValue()) << file;
        const auto list = names(*pieces);
        EXPECT_EQ(std::find(list.begin(), list.end(), chain), list.end()) << file;
    }
    // A mention in a comment is not a call.
    auto commented = samplingStagePieces({"mine.glsl", "// unlike sdfwb_metropolisChain(index, p)\n"
                                                       "bool samplePosition(uint index, out vec3 position) {\n"
                                                       "    position = vec3(0.0);\n    return true;\n}\n"});
    ASSERT_TRUE(commented.hasValue());
    EXPECT_EQ(names(*commented).size(), 5u);
    // A user's sampler: the chain towards the surface, weighted towards y > 0.
    PreparedSdf sdf = prepare("float sdf(vec3 p) { return length(p) - 0.5; }\n");
    ASSERT_TRUE(sdf.ok());
    auto user = samplingStagePieces({"upper.glsl", "float sdfwb_stateTerm(vec3 p, float f) { return p.y; }\n"
                                                   "float sdfwb_logTargetRatio(float fx, float tx, float fy, float ty) {\n"
                                                   "    return (abs(fx) - abs(fy)) / sdfwb_kBand + (ty - tx);\n}\n"
                                                   "bool samplePosition(uint index, out vec3 position) {\n"
                                                   "    return sdfwb_metropolisChain(index, position);\n}\n"});
    ASSERT_TRUE(user.hasValue());
    auto diagnostics = checkWithGlslang(composeSdfShader(sdf, Stage::Compute, *user, {}));
    EXPECT_FALSE(hasErrors(diagnostics)) << (diagnostics.empty() ? "" : formatDiagnostic(diagnostics[0]));
}

// Issue 46, point 3: a driver inlines a field at every call site, so the sampling stage calls it
// from one place (sdfwb_valueAndGradient's loop) besides the surface samplers' ray march; a mesh's
// own field from one place only. Twelve call sites compiled a mesh's walks twelve times: 10 s cold
// on llvmpipe for a 968-triangle mesh, 0.7 s with one.
TEST(SamplingStage, CallsTheFieldFromOnePlace) {
    std::string stage;
    for (const char* file : {"sampling/common.glsl", "sampling/sample.comp", "samplers/rand.glsl", "samplers/near.glsl",
                             "samplers/surface.glsl", "samplers/grid.glsl", "samplers/jitter.glsl"}) {
        auto text = builtinShader(file);
        ASSERT_TRUE(text.hasValue()) << file;
        stage += stripComments(*text) + "\n";
    }
    // A field without loops writes its calls out (SDFWB_FIELD_WITHOUT_LOOPS): that branch is cheap to
    // compile by definition; the rest must call the field from one place.
    const std::size_t writtenOut = stage.find("#if defined(SDFWB_FIELD_WITHOUT_LOOPS)");
    ASSERT_NE(writtenOut, std::string::npos);
    const std::size_t loopForm = stage.find("#else", writtenOut);
    ASSERT_NE(loopForm, std::string::npos);
    stage.erase(writtenOut, loopForm - writtenOut);
    auto calls = [&stage](const std::string& name) {
        const std::regex call("\\b" + name + R"(\s*\()");
        const std::regex definition(R"(\b(?:float|vec3|void|bool)\s+)" + name + R"(\s*\()");
        const auto count = [&](const std::regex& r) {
            return std::distance(std::sregex_iterator(stage.begin(), stage.end(), r), std::sregex_iterator());
        };
        return count(call) - count(definition);
    };
    EXPECT_EQ(calls("sdfwb_sdf"), 2) << "sdfwb_valueAndGradient's loop and sdfwb_traceRay's march";
    EXPECT_EQ(calls("sdfwb_meshSdfGradient"), 1) << "a mesh's own field: sdfwb_valueAndGradient's loop";
    EXPECT_EQ(calls("sdfwb_meshSdf"), 0);
    EXPECT_EQ(calls("sdfwb_valueAndGradient"), 2) << "the row's value, and sdfwb_gradientAt";
}

// Issue 47: an inline field's statements are read by regular expressions; one of 200,000
// characters (a golfed one-liner, or spaces) must neither overflow the stack nor stop the file
// from opening (core/Regex.h's linear executor).
TEST(EntryPoint, AnInlineFieldWithAVeryLongStatementOpens) {
    const std::string spaces(200000, ' ');
    const std::string text = "void mainImage(out vec4 c, in vec2 f) {\n"
                             "    float t = 0.0;\n"
                             "    for (int i = 0; i < 64; i++) {\n"
                             "        vec3 p = vec3(0.0, 0.0, -3.0) +" +
                             spaces + "vec3(0.0, 0.0, 1.0) * t;\n        float d = length(p) - 1.0;\n        t +=" + spaces +
                             "d;\n    }\n    c = vec4(t);\n}\n";
    PreparedSdf sdf = prepare(text);
    ASSERT_TRUE(sdf.ok());
    EXPECT_FALSE(sdf.signature.inlineBody.empty());
    EXPECT_NE(sdf.entryReason.find("writes the field inline"), std::string::npos) << sdf.entryReason;
}

// A float after the point is read as the time. Named as the entry, a function whose float is a
// radius (`sdSphere(vec3 p, float r)`) opens with a warning at its definition saying so and how to
// give a value; a float named as the time does not warn.
TEST(EntryPoint, AFloatAfterThePointNotNamedAsTheTimeIsWarnedAbout) {
    const std::string text = "// a primitive\nfloat sdSphere(vec3 p, float r) { return length(p) - r; }\n"
                             "float spin(vec3 p, float time) { return length(p.xz) - 0.5 + 0.1 * sin(time); }\n";
    PreparedSdf radius = prepareSdf(text, "<test>", {}, IncludeOptions{}, "sdSphere");
    ASSERT_TRUE(radius.ok());
    EXPECT_TRUE(radius.signature.animated);
    const auto warning = std::find_if(radius.diagnostics.begin(), radius.diagnostics.end(),
                                      [](const Diagnostic& d) { return d.severity == Severity::Warning; });
    ASSERT_NE(warning, radius.diagnostics.end());
    EXPECT_EQ(warning->line, 2);
    EXPECT_NE(warning->message.find("sdSphere's 'r' after the point is given the scene time"), std::string::npos)
        << warning->message;
    EXPECT_NE(warning->message.find("return sdSphere(p, VALUE);"), std::string::npos) << warning->message;
    PreparedSdf timed = prepareSdf(text, "<test>", {}, IncludeOptions{}, "spin");
    ASSERT_TRUE(timed.ok());
    EXPECT_TRUE(std::none_of(timed.diagnostics.begin(), timed.diagnostics.end(),
                             [](const Diagnostic& d) { return d.severity == Severity::Warning; }));
}

// Shrunk and golfed code (GLSL Shader Shrinker's output) names its types through macros: the march's
// field is found through them, a struct's and a vec2's, and the reason keeps the file's line. A
// macro whose body is not one type (a colour, a function-like macro) is left as it is.
TEST(EntryPoint, TypesNamedThroughMacrosAreReadAsTheirTypes) {
    const std::string head =
        "#define v3\tvec3\n#define v2 vec2\n#define _f  float\n#define W v3(.6, .8, .9)\n"
        "#define R(a) mat2(cos(a), sin(a), -sin(a), cos(a))\n"
        "_f box(v3 p, v3 r) { p = abs(p) - r; return length(max(p, 0.)) + min(max(p.x, max(p.y, p.z)), 0.); }\n";
    const std::string march = "void mainImage(out vec4 o, v2 w) {\n"
                              "    v2 uv = (w - .5 * iResolution.xy) / iResolution.y;\n"
                              "    v3 ro = v3(0, 0, -3), rd = normalize(v3(uv, 1.5)), p = ro;\n"
                              "    for (int i = 0; i < 80; i++) {\n"
                              "        FIELD\n"
                              "        p += d * rd;\n"
                              "    }\n"
                              "    o = vec4(W * length(p - ro) / 5., 1);\n"
                              "}\n";
    struct Case {
        const char* field;
        const char* step;
        const char* entry;
        const char* returnType;
    };
    const Case cases[] = {
        {"struct Hit { _f d; int id; };\n"
         "Hit E(v3 p) { p.xz *= R(.3); Hit h = Hit(box(p, v3(.4)), 1); _f s = length(p) - .5;\n"
         "    if (s < h.d) h = Hit(s, 2); return h; }\n",
         "Hit h = E(p); _f d = h.d; if (d < .001) break;", "E", "Hit"},
        {"v2 B(v3 p) { v2 z = v2(box(p, v3(.4)), 1); _f g = p.y + 1.; if (g < z.x) z = v2(g, 2); return z; }\n",
         "_f d = B(p).x; if (d < .001) break;", "B", "vec2"},
    };
    for (const Case& c : cases) {
        std::string text = head + c.field + march;
        text.replace(text.find("FIELD"), 5, c.step);
        PreparedSdf sdf = prepare(text);
        ASSERT_TRUE(sdf.ok()) << c.entry << ": " << (sdf.diagnostics.empty() ? "" : formatDiagnostic(sdf.diagnostics.back()));
        EXPECT_EQ(sdf.signature.entry, c.entry);
        EXPECT_EQ(sdf.signature.returnType, c.returnType);
        EXPECT_EQ(sdf.entrySource, EntrySource::March);
        EXPECT_TRUE(sdf.shadertoyMainImage) << "mainImage(out vec4 o, v2 w) is Shadertoy's form";
        const std::size_t call = text.find(std::string(c.entry) + "(p)", text.find("void mainImage"));
        const int line = 1 + int(std::count(text.begin(), text.begin() + std::ptrdiff_t(call), '\n'));
        EXPECT_EQ(sdf.entryReason, std::string(c.entry) + " (called by the march at line " + std::to_string(line) + ")");
        auto tracer = composeTracer(sdf, TracerFeatures{});
        ASSERT_TRUE(tracer.hasValue());
        EXPECT_FALSE(hasErrors(checkWithGlslang(*tracer))) << c.entry;
    }
    // The same shader with its aliases removed from the definitions reads the same way, and one
    // with no `#define v3 vec3` has no field: the names are what the macros say, nothing guessed.
    std::string undefined = head + cases[1].field + march;
    undefined.replace(undefined.find("FIELD"), 5, cases[1].step);
    undefined.replace(undefined.find("#define v3\tvec3"), 15, "struct v3 { float x; }");
    EXPECT_FALSE(prepare(undefined).ok());
}

// mainImage's own `discard` (glslCanvas's `if (t > tmax) discard;`) is a fragment shader's: in the
// sampler's compute stage it is a call that does nothing, and the fragment stage keeps it.
TEST(CompatNeeds, DiscardInMainImageCompilesInTheComputeStage) {
    PreparedSdf sdf = prepare("float map(vec3 p) { return length(p) - 0.5; }\n"
                              "void mainImage(out vec4 c, in vec2 f) {\n"
                              "    vec3 ro = vec3(0.0, 0.0, 3.0), rd = normalize(vec3(f / iResolution.xy - 0.5, -1.5));\n"
                              "    float t = 0.0;\n"
                              "    for (int i = 0; i < 64; i++) t += map(ro + rd * t);\n"
                              "    if (t > 10.0) discard;\n"
                              "    c = vec4(vec3(t * 0.1), 1.0);\n"
                              "}\n");
    ASSERT_TRUE(sdf.ok()) << (sdf.diagnostics.empty() ? "" : formatDiagnostic(sdf.diagnostics.back()));
    auto pieces = samplingStagePieces(*builtinPiece("samplers/rand.glsl"));
    ASSERT_TRUE(pieces.hasValue());
    ComposedShader compute = composeSdfShader(sdf, Stage::Compute, *pieces, {});
    EXPECT_NE(compute.text.find("if (t > 10.0) sdfwb_discard();"), std::string::npos);
    auto diagnostics = checkWithGlslang(compute);
    EXPECT_FALSE(hasErrors(diagnostics)) << (diagnostics.empty() ? "" : formatDiagnostic(diagnostics[0]));
    auto tracer = composeTracer(sdf, TracerFeatures{});
    ASSERT_TRUE(tracer.hasValue());
    EXPECT_NE(tracer->text.find("if (t > 10.0) discard;"), std::string::npos);
    EXPECT_FALSE(hasErrors(checkWithGlslang(*tracer)));
}

// A field overloaded with a float after the point (a cloud layer's `getDist(p, radius)` beside the
// planet's `getDist(p)`): the march that calls it with the point alone chose the overload without
// the float, not the one that would read the time as its radius.
TEST(EntryPoint, TheOverloadTheMarchCallsIsTheField) {
    PreparedSdf sdf = prepare(wholeShader("vec2 getDist(vec3 p) { return vec2(length(p) - 0.5, 1.0); }\n"
                                          "vec2 getDist(vec3 p, float radius) { return vec2(length(p) - radius, 2.0); }\n",
                                          "    float t = 0.0;\n    for (int i = 0; i < 64; i++) t += getDist(ro + rd * t).x;\n"
                                          "    return t;\n"));
    ASSERT_TRUE(sdf.ok()) << (sdf.diagnostics.empty() ? "" : formatDiagnostic(sdf.diagnostics.back()));
    EXPECT_EQ(sdf.signature.entry, "getDist");
    EXPECT_FALSE(sdf.signature.animated) << "getDist(p), not getDist(p, time)";
    EXPECT_TRUE(std::none_of(sdf.diagnostics.begin(), sdf.diagnostics.end(),
                             [](const Diagnostic& d) { return d.message.find("radius") != std::string::npos; }));
    auto tracer = composeTracer(sdf, TracerFeatures{});
    ASSERT_TRUE(tracer.hasValue());
    EXPECT_FALSE(hasErrors(checkWithGlslang(*tracer)));
}

// WebGL's zero for a variable declared without a value (ZeroInit.h): locals and a for loop's own get
// `= T(0)`; globals, a struct's members, parameters, arrays, qualified declarations, functions,
// directives and declarations that already have values do not; lines stay.
TEST(Composer, VariablesDeclaredWithoutAValueAreZeroAsInWebGl) {
    const std::string text = "#define F(x) \\\n    float y; x\n"
                             "struct Hit { float d; vec3 n; };\n"
                             "layout(std140) uniform Block { vec2 size; float scale; };\n"
                             "const float table[2] = float[2](1.0, 2.0);\n"
                             "uniform float speed;\nconst float K = 1.0;\nfloat glow;\n"
                             "float f(float a, vec3 b);\n"
                             "float sdf(vec3 p) {\n"
                             "    float r, i; vec3 q; vec4 acc[2]; mat2 m; int n = 3, k;\n"
                             "    for (float j, g = 1.0; j < 4.; j++) r += 0.125 * g;\n"
                             "    /* float hidden; */ q.x += 0.25;\n"
                             "    return length(p - q) - r;\n"
                             "}\n";
    PreparedSdf sdf = prepare(text);
    ASSERT_TRUE(sdf.ok()) << (sdf.diagnostics.empty() ? "" : formatDiagnostic(sdf.diagnostics.back()));
    auto tracer = composeTracer(sdf, TracerFeatures{});
    ASSERT_TRUE(tracer.hasValue());
    EXPECT_FALSE(hasErrors(checkWithGlslang(*tracer)));
    const std::string& out = tracer->text;
    EXPECT_NE(out.find("float r = float(0), i = float(0); vec3 q = vec3(0); vec4 acc[2]; for (int sdfwb_zero = 0; "
                       "sdfwb_zero < acc.length(); ++sdfwb_zero) acc[sdfwb_zero] = vec4(0); mat2 m = mat2(0); "
                       "int n = 3, k = int(0);"),
              std::string::npos)
        << out;
    EXPECT_NE(out.find("for (float j = float(0), g = 1.0; j < 4.; j++)"), std::string::npos) << out;
    EXPECT_NE(out.find("float glow;"), std::string::npos) << "a global is zero already" << out;
    EXPECT_NE(out.find("const float table[2] = float[2](1.0, 2.0);\n"), std::string::npos) << out;
    EXPECT_NE(out.find("struct Hit { float d; vec3 n; };"), std::string::npos) << out;
    EXPECT_NE(out.find("uniform Block { vec2 size; float scale; };"), std::string::npos) << out;
    EXPECT_NE(out.find("uniform float speed;\nconst float K = 1.0;"), std::string::npos) << out;
    EXPECT_NE(out.find("float f(float a, vec3 b);"), std::string::npos) << out;
    EXPECT_NE(out.find("    float y; x\n"), std::string::npos) << "a macro's continued line is the directive's" << out;
    EXPECT_NE(out.find("/* float hidden; */"), std::string::npos) << out;
}
