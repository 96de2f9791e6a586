// Headless rendering through EGL (llvmpipe without a GPU): silhouettes against closed forms,
// box clipping, last-good fallback, driver diagnostics, and the CLI writing a real PNG.

#include <dataset/Catalogue.h>
#include <renderer/HeadlessContext.h>
#include <renderer/ImageIO.h>
#include <renderer/OffscreenRenderer.h>
#include <renderer/SdfRenderer.h>
#include <shaders/SdfSource.h>

#include "GlTestContext.h"

#include <epoxy/gl.h>

#include <unistd.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <vector>

using namespace sdfwb;
namespace fs = std::filesystem;

namespace {

class RendererTest : public sdfwb::testing::GlTest {
protected:
    static shaders::PreparedSdf prepare(const std::string& text, const std::string& name = "<test>") {
        return shaders::prepareSdf(text, name, {}, shaders::IncludeOptions{});
    }

    // Pixels that differ from the background colour.
    static long foreground(const renderer::Image& image, const glm::vec3& background) {
        long count = 0;
        const int r = int(std::lround(background.r * 255)), g = int(std::lround(background.g * 255)),
                  b = int(std::lround(background.b * 255));
        for (int y = 0; y < image.height; ++y)
            for (int x = 0; x < image.width; ++x) {
                const std::uint8_t* p = image.pixel(x, y);
                if (std::abs(p[0] - r) > 2 || std::abs(p[1] - g) > 2 || std::abs(p[2] - b) > 2) ++count;
            }
        return count;
    }
};

} // namespace

TEST_F(RendererTest, ContextIsGl43CoreWithCompute) {
    const renderer::GlInfo& info = context().info();
    EXPECT_GE(info.major * 10 + info.minor, 43) << info.version;
    EXPECT_TRUE(info.coreProfile);
    EXPECT_TRUE(info.computeShaders);
    EXPECT_FALSE(info.renderer.empty());
}

TEST_F(RendererTest, SphereSilhouetteMatchesTheAnalyticProjection) {
    const float radius = 0.6f, distance = 3.0f, fov = 40.0f;
    const int size = 512;
    renderer::SdfRenderer sdfRenderer;
    auto diagnostics = sdfRenderer.setSdf(prepare("float sdf(vec3 p) { return length(p) - 0.6; }\n"));
    ASSERT_TRUE(diagnostics.empty()) << shaders::formatDiagnostic(diagnostics[0]);
    values::Camera camera;
    camera.position = {0.0f, 0.0f, distance};
    camera.fovYDegrees = fov;
    renderer::OffscreenRenderer offscreen;
    renderer::Image image = offscreen.render(sdfRenderer, size, size, camera, 0.0f);

    // A centred sphere projects to a disc of radius tan(asin(r/d)) / tan(fov/2) half-heights.
    const double pi = 3.14159265358979;
    double discRadius = std::tan(std::asin(radius / distance)) / std::tan(fov * pi / 360.0) * (size / 2.0);
    double expected = pi * discRadius * discRadius;
    long counted = foreground(image, sdfRenderer.shading().background);
    EXPECT_NEAR(double(counted) / expected, 1.0, 0.01) << "counted " << counted << " pixels, expected " << expected;
    sdfRenderer.releaseGl();
}

TEST_F(RendererTest, RaysAreClippedToTheUnitBox) {
    renderer::SdfRenderer sdfRenderer;
    // A sphere well outside [-1,1]^3: never marched, never drawn.
    ASSERT_TRUE(sdfRenderer.setSdf(prepare("float sdf(vec3 p) { return length(p - vec3(0.0, 1.6, 0.0)) - 0.3; }\n")).empty());
    values::Camera camera;
    camera.position = {0.0f, 0.0f, 4.0f};
    camera.fovYDegrees = 90.0f;
    renderer::OffscreenRenderer offscreen;
    renderer::Image image = offscreen.render(sdfRenderer, 128, 128, camera, 0.0f);
    EXPECT_EQ(foreground(image, sdfRenderer.shading().background), 0);
    sdfRenderer.releaseGl();
}

TEST_F(RendererTest, BrokenSdfKeepsTheLastGoodProgramAndMapsDriverErrors) {
    renderer::SdfRenderer sdfRenderer;
    ASSERT_TRUE(sdfRenderer.setSdf(prepare("float sdf(vec3 p) { return length(p) - 0.5; }\n")).empty());
    values::Camera camera;
    renderer::OffscreenRenderer offscreen;
    long before = foreground(offscreen.render(sdfRenderer, 160, 90, camera, 0.0f), sdfRenderer.shading().background);
    ASSERT_GT(before, 500);

    // glslang is bypassed here: the driver's own log must still land on the user's line.
    auto diagnostics =
        sdfRenderer.setSdf(prepare("float sdf(vec3 p) {\n    return length(p) - missingRadius;\n}\n", "broken.glsl"));
    ASSERT_FALSE(diagnostics.empty());
    EXPECT_EQ(diagnostics[0].file, "broken.glsl");
    EXPECT_EQ(diagnostics[0].line, 2);
    EXPECT_TRUE(sdfRenderer.hasProgram());
    long after = foreground(offscreen.render(sdfRenderer, 160, 90, camera, 0.0f), sdfRenderer.shading().background);
    EXPECT_EQ(before, after);
    sdfRenderer.releaseGl();
}

// A pasted file with a NUL byte in a comment: the driver compiles the code after it (Mesa's
// preprocessor ends the text at a NUL, so the composed text holds a space there).
TEST_F(RendererTest, ANulByteInACommentRenders) {
    renderer::SdfRenderer sdfRenderer;
    const std::string text("// pasted \0 junk\nfloat sdf(vec3 p) { return length(p) - 0.5; }\n", 63);
    auto diagnostics = sdfRenderer.setSdf(prepare(text, "nul.glsl"));
    ASSERT_TRUE(diagnostics.empty()) << shaders::formatDiagnostic(diagnostics[0]);
    renderer::OffscreenRenderer offscreen;
    EXPECT_GT(foreground(offscreen.render(sdfRenderer, 160, 90, values::Camera{}, 0.0f), sdfRenderer.shading().background), 500);
    sdfRenderer.releaseGl();
}

TEST_F(RendererTest, EveryDatasetShapeRenders) {
    dataset::Catalogue catalogue = dataset::Catalogue::scan(fs::path(SDFWB_SOURCE_DIR) / "dataset");
    ASSERT_FALSE(catalogue.entries().empty());
    shaders::IncludeOptions options;
    options.libraryRoots = {fs::path(SDFWB_SOURCE_DIR) / "shaders" / "lib", fs::path(SDFWB_SOURCE_DIR) / "dataset"};
    renderer::OffscreenRenderer offscreen;
    for (const dataset::Entry& entry : catalogue.entries()) {
        renderer::SdfRenderer sdfRenderer;
        auto diagnostics = sdfRenderer.setSdf(shaders::prepareSdfFile(entry.path, options));
        ASSERT_FALSE(shaders::hasErrors(diagnostics)) << entry.path << ": " << shaders::formatDiagnostic(diagnostics[0]);
        renderer::Image image = offscreen.render(sdfRenderer, 160, 90, values::Camera{}, 0.0f);
        long pixels = foreground(image, sdfRenderer.shading().background);
        EXPECT_GT(pixels, 160 * 90 / 100) << entry.metadata.name << " is (nearly) invisible";
        EXPECT_LT(pixels, 160 * 90 * 9 / 10) << entry.metadata.name << " fills the frame";
        sdfRenderer.releaseGl();
    }
}

