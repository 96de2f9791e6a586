// SDF code in the styles of public code (tests/foreign/, written here; see its README): every file
// opens unmodified (its entry point found, or named where it is not a conventional one), renders,
// samples (near, 1e5) and gets exactly the audit flags its construction implies (its `expect:` line,
// explained in its comments). Also: a file that defines the names public SDF code uses most (as
// functions, constants, structs, uniforms and macros) composes with every tracer variant and every
// sampler, and each program compiles and runs.

#include <renderer/NoiseTexture.h>
#include <renderer/OffscreenRenderer.h>
#include <renderer/SampleCompute.h>
#include <renderer/SdfRenderer.h>
#include <renderer/ShadertoyPicture.h>
#include <sampling/FieldAudit.h>
#include <sampling/Sampler.h>
#include <sampling/SamplerLibrary.h>
#include <shaders/BuiltinShaders.h>
#include <shaders/SdfSource.h>
#include <values/Camera.h>

#include "ForeignTest.h"
#include "GlTestContext.h"
#include "common/FirstError.h"

#include <glm/glm.hpp>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <optional>
#include <regex>
#include <set>
#include <sstream>

#include <unistd.h>

using namespace sdfwb;
using sdfwb::testing::firstError;
using sdfwb::testing::kFolder;
using sdfwb::testing::prepare;
namespace fs = std::filesystem;

namespace {

struct Expectation {
    std::string entry;
    std::vector<std::string> flags; // sorted
    bool animated = false;
};

Expectation readExpectation(const fs::path& file) {
    std::ifstream in(file);
    std::stringstream text;
    text << in.rdbuf();
    static const std::regex line(R"(// expect: entry=(\w+) flags=([a-z,-]+) animated=(yes|no))");
    std::smatch match;
    const std::string content = text.str();
    Expectation e;
    if (!std::regex_search(content, match, line)) {
        ADD_FAILURE() << file << ": no `// expect:` line";
        return e;
    }
    e.entry = match[1].str();
    std::stringstream flags(match[2].str());
    for (std::string flag; std::getline(flags, flag, ',');)
        if (flag != "none") e.flags.push_back(flag);
    std::sort(e.flags.begin(), e.flags.end());
    e.animated = match[3].str() == "yes";
    return e;
}

std::vector<std::string> corpusFiles() {
    std::vector<std::string> names;
    for (const auto& item : fs::directory_iterator(kFolder))
        if (item.path().extension() == ".glsl" && std::isdigit(static_cast<unsigned char>(item.path().filename().string()[0])))
            names.push_back(item.path().filename().string());
    std::sort(names.begin(), names.end());
    return names;
}

// A test's name from its file: the stem, with anything but letters and digits as '_'.
std::string fileTestName(const ::testing::TestParamInfo<std::string>& info) {
    std::string name = fs::path(info.param).stem().string();
    for (char& c : name)
        if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
    return name;
}

class ForeignCode : public sdfwb::testing::GlTest, public ::testing::WithParamInterface<std::string> {};

} // namespace

TEST(ForeignCorpus, HasTheStylesTheIssueAsksFor) {
    const auto files = corpusFiles();
    EXPECT_GE(files.size(), 25u);
    std::set<std::string> flags, entries;
    int includes = 0, animated = 0;
    for (const std::string& name : files) {
        Expectation e = readExpectation(kFolder / name);
        flags.insert(e.flags.begin(), e.flags.end());
        entries.insert(e.entry);
        animated += e.animated;
        std::ifstream in(kFolder / name);
        std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
        includes += text.find("#include") != std::string::npos;
    }
    EXPECT_EQ(flags, (std::set<std::string>{"discontinuous", "nan", "non-conservative", "truncated"}));
    EXPECT_GE(entries.size(), 4u) << "sdf, map and other entry names";
    EXPECT_GE(includes, 3);
    EXPECT_GE(animated, 3);
}

