// Whole shaders written for other hosts than Shadertoy (glslViewer, GLSL Sandbox, Bonzomatic, a
// WebGL page, a Shadertoy port's main() wrapper, Fragmentarium), read in sdfwb's terms: the field
// found, the host's inputs and parameters mapped, the user's line numbers kept. The corpus files
// tests/foreign/75-82 render, sample and audit them on GL (test_foreign_gl.cpp).
#include <shaders/GlslChecker.h>
#include <shaders/Parameters.h>
#include <shaders/SdfSource.h>
#include <shaders/ShaderComposer.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <string>

#include <unistd.h>

using namespace sdfwb::shaders;

namespace {

PreparedSdf prepare(const std::string& text, const std::string& name = "host.frag") {
    return prepareSdf(text, name, {}, IncludeOptions{});
}

std::string errors(const std::vector<Diagnostic>& diagnostics) {
    std::string all;
    for (const Diagnostic& d : diagnostics)
        if (d.severity == Severity::Error) all += formatDiagnostic(d) + "\n";
    return all;
}

// The user's code with the entry wrapper in a compute stage that calls it, as the samplers
// compile it, checked by glslang.
std::string compileErrors(const PreparedSdf& sdf) {
    const ShaderPiece caller{"caller", "layout(local_size_x = 1) in;\nvoid main() { float d = sdfwb_sdf(vec3(0.0)); }\n"};
    return errors(checkWithGlslang(composeSdfShader(sdf, Stage::Compute, {caller}, FeatureDefines{})));
}

// Lines of the text sdfwb composes (the root file in the host's terms, after its `#line 1 0`),
// against the user's.
long lines(const std::string& text) { return long(std::count(text.begin(), text.end(), '\n')); }
long rootLines(const PreparedSdf& sdf) {
    EXPECT_EQ(sdf.source.text.rfind("#line 1 0\n", 0), 0u);
    return lines(sdf.source.text) - 1;
}

// What every host test checks: the text opens, read as `host` (any, where empty) with `entry` as
// the field, every line where it was, and the compute stage the samplers compile has no errors.
void expectOpens(const PreparedSdf& sdf, const std::string& text, const std::string& host, const std::string& entry) {
    ASSERT_TRUE(sdf.ok()) << errors(sdf.diagnostics);
    if (!host.empty()) EXPECT_EQ(sdf.host, host);
    EXPECT_EQ(sdf.signature.entry, entry);
    EXPECT_EQ(rootLines(sdf), lines(text));
    EXPECT_EQ(compileErrors(sdf), "");
}

// The march a host's main runs: a ray through `uv` stepped by `field`, its length written to `colour`.
std::string marchTo(const std::string& field, const std::string& colour) {
    return "    vec3 ro = vec3(0.0, 0.0, -3.0), rd = normalize(vec3(uv, 1.5));\n    float t = 0.0;\n"
           "    for (int i = 0; i < 64; i++) { float d = " +
           field + "(ro + rd * t); if (d < 0.001) break; t += d; }\n    " + colour + " = vec4(vec3(t * 0.1), 1.0);\n";
}

const Parameter* find(const std::vector<Parameter>& parameters, const std::string& name) {
    for (const Parameter& p : parameters)
        if (p.name == name) return &p;
    return nullptr;
}

// The Book of Shaders / glslViewer's template around a march whose field has no conventional name.
const std::string kGlslViewer =
    "#ifdef GL_ES\n"
    "precision mediump float;\n"
    "#endif\n"
    "uniform vec2 u_resolution;\n"
    "uniform vec2 u_mouse;\n"
    "uniform float u_time;\n"
    "varying vec2 v_texcoord;\n"
    "float getDist(vec3 p) { return length(p - vec3(0.0, 0.1 * sin(u_time), 0.0)) - 0.5; }\n"
    "void main() {\n"
    "    vec2 st = (2.0 * gl_FragCoord.xy - u_resolution) / u_resolution.y;\n"
    "    vec3 ro = vec3(0.0, 0.0, 3.0), rd = normalize(vec3(st, -1.5));\n"
    "    float t = 0.0;\n"
    "    for (int i = 0; i < 64; i++) { float d = getDist(ro + rd * t); if (d < 0.001) break; t += d; }\n"
    "    gl_FragColor = vec4(vec3(t * 0.1) + 0.0 * u_mouse.x, 1.0);\n"
    "}\n";

} // namespace

TEST(ForeignHosts, GlslViewerMainIsReadAsMainImageAndItsMarchFindsTheField) {
    PreparedSdf sdf = prepare(kGlslViewer);
    ASSERT_TRUE(sdf.ok()) << errors(sdf.diagnostics);
    EXPECT_EQ(sdf.host, "glslViewer");
    EXPECT_TRUE(sdf.shadertoyMainImage);
    EXPECT_EQ(sdf.signature.entry, "getDist");
    EXPECT_EQ(sdf.entrySource, EntrySource::March);
    EXPECT_TRUE(sdf.usesTime()) << "u_time is the scene time";
    // The same lines: diagnostics name the user's.
    EXPECT_EQ(rootLines(sdf), lines(kGlslViewer));
    // The source map holds the text as read (the march analysis reads its statements there).
    EXPECT_EQ(lines(sdf.source.map.files.front().text), lines(kGlslViewer));
    EXPECT_EQ(compileErrors(sdf), "");
    EXPECT_NE(hostDescription(sdf.host).find("mainImage"), std::string::npos);
}

TEST(ForeignHosts, AnErrorInAHostsShaderIsReportedAtTheUsersLine) {
    std::string text = kGlslViewer;
    text.replace(text.find("float t = 0.0;"), 14, "float t = undeclaredThing;"); // line 12
    // Unnamed: the march cannot be read, and the compiler's error says why, at the user's line.
    PreparedSdf unnamed = prepare(text, "typo.frag");
    ASSERT_FALSE(unnamed.ok());
    ASSERT_GE(unnamed.diagnostics.size(), 2u) << errors(unnamed.diagnostics);
    EXPECT_EQ(unnamed.diagnostics.front().line, 12) << errors(unnamed.diagnostics);
    EXPECT_NE(unnamed.diagnostics.front().message.find("undeclaredThing"), std::string::npos);
    EXPECT_NE(unnamed.diagnostics.back().message.find("does not compile"), std::string::npos);
    // Named: the field compiles; the error is the composed shader's.
    PreparedSdf sdf = prepareSdf(text, "typo.frag", {}, IncludeOptions{}, "getDist");
    std::vector<Diagnostic> found = sdf.diagnostics;
    if (sdf.ok()) found = checkWithGlslang(composeSdfShader(sdf, Stage::Fragment, std::vector<ShaderPiece>{}, FeatureDefines{}));
    auto it = std::find_if(found.begin(), found.end(), [](const Diagnostic& d) {
        return d.severity == Severity::Error && d.message.find("undeclaredThing") != std::string::npos;
    });
    ASSERT_NE(it, found.end()) << errors(found);
    EXPECT_EQ(it->file, "typo.frag");
    EXPECT_EQ(it->line, 12);
    EXPECT_NE(sdf.source.map.lineText(0, 12).find("float t = undeclaredThing;"), std::string::npos) << "the user's line 12";
}