TEST_F(RendererTest, BatchRenderWritesAPngWithoutADisplay) {
    fs::path out = fs::temp_directory_path() / "sdfwb-batch-render.png";
    fs::remove(out);
    std::string command = "env -u DISPLAY -u WAYLAND_DISPLAY " + std::string(SDFWB_BINARY) +
                          " --batch render --sdf torus --output " + out.string() + " --size 640x360 --quiet";
    ASSERT_EQ(std::system(command.c_str()), 0);
    auto image = renderer::readImage(out);
    ASSERT_TRUE(image.hasValue()) << image.error().message;
    EXPECT_EQ(image->width, 640);
    EXPECT_EQ(image->height, 360);
    // The torus is drawn: it covers between a twentieth and half of the frame (a blank or a
    // filled frame fails).
    const glm::vec3 background = values::ShadingSettings{}.background;
    const long drawn = foreground(*image, background);
    EXPECT_GT(drawn, 640L * 360 / 20) << "too little of the torus";
    EXPECT_LT(drawn, 640L * 360 / 2) << "too much: not the torus";
    // --tracer compute: the compute tracer draws the same image.
    const fs::path computed = fs::temp_directory_path() / "sdfwb-batch-render-compute.png";
    fs::remove(computed);
    command = "env -u DISPLAY -u WAYLAND_DISPLAY " + std::string(SDFWB_BINARY) + " --batch render --sdf torus --output " +
              computed.string() + " --size 640x360 --tracer compute --quiet";
    ASSERT_EQ(std::system(command.c_str()), 0);
    auto other = renderer::readImage(computed);
    ASSERT_TRUE(other.hasValue()) << other.error().message;
    ASSERT_EQ(other->rgba.size(), image->rgba.size());
    long differing = 0;
    for (std::size_t i = 0; i < image->rgba.size(); ++i) differing += image->rgba[i] != other->rgba[i];
    EXPECT_LE(differing, long(image->rgba.size() / 1000));
    fs::remove(out);
    fs::remove(computed);
}

// A step factor of 1 (the default) compiles without the multiply on every step; any other value
// is one more variant, and moving between such values is a uniform (no compile): more steps at
// a smaller factor, the same shape.
TEST_F(RendererTest, StepFactorOtherThanOneIsOneVariantAndItsValueAUniform) {
    renderer::SdfRenderer sdfRenderer;
    values::ShadingSettings shading;
    shading.statsOutput = true;
    EXPECT_FALSE(shaders::hasErrors(sdfRenderer.setShading(shading)));
    ASSERT_FALSE(shaders::hasErrors(sdfRenderer.setSdf(prepare("float sdf(vec3 p) { return length(p) - 0.6; }\n"))));
    renderer::OffscreenRenderer offscreen;
    auto meanSteps = [&](long& hits) {
        double steps = 0.0;
        hits = 0;
        const auto pixels = offscreen.renderStats(sdfRenderer, 64, 48, values::Camera{}, 0.0f);
        for (const auto& pixel : pixels) {
            steps += pixel.steps;
            hits += pixel.hit();
        }
        return steps / double(pixels.size());
    };
    long hitsAtOne = 0, hitsAtHalf = 0, hitsBack = 0;
    const double atOne = meanSteps(hitsAtOne);
    EXPECT_EQ(sdfRenderer.fragmentSource().find("#define SDFWB_STEP_FACTOR"), std::string::npos);
    const std::uint64_t built = sdfRenderer.programsBuilt();
    values::TraceSettings trace;
    trace.stepFactor = 0.7f;
    EXPECT_FALSE(shaders::hasErrors(sdfRenderer.setTrace(trace)));
    EXPECT_EQ(sdfRenderer.programsBuilt(), built + 1);
    EXPECT_NE(sdfRenderer.fragmentSource().find("#define SDFWB_STEP_FACTOR"), std::string::npos);
    trace.stepFactor = 0.5f;
    EXPECT_FALSE(shaders::hasErrors(sdfRenderer.setTrace(trace)));
    EXPECT_EQ(sdfRenderer.programsBuilt(), built + 1) << "another factor is a uniform";
    const double atHalf = meanSteps(hitsAtHalf);
    EXPECT_GT(atHalf, atOne * 1.3) << "half steps take more of them";
    // The hit test compares the scaled value with the footprint: a smaller factor also counts a
    // few more grazing silhouette rays as hits, never fewer.
    EXPECT_GE(hitsAtHalf, hitsAtOne);
    EXPECT_LE(hitsAtHalf, hitsAtOne + hitsAtOne / 10);
    trace.stepFactor = 1.0f;
    EXPECT_FALSE(shaders::hasErrors(sdfRenderer.setTrace(trace)));
    EXPECT_EQ(sdfRenderer.programsBuilt(), built + 1) << "back to 1: the first program, from the cache";
    EXPECT_DOUBLE_EQ(meanSteps(hitsBack), atOne);
    sdfRenderer.releaseGl();
}

// A long SDF starts with the fused march (the quickest code generation after an edit). At rest, a
// full frame under the threshold trades it once for the separate march; the separate frame's time
// decides which stays. A slow frame, a short SDF or a new SDF behave as the renderer documents.
TEST_F(RendererTest, SettleMarchKeepsTheFasterOfTheTwoMarches) {
    unsetenv("SDFWB_FUSED_MARCH");
    const fs::path foreign = fs::path(SDFWB_SOURCE_DIR) / "tests" / "foreign";
    shaders::IncludeOptions options;
    options.libraryRoots = {fs::path(SDFWB_SOURCE_DIR) / "shaders" / "lib"};
    const shaders::PreparedSdf longSdf = shaders::prepareSdfFile(foreign / "01_iq_primitives.glsl", options);
    ASSERT_FALSE(shaders::hasErrors(longSdf.diagnostics));
    const double fast = renderer::SdfRenderer::kTrySeparateMarchBelowMilliseconds / 4;
    renderer::OffscreenRenderer offscreen;
    renderer::SdfRenderer sdfRenderer;
    values::TraceSettings trace;
    trace.cones = values::TraceSettings::Cones::Off;        // the march alone (ConePassIsKeptWhenItMakesFramesFaster)
    trace.tracer = values::TraceSettings::Tracer::Fragment; // (ComputeTracerIsTriedLastAndKeptWhenFaster)
    EXPECT_FALSE(shaders::hasErrors(sdfRenderer.setTrace(trace)));
    ASSERT_FALSE(shaders::hasErrors(sdfRenderer.setSdf(longSdf)));
    EXPECT_TRUE(sdfRenderer.fusedMarch());
    const renderer::Image fused = offscreen.render(sdfRenderer, 200, 120, values::Camera{}, 0.0f);

    // Faster separately: the separate march stays, and draws the same picture.
    EXPECT_TRUE(sdfRenderer.settleMarch(fast));
    EXPECT_FALSE(sdfRenderer.fusedMarch());
    const renderer::Image separate = offscreen.render(sdfRenderer, 200, 120, values::Camera{}, 0.0f);
    EXPECT_FALSE(sdfRenderer.settleMarch(fast * 0.9));
    EXPECT_FALSE(sdfRenderer.fusedMarch());
    EXPECT_FALSE(sdfRenderer.settleMarch(fast * 0.5)) << "the choice is made once per SDF";
    long differing = 0;
    for (std::size_t i = 0; i < fused.rgba.size(); ++i) differing += std::abs(fused.rgba[i] - separate.rgba[i]) > 2;
    EXPECT_LE(differing, long(fused.rgba.size() / 1000));

    // Other settings keep the choice (another variant of the same SDF marches separately too).
    values::ShadingSettings shading;
    shading.mode = shaders::ShadingMode::Normals;
    EXPECT_FALSE(shaders::hasErrors(sdfRenderer.setShading(shading)));
    EXPECT_FALSE(sdfRenderer.fusedMarch());

    // Slower separately: back to the fused program, from the cache (nothing compiled).
    ASSERT_FALSE(shaders::hasErrors(sdfRenderer.setSdf(longSdf)));
    EXPECT_TRUE(sdfRenderer.fusedMarch()) << "a new SDF starts fused again";
    EXPECT_TRUE(sdfRenderer.settleMarch(fast));
    EXPECT_FALSE(sdfRenderer.fusedMarch());
    const std::uint64_t built = sdfRenderer.programsBuilt();
    EXPECT_TRUE(sdfRenderer.settleMarch(fast * 1.5));
    EXPECT_TRUE(sdfRenderer.fusedMarch());
    EXPECT_EQ(sdfRenderer.programsBuilt(), built);
    EXPECT_FALSE(sdfRenderer.settleMarch(fast));

    // A slow frame (heavy SDF: the fused march's code generation pays) keeps the fused march.
    ASSERT_FALSE(shaders::hasErrors(sdfRenderer.setSdf(longSdf)));
    EXPECT_FALSE(sdfRenderer.settleMarch(renderer::SdfRenderer::kTrySeparateMarchBelowMilliseconds * 2));
    EXPECT_TRUE(sdfRenderer.fusedMarch());

    // A short SDF marches separately from the start: nothing to trade.
    ASSERT_FALSE(shaders::hasErrors(sdfRenderer.setSdf(prepare("float sdf(vec3 p) { return length(p) - 0.6; }\n"))));
    EXPECT_FALSE(sdfRenderer.fusedMarch());
    EXPECT_FALSE(sdfRenderer.settleMarch(fast));
    sdfRenderer.releaseGl();
}