TEST_P(ForeignCode, OpensRendersSamplesAndGetsItsFlags) {
    const fs::path file = kFolder / GetParam();
    const Expectation expected = readExpectation(file);
    // Opens unmodified: `sdf` and the conventional names are found without being named, and a
    // whole shader's field by its own march, whatever it is called (issue 47).
    const auto& conventional = shaders::conventionalEntries();
    std::ifstream in(file);
    const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    // Shadertoy's mainImage, or another host's main() (glslViewer, GLSL Sandbox, Bonzomatic, ...).
    const std::string code = shaders::stripComments(text);
    const bool hostMain = std::regex_search(code, std::regex(R"(\bvoid\s+main\s*\()"));
    const bool wholeShader = code.find("mainImage") != std::string::npos || hostMain;
    const bool findable = wholeShader || expected.entry == "sdf" ||
                          std::find(conventional.begin(), conventional.end(), expected.entry) != conventional.end();
    shaders::PreparedSdf sdf = prepare(file, findable ? std::string() : expected.entry);
    ASSERT_TRUE(sdf.ok()) << firstError(sdf);
    // Another host's shader is read as that host's (a host's main(), Fragmentarium's annotations).
    const bool otherHost = hostMain || code.find("slider[") != std::string::npos;
    EXPECT_EQ(sdf.host.empty(), !otherHost) << sdf.host;
    EXPECT_EQ(sdf.signature.entry, expected.entry);
    EXPECT_EQ(sdf.usesTime(), expected.animated);
    if (sdf.entrySource == shaders::EntrySource::March) {
        // A function the march calls, or the field the march writes inline in ENTRY's loop.
        EXPECT_TRUE(sdf.entryReason.rfind(expected.entry + " (called by the march at line ", 0) == 0 ||
                    sdf.entryReason.rfind(expected.entry + " (its march at line ", 0) == 0)
            << sdf.entryReason;
    }

    // Compiles in the march debugger's program too (the sampler's compute stage is below).
    {
        renderer::SdfRenderer probe;
        values::ShadingSettings probing;
        probing.probe = true;
        ASSERT_FALSE(shaders::hasErrors(probe.setShading(probing)));
        auto probeDiagnostics = probe.setSdf(sdf);
        EXPECT_FALSE(shaders::hasErrors(probeDiagnostics))
            << (probeDiagnostics.empty() ? "" : shaders::formatDiagnostic(probeDiagnostics.front()));
        probe.releaseGl();
    }

    // Renders: the shape is in view.
    renderer::SdfRenderer sdfRenderer;
    values::ShadingSettings shading;
    shading.statsOutput = true;
    ASSERT_FALSE(shaders::hasErrors(sdfRenderer.setShading(shading)));
    auto diagnostics = sdfRenderer.setSdf(sdf);
    ASSERT_FALSE(shaders::hasErrors(diagnostics)) << (diagnostics.empty() ? "" : shaders::formatDiagnostic(diagnostics.front()));
    values::Camera camera;
    camera.position = {1.8f, 1.4f, 2.6f};
    camera.target = {0.0f, 0.0f, 0.0f};
    renderer::OffscreenRenderer offscreen;
    auto pixels = offscreen.renderStats(sdfRenderer, 64, 48, camera, 0.5f);
    sdfRenderer.releaseGl();
    const auto hits = std::count_if(pixels.begin(), pixels.end(), [](const auto& p) { return p.hit(); });
    EXPECT_GT(hits, 64) << "fewer than 64 of 3072 pixels hit the shape";

    // The compute tracer draws the fragment tracer's picture (issue 49): the same text but for
    // its main, so the same pixels, but for a few where a driver rounds the stages differently.
    {
        std::vector<renderer::Image> pictures;
        for (auto tracer : {values::TraceSettings::Tracer::Fragment, values::TraceSettings::Tracer::Compute}) {
            renderer::SdfRenderer tracerRenderer;
            values::TraceSettings trace;
            trace.tracer = tracer;
            ASSERT_FALSE(shaders::hasErrors(tracerRenderer.setTrace(trace)));
            ASSERT_FALSE(shaders::hasErrors(tracerRenderer.setSdf(sdf)));
            EXPECT_EQ(tracerRenderer.computeTracer(), tracer == values::TraceSettings::Tracer::Compute);
            pictures.push_back(offscreen.render(tracerRenderer, 64, 48, camera, 0.5f));
            tracerRenderer.releaseGl();
        }
        long differing = 0;
        for (std::size_t i = 0; i < pictures[0].rgba.size(); i += 4)
            differing += !std::equal(&pictures[0].rgba[i], &pictures[0].rgba[i] + 3, &pictures[1].rgba[i]);
        std::printf("%s: %ld of 3072 pixels differ between the fragment and the compute tracer\n", GetParam().c_str(), differing);
        EXPECT_LE(differing, 3) << "of 3072 pixels differ between the fragment and the compute tracer";
    }

    // Samples near the surface: rows land near the zero set.
    auto sampler = sampling::findSampler("near", {});
    ASSERT_TRUE(sampler.hasValue());
    renderer::SampleCompute compute;
    ASSERT_FALSE(shaders::hasErrors(compute.build(sdf, *sampler)));
    sampling::SamplingJob job;
    job.count = 100000;
    job.time = 0.5f;
    std::vector<float> positions(3 * job.count), distances(job.count), gradients(3 * job.count);
    auto report = sampling::sampleInto(compute, job, positions.data(), distances.data(), gradients.data(), {});
    compute.releaseGl();
    ASSERT_TRUE(report.hasValue()) << report.error().message;
    EXPECT_EQ(report->rows, job.count);
    std::vector<float> finite;
    for (float d : distances)
        if (std::isfinite(d)) finite.push_back(std::abs(d));
    const bool hasNan = std::count(expected.flags.begin(), expected.flags.end(), "nan") != 0;
    if (!hasNan) { EXPECT_LT(double(report->badRows), 0.05 * double(job.count)) << "near: rows without a surface"; }
    ASSERT_FALSE(finite.empty());
    std::nth_element(finite.begin(), finite.begin() + long(finite.size() / 2), finite.end());
    EXPECT_LT(finite[finite.size() / 2], 0.05f) << "near samples are not near the surface";

    // Audited: exactly the findings the construction implies.
    sampling::AuditOptions options;
    options.samples = 20000;
    options.convergence = false;
    options.time = 0.5f;
    auto audit = sampling::auditField(sdf, options, {});
    ASSERT_TRUE(audit.hasValue()) << audit.error().message;
    std::vector<std::string> flags;
    for (const auto& f : audit->flags) flags.push_back(values::findingName(f.finding));
    std::sort(flags.begin(), flags.end());
    EXPECT_EQ(flags, expected.flags) << GetParam() << ": " << values::findingName(audit->verdict) << ": " << audit->reason;
    if (!expected.flags.empty()) { EXPECT_EQ(audit->verdict, audit->flags.front().finding); }
}

INSTANTIATE_TEST_SUITE_P(Corpus, ForeignCode, ::testing::ValuesIn(corpusFiles()), fileTestName);

// A march that steps a fixed amount and stops where a value of its point crosses a level: the
// field is that difference (issue 47's fixed-step marches). 84 stops where p.y < h under a height
// field, 85 where a potential turns positive; a loop that goes on while the terrain is below its
// point (`if (h < p.y) { t += dt; p = ...; h = ...; }`) stops where that ends, as does a golfed
// loop whose test compares a height written inline with p.y; a loop that adds up a density, or
// stops only when it leaves a ball, is no level.
class LevelFields : public sdfwb::testing::GlTest {};

namespace {
// The field a whole shader's march writes inline (its loop's body run once), at `p`.
float valueAt(const fs::path& name, glm::vec3 p) {
    shaders::PreparedSdf sdf = prepare(kFolder / name); // an absolute `name` stands for itself
    EXPECT_TRUE(sdf.ok()) << firstError(sdf);
    EXPECT_FALSE(sdf.signature.inlineBody.empty()) << name;
    renderer::SampleCompute compute;
    EXPECT_FALSE(shaders::hasErrors(compute.build(sdf, *shaders::builtinPiece("analysis/points.glsl"))));
    sampling::SamplingJob job;
    job.count = 1;
    job.inputPoints = &p.x;
    float position[3], distance = 0.0f, gradient[3];
    EXPECT_TRUE(sampling::sampleInto(compute, job, position, &distance, gradient, {}).hasValue());
    compute.releaseGl();
    return distance;
}
} // namespace