TEST(ForeignHosts, SandboxBonzomaticAndWebGlInputsBecomeShadertoys) {
    const std::string sandbox = "#ifdef GL_ES\nprecision highp float;\n#endif\n"
                                "#extension GL_OES_standard_derivatives : enable\n"
                                "uniform float time; uniform vec2 mouse; uniform vec2 resolution;\n"
                                "float de(vec3 p) { return length(p) - 0.4 - 0.05 * sin(time) * mouse.x; }\n"
                                "void main( void ) {\n"
                                "  vec2 uv = (gl_FragCoord.xy * 2.0 - resolution) / min(resolution.x, resolution.y);\n"
                                "  vec3 ro = vec3(0, 0, -3), rd = normalize(vec3(uv, 1)); float t = 0.;\n"
                                "  for (int i = 0; i < 80; i++) { float d = de(ro + rd * t); if (d < .001) break; t += d; }\n"
                                "  gl_FragColor = vec4(vec3(1.0 / (1.0 + t)), 1.0);\n"
                                "}\n";
    PreparedSdf s = prepare(sandbox);
    ASSERT_TRUE(s.ok()) << errors(s.diagnostics);
    EXPECT_EQ(s.host, "GLSL Sandbox");
    EXPECT_EQ(s.signature.entry, "de");
    EXPECT_TRUE(s.usesTime());
    // Sandbox's mouse is normalised: Shadertoy's pixels over the resolution.
    EXPECT_NE(s.source.text.find("(iMouse.xy / iResolution.xy).x"), std::string::npos);
    EXPECT_EQ(compileErrors(s), "");

    const std::string bonzomatic =
        "#version 410 core\n"
        "uniform float fGlobalTime;\nuniform vec2 v2Resolution;\n"
        "uniform sampler1D texFFTSmoothed;\nuniform sampler2D texNoise;\n"
        "layout(location = 0) out vec4 out_color;\n"
        "float map(vec3 p) { return length(p) - 0.5 + 0.1 * texture(texFFTSmoothed, 0.1).r; }\n"
        "void main(void) {\n"
        "  vec2 uv = gl_FragCoord.xy / v2Resolution - 0.5;\n"
        "  float t = 0.; for (int i = 0; i < 99; i++) { float d = map(vec3(uv, -3. + t)); if (d < 1e-3) break; t += d; }\n"
        "  out_color = vec4(t * 0.1 + fGlobalTime * 0.0);\n"
        "}\n";
    PreparedSdf b = prepare(bonzomatic);
    ASSERT_TRUE(b.ok()) << errors(b.diagnostics);
    EXPECT_EQ(b.host, "Bonzomatic");
    EXPECT_EQ(b.signature.entry, "map");
    // The file's `out vec4` is mainImage's colour; its textures read units nothing is bound to.
    EXPECT_NE(b.source.text.find("mainImage(out vec4 out_color, in vec2 fragCoord)"), std::string::npos);
    EXPECT_NE(b.source.text.find("layout(binding = 12) uniform sampler1D texFFTSmoothed;"), std::string::npos);
    EXPECT_NE(b.source.text.find("layout(binding = 13) uniform sampler2D texNoise;"), std::string::npos);
    EXPECT_EQ(compileErrors(b), "");

    // A WebGL page declares Shadertoy's inputs itself: sdfwb's (which it sets) replace them.
    const std::string webgl = "#version 300 es\nprecision highp float;\n"
                              "uniform vec3 iResolution;\nuniform float iTime;\nout vec4 fragColor;\n"
                              "float scene(vec3 p) { return length(p) - 0.5; }\n"
                              "void main() {\n"
                              "  vec2 uv = (gl_FragCoord.xy - 0.5 * iResolution.xy) / iResolution.y;\n"
                              "  float t = 0.; for (int i = 0; i < 90; i++) { float h = scene(vec3(uv, -2.5) + vec3(0, 0, t)); "
                              "if (h < 1e-3) break; t += h; }\n"
                              "  fragColor = vec4(vec3(exp(-0.3 * t)), 1.0);\n"
                              "}\n";
    PreparedSdf w = prepare(webgl);
    ASSERT_TRUE(w.ok()) << errors(w.diagnostics);
    EXPECT_EQ(w.host, "a WebGL page");
    EXPECT_EQ(w.signature.entry, "scene");
    EXPECT_EQ(w.source.text.find("uniform float iTime"), std::string::npos);
    EXPECT_NE(std::find(w.compat.symbols.begin(), w.compat.symbols.end(), "iResolution"), w.compat.symbols.end());
    EXPECT_EQ(compileErrors(w), "");
}

TEST(ForeignHosts, KodeLifesInputBlockAndThreeJsUniforms) {
    const std::string kodelife =
        "#version 150\n"
        "uniform float time;\nuniform vec2 resolution;\nuniform vec3 spectrum;\n"
        "uniform sampler2D prevFrame;\n"
        "in VertexData\n{\n    vec4 v_position;\n    vec2 v_texcoord;\n} inData;\n"
        "out vec4 fragColor;\n"
        "float field(vec3 p) { return length(p) - 0.5 - 0.1 * spectrum.x; }\n"
        "void main(void) {\n"
        "  vec2 uv = -1.0 + 2.0 * inData.v_texcoord; uv.x *= resolution.x / resolution.y;\n"
        "  float t = 0.; for (int i = 0; i < 64; i++) { float d = field(vec3(uv, -2.0 + t)); if (d < 1e-3) break; t += d; }\n"
        "  fragColor = vec4(vec3(t) + texture(prevFrame, uv).rgb * 0.0, 1.0);\n"
        "}\n";
    PreparedSdf k = prepare(kodelife);
    ASSERT_TRUE(k.ok()) << errors(k.diagnostics);
    EXPECT_EQ(k.host, "KodeLife");
    EXPECT_EQ(k.signature.entry, "field");
    EXPECT_EQ(rootLines(k), lines(kodelife));
    EXPECT_EQ(compileErrors(k), "");

    const std::string three =
        "#include <common>\nuniform float uTime;\nuniform vec2 uResolution;\nvarying vec2 vUv;\n"
        "float sdTorus(vec3 p) { vec2 q = vec2(length(p.xz) - 0.5, p.y); return length(q) - 0.2 + 0.0 * uTime; }\n"
        "void main() {\n"
        "  vec2 uv = (vUv - 0.5) * vec2(uResolution.x / uResolution.y, 1.0); float t = 0.;\n"
        "  for (int i = 0; i < 64; i++) { float d = sdTorus(vec3(uv, -2.0) + t * vec3(0, 0, 1)); if (d < 1e-3) break; t += d; }\n"
        "  gl_FragColor = vec4(vec3(t * 0.2), 1.0);\n"
        "  #include <tonemapping_fragment>\n"
        "}\n";
    PreparedSdf t = prepare(three);
    ASSERT_TRUE(t.ok()) << errors(t.diagnostics);
    EXPECT_EQ(t.host, "three.js");
    EXPECT_EQ(t.signature.entry, "sdTorus");
    EXPECT_TRUE(t.usesTime());
    EXPECT_EQ(compileErrors(t), "");
}

TEST(ForeignHosts, APortsMainWrapperIsLeftOut) {
    const std::string text =
        "uniform vec3 iResolution;\nuniform float iTime;\n"
        "float map(vec3 p) { return length(p) - 0.5; }\n"
        "void mainImage(out vec4 fragColor, in vec2 fragCoord) {\n"
        "  vec2 uv = (fragCoord - 0.5 * iResolution.xy) / iResolution.y; float t = 0.;\n"
        "  for (int i = 0; i < 64; i++) { float d = map(vec3(uv, -2.0 + t)); if (d < 1e-3) break; t += d; }\n"
        "  fragColor = vec4(t);\n"
        "}\n"
        "void main() { mainImage(gl_FragColor, gl_FragCoord.xy); }\n";
    PreparedSdf sdf = prepare(text);
    ASSERT_TRUE(sdf.ok()) << errors(sdf.diagnostics);
    EXPECT_EQ(sdf.host, "a Shadertoy port");
    EXPECT_TRUE(sdf.shadertoyMainImage);
    EXPECT_EQ(sdf.signature.entry, "map");
    EXPECT_EQ(sdf.source.text.find("void main()"), std::string::npos);
    EXPECT_EQ(compileErrors(sdf), "");
}

TEST(ForeignHosts, AnSdfFileIsLeftAsItIs) {
    const std::string text = "uniform float radius = 0.5; // @range 0.1 1\nfloat time = 1.0;\n"
                             "float sdf(vec3 p) { return length(p) - radius * time; }\n";
    PreparedSdf sdf = prepare(text);
    ASSERT_TRUE(sdf.ok()) << errors(sdf.diagnostics);
    EXPECT_EQ(sdf.host, "");
    EXPECT_EQ(sdf.source.text.find("iTime"), std::string::npos);
    // A main() that writes no colour is no host's: the workbench writes main, and says so.
    PreparedSdf withMain = prepare("float sdf(vec3 p) { return length(p) - 1.0; }\nvoid main() {}\n");
    EXPECT_EQ(withMain.host, "");
    EXPECT_NE(errors(withMain.diagnostics).find("main() is written by the workbench"), std::string::npos);
}

