// Golden images: every shading mode (and AO) on two SDFs, compared with reviewed PNGs under
// tests/renderer/files/ by maximum and mean channel difference. Regenerate after an intended
// change with SDFWB_UPDATE_GOLDEN=1 and look at every image before committing it.

#include <renderer/HeadlessContext.h>
#include <renderer/ImageIO.h>
#include <renderer/OffscreenRenderer.h>
#include <renderer/SdfRenderer.h>
#include <shaders/SdfSource.h>

#include "GlTestContext.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>

using namespace sdfwb;
namespace fs = std::filesystem;

namespace {

struct Case {
    const char* sdf; // dataset file
    const char* mode;
    bool ao;
};

std::string caseName(const Case& c) {
    std::string name = fs::path(c.sdf).stem().string() + "_" + c.mode + (c.ao ? "_ao" : "");
    for (char& ch : name) ch = char(std::tolower(static_cast<unsigned char>(ch)));
    return name;
}

class GoldenTest : public sdfwb::testing::GlTest, public ::testing::WithParamInterface<Case> {
protected:
};

} // namespace

TEST_P(GoldenTest, MatchesTheReviewedImage) {
    const Case& c = GetParam();
    fs::path source = fs::path(SDFWB_SOURCE_DIR) / "dataset" / c.sdf;
    shaders::IncludeOptions options;
    options.libraryRoots = {fs::path(SDFWB_SOURCE_DIR) / "shaders" / "lib", fs::path(SDFWB_SOURCE_DIR) / "dataset"};
    renderer::SdfRenderer sdfRenderer;
    renderer::ShadingSettings shading;
    shading.mode = *renderer::parseShadingMode(c.mode);
    shading.ambientOcclusion = c.ao;
    EXPECT_FALSE(shaders::hasErrors(sdfRenderer.setShading(shading)));
    auto diagnostics = sdfRenderer.setSdf(shaders::prepareSdfFile(source, options));
    ASSERT_FALSE(shaders::hasErrors(diagnostics)) << shaders::formatDiagnostic(diagnostics[0]);
    renderer::Image image;
    {
        renderer::OffscreenRenderer offscreen;
        image = offscreen.render(sdfRenderer, 192, 108, renderer::Camera{}, 0.0f);
    }
    sdfRenderer.releaseGl();

    fs::path golden = fs::path(SDFWB_SOURCE_DIR) / "tests" / "renderer" / "files" / ("golden_" + caseName(c) + ".png");
    if (const char* update = std::getenv("SDFWB_UPDATE_GOLDEN"); update && *update == '1') {
        ASSERT_TRUE(renderer::writeImage(golden, image).hasValue());
        GTEST_SKIP() << "wrote " << golden << ": look at it before committing";
    }
    auto expected = renderer::readImage(golden);
    ASSERT_TRUE(expected.hasValue()) << expected.error().message;
    ASSERT_EQ(expected->width, image.width);
    ASSERT_EQ(expected->height, image.height);
    int worst = 0;
    double sum = 0.0;
    for (std::size_t i = 0; i < image.rgba.size(); ++i) {
        if (i % 4 == 3) continue;
        int difference = std::abs(int(image.rgba[i]) - int(expected->rgba[i]));
        worst = std::max(worst, difference);
        sum += difference;
    }
    double mean = sum / double(image.width * image.height * 3);
    // Silhouette pixels may flip between drivers (GPU vs llvmpipe): allow a few strong differences,
    // but the average must stay tiny.
    EXPECT_LE(mean, 1.5) << caseName(c) << ": mean channel difference " << mean;
    long strong = 0;
    for (std::size_t i = 0; i < image.rgba.size(); i += 4) {
        int d = std::max({std::abs(int(image.rgba[i]) - int(expected->rgba[i])),
                          std::abs(int(image.rgba[i + 1]) - int(expected->rgba[i + 1])),
                          std::abs(int(image.rgba[i + 2]) - int(expected->rgba[i + 2]))});
        strong += d > 24;
    }
    // The worst single difference is reported, not bounded: a flipped silhouette pixel may differ fully.
    EXPECT_LE(strong, long(image.width * image.height) / 200)
        << caseName(c) << ": " << strong << " pixels differ by more than 24 (worst channel difference " << worst << ")";
    if (HasFailure())
        renderer::writeImage(fs::temp_directory_path() / ("sdfwb-golden-actual-" + caseName(c) + ".png"), image).hasValue();
}

INSTANTIATE_TEST_SUITE_P(
    ShadingModes, GoldenTest,
    ::testing::Values(Case{"Geometry/Torus.glsl", "normals", false}, Case{"Geometry/Torus.glsl", "gooch", false},
                      Case{"Geometry/Torus.glsl", "gooch", true}, Case{"Geometry/Torus.glsl", "matcap", false},
                      Case{"Geometry/Torus.glsl", "curvature", false}, Case{"Geometry/Torus.glsl", "steps", false},
                      Case{"Geometry/Box.glsl", "normals", false}, Case{"Geometry/Box.glsl", "gooch", false},
                      Case{"Geometry/Box.glsl", "gooch", true}, Case{"Geometry/Box.glsl", "matcap", false},
                      Case{"Geometry/Box.glsl", "curvature", false}, Case{"Geometry/Box.glsl", "steps", false}),
    [](const ::testing::TestParamInfo<Case>& info) { return caseName(info.param); });