// The fused march (march, thin-feature probe and normal taps in one loop around one call of the
// SDF, chosen for larger SDFs) draws what the separate functions draw: same hits, same normals,
// for users' code in several styles, plain and over-relaxed, in every shading mode with a normal.
TEST_F(RendererTest, FusedMarchDrawsWhatTheSeparateMarchDraws) {
    const fs::path foreign = fs::path(SDFWB_SOURCE_DIR) / "tests" / "foreign";
    shaders::IncludeOptions options;
    options.libraryRoots = {fs::path(SDFWB_SOURCE_DIR) / "shaders" / "lib"};
    const std::vector<shaders::PreparedSdf> sdfs = {shaders::prepareSdfFile(foreign / "01_iq_primitives.glsl", options),
                                                    shaders::prepareSdfFile(foreign / "05_hg_colonnade.glsl", options),
                                                    shaders::prepareSdfFile(foreign / "13_g3d_snake_truncated.glsl", options),
                                                    // A paper-thin shell: the thin-feature probe shrinks the normal's step.
                                                    prepare("float sdf(vec3 p) { return abs(length(p) - 0.6) - 0.0005; }\n")};
    renderer::OffscreenRenderer offscreen;
    for (const shaders::PreparedSdf& sdf : sdfs) {
        ASSERT_FALSE(shaders::hasErrors(sdf.diagnostics)) << shaders::formatDiagnostic(sdf.diagnostics[0]);
        for (float relaxation : {1.0f, 1.6f})
            for (shaders::ShadingMode mode :
                 {shaders::ShadingMode::Normals, shaders::ShadingMode::Gooch, shaders::ShadingMode::Curvature}) {
                renderer::Image images[2];
                for (int fused = 0; fused < 2; ++fused) {
                    setenv("SDFWB_FUSED_MARCH", fused ? "1" : "0", 1);
                    renderer::SdfRenderer sdfRenderer;
                    values::ShadingSettings shading;
                    shading.mode = mode;
                    EXPECT_FALSE(shaders::hasErrors(sdfRenderer.setShading(shading)));
                    values::TraceSettings trace;
                    trace.overRelaxation = relaxation;
                    EXPECT_FALSE(shaders::hasErrors(sdfRenderer.setTrace(trace)));
                    auto diagnostics = sdfRenderer.setSdf(sdf);
                    ASSERT_FALSE(shaders::hasErrors(diagnostics)) << shaders::formatDiagnostic(diagnostics[0]);
                    images[fused] = offscreen.render(sdfRenderer, 200, 120, values::Camera{}, 0.0f);
                    sdfRenderer.releaseGl();
                }
                long differing = 0;
                for (std::size_t i = 0; i < images[0].rgba.size(); ++i)
                    differing += std::abs(images[0].rgba[i] - images[1].rgba[i]) > 2;
                EXPECT_LE(differing, long(images[0].rgba.size() / 1000))
                    << sdf.source.map.fileName(0) << ", relaxation " << relaxation << ", mode " << int(mode);
                EXPECT_GT(foreground(images[1], values::ShadingSettings{}.background), 200 * 120 / 100);
            }
    }
    unsetenv("SDFWB_FUSED_MARCH");
}

// The cone pass (a ray per 4x4 tile finds where its pixels may start) changes where marches start,
// not what they find: on users' code in several styles, exact fields and bounds, plain,
// over-relaxed and with a step factor, the same pixels hit, at the same distances within the hit
// tolerance, in fewer steps. A camera inside the shape and one far away are included.
TEST_F(RendererTest, ConePassFindsTheSameHitsInFewerSteps) {
    const fs::path foreign = fs::path(SDFWB_SOURCE_DIR) / "tests" / "foreign";
    shaders::IncludeOptions options;
    options.libraryRoots = {fs::path(SDFWB_SOURCE_DIR) / "shaders" / "lib"};
    struct Case {
        shaders::PreparedSdf sdf;
        values::Camera camera;
        float relaxation = 1.0f, stepFactor = 1.0f;
        bool fewerSteps = true;
    };
    values::Camera far;
    far.position = glm::vec3(0.0f, 0.0f, 40.0f);
    far.fovYDegrees = 4.0f;
    values::Camera inside;
    inside.position = glm::vec3(0.0f, 0.0f, 0.2f);
    std::vector<Case> cases = {
        {shaders::prepareSdfFile(foreign / "01_iq_primitives.glsl", options), {}},
        {shaders::prepareSdfFile(foreign / "05_hg_colonnade.glsl", options), {}},
        {shaders::prepareSdfFile(foreign / "11_menger_iq.glsl", options), {}},
        {shaders::prepareSdfFile(foreign / "11_menger_iq.glsl", options), {}, 1.6f},
        {shaders::prepareSdfFile(foreign / "17_iq_displace.glsl", options), {}, 1.0f, 0.6f},
        {shaders::prepareSdfFile(foreign / "21_g3d_random_cells.glsl", options), {}},
        {shaders::prepareSdfFile(foreign / "23_st_metaballs_itime.glsl", options), {}},
        {prepare("float sdf(vec3 p) { return abs(length(p) - 0.6) - 0.0005; }\n"), {}}, // a paper-thin shell
        {prepare("float sdf(vec3 p) { return length(p) - 0.6; }\n"), far},
        {prepare("float sdf(vec3 p) { return length(p) - 0.6; }\n"), inside, 1.0f, 1.0f, false},
    };
    renderer::OffscreenRenderer offscreen;
    const int width = 200, height = 120;
    for (const Case& c : cases) {
        ASSERT_FALSE(shaders::hasErrors(c.sdf.diagnostics)) << shaders::formatDiagnostic(c.sdf.diagnostics[0]);
        const std::string label = c.sdf.source.map.fileName(0) + ", camera z " + std::to_string(c.camera.position.z) +
                                  ", relaxation " + std::to_string(c.relaxation) + ", step factor " +
                                  std::to_string(c.stepFactor);
        std::vector<renderer::OffscreenRenderer::PixelStats> stats[2];
        for (int cones = 0; cones < 2; ++cones) {
            renderer::SdfRenderer sdfRenderer;
            values::ShadingSettings shading;
            shading.statsOutput = true;
            EXPECT_FALSE(shaders::hasErrors(sdfRenderer.setShading(shading)));
            values::TraceSettings trace;
            trace.overRelaxation = c.relaxation;
            trace.stepFactor = c.stepFactor;
            trace.cones = cones ? values::TraceSettings::Cones::On : values::TraceSettings::Cones::Off;
            EXPECT_FALSE(shaders::hasErrors(sdfRenderer.setTrace(trace)));
            auto diagnostics = sdfRenderer.setSdf(c.sdf);
            ASSERT_FALSE(shaders::hasErrors(diagnostics)) << shaders::formatDiagnostic(diagnostics[0]);
            EXPECT_EQ(sdfRenderer.conePass(), cones == 1) << label;
            stats[cones] = offscreen.renderStats(sdfRenderer, width, height, c.camera, 0.5f);
            sdfRenderer.releaseGl();
        }
        const double pixelAngle = 2.0 * std::tan(c.camera.fovYDegrees * 3.14159265 / 360.0) / height;
        long hits = 0, changed = 0, moved = 0;
        double steps[2] = {0.0, 0.0};
        for (std::size_t i = 0; i < stats[0].size(); ++i) {
            const auto &off = stats[0][i], &on = stats[1][i];
            steps[0] += off.steps;
            steps[1] += on.steps;
            hits += off.hit();
            if (off.hit() != on.hit()) ++changed;
            // Both within the tolerance of the surface: they differ by at most a few footprints.
            if (off.hit() && on.hit() && std::abs(on.t - off.t) > 4.0 * pixelAngle * off.t) ++moved;
        }
        if (c.fewerSteps) { EXPECT_GT(hits, long(stats[0].size() / 50)) << label; }
        EXPECT_LE(changed, long(stats[0].size() / 500)) << label << ": pixels whose ray hit in one and not the other";
        EXPECT_LE(moved, hits / 200) << label << ": hits that moved by more than 4 footprints";
        if (c.fewerSteps)
            EXPECT_LT(steps[1], 0.9 * steps[0]) << label;
        else
            EXPECT_EQ(steps[1], steps[0]) << label << ": a camera inside the shape: every march starts at its own start";
    }
}

