// Sphere tracer benchmark: every dataset SDF at 1280x720 (Gooch shading): time to the
// full-resolution frame, the frame time while moving (at the scale the viewport picks for a 33 ms
// budget), steps per pixel. Timings are medians of 3 frames after a warm-up frame (shader JIT
// excluded). Error against run time (hit error, samplers, gradients, audit) is `sdfwb --batch
// bench` (bench/Benchmarks.cpp).
//
//   build/bench/bench_tracer

#include <core/Paths.h>
#include <dataset/Catalogue.h>
#include <renderer/HeadlessContext.h>
#include <renderer/OffscreenRenderer.h>
#include <renderer/SdfRenderer.h>
#include <shaders/SdfSource.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

using namespace sdfwb;

namespace {

double median3(double a, double b, double c) { return std::max(std::min(a, b), std::min(std::max(a, b), c)); }

// Median frame time over 3 frames, after one warm-up frame.
double frameMilliseconds(renderer::OffscreenRenderer& offscreen, renderer::SdfRenderer& sdfRenderer, int width, int height,
                         float scale) {
    renderer::FrameStats stats;
    offscreen.render(sdfRenderer, width, height, renderer::Camera{}, 0.0f, &stats, scale);
    double t[3];
    for (double& value : t) {
        offscreen.render(sdfRenderer, width, height, renderer::Camera{}, 0.0f, &stats, scale);
        value = stats.cpuMilliseconds;
    }
    return median3(t[0], t[1], t[2]);
}

shaders::IncludeOptions includeOptions() {
    shaders::IncludeOptions options;
    options.libraryRoots = {paths::shaderLibraryRoot(), paths::datasetRoot()};
    return options;
}

void datasetReport() {
    dataset::Catalogue catalogue = dataset::Catalogue::scan(paths::datasetRoot());
    std::printf("## Interactive rendering, 1280x720, Gooch shading, default camera\n\n");
    std::printf(
        "| SDF | full-resolution frame (ms) | moving: scale | moving frame (ms) | steps/pixel (all) | steps/pixel (hits) |\n");
    std::printf("|---|---|---|---|---|---|\n");
    renderer::OffscreenRenderer offscreen;
    for (const dataset::Entry& entry : catalogue.entries()) {
        renderer::SdfRenderer sdfRenderer;
        renderer::ShadingSettings shading;
        shading.mode = renderer::ShadingMode::Gooch;
        (void)sdfRenderer.setShading(shading);
        auto diagnostics = sdfRenderer.setSdf(shaders::prepareSdfFile(entry.path, includeOptions()));
        if (shaders::hasErrors(diagnostics)) {
            std::printf("| %s | does not compile | | | | |\n", entry.metadata.name.c_str());
            continue;
        }
        double full = frameMilliseconds(offscreen, sdfRenderer, 1280, 720, 1.0f);
        // The viewport's rule: start from the full frame's cost, then adapt frame by frame.
        float scale = std::clamp(float(std::sqrt(0.8 * 33.0 / full)), 0.1f, 1.0f);
        double moving = 0.0;
        float measuredScale = scale;
        for (int frame = 0; frame < 6; ++frame) {
            measuredScale = scale;
            moving = frameMilliseconds(offscreen, sdfRenderer, 1280, 720, scale);
            float next = scale * float(std::sqrt(0.8 * 33.0 / moving));
            scale = std::clamp(0.5f * (scale + next), 0.1f, 1.0f);
        }
        scale = measuredScale;
        shading.statsOutput = true;
        (void)sdfRenderer.setShading(shading);
        auto stats = offscreen.renderStats(sdfRenderer, 320, 180, renderer::Camera{}, 0.0f);
        double steps = 0.0, hitSteps = 0.0;
        long hits = 0;
        for (const auto& pixel : stats) {
            steps += pixel.steps;
            if (pixel.t >= 0.0f) {
                hitSteps += pixel.steps;
                ++hits;
            }
        }
        std::printf("| %s | %.1f | %.0f %% | %.1f | %.1f | %.1f |\n", entry.metadata.name.c_str(), full, scale * 100.0f, moving,
                    steps / double(stats.size()), hits ? hitSteps / double(hits) : 0.0);
        std::fflush(stdout);
        sdfRenderer.releaseGl();
    }
    std::printf("\n");
}

} // namespace

int main() {
    auto context = renderer::HeadlessContext::create();
    if (!context) {
        std::fprintf(stderr, "bench_tracer: %s\n", context.error().message.c_str());
        return 3;
    }
    std::printf("GL: %s\n\n", renderer::describe(context.value()->info()).c_str());
    datasetReport();
    return 0;
}