TEST_F(LevelFields, TheComparedDifferenceIsTheField) {
    auto terrain = [](float x, float z) {
        return 0.25f * std::sin(1.7f * x) * std::cos(1.3f * z) + 0.1f * std::sin(3.1f * x + 2.3f * z) - 0.2f;
    };
    for (const glm::vec3 p : {glm::vec3(0.3f, 0.5f, 0.2f), glm::vec3(-0.7f, -0.6f, 0.4f)})
        EXPECT_NEAR(valueAt("84_st_terrain_height_march.glsl", p), p.y - terrain(p.x, p.z), 1e-5f);
    auto blob = [](glm::vec3 p, glm::vec3 c, float e, float r) {
        const float x = std::clamp(glm::length(p - c) / r, 0.0f, 1.0f);
        return e * std::pow(1.0f - x * x, 3.0f);
    };
    for (const glm::vec3 p : {glm::vec3(-0.35f, 0.0f, 0.0f), glm::vec3(0.2f, 0.3f, 0.1f), glm::vec3(1.5f, 0.0f, 0.0f)}) {
        const float potential = blob(p, {-0.35f, 0.0f, 0.0f}, 1.0f, 0.9f) + blob(p, {0.35f, 0.1f, 0.0f}, 1.0f, 0.8f) +
                                blob(p, {0.0f, -0.25f, 0.3f}, 0.8f, 0.7f) - 0.45f;
        EXPECT_NEAR(valueAt("85_st_potential_fixed_step.glsl", p), 0.0f - potential, 1e-5f);
    }
    const shaders::PreparedSdf heights = prepare(kFolder / "84_st_terrain_height_march.glsl");
    EXPECT_NE(heights.entryReason.find("steps t += dt and stops where p.y < h: the field is p.y - h"), std::string::npos)
        << heights.entryReason;
    EXPECT_TRUE(std::any_of(heights.diagnostics.begin(), heights.diagnostics.end(), [](const shaders::Diagnostic& d) {
        return d.severity == shaders::Severity::Warning && d.message.find("not distances") != std::string::npos;
    }));

    const fs::path folder = fs::temp_directory_path() / ("sdfwb-foreign-level-" + std::to_string(::getpid()));
    fs::create_directories(folder);
    std::ofstream(folder / "going.glsl") << "float height(vec2 q) { return 0.3 * sin(2.0 * q.x) - 0.1; }\n"
                                            "void mainImage(out vec4 c, in vec2 f) {\n"
                                            "    vec3 ro = vec3(0.0, 1.0, -3.0), rd = normalize(vec3(0.0, -0.2, 1.0));\n"
                                            "    float t = 0.0, h = 0.0;\n"
                                            "    vec3 at = ro;\n"
                                            "    for (int i = 0; i < 200; i++) {\n"
                                            "        if (h < at.y) {\n"
                                            "            t += 0.05;\n"
                                            "            at = ro + rd * t;\n"
                                            "            h = height(at.xz);\n"
                                            "        }\n"
                                            "    }\n"
                                            "    c = vec4(t);\n"
                                            "}\n";
    std::ofstream(folder / "density.glsl") << "float density(vec3 p) { return max(0.0, 0.5 - length(p)); }\n"
                                              "void mainImage(out vec4 c, in vec2 f) {\n"
                                              "    vec3 ro = vec3(0.0, 0.0, -3.0), rd = vec3(0.0, 0.0, 1.0);\n"
                                              "    float sum = 0.0;\n"
                                              "    for (float t = 0.0; t < 6.0; t += 0.05) {\n"
                                              "        vec3 p = ro + rd * t;\n"
                                              "        sum += density(p) * 0.05;\n"
                                              "        if (sum > 0.95) break;\n"
                                              "    }\n"
                                              "    c = vec4(sum);\n"
                                              "}\n";
    // Golfed: the height written inline in the loop's test, both sides of the point; a fixed-step
    // loop whose only test is an escape (a value of the point against a constant) is none.
    std::ofstream(folder / "golfed.glsl") << "void mainImage(out vec4 f, in vec2 w) {\n"
                                             "    vec3 d = vec3(w / iResolution.xy - .5, 1), o = vec3(0, 1, 0), p;\n"
                                             "    float i = 0.;\n"
                                             "    for (; i < 9. && sin(p.x) * .3 < p.y; i += .01) p = o + d * i;\n"
                                             "    f = vec4(i / 9.);\n"
                                             "}\n";
    std::ofstream(folder / "escape.glsl") << "void mainImage(out vec4 c, in vec2 f) {\n"
                                             "    vec3 ro = vec3(0.0, 0.0, -3.0), rd = vec3(0.0, 0.0, 1.0);\n"
                                             "    float glow = 0.0;\n"
                                             "    for (float t = 0.0; t < 8.0; t += 0.05) {\n"
                                             "        vec3 p = ro + rd * t;\n"
                                             "        if (length(p) > 4.0) break;\n"
                                             "        glow += 0.01 / (0.01 + dot(p, p));\n"
                                             "    }\n"
                                             "    c = vec4(glow);\n"
                                             "}\n";
    EXPECT_NEAR(valueAt(folder / "golfed.glsl", {0.5f, 0.2f, 0.0f}), 0.2f - 0.3f * std::sin(0.5f), 1e-5f);
    EXPECT_FALSE(prepare(folder / "escape.glsl").ok()) << "an escape test is no level";
    EXPECT_NEAR(valueAt(folder / "going.glsl", {0.4f, 0.2f, 0.0f}), 0.2f - (0.3f * std::sin(0.8f) - 0.1f), 1e-5f);
    const shaders::PreparedSdf going = prepare(folder / "going.glsl");
    EXPECT_NE(going.entryReason.find("stops where h < at.y: the field is at.y - h"), std::string::npos) << going.entryReason;
    EXPECT_FALSE(prepare(folder / "density.glsl").ok()) << "a density added up is no level";
    fs::remove_all(folder);
}