TEST(ForeignHosts, FragmentariumSlidersPresetsAndSystemIncludes) {
    const std::string text = "#info Mandelbox (a test)\n"                                    // 1
                             "#define providesInit\n"                                        // 2
                             "#include \"MathUtils.frag\"\n"                                 // 3
                             "#include \"DE-Raytracer.frag\"\n"                              // 4
                             "#group Mandelbox\n"                                            // 5
                             "uniform int Iterations;  slider[0,17,300]\n"                   // 6
                             "uniform float Scale; slider[-3.0,3.0,5.0] Locked\n"            // 7
                             "uniform vec3 RotVector; slider[(0,0,0),(1,1,1),(1,1,1)]\n"     // 8
                             "uniform bool DoRotate; checkbox[true]\n"                       // 9
                             "uniform vec3 BaseColor; color[1.0,0.5,0.25]\n"                 // 10
                             "uniform vec4 Trap; color[-1,0.7,1,0.5,0.6,0.6];\n mat3 rot;\n" // 11, 12
                             "void init() { rot = rotationMatrix3(normalize(RotVector), 30.0); }\n"
                             "float DE(vec3 pos) {\n"
                             "  vec3 p = DoRotate ? rot * pos : pos;\n"
                             "  for (int i = 0; i < Iterations; i++) orbitTrap = min(orbitTrap, vec4(abs(p), 1.0));\n"
                             "  return (length(p) - 0.5 * abs(Scale) * 0.5) + 0.0 * sin(time) * OrbitStrength * Trap.w;\n"
                             "}\n"
                             "#preset Default\n"
                             "FOV = 0.62536\n"
                             "Scale = 2.5 Locked\n"
                             "RotVector = 0,1,0\n"
                             "OrbitStrength = 0.25\n"
                             "#endpreset\n"
                             "#preset Other\nScale = 1.0\n#endpreset\n";
    ParameterScan scan = parseParameters(text, "box.frag");
    EXPECT_TRUE(scan.diagnostics.empty()) << errors(scan.diagnostics);
    ASSERT_EQ(scan.parameters.size(), 6u);
    const Parameter* iterations = find(scan.parameters, "Iterations");
    ASSERT_NE(iterations, nullptr);
    EXPECT_EQ(iterations->type, ParameterType::Int);
    EXPECT_EQ(iterations->defaultValue[0], 17.0f);
    EXPECT_EQ(iterations->minimum, 0.0f);
    EXPECT_EQ(iterations->maximum, 300.0f);
    EXPECT_EQ(iterations->line, 6);
    const Parameter* scale = find(scan.parameters, "Scale");
    ASSERT_NE(scale, nullptr);
    EXPECT_EQ(scale->defaultValue[0], 2.5f) << "the Default preset overrides the slider";
    EXPECT_EQ(scale->syntax, Parameter::Syntax::FragmentariumPreset);
    const Parameter* axis = find(scan.parameters, "RotVector");
    ASSERT_NE(axis, nullptr);
    EXPECT_EQ(axis->defaultValue[0], 0.0f);
    EXPECT_EQ(axis->defaultValue[1], 1.0f);
    const Parameter* rotate = find(scan.parameters, "DoRotate");
    ASSERT_NE(rotate, nullptr);
    EXPECT_EQ(rotate->defaultValue[0], 1.0f);
    const Parameter* colour = find(scan.parameters, "BaseColor");
    ASSERT_NE(colour, nullptr);
    EXPECT_TRUE(colour->color);
    EXPECT_EQ(colour->defaultValue[1], 0.5f);
    // A vec4 colour in Fragmentarium's six numbers: the alpha's slider, then the colour.
    const Parameter* trap = find(scan.parameters, "Trap");
    ASSERT_NE(trap, nullptr);
    EXPECT_EQ(trap->defaultValue, (std::array<float, 4>{0.5f, 0.6f, 0.6f, 0.7f}));

    // Saved defaults go where Fragmentarium reads them, in its syntax, and read back.
    const std::string saved = withDefaults(text, scan.parameters,
                                           {{"Iterations", ParameterType::Int, {12, 0, 0, 0}},
                                            {"Scale", ParameterType::Float, {-1.5f, 0, 0, 0}},
                                            {"RotVector", ParameterType::Vec3, {1, 0, 0, 0}},
                                            {"DoRotate", ParameterType::Bool, {0, 0, 0, 0}},
                                            {"BaseColor", ParameterType::Vec3, {0.25f, 0.5f, 1, 0}}});
    EXPECT_NE(saved.find("uniform int Iterations;  slider[0,12,300]"), std::string::npos) << saved;
    EXPECT_NE(saved.find("Scale = -1.5 Locked\n"), std::string::npos) << saved;
    EXPECT_NE(saved.find("RotVector = 1,0,0\n"), std::string::npos) << saved;
    EXPECT_NE(saved.find("checkbox[false]"), std::string::npos) << saved;
    EXPECT_NE(saved.find("color[0.25,0.5,1]"), std::string::npos) << saved;
    ParameterScan again = parseParameters(saved, "box.frag");
    EXPECT_EQ(find(again.parameters, "Scale")->defaultValue[0], -1.5f);
    EXPECT_EQ(find(again.parameters, "Iterations")->defaultValue[0], 12.0f);

    // The fragment itself: the DE found, init() run first, what the includes give provided, the
    // directives gone, every line where it was, and it compiles.
    PreparedSdf sdf = prepare(text, "box.frag");
    ASSERT_TRUE(sdf.ok()) << errors(sdf.diagnostics);
    EXPECT_EQ(sdf.host, "Fragmentarium");
    EXPECT_EQ(sdf.signature.entry, "DE");
    EXPECT_EQ(sdf.signature.prelude, "init();");
    EXPECT_EQ(sdf.parameters.size(), 6u);
    EXPECT_TRUE(sdf.usesTime()) << "Fragmentarium's time is the scene time";
    EXPECT_EQ(rootLines(sdf), lines(text));
    EXPECT_EQ(sdf.source.text.find("#info"), std::string::npos);
    EXPECT_EQ(sdf.source.text.find("slider"), std::string::npos);
    EXPECT_EQ(sdf.source.text.find("FOV"), std::string::npos);
    EXPECT_NE(sdf.source.text.find("uniform float Scale = 2.5;"), std::string::npos) << sdf.source.text;
    EXPECT_NE(sdf.source.text.find("vec4 orbitTrap"), std::string::npos);
    // The raytracer's slider the DE reads, at the Default preset's value.
    EXPECT_NE(sdf.source.text.find("uniform float OrbitStrength = 0.25;"), std::string::npos) << sdf.source.text;
    EXPECT_NE(sdf.source.text.find("mat3 rotationMatrix3(vec3 v, float angle)"), std::string::npos);
    // init() once per invocation, as Fragmentarium runs it once per pixel before its DE calls.
    EXPECT_NE(entryWrapper(sdf).find("if (!sdfwb_preludeRun) { sdfwb_preludeRun = true;\n{\ninit();\n}\n}\nreturn DE(p"),
              std::string::npos)
        << entryWrapper(sdf);
    EXPECT_EQ(compileErrors(sdf), "");
}

TEST(ForeignHosts, BadFragmentariumAnnotationsAreNamedAtTheirLine) {
    struct Case {
        std::string text, says;
    };
    for (const Case& c : std::vector<Case>{
             {"uniform float Scale; slider[-3.0,3.0\nfloat DE(vec3 p) { return length(p) - Scale; }\n", "no closing ]"},
             {"uniform float Scale; slider[-3.0,big,5.0]\nfloat DE(vec3 p) { return length(p) - Scale; }\n",
              "'big' is not a default for a float"},
             {"uniform bool Julia; slider[0,1,2]\nfloat DE(vec3 p) { return length(p); }\n", "does not fit a bool"},
             {"uniform float Power; checkbox[true]\nfloat DE(vec3 p) { return length(p); }\n", "does not fit a float"},
             {"uniform vec3 C; slider[(0,0,0),(1,1),(2,2,2)]\nfloat DE(vec3 p) { return length(p); }\n",
              "'(1,1)' is not a default for a vec3"},
         }) {
        ParameterScan scan = parseParameters(c.text, "bad.frag");
        ASSERT_FALSE(scan.diagnostics.empty()) << c.text;
        EXPECT_EQ(scan.diagnostics.front().line, 1) << c.text;
        EXPECT_NE(scan.diagnostics.front().message.find(c.says), std::string::npos) << scan.diagnostics.front().message;
    }
    // A preset value that does not fit keeps the slider's default, with a warning at its line.
    ParameterScan scan =
        parseParameters("uniform float Scale; slider[0,2,4]\n#preset Default\nScale = 1,2\n#endpreset\n", "p.frag");
    ASSERT_EQ(scan.parameters.size(), 1u);
    EXPECT_EQ(scan.parameters[0].defaultValue[0], 2.0f);
    ASSERT_EQ(scan.diagnostics.size(), 1u);
    EXPECT_EQ(scan.diagnostics[0].severity, Severity::Warning);
    EXPECT_EQ(scan.diagnostics[0].line, 3);
}

TEST(ForeignHosts, FragmentariumsHistoricalIncludesAndMatrices) {
    // An old fragment: its includes named with their folder, matrix.frag's rotationMatrix kept in a
    // mat3 (later versions return a mat4), MathUtils' translate and scale4.
    const std::string text = "#include \"include/DE-Raytracer.frag\"\n"
                             "#include \"include/matrix.frag\"\n"
                             "uniform vec3 Axis; slider[(0,0,0),(0,1,0),(1,1,1)]\n"
                             "mat3 rot = rotationMatrix(normalize(Axis), 30.0);\n"
                             "mat4 place = translate(vec3(0.1, 0.0, 0.0)) * scale4(0.5);\n"
                             "float DE(vec3 p) { p = (place * vec4(rot * p, 1.0)).xyz; return length(p) - 0.3; }\n";
    PreparedSdf sdf = prepare(text, "old.frag");
    ASSERT_TRUE(sdf.ok()) << errors(sdf.diagnostics);
    EXPECT_EQ(sdf.host, "Fragmentarium");
    EXPECT_EQ(sdf.signature.entry, "DE");
    EXPECT_NE(sdf.source.text.find("mat3 rotationMatrix(vec3 v, float angle)"), std::string::npos);
    EXPECT_EQ(compileErrors(sdf), "");
}

// Orbit traps older system includes declared (Fragmentarium's Mandelbulb with `minDist2 = min(minDist2,
// r*r)`, an octahedron's `mDist`): provided once each as floats; one the fragment declares is left alone.
TEST(ForeignHosts, FragmentariumsUndeclaredOrbitTrapsAreProvided) {
    const std::string text = "#include \"DE-Raytracer.frag\"\n"
                             "uniform int Iterations; slider[0,9,100]\n"
                             "float own = 1.0, kept;\n"
                             "float DE(vec3 p) {\n"
                             "  float r = length(p);\n"
                             "  for (int i = 0; i < Iterations; i++) {\n"
                             "    minDist2 = min(minDist2, r * r); mDist = min(mDist, r); kept = min(kept, r); p *= 0.9;\n"
                             "  }\n"
                             "  return r - 0.5;\n"
                             "}\n";
    PreparedSdf sdf = prepare(text, "traps.frag");
    ASSERT_TRUE(sdf.ok()) << errors(sdf.diagnostics);
    EXPECT_EQ(sdf.host, "Fragmentarium");
    EXPECT_NE(sdf.source.text.find("float mDist = 10000.0; float minDist2 = 10000.0;"), std::string::npos) << sdf.source.text;
    EXPECT_EQ(sdf.source.text.find("float kept = 10000.0"), std::string::npos) << "kept is the fragment's own";
    EXPECT_EQ(compileErrors(sdf), "");
}