// Cones::Auto: at rest the cone pass is tried once on the march chosen so far, and kept when the
// full frame got faster; from the cache when dropped. On and Off are never traded; the step heat
// map and the march debugger never draw it (they show each pixel's own march).
TEST_F(RendererTest, ConePassIsKeptWhenItMakesFramesFaster) {
    const shaders::PreparedSdf sdf = prepare("float sdf(vec3 p) { return length(p) - 0.6; }\n");
    renderer::OffscreenRenderer offscreen;
    renderer::SdfRenderer sdfRenderer;
    values::TraceSettings fragmentOnly; // the compute tracer's trial: ComputeTracerIsTriedLastAndKeptWhenFaster
    fragmentOnly.tracer = values::TraceSettings::Tracer::Fragment;
    EXPECT_FALSE(shaders::hasErrors(sdfRenderer.setTrace(fragmentOnly)));
    ASSERT_FALSE(shaders::hasErrors(sdfRenderer.setSdf(sdf)));
    EXPECT_FALSE(sdfRenderer.conePass()) << "a new SDF starts without";
    const renderer::Image without = offscreen.render(sdfRenderer, 200, 120, values::Camera{}, 0.0f);
    EXPECT_TRUE(sdfRenderer.settleMarch(40.0));
    EXPECT_TRUE(sdfRenderer.conePass());
    const renderer::Image with = offscreen.render(sdfRenderer, 200, 120, values::Camera{}, 0.0f);
    EXPECT_FALSE(sdfRenderer.marchSettled()) << "on trial";
    EXPECT_FALSE(sdfRenderer.settleMarch(30.0)) << "faster: kept";
    EXPECT_TRUE(sdfRenderer.conePass());
    EXPECT_TRUE(sdfRenderer.marchSettled());
    EXPECT_FALSE(sdfRenderer.settleMarch(10.0)) << "the choice is made once per SDF";
    long differing = 0;
    for (std::size_t i = 0; i < with.rgba.size(); ++i) differing += std::abs(with.rgba[i] - without.rgba[i]) > 2;
    EXPECT_LE(differing, long(with.rgba.size() / 200));
    EXPECT_GT(foreground(with, values::ShadingSettings{}.background), 200 * 120 / 10);

    // An edit of the same file keeps it (no trial); another file starts without.
    ASSERT_FALSE(shaders::hasErrors(sdfRenderer.setSdf(prepare("float sdf(vec3 p) { return length(p) - 0.5; }\n"))));
    EXPECT_TRUE(sdfRenderer.conePass()) << "an edit of the same file keeps the cone pass";
    EXPECT_FALSE(sdfRenderer.settleMarch(40.0));
    EXPECT_TRUE(sdfRenderer.conePass());
    ASSERT_FALSE(
        shaders::hasErrors(sdfRenderer.setSdf(prepare("float sdf(vec3 p) { return length(p) - 0.6; }\n", "other.glsl"))));
    EXPECT_FALSE(sdfRenderer.conePass()) << "another file starts without";
    EXPECT_TRUE(sdfRenderer.settleMarch(40.0));
    const std::uint64_t built = sdfRenderer.programsBuilt();
    EXPECT_TRUE(sdfRenderer.settleMarch(45.0)) << "slower: dropped, and the caller draws again";
    EXPECT_FALSE(sdfRenderer.conePass());
    EXPECT_EQ(sdfRenderer.programsBuilt(), built) << "the program without cones comes from the cache";
    EXPECT_FALSE(sdfRenderer.settleMarch(10.0));

    values::TraceSettings trace = fragmentOnly;
    trace.cones = values::TraceSettings::Cones::Off;
    EXPECT_FALSE(shaders::hasErrors(sdfRenderer.setTrace(trace)));
    ASSERT_FALSE(shaders::hasErrors(sdfRenderer.setSdf(sdf)));
    EXPECT_FALSE(sdfRenderer.conePass());
    EXPECT_FALSE(sdfRenderer.settleMarch(40.0));
    EXPECT_FALSE(sdfRenderer.conePass());
    trace.cones = values::TraceSettings::Cones::On;
    EXPECT_FALSE(shaders::hasErrors(sdfRenderer.setTrace(trace)));
    EXPECT_TRUE(sdfRenderer.conePass()) << "on: no trial needed";
    trace.cones = values::TraceSettings::Cones::Auto;
    EXPECT_FALSE(shaders::hasErrors(sdfRenderer.setTrace(trace)));
    EXPECT_FALSE(sdfRenderer.conePass()) << "back to auto: without, until tried";
    EXPECT_FALSE(sdfRenderer.marchSettled());
    EXPECT_TRUE(sdfRenderer.settleMarch(40.0));
    EXPECT_TRUE(sdfRenderer.conePass());
    EXPECT_FALSE(sdfRenderer.settleMarch(20.0));
    EXPECT_TRUE(sdfRenderer.conePass()) << "tried again and kept";
    trace.cones = values::TraceSettings::Cones::On;
    EXPECT_FALSE(shaders::hasErrors(sdfRenderer.setTrace(trace)));
    values::ShadingSettings shading;
    shading.mode = shaders::ShadingMode::Steps;
    EXPECT_FALSE(shaders::hasErrors(sdfRenderer.setShading(shading)));
    EXPECT_FALSE(sdfRenderer.conePass()) << "the heat map shows each pixel's own steps";
    shading.mode = shaders::ShadingMode::Normals;
    shading.probe = true;
    EXPECT_FALSE(shaders::hasErrors(sdfRenderer.setShading(shading)));
    EXPECT_FALSE(sdfRenderer.conePass()) << "the march debugger records each pixel's own march";
    sdfRenderer.releaseGl();
}