namespace {
class UserNames : public sdfwb::testing::GlTest {};
} // namespace

// Issue 14, point 1: the user's names are the user's. common_names.glsl defines the names public
// SDF code uses most, macros included; every tracer variant and every sampler composes with it,
// compiles, links and runs.
TEST_F(UserNames, EveryVariantAndSamplerCompilesAndRunsWithCommonNames) {
    const fs::path file = kFolder / "common_names.glsl";
    shaders::PreparedSdf sdf = prepare(file);
    ASSERT_TRUE(sdf.ok()) << firstError(sdf);
    // The file defines at least 60 distinct names, at least 15 of them as macros.
    {
        std::ifstream in(file);
        std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
        const std::string stripped = shaders::stripComments(text);
        static const std::regex declaration(
            R"((?:^|[;{}\n])\s*(?:const\s+|uniform\s+)?(?:float|int|bool|vec[234]|mat[234]|struct|void|[A-Z]\w*)\s+([A-Za-z_]\w*)\s*[=;(\[{])");
        std::set<std::string> names;
        for (auto it = std::sregex_iterator(stripped.begin(), stripped.end(), declaration); it != std::sregex_iterator(); ++it)
            names.insert((*it)[1].str());
        const auto macros = shaders::definedMacros(stripped);
        names.insert(macros.begin(), macros.end());
        EXPECT_GE(names.size(), 60u);
        EXPECT_GE(macros.size(), 15u);
        for (const char* common : {"map", "calcNormal", "hash", "smin", "sdBox", "PI", "EPS", "MAX_STEPS", "rot"})
            EXPECT_TRUE(names.count(common)) << common;
    }
    values::Camera camera;
    camera.position = {1.5f, 1.2f, 2.5f};
    int programs = 0;
    for (shaders::ShadingMode mode : {shaders::ShadingMode::Normals, shaders::ShadingMode::Gooch, shaders::ShadingMode::Matcap,
                                      shaders::ShadingMode::Curvature, shaders::ShadingMode::Steps})
        for (int ao = 0; ao < 2; ++ao)
            for (int plane = 0; plane < 4; ++plane) // off, on, clipping, clipping + Lipschitz overlay
                for (int relax = 0; relax < 2; ++relax)
                    for (int stats = 0; stats < 2; ++stats) {
                        if (stats && mode != shaders::ShadingMode::Normals) continue;
                        renderer::SdfRenderer sdfRenderer;
                        values::ShadingSettings shading;
                        shading.mode = mode;
                        shading.ambientOcclusion = ao;
                        shading.statsOutput = stats;
                        values::TraceSettings trace;
                        trace.overRelaxation = relax ? 1.5f : 1.0f;
                        values::CuttingPlane cut;
                        cut.enabled = plane > 0;
                        cut.clipSurface = plane > 1;
                        cut.lipschitzOverlay = plane > 2;
                        ASSERT_FALSE(shaders::hasErrors(sdfRenderer.setShading(shading)));
                        ASSERT_FALSE(shaders::hasErrors(sdfRenderer.setTrace(trace)));
                        ASSERT_FALSE(shaders::hasErrors(sdfRenderer.setPlane(cut)));
                        auto diagnostics = sdfRenderer.setSdf(sdf);
                        ASSERT_FALSE(shaders::hasErrors(diagnostics))
                            << shadingModeName(mode) << " ao " << ao << " plane " << plane << " relax " << relax << ": "
                            << (diagnostics.empty() ? "" : shaders::formatDiagnostic(diagnostics.front()));
                        ASSERT_TRUE(sdfRenderer.hasProgram());
                        renderer::OffscreenRenderer offscreen;
                        renderer::Image image = offscreen.render(sdfRenderer, 32, 24, camera, 0.25f);
                        sdfRenderer.releaseGl();
                        ASSERT_EQ(image.width, 32);
                        // Runs: some pixel differs from the background (the shape or the plane shows).
                        const std::uint8_t* corner = image.pixel(0, 0);
                        bool varied = false;
                        for (int y = 0; y < image.height && !varied; ++y)
                            for (int x = 0; x < image.width && !varied; ++x)
                                varied = !std::equal(corner, corner + 3, image.pixel(x, y));
                        EXPECT_TRUE(varied) << shadingModeName(mode) << " ao " << ao << " plane " << plane;
                        ++programs;
                    }
    // Every built-in sampler and analysis piece.
    std::vector<shaders::ShaderPiece> pieces;
    for (const char* pattern : {"grid", "image", "jitter", "rand", "surface", "near", "metropolis", "metropolis_curvature"}) {
        auto piece = sampling::findSampler(pattern, {});
        ASSERT_TRUE(piece.hasValue()) << pattern;
        pieces.push_back(*piece);
    }
    for (const char* analysis : {"analysis/noise_lines.glsl", "analysis/plane_grid.glsl"})
        pieces.push_back(*shaders::builtinPiece(analysis));
    for (const auto& piece : pieces) {
        renderer::SampleCompute compute;
        auto diagnostics = compute.build(sdf, piece);
        ASSERT_FALSE(shaders::hasErrors(diagnostics)) << piece.name << ": " << shaders::formatDiagnostic(diagnostics.front());
        sampling::SamplingJob job;
        job.count = 256;
        job.parameters[0] = 1e-3f;
        job.parameters[3] = 2.0f;
        job.parameters[4] = 1.0f;
        job.parameters[9] = 1.0f;
        std::vector<float> positions(3 * job.count), distances(job.count), gradients(3 * job.count);
        auto report = sampling::sampleInto(compute, job, positions.data(), distances.data(), gradients.data(), {});
        compute.releaseGl();
        ASSERT_TRUE(report.hasValue()) << piece.name;
        EXPECT_LT(report->badRows, job.count / 4) << piece.name;
        ++programs;
    }
    EXPECT_EQ(programs, 5 * 2 * 4 * 2 + 2 * 4 * 2 + 10);
}