// An ISF shader as VDMX, Resolume or editor.isf.video run it (and as its public collections write
// them, often converted from Shadertoy): a JSON header whose INPUTS the host declares, TIME and
// RENDERSIZE, gl_FragColor in main(). Its value inputs are parameters (range, label, colour), an image
// input a sampler, the built-ins Shadertoy's; saved defaults go into the header's DEFAULTs as JSON.
TEST(ForeignHosts, AnIsfShadersInputsAreParametersAndItsBuiltinsShadertoys) {
    const std::string text =
        "/*\n{\n  \"CATEGORIES\" : [ \"Generator\" ],\n  \"ISFVSN\": \"2\",\n  \"INPUTS\" : [\n"
        "    { \"NAME\": \"boxSize\", \"LABEL\": \"Box Size\", \"TYPE\": \"float\", \"DEFAULT\": 0.5,"
        " \"MIN\": 0.1, \"MAX\": 2 },\n"
        "    { \"NAME\": \"tint\", \"TYPE\": \"color\", \"DEFAULT\": [0.5, 0.4, 0.6, 1] },\n"
        "    { \"NAME\": \"hollow\", \"TYPE\": \"bool\", \"DEFAULT\": false },\n"
        "    { \"NAME\": \"steps\", \"TYPE\": \"long\", \"VALUES\": [16, 32, 64], \"LABELS\": [\"a\", "
        "\"b\", \"c\"], \"DEFAULT\": 32 },\n"
        "    { \"NAME\": \"centre\", \"TYPE\": \"point2D\", \"DEFAULT\": [0, 0], \"MIN\": [-1, -2], \"MAX\": [1, 2] },\n"
        "    { \"NAME\": \"inputImage\", \"TYPE\": \"image\" },\n"
        "    { \"NAME\": \"spin\", \"TYPE\": \"float\" },\n"
        "  ]\n}\n*/\n"
        "float sdBox(vec3 p, vec3 b) { vec3 q = abs(p) - b; return length(max(q, 0.0)) + min(max(q.x, "
        "max(q.y, q.z)), 0.0); }\n"
        "float scene(vec3 p) { float d = sdBox(p, vec3(boxSize)) + 0.1 * sin(TIME); return hollow ? abs(d) "
        ": d; }\n"
        "void main() {\n"
        "    vec2 uv = (2.0 * gl_FragCoord.xy - RENDERSIZE) / RENDERSIZE.y + centre;\n"
        "    vec3 ro = vec3(0.0, 0.0, 3.0), rd = normalize(vec3(uv, -1.5));\n"
        "    float t = 0.0;\n"
        "    for (int i = 0; i < steps; i++) { float d = scene(ro + rd * t); if (d < 0.001) break; t += d; }\n"
        "    gl_FragColor = vec4(tint.rgb * t * 0.1, 1.0) + 0.0 * IMG_NORM_PIXEL(inputImage, "
        "isf_FragNormCoord) + 0.0 * IMG_THIS_PIXEL(inputImage);\n}\n";
    ParameterScan scan = parseParameters(text, "box.fs");
    EXPECT_TRUE(scan.diagnostics.empty()) << errors(scan.diagnostics);
    ASSERT_EQ(scan.parameters.size(), 6u) << "the image input is no parameter";
    const Parameter* size = find(scan.parameters, "boxSize");
    ASSERT_NE(size, nullptr);
    EXPECT_EQ(size->type, ParameterType::Float);
    EXPECT_EQ(size->defaultValue[0], 0.5f);
    EXPECT_EQ(size->minimum, 0.1f);
    EXPECT_EQ(size->maximum, 2.0f);
    EXPECT_EQ(size->label, "Box Size");
    EXPECT_EQ(size->line, 6);
    EXPECT_EQ(size->syntax, Parameter::Syntax::Isf);
    const Parameter* tint = find(scan.parameters, "tint");
    ASSERT_NE(tint, nullptr);
    EXPECT_TRUE(tint->color);
    EXPECT_EQ(tint->defaultValue, (std::array<float, 4>{0.5f, 0.4f, 0.6f, 1.0f}));
    const Parameter* steps = find(scan.parameters, "steps");
    ASSERT_NE(steps, nullptr);
    EXPECT_EQ(steps->type, ParameterType::Int);
    EXPECT_EQ(steps->minimum, 16.0f) << "a long's VALUES give its range";
    EXPECT_EQ(steps->maximum, 64.0f);
    const Parameter* centre = find(scan.parameters, "centre");
    ASSERT_NE(centre, nullptr);
    EXPECT_EQ(centre->type, ParameterType::Vec2);
    EXPECT_EQ(centre->minimum, -2.0f) << "a point2D's widest range";
    EXPECT_EQ(find(scan.parameters, "hollow")->type, ParameterType::Bool);

    const PreparedSdf sdf = prepare(text, "box.fs");
    ASSERT_TRUE(sdf.ok()) << errors(sdf.diagnostics);
    EXPECT_EQ(sdf.host, "ISF");
    EXPECT_EQ(sdf.signature.entry, "scene");
    EXPECT_EQ(rootLines(sdf), lines(text)) << "every line keeps its number";
    EXPECT_NE(sdf.source.text.find("uniform float boxSize;"), std::string::npos);
    EXPECT_NE(sdf.source.text.find("uniform sampler2D inputImage;"), std::string::npos);
    EXPECT_NE(sdf.source.text.find("sin(iTime)"), std::string::npos);
    EXPECT_EQ(compileErrors(sdf), "");

    // Saved defaults: JSON in the header, read back; an input without DEFAULT is left out.
    const std::string saved = withDefaults(text, scan.parameters,
                                           {{"boxSize", ParameterType::Float, {0.75f, 0, 0, 0}},
                                            {"tint", ParameterType::Vec4, {1, 0.5f, 0.25f, 1}},
                                            {"hollow", ParameterType::Bool, {1, 0, 0, 0}},
                                            {"spin", ParameterType::Float, {3, 0, 0, 0}}});
    EXPECT_NE(saved.find("\"DEFAULT\": 0.75,"), std::string::npos) << saved;
    EXPECT_NE(saved.find("\"DEFAULT\": [1, 0.5, 0.25, 1]"), std::string::npos) << saved;
    EXPECT_NE(saved.find("\"DEFAULT\": true"), std::string::npos) << saved;
    EXPECT_EQ(lines(saved), lines(text));
    const ParameterScan again = parseParameters(saved, "box.fs");
    EXPECT_EQ(find(again.parameters, "boxSize")->defaultValue[0], 0.75f);
    EXPECT_EQ(find(again.parameters, "hollow")->defaultValue[0], 1.0f);
    EXPECT_EQ(find(again.parameters, "spin")->defaultValue[0], 0.0f);
}