// The compute tracer (issue 49) is tried at rest after the march and the cone pass, and kept when
// a full frame is faster; it draws the fragment tracer's picture (markers and a background image
// included); forced on, it serves every frame it applies to, and the cutting plane, the march
// debugger and the statistics output stay with the fragment tracer.
TEST_F(RendererTest, ComputeTracerIsTriedLastAndKeptWhenFaster) {
    const shaders::PreparedSdf sdf = prepare("float sdf(vec3 p) { return length(p) - 0.6; }\n");
    renderer::OffscreenRenderer offscreen;
    renderer::SdfRenderer sdfRenderer;
    values::TraceSettings trace;
    trace.cones = values::TraceSettings::Cones::Off;
    EXPECT_FALSE(shaders::hasErrors(sdfRenderer.setTrace(trace)));
    ASSERT_FALSE(shaders::hasErrors(sdfRenderer.setSdf(sdf)));
    EXPECT_FALSE(sdfRenderer.computeTracer()) << "a new SDF starts with the fragment tracer";
    const renderer::Image fragment = offscreen.render(sdfRenderer, 200, 120, values::Camera{}, 0.0f);
    EXPECT_TRUE(sdfRenderer.settleMarch(40.0));
    EXPECT_TRUE(sdfRenderer.computeTracer());
    EXPECT_NE(sdfRenderer.fragmentSource().find("#define SDFWB_COMPUTE"), std::string::npos);
    EXPECT_FALSE(sdfRenderer.marchSettled()) << "on trial";
    const renderer::Image compute = offscreen.render(sdfRenderer, 200, 120, values::Camera{}, 0.0f);
    EXPECT_FALSE(sdfRenderer.settleMarch(30.0)) << "faster: kept";
    EXPECT_TRUE(sdfRenderer.computeTracer());
    EXPECT_TRUE(sdfRenderer.marchSettled());
    EXPECT_GT(foreground(compute, values::ShadingSettings{}.background), 200 * 120 / 10);
    long differing = 0;
    for (std::size_t i = 0; i < compute.rgba.size(); ++i) differing += compute.rgba[i] != fragment.rgba[i];
    EXPECT_LE(differing, long(compute.rgba.size() / 1000));

    // An edit of the same file keeps it; another file tries again, and a slower compute frame
    // goes back to the fragment program, from the cache.
    ASSERT_FALSE(shaders::hasErrors(sdfRenderer.setSdf(prepare("float sdf(vec3 p) { return length(p) - 0.5; }\n"))));
    EXPECT_TRUE(sdfRenderer.computeTracer()) << "an edit of the same file keeps the compute tracer";
    ASSERT_FALSE(
        shaders::hasErrors(sdfRenderer.setSdf(prepare("float sdf(vec3 p) { return length(p) - 0.6; }\n", "other.glsl"))));
    EXPECT_FALSE(sdfRenderer.computeTracer());
    EXPECT_TRUE(sdfRenderer.settleMarch(40.0));
    EXPECT_TRUE(sdfRenderer.computeTracer());
    const std::uint64_t built = sdfRenderer.programsBuilt();
    EXPECT_TRUE(sdfRenderer.settleMarch(45.0)) << "slower: dropped, and the caller draws again";
    EXPECT_FALSE(sdfRenderer.computeTracer());
    EXPECT_EQ(sdfRenderer.programsBuilt(), built);
    EXPECT_FALSE(sdfRenderer.settleMarch(10.0));

    // After the cone pass: kept cones, then the compute tracer (without them) tried against them.
    trace.cones = values::TraceSettings::Cones::Auto;
    EXPECT_FALSE(shaders::hasErrors(sdfRenderer.setTrace(trace)));
    ASSERT_FALSE(
        shaders::hasErrors(sdfRenderer.setSdf(prepare("float sdf(vec3 p) { return length(p) - 0.6; }\n", "third.glsl"))));
    EXPECT_TRUE(sdfRenderer.settleMarch(40.0));
    EXPECT_TRUE(sdfRenderer.conePass());
    EXPECT_TRUE(sdfRenderer.settleMarch(30.0)) << "cones kept; the compute tracer on trial";
    EXPECT_TRUE(sdfRenderer.computeTracer());
    EXPECT_FALSE(sdfRenderer.conePass());
    EXPECT_TRUE(sdfRenderer.settleMarch(35.0)) << "slower than the cone pass: dropped";
    EXPECT_FALSE(sdfRenderer.computeTracer());
    EXPECT_TRUE(sdfRenderer.conePass());
    EXPECT_TRUE(sdfRenderer.marchSettled());

    // Forced: no trial; where it does not apply, the fragment tracer draws.
    trace.tracer = values::TraceSettings::Tracer::Compute;
    EXPECT_FALSE(shaders::hasErrors(sdfRenderer.setTrace(trace)));
    EXPECT_TRUE(sdfRenderer.computeTracer()) << "forced on";
    EXPECT_FALSE(sdfRenderer.conePass());
    values::CuttingPlane plane;
    plane.enabled = true;
    EXPECT_FALSE(shaders::hasErrors(sdfRenderer.setPlane(plane)));
    EXPECT_FALSE(sdfRenderer.computeTracer()) << "the plane's lines need a fragment shader's derivatives";
    plane.enabled = false;
    EXPECT_FALSE(shaders::hasErrors(sdfRenderer.setPlane(plane)));
    EXPECT_TRUE(sdfRenderer.computeTracer());
    for (int which = 0; which < 2; ++which) {
        values::ShadingSettings shading;
        (which == 0 ? shading.probe : shading.statsOutput) = true;
        EXPECT_FALSE(shaders::hasErrors(sdfRenderer.setShading(shading)));
        EXPECT_FALSE(sdfRenderer.computeTracer()) << (which == 0 ? "the march debugger" : "the statistics output");
    }

    // Markers and a background image: the same picture from both tracers.
    values::ShadingSettings shading;
    shading.mode = shaders::ShadingMode::Matcap;
    shading.markers = {{0.0f, 0.0f, 0.6f}, {0.5f, 0.3f, 0.2f}};
    shading.backgroundImage = (fs::path(SDFWB_SOURCE_DIR) / "resources" / "matcaps" / "clay.png").string();
    std::vector<renderer::Image> pictures;
    for (auto tracer : {values::TraceSettings::Tracer::Fragment, values::TraceSettings::Tracer::Compute}) {
        renderer::SdfRenderer drawing;
        values::TraceSettings forced;
        forced.tracer = tracer;
        EXPECT_FALSE(shaders::hasErrors(drawing.setTrace(forced)));
        EXPECT_FALSE(shaders::hasErrors(drawing.setShading(shading)));
        ASSERT_FALSE(shaders::hasErrors(drawing.setSdf(sdf)));
        EXPECT_EQ(drawing.computeTracer(), tracer == values::TraceSettings::Tracer::Compute);
        pictures.push_back(offscreen.render(drawing, 200, 120, values::Camera{}, 0.0f));
        drawing.releaseGl();
    }
    differing = 0;
    for (std::size_t i = 0; i < pictures[0].rgba.size(); ++i) differing += pictures[0].rgba[i] != pictures[1].rgba[i];
    EXPECT_LE(differing, long(pictures[0].rgba.size() / 1000));
    sdfRenderer.releaseGl();
}