// Issue 14, point 3: `pi` used only deep inside a helper of an included file brings the prelude in;
// g3d_uniformRandom is a real, bound, deterministic noise texture.
TEST_F(UserNames, CompatDialectIsDetectedByUseAndTheNoiseTextureIsReal) {
    const fs::path folder = fs::temp_directory_path() / ("sdfwb-compat-" + std::to_string(::getpid()));
    fs::create_directories(folder);
    std::ofstream(folder / "helpers.glsl")
        << "#ifndef HELPERS_GLSL\n#define HELPERS_GLSL\nfloat wave(float x) {\n    float k = 2.0;\n"
           "    return sin(k * pi * x);\n}\n#endif\n";
    std::ofstream(folder / "shape.glsl")
        << "#include \"helpers.glsl\"\nfloat sdf(vec3 p) { return length(p) - 0.5 + 0.01 * wave(p.x); }\n";
    auto sdf = prepare(folder / "shape.glsl");
    ASSERT_TRUE(sdf.ok()) << firstError(sdf);
    EXPECT_EQ(sdf.compat.symbols, std::vector<std::string>{"pi"});
    renderer::SampleCompute compute;
    ASSERT_FALSE(shaders::hasErrors(compute.build(sdf, *sampling::findSampler("rand", {}))));
    compute.releaseGl();

    // f is the noise texture's red channel at texel (i, j) for p = ((i + 0.5) / 256, (j + 0.5) / 256, 0).
    std::ofstream(folder / "noise.glsl") << "float sdf(vec3 p) { return texture(g3d_uniformRandom, p.xy).r; }\n";
    auto noisy = prepare(folder / "noise.glsl");
    ASSERT_TRUE(noisy.ok()) << firstError(noisy);
    const int n = renderer::kNoiseTextureSize;
    std::vector<float> points;
    for (int j = 0; j < 8; ++j)
        for (int i = 0; i < n; ++i)
            points.insert(points.end(), {(float(i) + 0.5f) / float(n), (float(j) + 0.5f) / float(n), 0.0f});
    auto run = [&] {
        renderer::SampleCompute compute;
        EXPECT_FALSE(shaders::hasErrors(compute.build(noisy, *shaders::builtinPiece("analysis/points.glsl"))));
        sampling::SamplingJob job;
        job.count = points.size() / 3;
        job.inputPoints = points.data();
        std::vector<float> positions(3 * job.count), distances(job.count), gradients(3 * job.count);
        EXPECT_TRUE(sampling::sampleInto(compute, job, positions.data(), distances.data(), gradients.data(), {}).hasValue());
        compute.releaseGl();
        return distances;
    };
    const std::vector<float> first = run(), second = run();
    EXPECT_EQ(first, second) << "the same texture on every run";
    const std::vector<std::uint8_t> texels = renderer::noiseTexels();
    int matching = 0;
    double mean = 0.0;
    for (std::size_t k = 0; k < first.size(); ++k) {
        matching += std::abs(first[k] - float(texels[4 * k]) / 255.0f) < 1.0f / 512.0f;
        mean += first[k];
    }
    EXPECT_EQ(matching, int(first.size())) << "the bound texture is noiseTexels(), not the matcap or nothing";
    EXPECT_NEAR(mean / double(first.size()), 0.5, 0.05) << "uniform values in [0, 1]";
    fs::remove_all(folder);
}

namespace {

// The camera a whole shader's mainImage uses at iTime = 0 and iMouse = 0 (its `// picture:` line):
// IQ's setCamera(ro, ta, 0) with rays normalize(vec3(p, focal)), p.y from -1 to 1 over the frame.
struct PictureCamera {
    glm::vec3 eye{0.0f}, target{0.0f};
    float focal = 0.0f;
};

std::optional<PictureCamera> readPictureCamera(const fs::path& file) {
    std::ifstream in(file);
    std::stringstream text;
    text << in.rdbuf();
    static const std::regex line(
        R"(// picture: eye=([-0-9.]+),([-0-9.]+),([-0-9.]+) target=([-0-9.]+),([-0-9.]+),([-0-9.]+) focal=([0-9.]+))");
    std::smatch m;
    const std::string content = text.str();
    if (!std::regex_search(content, m, line)) return std::nullopt;
    PictureCamera camera;
    camera.eye = {std::stof(m[1].str()), std::stof(m[2].str()), std::stof(m[3].str())};
    camera.target = {std::stof(m[4].str()), std::stof(m[5].str()), std::stof(m[6].str())};
    camera.focal = std::stof(m[7].str());
    return camera;
}

std::vector<std::string> pictureFiles() {
    std::vector<std::string> names;
    for (const std::string& name : corpusFiles())
        if (readPictureCamera(kFolder / name)) names.push_back(name);
    return names;
}

class ShadertoyPictureOf : public sdfwb::testing::GlTest, public ::testing::WithParamInterface<std::string> {};

} // namespace

// A field whose parameters after the point mainImage computes (issue 47): the wrapper runs
// mainImage's code before the march at the sampler's time. 62's ball is centred at
// (0.6, 0.1 + 0.15 sin(1.7 t), 0) with radius 0.2, so its centre at t = 1 reads -0.2 at t = 1 and
// 0.15 sin(1.7) - 0.2 at t = 0; 61's tilt is 0 with iMouse at rest, so its ball's centre reads -0.15.
// A field the march writes inline (issue 47): the loop's body run once at the point. 63's ball
// (centre (0, 0.1, 0), radius 0.45) reads -0.45 at its centre; 65's rounded box, in a helper's
// loop that returns from inside, -0.45 at the origin; 66's torus, stepped in the loop's header,
// -0.22 on its core circle; 64's golfed fractal is placed by its camera's statements (`p.z -= 3.`
// then a turn), which are skipped: at the origin it reads the folds' value there, not 3 units off.
class InlineFields : public sdfwb::testing::GlTest {};