// The VS Code Shader Toy extension (stevensona.shader-toy): `#iUniform` lines are parameters, also
// inside a function (the extension hoists them: sdfwb declares them before that function); its
// #iChannel, #iKeyboard and #iFirstPersonControls lines go, its key functions answer no key and
// iViewMatrix is the identity it starts as. Saving rewrites VALUE in place.
TEST(ForeignHosts, TheVscodeExtensionsDirectivesAreParametersAndItsInputs) {
    const std::string text = "#iChannel0 \"file://noise.png\"\n"
                             "#iChannel0::WrapMode \"Repeat\"\n"
                             "#iKeyboard\n"
                             "#iFirstPersonControls\n"
                             "#iUniform float radius = 0.5 in { 0.1, 2.0 } step 0.05 // a slider\n"
                             "#iUniform color3 tint = color3(0.8, 0.5, 0.2)\n"
                             "#iUniform int steps = 96 in{16, 256 };\n"
                             "#iUniform vec2 offset = vec2(0.25)\n"
                             "float map(vec3 p) {\n"
                             "    #iUniform float wobble = 0.1 in {0.0, 1.0}\n"
                             "    return length(p - vec3(offset, 0.0)) - radius - wobble * sin(iGlobalTime);\n"
                             "}\n"
                             "void mainImage(out vec4 fragColor, in vec2 fragCoord) {\n"
                             "    vec2 uv = (2.0 * fragCoord - iResolution.xy) / iResolution.y;\n"
                             "    vec3 ro = iViewMatrix[3].xyz + vec3(0.0, 0.0, 3.0), rd = normalize(vec3(uv, -1.5));\n"
                             "    if (isKeyPressed(Key_Space) || isKeyToggled(Key_A)) ro.z += 1.0;\n"
                             "    float t = 0.0;\n"
                             "    for (int i = 0; i < steps; i++) { float d = map(ro + rd * t); if (d < 0.001) break; t += d; }\n"
                             "    fragColor = vec4(tint * t * 0.1, 1.0) + 0.0 * texture(iChannel0, uv);\n"
                             "}\n";
    ParameterScan scan = parseParameters(text, "ball.glsl");
    EXPECT_TRUE(scan.diagnostics.empty()) << errors(scan.diagnostics);
    ASSERT_EQ(scan.parameters.size(), 5u);
    const Parameter* radius = find(scan.parameters, "radius");
    ASSERT_NE(radius, nullptr);
    EXPECT_EQ(radius->type, ParameterType::Float);
    EXPECT_EQ(radius->defaultValue[0], 0.5f);
    EXPECT_EQ(radius->minimum, 0.1f);
    EXPECT_EQ(radius->maximum, 2.0f);
    EXPECT_EQ(radius->step, 0.05f);
    EXPECT_EQ(radius->line, 5);
    const Parameter* tint = find(scan.parameters, "tint");
    ASSERT_NE(tint, nullptr);
    EXPECT_EQ(tint->type, ParameterType::Vec3);
    EXPECT_TRUE(tint->color);
    EXPECT_EQ(tint->defaultValue, (std::array<float, 4>{0.8f, 0.5f, 0.2f, 0.0f}));
    const Parameter* steps = find(scan.parameters, "steps");
    ASSERT_NE(steps, nullptr);
    EXPECT_EQ(steps->type, ParameterType::Int);
    EXPECT_EQ(steps->defaultValue[0], 96.0f);
    EXPECT_EQ(steps->maximum, 256.0f);
    EXPECT_EQ(find(scan.parameters, "offset")->defaultValue, (std::array<float, 4>{0.25f, 0.25f, 0.0f, 0.0f}))
        << "one argument fills every component";
    EXPECT_EQ(find(scan.parameters, "wobble")->line, 10);

    const PreparedSdf sdf = prepare(text, "ball.glsl");
    ASSERT_TRUE(sdf.ok()) << errors(sdf.diagnostics);
    EXPECT_EQ(sdf.host, "the VS Code Shader Toy extension");
    EXPECT_EQ(sdf.signature.entry, "map");
    EXPECT_EQ(rootLines(sdf), lines(text)) << "every line keeps its number";
    EXPECT_NE(sdf.source.text.find("uniform float wobble;"), std::string::npos);
    EXPECT_LT(sdf.source.text.find("uniform float wobble;"), sdf.source.text.find("float map(")) << "declared before use";
    EXPECT_NE(sdf.source.text.find("uniform vec3 tint;"), std::string::npos);
    EXPECT_EQ(sdf.source.text.find("#i"), std::string::npos) << sdf.source.text;
    EXPECT_NE(sdf.source.text.find("sin(iTime)"), std::string::npos);
    EXPECT_EQ(compileErrors(sdf), "");

    const std::string saved = withDefaults(text, scan.parameters,
                                           {{"radius", ParameterType::Float, {0.75f, 0, 0, 0}},
                                            {"tint", ParameterType::Vec3, {1, 0.5f, 0.25f, 0}},
                                            {"wobble", ParameterType::Float, {0.3f, 0, 0, 0}}});
    EXPECT_NE(saved.find("#iUniform float radius = 0.75 in { 0.1, 2.0 } step 0.05 // a slider\n"), std::string::npos) << saved;
    EXPECT_NE(saved.find("#iUniform color3 tint = vec3(1.0, 0.5, 0.25)\n"), std::string::npos) << saved;
    EXPECT_EQ(lines(saved), lines(text));
    const ParameterScan again = parseParameters(saved, "ball.glsl");
    EXPECT_EQ(find(again.parameters, "radius")->defaultValue[0], 0.75f);
    EXPECT_EQ(find(again.parameters, "wobble")->defaultValue[0], 0.3f);
    EXPECT_EQ(find(again.parameters, "tint")->defaultValue, (std::array<float, 4>{1.0f, 0.5f, 0.25f, 0.0f}));

    // A `#iUniform` of a type the extension has not (a mat3) is no parameter.
    EXPECT_TRUE(parseParameters("#iUniform mat3 m = mat3(1.0)\n", "m.glsl").parameters.empty());
}

// A Synesthesia scene (a .synScene folder): main.glsl's `vec4 renderMain()` is the shader, the
// scene.json beside it declares its controls (parameters, read not rewritten), its inputs are
// Shadertoy's and its built-in functions are provided where used and not defined. Without
// scene.json the run says where it looked, and a control is an undeclared identifier.
TEST(ForeignHosts, ASynesthesiaScenesControlsComeFromItsSceneJson) {
    namespace fs = std::filesystem;
    const fs::path folder = fs::temp_directory_path() / ("sdfwb-synscene-" + std::to_string(::getpid())) / "ball.synScene";
    fs::create_directories(folder);
    const std::string text = "// a ball that breathes\n"
                             "float ball(vec3 p) {\n"
                             "    p.xz = _rotate(p.xz, spin * PI);\n"
                             "    return length(p - vec3(centre, 0.0)) - size - 0.05 * _nsin(TIME) - 0.01 * syn_BassLevel;\n"
                             "}\n"
                             "vec4 renderMainImage() {\n"
                             "    vec3 rd = normalize(vec3(_uvc, 1.0)), o = vec3(0.0, 0.0, -3.0);\n"
                             "    float t = 0.0;\n"
                             "    for (int i = 0; i < 64; i++) { float d = ball(o + rd * t); if (d < 0.001) break; t += d; }\n"
                             "    return vec4(tint * t * 0.2, 1.0) + 0.0 * texture(syn_Spectrum, _uv) + 0.1 * _loadMedia();\n"
                             "}\n"
                             "vec4 renderMain() {\n"
                             "    if (PASSINDEX == 0) return renderMainImage();\n"
                             "}\n";
    std::ofstream(folder / "main.glsl") << text;
    std::ofstream(folder / "scene.json")
        << "{\n\t\"CONTROLS\" : [\n"
           "\t\t{ \"NAME\" : \"size\", \"TYPE\" : \"slider smooth\", \"DEFAULT\" : 0.5, \"MIN\" : 0.1, \"MAX\" : 1 },\n"
           "\t\t{ \"NAME\" : \"spin\", \"TYPE\" : \"knob\", \"DEFAULT\" : 0.25 },\n"
           "\t\t{ \"NAME\" : \"centre\", \"TYPE\" : \"xy smooth\", \"DEFAULT\" : [0.1, 0.2], \"MIN\" : [-1, -2], \"MAX\" : [1, "
           "2] },\n"
           "\t\t{ \"NAME\" : \"tint\", \"TYPE\" : \"color\", \"DEFAULT\" : [1, 0.5, 0] },\n"
           "\t],\n\t\"TITLE\" : \"Ball\"\n}\n";
    const std::string path = (folder / "main.glsl").string();
    const ParameterScan scan = parseParameters(text, path);
    ASSERT_EQ(scan.parameters.size(), 4u);
    EXPECT_EQ(find(scan.parameters, "size")->defaultValue[0], 0.5f);
    EXPECT_EQ(find(scan.parameters, "size")->maximum, 1.0f);
    EXPECT_EQ(find(scan.parameters, "centre")->type, ParameterType::Vec2);
    EXPECT_EQ(find(scan.parameters, "centre")->minimum, -2.0f) << "an xy pad's widest range";
    EXPECT_TRUE(find(scan.parameters, "tint")->color);
    EXPECT_EQ(find(scan.parameters, "tint")->defaultValue, (std::array<float, 4>{1.0f, 0.5f, 0.0f, 0.0f}));
    EXPECT_EQ(withDefaults(text, scan.parameters, {{"size", ParameterType::Float, {0.7f, 0, 0, 0}}}), text)
        << "scene.json is not the text: saving leaves the controls out";

    const PreparedSdf sdf = prepareSdf(text, path, folder / "main.glsl", IncludeOptions{});
    ASSERT_TRUE(sdf.ok()) << errors(sdf.diagnostics);
    EXPECT_EQ(sdf.host, "Synesthesia");
    EXPECT_EQ(sdf.signature.entry, "ball");
    EXPECT_EQ(sdf.parameters.size(), 4u);
    EXPECT_EQ(rootLines(sdf), lines(text)) << "every line keeps its number";
    EXPECT_NE(sdf.source.text.find("uniform vec2 centre;"), std::string::npos);
    EXPECT_NE(sdf.source.text.find("vec2 _rotate("), std::string::npos);
    EXPECT_EQ(sdf.source.text.find("_hsv2rgb"), std::string::npos) << "only what the scene uses";
    EXPECT_EQ(compileErrors(sdf), "");

    fs::remove(folder / "scene.json");
    const PreparedSdf alone = prepareSdf(text, path, folder / "main.glsl", IncludeOptions{});
    EXPECT_EQ(alone.host, "Synesthesia");
    EXPECT_FALSE(alone.ok());
    const auto warned = std::find_if(alone.diagnostics.begin(), alone.diagnostics.end(), [](const Diagnostic& d) {
        return d.severity == Severity::Warning && d.message.find("scene.json: missing or no CONTROLS") != std::string::npos;
    });
    EXPECT_NE(warned, alone.diagnostics.end()) << errors(alone.diagnostics);
    fs::remove_all(folder.parent_path());
}

// twigl.app's geeker and geekest modes: the text is main's body (FC, r, t in, o out), with twigl's
// rotate2D, rotate3D and hsv. It is read inside a mainImage on its first line, and its march's inline
// field is the field. A text that defines a function is no such body.
TEST(ForeignHosts, ATwiglBodyIsMainImagesBody) {
    const std::string text = "vec3 p=vec3(0,0,-3),d=normalize(vec3((FC.xy*2.-r)/r.y,1.));float e=1.,g=0.;\n"
                             "for(int i=0;i<64;i++){vec3 q=p;q.xz*=rotate2D(t);e=length(q)-.5;p+=d*e;g+=.01/abs(e);}\n"
                             "o=vec4(hsv(g,.5,1.),1);\n";
    const PreparedSdf sdf = prepare(text, "twigl.glsl");
    ASSERT_TRUE(sdf.ok()) << errors(sdf.diagnostics);
    EXPECT_EQ(sdf.host, "twigl");
    EXPECT_EQ(sdf.signature.entry, "mainImage");
    EXPECT_FALSE(sdf.signature.inlineBody.empty()) << "the march's inline field";
    EXPECT_EQ(rootLines(sdf), lines(text)) << "every line keeps its number";
    EXPECT_NE(sdf.source.text.find("mat2 rotate2D(float a)"), std::string::npos);
    EXPECT_EQ(sdf.source.text.find("rotate3D"), std::string::npos) << "only the helpers it calls";
    EXPECT_EQ(compileErrors(sdf), "");

    const PreparedSdf function = prepare("float f(vec2 c) { return c.x; }\no = vec4(f(FC.xy));\n", "notwigl.glsl");
    EXPECT_NE(function.host, "twigl");
}