// The compute tracer stores into the target's own texture (no float image, no blit) where the
// target is a single-sampled RGBA8 or RGBA32F texture, as the offscreen renderer's are: the
// pictures equal the blitted ones bit for bit (full and scaled frames, 8-bit and float), and a
// renderbuffer target, which cannot be stored into, still gets the blit.
TEST_F(RendererTest, TheComputeTracerStoresIntoATextureTargetExactlyAsItsBlitWould) {
    const shaders::PreparedSdf sdf = prepare("float sdf(vec3 p) { return max(length(p) - 0.7, abs(p.y) - 0.4); }\n");
    values::ShadingSettings shading;
    shading.mode = shaders::ShadingMode::Matcap;
    shading.markers = {{0.2f, 0.1f, 0.6f}};
    values::TraceSettings trace;
    trace.tracer = values::TraceSettings::Tracer::Compute;
    values::Camera camera;
    camera.position = {1.2f, 0.9f, 2.6f};
    struct Pictures {
        renderer::Image full, scaled, renderbuffer;
        renderer::FloatImage floats;
        bool stored[4] = {false, false, false, false};
    } pictures[2];
    renderer::OffscreenRenderer offscreen;
    for (int blit = 0; blit < 2; ++blit) {
        if (blit) ::setenv("SDFWB_COMPUTE_BLIT", "1", 1);
        renderer::SdfRenderer drawing; // reads SDFWB_COMPUTE_BLIT when made
        ::unsetenv("SDFWB_COMPUTE_BLIT");
        EXPECT_FALSE(shaders::hasErrors(drawing.setTrace(trace)));
        EXPECT_FALSE(shaders::hasErrors(drawing.setShading(shading)));
        ASSERT_FALSE(shaders::hasErrors(drawing.setSdf(sdf)));
        ASSERT_TRUE(drawing.computeTracer());
        Pictures& p = pictures[blit];
        renderer::FrameStats stats;
        p.full = offscreen.render(drawing, 203, 117, camera, 0.0f, &stats);
        p.stored[0] = stats.storedInTarget;
        p.scaled = offscreen.render(drawing, 203, 117, camera, 0.0f, &stats, 0.5f);
        p.stored[1] = stats.storedInTarget;
        p.floats = offscreen.renderFloat(drawing, 97, 61, camera, 0.0f, &stats);
        p.stored[2] = stats.storedInTarget;
        // A framebuffer around a renderbuffer (as a window system's may be).
        GLuint buffers[2] = {0, 0};
        glGenRenderbuffers(1, &buffers[0]);
        glBindRenderbuffer(GL_RENDERBUFFER, buffers[0]);
        glRenderbufferStorage(GL_RENDERBUFFER, GL_RGBA8, 203, 117);
        glGenFramebuffers(1, &buffers[1]);
        glBindFramebuffer(GL_FRAMEBUFFER, buffers[1]);
        glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, buffers[0]);
        p.stored[3] = drawing.render(203, 117, camera, 0.0f, true).storedInTarget;
        p.renderbuffer = {203, 117, std::vector<std::uint8_t>(203 * 117 * 4), {}};
        glPixelStorei(GL_PACK_ALIGNMENT, 1);
        glReadPixels(0, 0, 203, 117, GL_RGBA, GL_UNSIGNED_BYTE, p.renderbuffer.rgba.data());
        glBindFramebuffer(GL_FRAMEBUFFER, 0);
        glDeleteFramebuffers(1, &buffers[1]);
        glDeleteRenderbuffers(1, &buffers[0]);
        EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
        drawing.releaseGl();
    }
    for (int k = 0; k < 3; ++k) {
        EXPECT_TRUE(pictures[0].stored[k]) << "frame " << k << ": a texture target is stored into";
        EXPECT_FALSE(pictures[1].stored[k]) << "frame " << k << ": SDFWB_COMPUTE_BLIT=1 blits";
    }
    EXPECT_FALSE(pictures[0].stored[3]) << "a renderbuffer cannot be stored into";
    EXPECT_GT(foreground(pictures[0].full, shading.background), 203 * 117 / 8);
    EXPECT_TRUE(pictures[0].full.rgba == pictures[1].full.rgba);
    EXPECT_TRUE(pictures[0].scaled.rgba == pictures[1].scaled.rgba);
    EXPECT_TRUE(pictures[0].floats.rgba == pictures[1].floats.rgba);
    // Row order aside (the readback here is bottom-up), the renderbuffer's frame is the same picture.
    long differing = 0;
    for (int y = 0; y < 117; ++y)
        for (int x = 0; x < 203; ++x)
            differing += !std::equal(pictures[0].full.pixel(x, y), pictures[0].full.pixel(x, y) + 4,
                                     pictures[1].renderbuffer.rgba.data() + (std::size_t(116 - y) * 203 + x) * 4);
    EXPECT_EQ(differing, 0);
}

// The cone pass's texture grows with the frame; making it must leave the matcap (texture unit 0)
// bound: a matcap frame drawn right after a smaller one matches the frame without the cone pass.
TEST_F(RendererTest, ConePassLeavesTheMatcapInPlace) {
    const shaders::PreparedSdf sdf =
        prepare("float sdf(vec3 p) { vec2 q = vec2(length(p.xz) - 0.6, p.y); return length(q) - 0.25; }\n");
    renderer::OffscreenRenderer offscreen;
    renderer::Image images[2];
    for (int cones = 0; cones < 2; ++cones) {
        renderer::SdfRenderer sdfRenderer;
        values::ShadingSettings shading;
        shading.mode = shaders::ShadingMode::Matcap;
        EXPECT_FALSE(shaders::hasErrors(sdfRenderer.setShading(shading)));
        values::TraceSettings trace;
        trace.cones = cones ? values::TraceSettings::Cones::On : values::TraceSettings::Cones::Off;
        EXPECT_FALSE(shaders::hasErrors(sdfRenderer.setTrace(trace)));
        ASSERT_FALSE(shaders::hasErrors(sdfRenderer.setSdf(sdf)));
        (void)offscreen.render(sdfRenderer, 60, 40, values::Camera{}, 0.0f);
        images[cones] = offscreen.render(sdfRenderer, 200, 120, values::Camera{}, 0.0f);
        sdfRenderer.releaseGl();
    }
    long differing = 0;
    for (std::size_t i = 0; i < images[0].rgba.size(); ++i) differing += std::abs(images[0].rgba[i] - images[1].rgba[i]) > 2;
    EXPECT_LE(differing, long(images[0].rgba.size() / 200));
    EXPECT_GT(foreground(images[1], values::ShadingSettings{}.background), 200 * 120 / 10);
}

// Loading a background image binds it on the active texture unit: it must not be the matcap's.
// The first frame with both (a CLI render is only that frame) shows the shape in the matcap's
// colours, not black.
TEST_F(RendererTest, MatcapShowsOnTheFrameThatLoadsABackgroundImage) {
    renderer::SdfRenderer sdfRenderer;
    values::ShadingSettings shading;
    shading.mode = shaders::ShadingMode::Matcap;
    shading.backgroundImage = (fs::path(SDFWB_SOURCE_DIR) / "resources" / "matcaps" / "jade.png").string();
    EXPECT_FALSE(shaders::hasErrors(sdfRenderer.setShading(shading)));
    ASSERT_FALSE(shaders::hasErrors(sdfRenderer.setSdf(prepare("float sdf(vec3 p) { return length(p) - 0.6; }\n"))));
    renderer::OffscreenRenderer offscreen;
    const renderer::Image image = offscreen.render(sdfRenderer, 120, 80, values::Camera{}, 0.0f);
    long black = 0;
    for (int y = 30; y < 50; ++y)
        for (int x = 50; x < 70; ++x) {
            const std::uint8_t* p = image.pixel(x, y);
            black += p[0] < 12 && p[1] < 12 && p[2] < 12;
        }
    EXPECT_EQ(black, 0) << "the sphere's middle is black: the matcap was unbound";
    sdfRenderer.releaseGl();
}

// The tiniest SDFs (under 400 characters of code, no loop) unroll the normal's taps; an SDF with
// a loop (the driver may unroll it: a short text, a large program) and a longer one keep the loop.
// Unrolled or not, the picture is the same.
TEST_F(RendererTest, TinySdfsWithoutLoopsUnrollTheNormalTaps) {
    const std::string tiny = "float sdf(vec3 p) { vec2 q = vec2(length(p.xz) - 0.6, p.y); return length(q) - 0.25; }\n";
    const std::string looped =
        "float sdf(vec3 p) { float d = 1e9;\n"
        "    for (int i = 0; i < 3; ++i) d = min(d, length(p - vec3(0.3 * float(i - 1), 0.0, 0.0)) - 0.2);\n"
        "    return d; }\n";
    std::string longer = "float sdf(vec3 p) {\n    float d = length(p) - 0.6;\n";
    for (int i = 0; i < 12; ++i)
        longer += "    d = max(d, -(length(p - vec3(0.0, 0.0, 0.6)) - 0.0" + std::to_string(i + 1) + "));\n";
    longer += "    return d; }\n";
    renderer::OffscreenRenderer offscreen;
    auto unrolled = [](renderer::SdfRenderer& r) {
        return r.fragmentSource().find("#define SDFWB_UNROLLED_TAPS") != std::string::npos;
    };
    renderer::SdfRenderer sdfRenderer;
    ASSERT_FALSE(shaders::hasErrors(sdfRenderer.setSdf(prepare(tiny))));
    EXPECT_TRUE(unrolled(sdfRenderer));
    const renderer::Image withUnrolled = offscreen.render(sdfRenderer, 200, 120, values::Camera{}, 0.0f);
    ASSERT_FALSE(shaders::hasErrors(sdfRenderer.setSdf(prepare(looped))));
    EXPECT_FALSE(unrolled(sdfRenderer));
    ASSERT_FALSE(shaders::hasErrors(sdfRenderer.setSdf(prepare(longer))));
    EXPECT_FALSE(unrolled(sdfRenderer));
    // The same torus with enough comment-free padding to pass the limit draws the same picture.
    std::string padded = "float pad(vec3 p) { return p.x";
    for (int i = 0; i < 60; ++i) padded += " + 0.0 * p.y";
    padded += "; }\n" + tiny;
    ASSERT_FALSE(shaders::hasErrors(sdfRenderer.setSdf(prepare(padded))));
    EXPECT_FALSE(unrolled(sdfRenderer));
    const renderer::Image withLoop = offscreen.render(sdfRenderer, 200, 120, values::Camera{}, 0.0f);
    long differing = 0;
    for (std::size_t i = 0; i < withLoop.rgba.size(); ++i) differing += std::abs(withLoop.rgba[i] - withUnrolled.rgba[i]) > 2;
    EXPECT_LE(differing, long(withLoop.rgba.size() / 1000));
    EXPECT_GT(foreground(withUnrolled, values::ShadingSettings{}.background), 200 * 120 / 10);
    sdfRenderer.releaseGl();
}