TEST_F(InlineFields, TheLoopBodyRunOnceIsTheField) {
    EXPECT_NEAR(valueAt("63_st_inline_sphere_on_floor.glsl", {0.0f, 0.1f, 0.0f}), -0.45f, 1e-5f);
    EXPECT_NEAR(valueAt("63_st_inline_sphere_on_floor.glsl", {0.0f, 2.0f, 0.0f}), 1.45f, 1e-5f);
    EXPECT_NEAR(valueAt("65_st_inline_trace_function.glsl", {0.0f, 0.0f, 0.0f}), -0.45f, 1e-5f);
    EXPECT_NEAR(valueAt("66_st_inline_step_in_header.glsl", {0.6f, 0.0f, 0.0f}), -0.22f, 1e-5f);
    EXPECT_NEAR(valueAt("66_st_inline_step_in_header.glsl", {0.0f, 0.0f, 0.0f}), 0.38f, 1e-5f);
    // 64 near the origin: three folds p = |p| 2 - (.8, .7, .8), then (|p| - .6) / 2^3.
    const glm::vec3 at(0.05f, -0.1f, 0.2f);
    glm::vec3 folded = at;
    for (int j = 0; j < 3; ++j) folded = glm::abs(folded) * 2.0f - glm::vec3(0.8f, 0.7f, 0.8f);
    EXPECT_NEAR(valueAt("64_st_golfed_glow_ifs.glsl", at), (glm::length(folded) - 0.6f) / 8.0f, 1e-5f);

    // Loops that march the point itself: 67 (`p += rd * d`, d computed before the step: a capsule
    // on y = 0.2 and a ball squashed in y) and 68 (`p = c += e * d`, e computed after it: tori of
    // radii 0.5 and 0.12 repeated every 0.6 in y, cut at |y| = 0.9).
    EXPECT_NEAR(valueAt("67_st_point_march_capsules.glsl", {0.0f, -0.3f, 0.0f}), 0.7f * (0.3f / 0.7f - 0.5f), 1e-5f);
    EXPECT_NEAR(valueAt("67_st_point_march_capsules.glsl", {0.6f, 0.2f, 0.0f}), -0.15f, 1e-5f);
    EXPECT_NEAR(valueAt("68_st_golfed_point_copy.glsl", {0.5f, 0.6f, 0.0f}), -0.12f, 1e-5f);
    EXPECT_NEAR(valueAt("68_st_golfed_point_copy.glsl", {0.5f, 1.2f, 0.0f}), 0.3f, 1e-5f);

    // 69 steps by the comma operator (`d = min(...), t += d;`): a rounded box and a ball. 70 marches
    // backwards (`z -= d`, d positive inside): the field is -d. 71's march sits in two
    // anti-aliasing loops, entered at their first pass: a capped cylinder on a torus.
    EXPECT_NEAR(valueAt("69_st_comma_step_glow.glsl", {0.55f, 0.0f, 0.0f}), -0.25f, 1e-5f);
    EXPECT_NEAR(valueAt("69_st_comma_step_glow.glsl", {0.0f, 0.0f, 0.0f}), -0.30f, 1e-5f);
    EXPECT_NEAR(valueAt("70_st_inside_positive_march.glsl", {0.0f, 0.25f, 0.0f}), -0.35f, 1e-5f);
    EXPECT_NEAR(valueAt("70_st_inside_positive_march.glsl", {0.0f, 2.0f, 0.0f}), 1.4f, 1e-5f);
    EXPECT_NEAR(valueAt("71_st_antialiased_inline_march.glsl", {0.0f, 0.1f, 0.0f}), -0.2f, 1e-5f);
    EXPECT_NEAR(valueAt("71_st_antialiased_inline_march.glsl", {0.45f, -0.25f, 0.0f}), -0.1f, 1e-5f);
    // 73's march is written in a macro used twice (view and shadow): the view's is the field, the
    // union of four balls on the x axis and the floor y = -1.
    EXPECT_NEAR(valueAt("73_st_golfed_macro_march.glsl", {-0.5f, 0.0f, 0.0f}), -0.4f, 1e-5f);
    EXPECT_NEAR(valueAt("73_st_golfed_macro_march.glsl", {0.0f, 2.0f, 0.0f}), std::sqrt(4.25f) - 0.4f, 1e-5f);
    EXPECT_NEAR(valueAt("73_st_golfed_macro_march.glsl", {3.0f, -0.5f, 0.0f}), 0.5f, 1e-5f);
    // 74's distance comes from a loop nested in the march: a smooth minimum of the floor and balls.
    auto blobs = [](glm::vec3 p) {
        float s = p.y + 1.5f;
        for (int j = 0; j < 3; ++j) {
            const float b = glm::length(p - glm::vec3(float(j) * 0.8f - 0.8f, 0.0f, 0.0f)) - 0.35f;
            const float h = glm::clamp(0.5f + 0.5f * (b - s) / 0.25f, 0.0f, 1.0f);
            s = glm::mix(b, s, h) - 0.25f * h * (1.0f - h);
        }
        return s;
    };
    for (const glm::vec3 p : {glm::vec3(-0.8f, 0.0f, 0.0f), glm::vec3(0.0f, 1.5f, 0.0f), glm::vec3(0.4f, -0.9f, 0.3f)})
        EXPECT_NEAR(valueAt("74_st_golfed_blob_cube.glsl", p), blobs(p), 1e-5f);
    EXPECT_NEAR(valueAt("74_st_golfed_blob_cube.glsl", {-0.8f, 0.0f, 0.0f}), -0.35f, 1e-5f);
    const shaders::PreparedSdf backwards = prepare(kFolder / "70_st_inside_positive_march.glsl");
    EXPECT_NE(backwards.entryReason.find("the step z -= d)"), std::string::npos) << backwards.entryReason;

    // A loop whose step is taken only on a condition is not a field run once: the file does not
    // open, and the error says why.
    const fs::path folder = fs::temp_directory_path() / ("sdfwb-foreign-inline-" + std::to_string(::getpid()));
    fs::create_directories(folder);
    std::ofstream(folder / "conditional.glsl") << "void mainImage(out vec4 c, in vec2 f) {\n"
                                                  "    float t = 0.0;\n"
                                                  "    for (int i = 0; i < 64; i++) {\n"
                                                  "        vec3 p = vec3(0.0, 0.0, -3.0) + vec3(0.0, 0.0, 1.0) * t;\n"
                                                  "        float d = length(p) - 1.0;\n"
                                                  "        if (d > 0.001) t += d;\n"
                                                  "    }\n"
                                                  "    c = vec4(t);\n"
                                                  "}\n";
    // The point marched in the for header, the body a single statement without braces.
    std::ofstream(folder / "header.glsl")
        << "void mainImage(out vec4 c, in vec2 f) {\n"
           "    vec3 p = vec3(0.0, 0.0, -3.0), rd = vec3(0.0, 0.0, 1.0);\n"
           "    float d = 1.0;\n"
           "    for (int i = 0; i < 64; i++, p += rd * d) d = length(p - vec3(0.2, 0.0, 0.0)) - 0.5;\n"
           "    c = vec4(d);\n"
           "}\n";
    EXPECT_NEAR(valueAt(folder / "header.glsl", {0.2f, 0.0f, 0.0f}), -0.5f, 1e-5f);
    // Golfed vec4 points, whose xyz is the point: the whole march in the for header, after the
    // step (`z += d, p = vec4(...), p.z -= 3., d = ...`), and in the body.
    std::ofstream(folder / "vec4header.glsl")
        << "void mainImage(out vec4 O, vec2 C) {\n"
           "    float i, d, z;\n"
           "    vec4 o, p;\n"
           "    for (vec2 r = iResolution.xy; ++i < 60.; z += d, p = vec4(normalize(vec3(C - .5 * r, r.y)) * z, .5),\n"
           "         p.z -= 3., d = length(p.xyz - vec3(.2, 0, 0)) - p.w)\n"
           "        o += 1. / max(d, 1e-3);\n"
           "    O = tanh(o / 1e3);\n"
           "}\n";
    std::ofstream(folder / "vec4body.glsl") << "void mainImage(out vec4 O, vec2 C) {\n"
                                               "    vec3 ro = vec3(0, 0, -3), rd = vec3(0, 0, 1);\n"
                                               "    float t = 0., d;\n"
                                               "    for (int i = 0; i < 60; i++) {\n"
                                               "        vec4 q = vec4(ro + rd * t, .3);\n"
                                               "        d = length(q.xyz) - q.w;\n"
                                               "        t += d;\n"
                                               "    }\n"
                                               "    O = vec4(t);\n"
                                               "}\n";
    EXPECT_NEAR(valueAt(folder / "vec4header.glsl", {0.2f, 0.0f, 0.0f}), -0.5f, 1e-5f);
    EXPECT_NEAR(valueAt(folder / "vec4header.glsl", {0.2f, 1.0f, 0.0f}), 0.5f, 1e-5f);
    EXPECT_NEAR(valueAt(folder / "vec4body.glsl", {0.0f, 0.0f, 0.0f}), -0.3f, 1e-5f);
    EXPECT_NEAR(valueAt(folder / "vec4body.glsl", {0.0f, 0.0f, 1.0f}), 0.7f, 1e-5f);
    shaders::PreparedSdf conditional = prepare(folder / "conditional.glsl");
    EXPECT_FALSE(conditional.ok());
    EXPECT_NE(firstError(conditional).find("writes its field inline, but the statement that advances 't'"), std::string::npos)
        << firstError(conditional);
    fs::remove_all(folder);
}