// FragmentariumWeb's own includes (its web app's examples and its guide's "preferred include
// strategy"): the camera's uniforms, its primitives and its Mandelbulb step, none on disk.
TEST(ForeignHosts, FragmentariumWebsIncludesGiveItsPrimitives) {
    const std::string text = "#include \"common-camera-3d.frag\"\n"
                             "#include \"common-primitives.frag\"\n"
                             "#include \"common-fractal-utils.frag\"\n"
                             "#group Shape\n"
                             "uniform float Angle; slider[-180.0,25.0,180.0]\n"
                             "float DE(vec3 p) {\n"
                             "  vec3 q = rotationMatrix(vec3(0.0, 1.0, 0.0), radians(Angle)) * p;\n"
                             "  float dr = 1.0;\n"
                             "  vec3 z = powN1(q, 8.0, dr);\n"
                             "  return max(sdRoundBox(q, vec3(1.0), 0.1), -sdSphere(q, 0.5)) + 0.0 * z.x * dr;\n"
                             "}\n"
                             "#preset Default\n"
                             "Angle = 30\n"
                             "#endpreset\n";
    PreparedSdf sdf = prepare(text, "web.frag");
    ASSERT_TRUE(sdf.ok()) << errors(sdf.diagnostics);
    EXPECT_EQ(sdf.host, "Fragmentarium");
    EXPECT_EQ(sdf.signature.entry, "DE");
    EXPECT_NE(sdf.source.text.find("mat3 rotationMatrix(vec3 axis, float angle)"), std::string::npos) << sdf.source.text;
    EXPECT_EQ(sdf.source.text.find("mat4 rotationMatrix"), std::string::npos) << "MathUtils.frag's is not this include's";
    EXPECT_EQ(sdf.source.text.find("float sdBox("), std::string::npos) << "only what the code calls";
    EXPECT_EQ(rootLines(sdf), lines(text));
    EXPECT_EQ(compileErrors(sdf), "");
}

// GLSL 1.10 and WebGL 1 code names things with words later GLSL made keywords (Processing's
// Landscape example: `vec3 smoothmix(vec3 a, vec3 b, float base, float smooth, float source)`).
TEST(ForeignHosts, NamesLaterGlslTookAreRenamedWhereTheyAreNames) {
    const std::string text =
        "uniform float time;\n"
        "uniform vec2 resolution;\n"
        "float blend(float a, float b, float smooth) { return mix(a, b, smoothstep(0.0, smooth, a - b)); }\n"
        "float sample(vec3 p) { float filter = 0.5, common = 0.25; return blend(length(p) - filter, p.y + common, 0.1); }\n"
        "void main() {\n"
        "  vec3 rd = normalize(vec3((gl_FragCoord.xy - 0.5 * resolution) / resolution.y, 1.0)), ro = vec3(0.0, 0.0, -3.0);\n"
        "  float t = 0.0;\n"
        "  for (int i = 0; i < 64; i++) { float d = sample(ro + rd * t); if (d < 0.001) break; t += d; }\n"
        "  gl_FragColor = vec4(vec3(t * 0.1), 1.0);\n"
        "}\n";
    PreparedSdf sdf = prepare(text, "landscape.glsl");
    ASSERT_TRUE(sdf.ok()) << errors(sdf.diagnostics);
    EXPECT_EQ(sdf.signature.entry, "sample");
    for (const char* word : {"smooth", "sample", "filter", "common"})
        EXPECT_NE(std::find(sdf.compat.renamed.begin(), sdf.compat.renamed.end(), word), sdf.compat.renamed.end()) << word;
    EXPECT_EQ(compileErrors(sdf), "");
    // A qualifier stays one: `smooth` followed by a word is GLSL's, and the file's code is left alone.
    PreparedSdf qualified = prepare("smooth in vec3 normal;\nfloat sdf(vec3 p) { return length(p) - 0.5; }\n", "qualified.glsl");
    EXPECT_EQ(std::find(qualified.compat.renamed.begin(), qualified.compat.renamed.end(), "smooth"),
              qualified.compat.renamed.end());
}

// A TouchDesigner GLSL TOP pixel shader: TouchDesigner declares vUV, uTDOutputInfo and the TD
// functions; the user adds uTime and uResolution on the TOP's Vectors page.
TEST(ForeignHosts, ATouchDesignerPixelShadersBuiltinsAreProvided) {
    const std::string text = "uniform float uTime;\n"
                             "out vec4 fragColor;\n"
                             "float scene(vec3 p) { return length(p - vec3(0.0, 0.0, 0.1 * sin(uTime))) - 0.5; }\n"
                             "void main()\n"
                             "{\n"
                             "    vec2 res = uTDOutputInfo.res.zw;\n"
                             "    vec2 uv = vUV.st * 2.0 - 1.0;\n"
                             "    uv.x *= res.x / res.y;\n"
                             "    vec3 ro = vec3(0.0, 0.0, -3.0), rd = normalize(vec3(uv, 1.5));\n"
                             "    float t = 0.0;\n"
                             "    for (int i = 0; i < 64; i++) { float d = scene(ro + rd * t); if (d < 0.001) break; t += d; }\n"
                             "    vec3 col = TDHSVToRGB(vec3(t * 0.1, 0.5, 1.0));\n"
                             "    fragColor = TDOutputSwizzle(TDDither(vec4(col, 1.0)));\n"
                             "}\n";
    PreparedSdf sdf = prepare(text, "raymarch_pixel.frag");
    ASSERT_TRUE(sdf.ok()) << errors(sdf.diagnostics);
    EXPECT_EQ(sdf.host, "TouchDesigner");
    EXPECT_EQ(sdf.signature.entry, "scene");
    EXPECT_EQ(sdf.source.text.find("TDRGBToHSV"), std::string::npos) << "only what the code calls";
    EXPECT_EQ(rootLines(sdf), lines(text));
    EXPECT_EQ(compileErrors(sdf), "");
}

// A pixel shader that writes its own TDDither (the TD functions are only declared by the host when
// the file does not define them) keeps it, and only the one it calls but lacks is provided.
TEST(ForeignHosts, ATouchDesignerShadersOwnHelperIsKept) {
    const std::string text = "out vec4 fragColor;\n"
                             "vec4 TDDither (vec4 c)\n"
                             "{ return c + 0.002; }\n"
                             "float scene(vec3 p) { return length(p) - 0.5; }\n"
                             "void main()\n"
                             "{\n"
                             "    vec2 uv = vUV.st * 2.0 - 1.0;\n"
                             "    vec3 ro = vec3(0.0, 0.0, -3.0), rd = normalize(vec3(uv, 1.5));\n"
                             "    float t = 0.0;\n"
                             "    for (int i = 0; i < 64; i++) { float d = scene(ro + rd * t); if (d < 0.001) break; t += d; }\n"
                             "    if (TDDither(vec4(t)).x > 0.0) fragColor = TDOutputSwizzle(TDDither(vec4(t * 0.1)));\n"
                             "}\n";
    PreparedSdf sdf = prepare(text, "own_dither.frag");
    ASSERT_TRUE(sdf.ok()) << errors(sdf.diagnostics);
    EXPECT_EQ(sdf.host, "TouchDesigner");
    const std::string& composed = sdf.source.text;
    EXPECT_EQ(composed.find("TDDither(vec4 c)"), std::string::npos) << "the file's own TDDither, not a second one";
    EXPECT_NE(composed.find("TDOutputSwizzle(vec4 c)"), std::string::npos);
    EXPECT_EQ(compileErrors(sdf), "");
}

// A TouchDesigner TOP's inputs (an iq terrain reading its noise from `sTD2DInputs[0]`, written
// without the TD output functions): the host is recognised from them, and each input, connected to
// nothing here, reads the empty unit. The names sdfwb writes for them are not the user's, so the
// reserved-name check leaves them alone.
TEST(ForeignHosts, ATouchDesignerTopsInputsReadTheEmptyUnit) {
    const std::string text =
        "uniform vec4 iResolution;\n"
        "uniform float iGlobalTime;\n"
        "out vec4 fragColor;\n"
        "float terrain(vec2 x) { return texture(sTD2DInputs[0], x / 256.0, -100.0).x\n"
        "    + texture( sTD2DInputs [ 1 ], x).y + texture(sTD3DInputs[0], vec3(x, 0.0)).x; }\n"
        "float map(vec3 p) { return p.y - terrain(p.xz); }\n"
        "void main() {\n"
        "    vec2 uv = (2.0 * gl_FragCoord.xy - iResolution.xy) / iResolution.y;\n"
        "    vec3 ro = vec3(0.0, 1.0, iGlobalTime), rd = normalize(vec3(uv, 1.5));\n"
        "    float t = 0.0;\n"
        "    for (int i = 0; i < 64; i++) { float d = map(ro + rd * t); if (d < 0.001) break; t += 0.5 * d; }\n"
        "    fragColor = vec4(vec3(t * 0.1), 1.0);\n"
        "}\n";
    PreparedSdf sdf = prepare(text, "mountains_fragment.glsl");
    expectOpens(sdf, text, "TouchDesigner", "map");
    EXPECT_NE(sdf.source.text.find("layout(binding = 13) uniform sampler2D sdfwb_sTD2DInputs;"), std::string::npos);
    EXPECT_NE(sdf.source.text.find("layout(binding = 14) uniform sampler3D sdfwb_sTD3DInputs;"), std::string::npos);
    EXPECT_EQ(sdf.source.text.find("sTD2DInputs["), std::string::npos);
    // The user's own name with the reserved prefix is still refused.
    std::string own = text;
    own.replace(own.find("float terrain"), 13, "float sdfwb_terrain");
    own.replace(own.find("- terrain("), 10, "- sdfwb_terrain(");
    const PreparedSdf refused = prepare(own, "mountains_fragment.glsl");
    EXPECT_FALSE(refused.ok());
    EXPECT_NE(errors(refused.diagnostics).find("'sdfwb_terrain': names beginning with sdfwb_"), std::string::npos);
}