// A frame drawn as the box's far faces over the cleared background (only pixels whose ray meets
// the box run the tracer) is the full-frame picture, pixel for pixel: from outside the box, from
// a camera beside it with box corners behind it (the near side clipped), from inside it, looking
// away from it, far away, at a reduced scale, with the cone pass and with the cutting plane (its
// isocontours take screen-space derivatives); with a shape that fills the box to its faces, so
// that the box's outline is the shape's.
TEST_F(RendererTest, BoxProxyDrawsTheFullFramePicture) {
    const fs::path foreign = fs::path(SDFWB_SOURCE_DIR) / "tests" / "foreign";
    shaders::IncludeOptions options;
    options.libraryRoots = {fs::path(SDFWB_SOURCE_DIR) / "shaders" / "lib"};
    // Ours (a torus, a box to the box's faces, a thin shell), then users' code: IQ's primitives
    // (map()), an hg_sdf colonnade, a G3D scene with its noise texture, a field with NaN regions.
    const std::vector<shaders::PreparedSdf> sdfs = {
        prepare("float sdf(vec3 p) { vec2 q = vec2(length(p.xz) - 0.6, p.y); return length(q) - 0.25; }\n"),
        prepare("float sdf(vec3 p) { vec3 q = abs(p) - vec3(1.0); return length(max(q, 0.0)) + min(max(q.x, max(q.y, q.z)), "
                "0.0); }\n"),
        prepare("float sdf(vec3 p) { return abs(length(p - vec3(0.2, 0.1, 0.0)) - 0.3) - 0.02; }\n"),
        shaders::prepareSdfFile(foreign / "01_iq_primitives.glsl", options),
        shaders::prepareSdfFile(foreign / "05_hg_colonnade.glsl", options),
        shaders::prepareSdfFile(foreign / "21_g3d_random_cells.glsl", options),
        shaders::prepareSdfFile(foreign / "15_nan_superquadric.glsl", options)};
    auto camera = [](glm::vec3 position, glm::vec3 target, float fov = 40.0f) {
        values::Camera c;
        c.position = position;
        c.target = target;
        c.fovYDegrees = fov;
        return c;
    };
    const std::vector<values::Camera> cameras = {
        values::Camera{},
        camera({1.3f, 0.25f, 0.35f}, {0.0f, 0.1f, 0.0f}, 70.0f), // beside the box: corners behind the camera
        camera({0.6f, 0.5f, 0.7f}, {0.0f, 0.0f, 0.0f}, 80.0f),   // inside it
        camera({0.6f, 0.5f, 0.7f}, {2.0f, 1.5f, 2.0f}),          // inside it, looking out
        camera({3.0f, 0.5f, 2.0f}, {6.0f, 1.0f, 4.0f}),          // outside, looking away
        camera({40.0f, 25.0f, 30.0f}, {0.0f, 0.0f, 0.0f}, 4.0f)};
    renderer::OffscreenRenderer offscreen;
    for (std::size_t k = 0; k < sdfs.size(); ++k) {
        const shaders::PreparedSdf& sdf = sdfs[k];
        ASSERT_FALSE(shaders::hasErrors(sdf.diagnostics)) << shaders::formatDiagnostic(sdf.diagnostics[0]);
        const std::string label = sdf.source.map.fileName(0);
        for (std::size_t c = 0; c < cameras.size(); ++c) {
            // Full scale, half scale, cone pass, cutting plane: without and with the proxy box;
            // then the fragment tracer without the proxy against the compute tracer (issue 49).
            for (int variant = 0; variant < 5; ++variant) {
                renderer::Image images[2];
                for (int proxy = 0; proxy < 2; ++proxy) {
                    renderer::SdfRenderer sdfRenderer;
                    values::ShadingSettings shading;
                    shading.mode = shaders::ShadingMode::Gooch;
                    EXPECT_FALSE(shaders::hasErrors(sdfRenderer.setShading(shading)));
                    values::TraceSettings trace;
                    trace.boxProxy = proxy == 1 && variant != 4;
                    trace.cones = variant == 2 ? values::TraceSettings::Cones::On : values::TraceSettings::Cones::Off;
                    trace.tracer = variant == 4 && proxy == 1 ? values::TraceSettings::Tracer::Compute
                                                              : values::TraceSettings::Tracer::Fragment;
                    EXPECT_FALSE(shaders::hasErrors(sdfRenderer.setTrace(trace)));
                    if (variant == 3) {
                        values::CuttingPlane plane;
                        plane.enabled = true;
                        plane.normal = glm::vec3(0.3f, 0.2f, 1.0f);
                        plane.offset = 0.1f;
                        EXPECT_FALSE(shaders::hasErrors(sdfRenderer.setPlane(plane)));
                    }
                    ASSERT_FALSE(shaders::hasErrors(sdfRenderer.setSdf(sdf)));
                    renderer::FrameStats stats;
                    images[proxy] = offscreen.render(sdfRenderer, 160, 100, cameras[c], 0.0f, &stats, variant == 1 ? 0.5f : 1.0f);
                    EXPECT_EQ(stats.boxProxy, proxy == 1 && variant != 4);
                    EXPECT_EQ(sdfRenderer.computeTracer(), proxy == 1 && variant == 4);
                    sdfRenderer.releaseGl();
                }
                long differing = 0;
                for (std::size_t i = 0; i < images[0].rgba.size(); ++i) differing += images[0].rgba[i] != images[1].rgba[i];
                EXPECT_EQ(differing, 0) << label << ", camera " << c << ", variant " << variant;
                // Our shapes show, except looking away from the box or from inside the solid box;
                // every shape shows from the default camera.
                const bool shows = c == 0 || (k < 3 && (c == 1 || c == 5 || (c == 2 && k != 1)));
                if (shows) {
                    EXPECT_GT(foreground(images[1], values::ShadingSettings{}.background), 100) << label << ", camera " << c;
                }
            }
        }
    }
}