// Shadertoy's cube maps (issue 47): a channel read with a direction is declared samplerCube, the
// others stay sampler2D, and the author's picture reads a real cube texture (the noise texels on
// each face: an unbound or wrongly bound cube map reads black).
class CubeChannels : public sdfwb::testing::GlTest {};

TEST_F(CubeChannels, AreDeclaredByUseAndBoundAsCubeMaps) {
    EXPECT_EQ(prepare(kFolder / "72_st_cubemap_reflection.glsl").compat.cubeChannels, std::vector<std::string>{"iChannel0"});
    EXPECT_EQ(prepare(kFolder / "74_st_golfed_blob_cube.glsl").compat.cubeChannels, std::vector<std::string>{"iChannel0"});
    EXPECT_TRUE(prepare(kFolder / "35_st_channel_bumps.glsl").compat.cubeChannels.empty());
    EXPECT_TRUE(prepare(kFolder / "59_st_blurry_reflection_bias.glsl").compat.cubeChannels.empty());

    shaders::PreparedSdf sdf = prepare(kFolder / "72_st_cubemap_reflection.glsl");
    ASSERT_TRUE(sdf.ok()) << firstError(sdf);
    renderer::ShadertoyPicture picture;
    auto diagnostics = picture.setSdf(sdf);
    ASSERT_FALSE(shaders::hasErrors(diagnostics)) << shaders::formatDiagnostic(diagnostics.front());
    renderer::OffscreenRenderer offscreen;
    const int width = 96, height = 54;
    const renderer::Image image = offscreen.renderPicture(picture, width, height, renderer::ShadertoyInputs{});
    picture.releaseGl();
    // The corner (sky: the cube map's texels, gamma 0.4545) is noise of mean ~0.5^0.4545 = 0.73;
    // neighbouring pixels differ.
    double sum = 0.0, steps = 0.0;
    int pixels = 0;
    for (int y = 0; y < 12; ++y)
        for (int x = 0; x + 1 < 24; ++x, ++pixels)
            for (int c = 0; c < 3; ++c) {
                sum += image.pixel(x, y)[c] / 255.0;
                steps += std::abs(int(image.pixel(x + 1, y)[c]) - int(image.pixel(x, y)[c])) / 255.0;
            }
    EXPECT_GT(sum / (3.0 * pixels), 0.5) << "the sky reads the cube map";
    EXPECT_GT(steps / (3.0 * pixels), 0.02) << "the cube map holds the noise texels";
}