// Fragmentarium's MathUtils.frag defines PI, which fragments use without defining it (DarkBeam's knot
// in FragM's examples); a fragment's own PI is kept.
TEST(ForeignHosts, FragmentariumsMathUtilsGivesPi) {
    const std::string text =
        "#include \"MathUtils.frag\"\n"
        "#include \"DE-Raytracer.frag\"\n"
        "uniform float Turns; slider[1,3,8]\n"
        "float DE(vec3 p) { float a = Turns / (2.0 * PI) * atan(p.y, p.x); return length(p) - 0.5 - 0.01 * sin(a); }\n";
    PreparedSdf sdf = prepare(text, "knot.frag");
    ASSERT_TRUE(sdf.ok()) << errors(sdf.diagnostics);
    EXPECT_EQ(sdf.host, "Fragmentarium");
    EXPECT_NE(sdf.source.text.find("const float PI = 3.14159265358979;"), std::string::npos);
    EXPECT_EQ(compileErrors(sdf), "");
    const std::string own = "#define PI 3.14159\n" + text;
    PreparedSdf kept = prepare(own, "knot.frag");
    ASSERT_TRUE(kept.ok()) << errors(kept.diagnostics);
    EXPECT_EQ(kept.source.text.find("const float PI"), std::string::npos);
}

// A Processing sketch's port layer (SableRaf's Processing experiments): Shadertoy's names declared
// as globals copied from Processing's uniforms, which sdfwb declares and sets itself.
TEST(ForeignHosts, AProcessingPortsLayerOfShadertoyNamesGoes) {
    const std::string text = "#define PROCESSING_COLOR_SHADER\n"
                             "uniform float time;\n"
                             "uniform vec2 resolution;\n"
                             "uniform vec2 mouse;\n"
                             "vec3 iResolution = vec3(resolution, 0.0);\n"
                             "float iGlobalTime = time;\n"
                             "uniform vec2 mousePressed;\n"
                             "vec4 iMouse = vec4(mouse.xy, mousePressed.xy);\n"
                             "float scene(vec3 p) { return length(p) - 0.5 - 0.1 * sin(iGlobalTime); }\n"
                             "void main() {\n"
                             "    vec2 uv = (2.0 * gl_FragCoord.xy - iResolution.xy) / iResolution.y + iMouse.xy * 0.0;\n" +
                             marchTo("scene", "gl_FragColor") + "}\n";
    PreparedSdf sdf = prepare(text, "shader.glsl");
    expectOpens(sdf, text, "", "scene");
    EXPECT_EQ(sdf.source.text.find("vec3 iResolution ="), std::string::npos);
    EXPECT_EQ(sdf.source.text.find("vec4 iMouse ="), std::string::npos);
}

// A main() that writes its colour and reads its pixel through macros (`#define O gl_FragColor`,
// `#define U gl_FragCoord.xy`: darkeclipz's temple for the VS Code preview) is the host's main.
TEST(ForeignHosts, AMainWritingThroughMacrosIsTheHostsMain) {
    const std::string text = "#define O gl_FragColor\n"
                             "#define U gl_FragCoord.xy\n"
                             "#define R iResolution.xy\n"
                             "float map(vec3 p) { return length(p) - 0.5; }\n"
                             "void main() {\n"
                             "    vec2 uv = (2.0 * U - R) / R.y;\n" +
                             marchTo("map", "O") + "}\n";
    PreparedSdf sdf = prepare(text, "raymarch_temple.glsl");
    expectOpens(sdf, text, "", "map");
    EXPECT_EQ(sdf.source.text.find("gl_FragColor"), std::string::npos);
    EXPECT_EQ(sdf.source.text.find("gl_FragCoord"), std::string::npos);
}

// sokol-shdc's annotated file (sokol_gp's SDF sample): the vertex stage and the annotations go, the
// fragment stage is the shader, and its uniform block without an instance name (`uniform sdf_uniform
// { vec2 iResolution; float iTime; };`) gives plain uniforms, read as Shadertoy's inputs.
TEST(ForeignHosts, ASokolShdcFilesFragmentStageIsTheShader) {
    const std::string text = "@ctype vec2 sgp_vec2\n"
                             "@vs sdf_vs\n"
                             "in vec4 coord;\n"
                             "out vec2 fragUV;\n"
                             "void main() { gl_Position = vec4(coord.xy, 0.0, 1.0); fragUV = coord.zw; }\n"
                             "@end\n"
                             "@fs sdf_fs\n"
                             "uniform sdf_uniform {\n"
                             "    vec2 iResolution;\n"
                             "    float iTime;\n"
                             "};\n"
                             "in vec2 fragUV;\n"
                             "out vec4 fragColor;\n"
                             "float get_sdf(vec3 p) { return length(p - vec3(0.0, 0.1 * sin(iTime), 0.0)) - 0.5; }\n"
                             "void main() {\n"
                             "    vec2 uv = (fragUV * iResolution - 0.5 * iResolution) / iResolution.y;\n" +
                             marchTo("get_sdf", "fragColor") +
                             "}\n"
                             "@end\n"
                             "@program sdf sdf_vs sdf_fs\n";
    PreparedSdf sdf = prepare(text, "sample-sdf.glsl");
    expectOpens(sdf, text, "sokol-shdc", "get_sdf");
    EXPECT_TRUE(sdf.usesTime()) << "iTime from the block is sdfwb's time";
    EXPECT_EQ(sdf.source.text.find("gl_Position"), std::string::npos);
    EXPECT_EQ(sdf.source.text.find("@"), std::string::npos);
}

// The same block with a layout, and a second block right after it (`};uniform`), in a raw OpenGL
// program's fragment shader: both blocks' members are plain uniforms.
TEST(ForeignHosts, UniformBlocksWithoutNamesAndWithLayoutsGivePlainUniforms) {
    const std::string text = "#version 330 core\n"
                             "layout(std140) uniform Frame { vec2 iResolution; };uniform Clock { float iTime; };\n"
                             "out vec4 color;\n"
                             "float scene(vec3 p) { return length(p) - 0.5 - 0.1 * sin(iTime); }\n"
                             "void main() {\n"
                             "    vec2 uv = (gl_FragCoord.xy - 0.5 * iResolution) / iResolution.y;\n" +
                             marchTo("scene", "color") + "}\n";
    PreparedSdf sdf = prepare(text, "raymarch.frag");
    expectOpens(sdf, text, "", "scene");
    EXPECT_TRUE(sdf.usesTime()) << sdf.source.text;
    EXPECT_EQ(sdf.source.text.find("std140"), std::string::npos) << sdf.source.text;
    EXPECT_EQ(sdf.source.text.find("Clock"), std::string::npos) << sdf.source.text;
}

// Vulkan GLSL (a vulkano raymarcher): a push-constant block is a struct and a global of it, and
// `set = N` leaves the layouts; an error is still reported at the user's line.
TEST(ForeignHosts, VulkanPushConstantsAndDescriptorSetsAreReadAsOpenGls) {
    const std::string text = "#version 450\n"
                             "layout(push_constant) uniform PushConstants {\n"
                             "    mat4 view;\n"
                             "    vec2 resolution;\n"
                             "} push;\n"
                             "layout(set = 0, binding = 1) uniform sampler2D tex;\n"
                             "layout(set = 1) uniform Extra { float radius; } extra;\n"
                             "layout(location = 0) out vec4 f_color;\n"
                             "float f(vec3 p) { return length(p) - 0.5 - 0.0 * texture(tex, p.xy).x - extra.radius; }\n"
                             "void main() {\n"
                             "    vec2 uv = (gl_FragCoord.xy - 0.5 * push.resolution) / max(push.resolution.y, 1.0);\n" +
                             marchTo("f", "f_color") + "}\n";
    PreparedSdf sdf = prepare(text, "raymarching-3d.frag");
    expectOpens(sdf, text, "Vulkan GLSL", "f");
    EXPECT_NE(sdf.source.text.find("struct PushConstants"), std::string::npos);
    EXPECT_EQ(sdf.source.text.find("push_constant"), std::string::npos);
    EXPECT_EQ(sdf.source.text.find("set ="), std::string::npos);
    std::string broken = text;
    broken.replace(broken.find("- extra.radius"), 14, "- extra.radius + undefinedName");
    const PreparedSdf bad = prepare(broken, "raymarching-3d.frag");
    EXPECT_FALSE(bad.ok());
    EXPECT_NE(errors(bad.diagnostics).find("raymarching-3d.frag:9:"), std::string::npos) << errors(bad.diagnostics);
}