// Where the picture shows something other than the background outside the box (a background
// image, markers, the step heat map), every pixel runs the tracer.
TEST_F(RendererTest, BoxProxyIsNotUsedWhereThePictureReachesPastTheBox) {
    renderer::SdfRenderer sdfRenderer;
    ASSERT_FALSE(shaders::hasErrors(sdfRenderer.setSdf(prepare("float sdf(vec3 p) { return length(p) - 0.6; }\n"))));
    renderer::OffscreenRenderer offscreen;
    renderer::FrameStats stats;
    (void)offscreen.render(sdfRenderer, 60, 40, values::Camera{}, 0.0f, &stats);
    EXPECT_TRUE(stats.boxProxy);
    for (int setting = 0; setting < 3; ++setting) {
        values::ShadingSettings shading;
        if (setting == 0) shading.backgroundImage = (fs::path(SDFWB_SOURCE_DIR) / "resources" / "matcaps" / "jade.png").string();
        if (setting == 1) shading.markers = {glm::vec3(0.0f)};
        if (setting == 2) shading.mode = shaders::ShadingMode::Steps;
        EXPECT_FALSE(shaders::hasErrors(sdfRenderer.setShading(shading)));
        (void)offscreen.render(sdfRenderer, 60, 40, values::Camera{}, 0.0f, &stats);
        EXPECT_FALSE(stats.boxProxy) << "setting " << setting;
    }
    sdfRenderer.releaseGl();
}

// Issue 49, point 5: where the media module cannot load (the GPU machine gets only the headless
// binaries, scripts/device_bundle), .png files go through libpng: the golden images and a batch
// render pass in a child process whose plugin folder is empty, and the log says why.
TEST_F(RendererTest, GoldenImagesAndPngRendersPassWithoutTheMediaModule) {
    const fs::path empty = fs::temp_directory_path() / ("sdfwb-no-media-" + std::to_string(::getpid()));
    fs::create_directories(empty);
    const std::string command = "env SDFWB_PLUGIN_DIR=" + empty.string() + " " + fs::read_symlink("/proc/self/exe").string() +
                                " '--gtest_filter=ShadingModes/GoldenTest.*:RendererTest.BatchRenderWritesAPng*' 2>&1";
    std::string output;
    FILE* pipe = popen(command.c_str(), "r");
    ASSERT_NE(pipe, nullptr);
    char buffer[4096];
    while (std::size_t n = std::fread(buffer, 1, sizeof buffer, pipe)) output.append(buffer, n);
    const int status = pclose(pipe);
    fs::remove_all(empty);
    EXPECT_EQ(status, 0) << output;
    EXPECT_NE(output.find(".png through libpng only"), std::string::npos) << output;
    EXPECT_NE(output.find("[  PASSED  ] 13 tests."), std::string::npos) << output;
}

// Issue 49: a timed frame (drawn to glFinish) carries its GPU time from a timer query, full size
// and scaled, within the frame's wall time (a frame the viewport does not wait for takes none).
TEST_F(RendererTest, TimedFramesCarryTheirGpuTime) {
    renderer::SdfRenderer sdfRenderer;
    ASSERT_FALSE(shaders::hasErrors(sdfRenderer.setSdf(prepare("float sdf(vec3 p) { return length(p) - 0.6; }\n"))));
    renderer::OffscreenRenderer offscreen;
    renderer::FrameStats stats;
    (void)offscreen.render(sdfRenderer, 60, 40, values::Camera{}, 0.0f, &stats); // the program's first draw
    (void)offscreen.render(sdfRenderer, 60, 40, values::Camera{}, 0.0f, &stats);
    EXPECT_GE(stats.gpuMilliseconds, 0.0);
    EXPECT_LE(stats.gpuMilliseconds, stats.cpuMilliseconds) << "the commands lie inside the frame's wall time";
    (void)offscreen.render(sdfRenderer, 60, 40, values::Camera{}, 0.0f, &stats, 0.5f);
    EXPECT_GE(stats.gpuMilliseconds, 0.0) << "scaled";
    sdfRenderer.releaseGl();
}

// With query timing (the viewport's on a GPU), a frame drawn without finish is timed by a query
// read later, without waiting: its serial comes back with its GPU time, oldest first, marked
// with whether the program that drew it is still current; at most four are out at once.
TEST_F(RendererTest, QueryTimedFramesComeBackLaterWithoutWaiting) {
    GLuint texture = 0, framebuffer = 0;
    glGenTextures(1, &texture);
    glBindTexture(GL_TEXTURE_2D, texture);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, 64, 48, 0, GL_RGBA, GL_UNSIGNED_BYTE, nullptr);
    glGenFramebuffers(1, &framebuffer);
    glBindFramebuffer(GL_FRAMEBUFFER, framebuffer);
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, texture, 0);
    renderer::SdfRenderer sdfRenderer;
    ASSERT_FALSE(shaders::hasErrors(sdfRenderer.setSdf(prepare("float sdf(vec3 p) { return length(p) - 0.6; }\n"))));
    EXPECT_EQ(sdfRenderer.render(64, 48, values::Camera{}, 0.0f).serial, 0u) << "off by default";
    sdfRenderer.setQueryTiming(true);
    EXPECT_EQ(sdfRenderer.render(64, 48, values::Camera{}, 0.0f, true).serial, 0u) << "a finished frame has its own time";
    std::vector<std::uint64_t> serials;
    for (int frame = 0; frame < 5; ++frame)
        serials.push_back(frame % 2 ? sdfRenderer.renderScaled(64, 48, 0.5f, values::Camera{}, 0.0f).serial
                                    : sdfRenderer.render(64, 48, values::Camera{}, 0.0f).serial);
    for (int frame = 0; frame < 4; ++frame) EXPECT_NE(serials[std::size_t(frame)], 0u);
    EXPECT_EQ(serials[4], 0u) << "four frames are out: the fifth goes untimed";
    ASSERT_FALSE(shaders::hasErrors(sdfRenderer.setSdf(prepare("float sdf(vec3 p) { return length(p) - 0.5; }\n"))));
    glFinish();
    const std::vector<renderer::TimedFrame> timed = sdfRenderer.timedFrames();
    ASSERT_EQ(timed.size(), 4u);
    for (std::size_t k = 0; k < timed.size(); ++k) {
        EXPECT_EQ(timed[k].serial, serials[k]);
        EXPECT_GE(timed[k].gpuMilliseconds, 0.0);
        EXPECT_FALSE(timed[k].currentProgram) << "drawn by the sphere before the edit";
    }
    EXPECT_TRUE(sdfRenderer.timedFrames().empty()) << "each time is handed over once";
    const std::uint64_t next = sdfRenderer.render(64, 48, values::Camera{}, 0.0f).serial;
    EXPECT_GT(next, serials[3]);
    glFinish();
    const auto after = sdfRenderer.timedFrames();
    ASSERT_EQ(after.size(), 1u);
    EXPECT_EQ(after[0].serial, next);
    EXPECT_TRUE(after[0].currentProgram);
    sdfRenderer.releaseGl();
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glDeleteFramebuffers(1, &framebuffer);
    glDeleteTextures(1, &texture);
}

// Every SDF's fragment program is paired with one vertex program (a program pipeline): after
// releaseGl() (the context is about to go) the renderer makes them again and draws the same
// picture, without a GL error, for a second SDF too.
TEST_F(RendererTest, ProgramPipelineIsMadeAgainAfterReleaseGl) {
    renderer::SdfRenderer sdfRenderer;
    renderer::OffscreenRenderer offscreen;
    ASSERT_FALSE(shaders::hasErrors(sdfRenderer.setSdf(prepare("float sdf(vec3 p) { return length(p) - 0.6; }\n"))));
    const renderer::Image before = offscreen.render(sdfRenderer, 120, 80, values::Camera{}, 0.0f);
    sdfRenderer.releaseGl();
    const renderer::Image after = offscreen.render(sdfRenderer, 120, 80, values::Camera{}, 0.0f);
    EXPECT_EQ(before.rgba, after.rgba);
    ASSERT_FALSE(shaders::hasErrors(sdfRenderer.setSdf(prepare("float sdf(vec3 p) { return length(p.xz) - 0.3; }\n"))));
    const renderer::Image other = offscreen.render(sdfRenderer, 120, 80, values::Camera{}, 0.0f);
    EXPECT_NE(before.rgba, other.rgba);
    EXPECT_GT(foreground(other, values::ShadingSettings{}.background), 120 * 80 / 10);
    EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
    sdfRenderer.releaseGl();
}