TEST(ForeignCorpus, HasWholeShadertoyShaders) {
    int whole = 0, versioned = 0, channels = 0;
    for (const std::string& name : corpusFiles()) {
        std::ifstream in(kFolder / name);
        std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
        whole += std::regex_search(text, std::regex(R"(void\s+mainImage\s*\()"));
        versioned += text.find("#version 300 es") != std::string::npos;
        channels += text.find("iChannel0") != std::string::npos;
    }
    EXPECT_GE(whole, 10) << "whole Shadertoy shaders (with mainImage)";
    EXPECT_GE(versioned, 1);
    EXPECT_GE(channels, 1);
    EXPECT_GE(pictureFiles().size(), 2u) << "files whose Shadertoy picture is compared with sdfwb's frame";
}

// Issue 32, point 3: the author's own picture (mainImage at iTime 0) and sdfwb's tracer from the
// same camera show the same silhouette. The author's silhouette is every pixel that differs from
// the background by more than 0.1 in a channel; the background, a sky that changes slowly across
// the frame, is interpolated from the frame's four corners. sdfwb's is its tracer's hits.
TEST_P(ShadertoyPictureOf, SilhouetteMatchesSdfwbsTracer) {
    const fs::path file = kFolder / GetParam();
    const PictureCamera view = *readPictureCamera(file);
    shaders::PreparedSdf sdf = prepare(file);
    ASSERT_TRUE(sdf.ok()) << firstError(sdf);
    ASSERT_TRUE(sdf.shadertoyMainImage);
    const int width = 384, height = 216; // the tracer's hit tolerance widens edges by under a pixel

    renderer::ShadertoyPicture picture;
    auto diagnostics = picture.setSdf(sdf);
    ASSERT_FALSE(shaders::hasErrors(diagnostics)) << shaders::formatDiagnostic(diagnostics.front());
    renderer::OffscreenRenderer offscreen;
    const renderer::Image author = offscreen.renderPicture(picture, width, height, renderer::ShadertoyInputs{});
    picture.releaseGl();

    // sdfwb's hits at a hit tolerance of `epsilonScale` pixel footprints.
    auto hitsAt = [&](float epsilonScale) {
        renderer::SdfRenderer sdfRenderer;
        values::ShadingSettings shading;
        shading.statsOutput = true;
        EXPECT_FALSE(shaders::hasErrors(sdfRenderer.setShading(shading)));
        values::TraceSettings trace;
        trace.epsilonScale = epsilonScale;
        EXPECT_FALSE(shaders::hasErrors(sdfRenderer.setTrace(trace)));
        EXPECT_FALSE(shaders::hasErrors(sdfRenderer.setSdf(sdf)));
        values::Camera camera;
        camera.position = view.eye;
        camera.target = view.target;
        camera.fovYDegrees = float(2.0 * std::atan(1.0 / double(view.focal)) * 180.0 / M_PI);
        const auto stats = offscreen.renderStats(sdfRenderer, width, height, camera, 0.0f);
        sdfRenderer.releaseGl();
        return stats;
    };
    // The authors' casters stop at |d| < 1e-4 t (a hundredth of a pixel here); sdfwb's shipped hit
    // tolerance, half a pixel's footprint, widens a silhouette by up to half a pixel, which on thin
    // columns alone costs 5 % of the IoU. Compared at a like tolerance (the geometry: IoU >= 0.95)
    // and at the shipped one (what a user sees: IoU >= 0.90).
    const auto like = hitsAt(0.05f);
    const auto shipped = hitsAt(values::TraceSettings{}.epsilonScale);

    auto corner = [&](int x, int y, int c) { return float(author.pixel(x, y)[c]); };
    std::size_t authors = 0;
    std::size_t both[2] = {0, 0}, either[2] = {0, 0}, ours[2] = {0, 0};
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            const float u = float(x) / float(width - 1), v = float(y) / float(height - 1);
            float difference = 0.0f;
            for (int c = 0; c < 3; ++c) {
                const float top = corner(0, 0, c) * (1.0f - u) + corner(width - 1, 0, c) * u;
                const float bottom = corner(0, height - 1, c) * (1.0f - u) + corner(width - 1, height - 1, c) * u;
                const float background = top * (1.0f - v) + bottom * v;
                difference = std::max(difference, std::abs(float(author.pixel(x, y)[c]) - background) / 255.0f);
            }
            const bool a = difference > 0.1f;
            authors += a;
            const std::size_t at = std::size_t(y) * std::size_t(width) + std::size_t(x);
            for (int k = 0; k < 2; ++k) {
                const bool b = (k == 0 ? like : shipped)[at].hit();
                ours[k] += b;
                both[k] += a && b;
                either[k] += a || b;
            }
        }
    const double pixels = double(width) * double(height);
    EXPECT_GT(double(authors), 0.02 * pixels) << "the author's picture shows the shape";
    EXPECT_LT(double(authors), 0.8 * pixels) << "the author's picture has a background";
    double iou[2];
    for (int k = 0; k < 2; ++k) iou[k] = either[k] == 0 ? 0.0 : double(both[k]) / double(either[k]);
    EXPECT_GE(iou[0], 0.95) << GetParam() << " at a like tolerance: author's silhouette " << authors << " px, sdfwb's " << ours[0]
                            << " px, both " << both[0];
    EXPECT_GE(iou[1], 0.90) << GetParam() << " at the shipped tolerance: author's silhouette " << authors << " px, sdfwb's "
                            << ours[1] << " px, both " << both[1];
    std::cout << GetParam() << ": silhouette IoU " << iou[0] << " at a like tolerance, " << iou[1]
              << " at the shipped one (author " << authors << " px, sdfwb " << ours[0] << " / " << ours[1] << " px)\n";
}

INSTANTIATE_TEST_SUITE_P(Corpus, ShadertoyPictureOf, ::testing::ValuesIn(pictureFiles()), fileTestName);