// A MadMapper material (its Raymarching Template): an ISF-like header with an `int` input and a
// time_base generator, `#include "MadCommon.glsl"` (MadMapper's own, giving PI), the ray handed
// over by its vertex stage (`flat in vec3 vro;`), and `vec4 materialColorForPixel(vec2 texCoord)`
// instead of main.
TEST(ForeignHosts, AMadMapperMaterialsInputsGeneratorsAndColourFunction) {
    const std::string text =
        "/*{\n"
        "    \"RESOURCE_TYPE\": \"Material For MadMapper\",\n"
        "    \"INPUTS\": [\n"
        "        { \"LABEL\": \"Quality\", \"NAME\": \"mat_quality\", \"TYPE\": \"int\", \"MIN\": 10, \"MAX\": "
        "100, \"DEFAULT\": 64 },\n"
        "        { \"LABEL\": \"Speed\", \"NAME\": \"mat_speed\", \"TYPE\": \"float\", \"MIN\": 0.0, \"MAX\": "
        "2.0, \"DEFAULT\": 1. },\n"
        "    ],\n"
        "    \"GENERATORS\": [\n"
        "        {\"NAME\": \"mat_time\", \"TYPE\": \"time_base\", \"PARAMS\": {\"speed\": \"mat_speed\",}},\n"
        "    ],\n"
        "}*/\n"
        "#include \"MadCommon.glsl\"\n"
        "flat in vec3 vro;\n"
        "in vec3 vrd;\n"
        "float map(vec3 p) { return length(p) - 0.5 - 0.05 * sin(mat_time + PI * p.y); }\n"
        "float intersect(vec3 ro, vec3 rd) {\n"
        "    float t = 0.0;\n"
        "    for (int i = 0; i < mat_quality; i++) { float h = map(ro + rd * t); if (h < 0.001) break; t += h; }\n"
        "    return t;\n"
        "}\n"
        "vec4 materialColorForPixel(vec2 texCoord) {\n"
        "    vec3 ro = vro, rd = normalize(vrd + vec3(texCoord * 2.0 - 1.0, 0.0));\n"
        "    return vec4(vec3(intersect(ro, rd) * 0.1), 1.0);\n"
        "}\n";
    PreparedSdf sdf = prepare(text, "Raymarching Template.fs");
    expectOpens(sdf, text, "MadMapper", "map");
    EXPECT_TRUE(sdf.usesTime()) << "the time_base generator is the time";
    const Parameter* quality = find(sdf.parameters, "mat_quality");
    ASSERT_NE(quality, nullptr);
    EXPECT_EQ(quality->type, ParameterType::Int);
    EXPECT_EQ(quality->defaultValue[0], 64.0f);
    EXPECT_NE(sdf.source.text.find("const float PI"), std::string::npos);
    EXPECT_EQ(sdf.source.text.find("MadCommon"), std::string::npos);
}

// A Max/Jitter shader file (a .jxs: XML holding the vertex and fragment programs in CDATA, the
// parameters as <param> elements): the fragment program is the shader, its `uniform vec2
// iResolution` (Jitter's RESOLUTION state) sdfwb's frame size.
TEST(ForeignHosts, AMaxJitterShaderFilesFragmentProgramIsTheShader) {
    const std::string text = "<jittershader name=\"Raymarching Template\">\n"
                             "<param name=\"iTime\" type=\"float\" default=\"0.0\" />\n"
                             "<param name=\"iResolution\" type=\"vec2\" state=\"RESOLUTION\" />\n"
                             "<language name=\"glsl\" version=\"1.5\">\n"
                             "<bind param=\"iTime\" program=\"fp\" />\n"
                             "<program name=\"vp\" type=\"vertex\">\n"
                             "<![CDATA[\n"
                             "#version 330 core\n"
                             "in vec3 position;\n"
                             "void main(void) { gl_Position = vec4(position, 1.0); }\n"
                             "]]>\n"
                             "</program>\n"
                             "<program name=\"fp\" type=\"fragment\">\n"
                             "<![CDATA[\n"
                             "#version 330 core\n"
                             "in jit_PerVertex { vec2 texcoord; } jit_in;\n"
                             "layout (location = 0) out vec4 outColor;\n"
                             "uniform float iTime;\n"
                             "uniform vec2 iResolution;\n"
                             "float getDist(vec3 p) { return length(p - vec3(0.0, 0.0, 0.1 * sin(iTime))) - 0.5; }\n"
                             "void main() {\n"
                             "    vec2 uv = (gl_FragCoord.xy - 0.5 * iResolution) / iResolution.y;\n" +
                             marchTo("getDist", "outColor") +
                             "}\n"
                             "]]>\n"
                             "</program>\n"
                             "</language>\n"
                             "</jittershader>\n";
    PreparedSdf sdf = prepare(text, "raymarching-template.jxs");
    expectOpens(sdf, text, "Max/Jitter", "getDist");
    EXPECT_TRUE(sdf.usesTime());
    EXPECT_EQ(sdf.source.text.find("jittershader"), std::string::npos);
    EXPECT_EQ(sdf.source.text.find("gl_Position"), std::string::npos);
}

// A RetroArch shader (libretro's glsl-shaders/procedural: Shadertoy ports): both stages in one file
// under `#if defined(VERTEX) ... #elif defined(FRAGMENT) ... #endif`, the port's layer
// `vec2 iResolution = OutputSize.xy;` and a main() that wraps mainImage. The fragment part is the
// shader, its vec2 frame size sdfwb's iResolution.xy.
TEST(ForeignHosts, ARetroArchShadersFragmentPartIsTheShader) {
    const std::string text = "#if defined(VERTEX)\n"
                             "#if __VERSION__ >= 130\n"
                             "#define COMPAT_VARYING out\n"
                             "#endif\n"
                             "COMPAT_VARYING vec4 TEX0;\n"
                             "void main() { gl_Position = vec4(0.0); }\n"
                             "#elif defined(FRAGMENT)\n"
                             "#define COMPAT_VARYING in\n"
                             "COMPAT_VARYING vec4 TEX0;\n"
                             "out vec4 FragColor;\n"
                             "uniform int FrameCount;\n"
                             "uniform vec2 OutputSize;\n"
                             "vec2 iResolution = OutputSize.xy;\n"
                             "float map(vec3 p) { return length(p) - 0.5; }\n"
                             "void mainImage(out vec4 fragColor, in vec2 fragCoord) {\n"
                             "    vec2 uv = (fragCoord - 0.5 * iResolution) / iResolution.y;\n" +
                             marchTo("map", "fragColor") +
                             "}\n"
                             "void main(void) { mainImage(FragColor, gl_FragCoord.xy); }\n"
                             "#endif\n";
    PreparedSdf sdf = prepare(text, "leon-mam-stairs.glsl");
    expectOpens(sdf, text, "RetroArch", "map");
    EXPECT_EQ(sdf.source.text.find("gl_Position"), std::string::npos);
    EXPECT_EQ(sdf.source.text.find("defined(FRAGMENT)"), std::string::npos);
}

// glslify's imports (`#pragma glslify: rotate = require(../common/rotate)`, three.js projects):
// sdfwb does not bundle, and says so at the line, naming the function left undefined.
TEST(ForeignHosts, AGlslifyImportIsNamedAtItsLine) {
    const std::string text = "uniform float u_time;\n"
                             "#pragma glslify: rotate = require(../../common/rotate)\n"
                             "float scene(vec3 p) { return length(rotate(p, vec3(0.0, 1.0, 0.0), u_time)) - 0.5; }\n"
                             "void main() { gl_FragColor = vec4(scene(vec3(0.0))); }\n";
    const PreparedSdf sdf = prepare(text, "frag.glsl");
    const auto warning = std::find_if(sdf.diagnostics.begin(), sdf.diagnostics.end(), [](const Diagnostic& d) {
        return d.message.find("glslify's import of 'rotate'") != std::string::npos;
    });
    ASSERT_NE(warning, sdf.diagnostics.end()) << errors(sdf.diagnostics);
    EXPECT_EQ(warning->line, 2);
    EXPECT_EQ(warning->severity, Severity::Warning);
    EXPECT_NE(warning->message.find("npx glslify"), std::string::npos);
}

// raylib's hybrid ray marching example (`in vec2 fragTexCoord;`, gl_FragColor and gl_FragDepth
// written in main): the depth is a global of its own, as a compute stage has no gl_FragDepth.
TEST(ForeignHosts, AMainWritingItsDepthOpensAndSamples) {
    const std::string text = "#version 330\n"
                             "in vec2 fragTexCoord;\n"
                             "uniform vec2 resolution;\n"
                             "float map(vec3 p) { return length(p) - 0.5; }\n"
                             "void main() {\n"
                             "    vec2 uv = (2.0 * gl_FragCoord.xy - resolution) / resolution.y;\n" +
                             marchTo("map", "gl_FragColor") +
                             "    gl_FragDepth = t / 100.0;\n"
                             "}\n";
    PreparedSdf sdf = prepare(text, "hybrid_raymarch.fs");
    expectOpens(sdf, text, "", "map");
    EXPECT_EQ(sdf.source.text.find("gl_FragDepth"), std::string::npos);
}
