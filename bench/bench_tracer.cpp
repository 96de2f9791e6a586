// Sphere tracer benchmarks, two reports:
//   1. every dataset SDF at 1280x720 (Gooch shading): time to the full-resolution frame, the frame
//      time while moving (at the scale the viewport picks for a 33 ms budget), steps per pixel;
//   2. error against run time on three exact SDFs: mean and max |f| at the hit point (for an exact
//      SDF, the distance from the hit to the true surface) against steps and milliseconds, for
//      plain, over-relaxed and step-factor tracing over a range of hit tolerances.
// Timings are medians of 3 frames after a warm-up frame (shader JIT excluded).
//
//   build/bench/bench_tracer [--dataset-only | --error-only] [--csv FILE]

#include <core/Paths.h>
#include <dataset/Catalogue.h>
#include <renderer/HeadlessContext.h>
#include <renderer/OffscreenRenderer.h>
#include <renderer/SdfRenderer.h>
#include <shaders/SdfSource.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <string>
#include <vector>

using namespace sdfwb;

namespace {

double median3(double a, double b, double c) { return std::max(std::min(a, b), std::min(std::max(a, b), c)); }

// Median frame time over 3 frames, after one warm-up frame.
double frameMilliseconds(renderer::OffscreenRenderer& offscreen, renderer::SdfRenderer& sdfRenderer, int width, int height, float scale) {
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
    std::printf("| SDF | full-resolution frame (ms) | moving: scale | moving frame (ms) | steps/pixel (all) | steps/pixel (hits) |\n");
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

struct Field {
    const char* name;
    const char* glsl;
};

const Field kExactFields[] = {
    {"torus", "float sdf(vec3 p) { vec2 q = vec2(length(p.xz) - 0.6, p.y); return length(q) - 0.25; }\n"},
    {"box", "float sdf(vec3 p) { vec3 q = abs(p) - vec3(0.7, 0.45, 0.55); return length(max(q, 0.0)) + min(max(q.x, max(q.y, q.z)), 0.0); }\n"},
    {"capsule", "float sdf(vec3 p) { vec3 a = vec3(-0.6, -0.3, 0.0), b = vec3(0.6, 0.4, 0.1); vec3 pa = p - a, ba = b - a;\n"
                "  float h = clamp(dot(pa, ba) / dot(ba, ba), 0.0, 1.0); return length(pa - ba * h) - 0.3; }\n"},
};

void errorReport(std::FILE* csv) {
    std::printf("## Sphere tracer: hit error against run time, 1280x720, default camera\n\n");
    std::printf("error = |f(hit)| in scene units (exact SDFs: distance from the hit to the surface); ms = one stats frame\n\n");
    std::printf("| SDF | method | hit tolerance (px) | steps/pixel (hits) | mean error | max error | ms |\n|---|---|---|---|---|---|---|\n");
    if (csv) std::fprintf(csv, "sdf,method,epsilon_scale,steps_hits,steps_all,mean_error,max_error,milliseconds,hit_pixels\n");
    struct Method {
        const char* name;
        float relaxation, stepFactor;
    };
    const Method methods[] = {{"plain", 1.0f, 1.0f}, {"over-relaxed 1.6", 1.6f, 1.0f}, {"step factor 0.7", 1.0f, 0.7f}};
    renderer::OffscreenRenderer offscreen;
    for (const Field& field : kExactFields) {
        for (const Method& method : methods) {
            for (float epsilonScale : {4.0f, 2.0f, 1.0f, 0.5f, 0.25f, 0.1f}) {
                renderer::SdfRenderer sdfRenderer;
                renderer::ShadingSettings shading;
                shading.statsOutput = true;
                renderer::TraceSettings trace;
                trace.overRelaxation = method.relaxation;
                trace.stepFactor = method.stepFactor;
                trace.epsilonScale = epsilonScale;
                trace.maxSteps = 512;
                (void)sdfRenderer.setShading(shading);
                (void)sdfRenderer.setTrace(trace);
                if (shaders::hasErrors(sdfRenderer.setSdf(shaders::prepareSdf(field.glsl, field.name, {}, {})))) continue;
                renderer::FrameStats frame;
                offscreen.renderStats(sdfRenderer, 1280, 720, renderer::Camera{}, 0.0f, &frame);  // warm-up (JIT)
                double times[3];
                std::vector<renderer::OffscreenRenderer::PixelStats> stats;
                for (double& t : times) {
                    stats = offscreen.renderStats(sdfRenderer, 1280, 720, renderer::Camera{}, 0.0f, &frame);
                    t = frame.cpuMilliseconds;
                }
                double stepsAll = 0.0, stepsHits = 0.0, sum = 0.0, worst = 0.0;
                long hits = 0;
                for (const auto& pixel : stats) {
                    stepsAll += pixel.steps;
                    if (pixel.t < 0.0f) continue;
                    ++hits;
                    stepsHits += pixel.steps;
                    sum += pixel.residual;
                    worst = std::max(worst, double(pixel.residual));
                }
                double ms = median3(times[0], times[1], times[2]);
                double mean = hits ? sum / double(hits) : 0.0;
                std::printf("| %s | %s | %.2g | %.1f | %.2e | %.2e | %.1f |\n", field.name, method.name, epsilonScale,
                            hits ? stepsHits / double(hits) : 0.0, mean, worst, ms);
                if (csv)
                    std::fprintf(csv, "%s,%s,%g,%g,%g,%g,%g,%g,%ld\n", field.name, method.name, epsilonScale, hits ? stepsHits / double(hits) : 0.0,
                                 stepsAll / double(stats.size()), mean, worst, ms, hits);
                sdfRenderer.releaseGl();
            }
        }
    }
    std::printf("\n");
}

} // namespace

int main(int argc, char** argv) {
    bool dataset = true, error = true;
    std::FILE* csv = nullptr;
    for (int i = 1; i < argc; ++i) {
        if (!std::strcmp(argv[i], "--dataset-only")) error = false;
        else if (!std::strcmp(argv[i], "--error-only")) dataset = false;
        else if (!std::strcmp(argv[i], "--csv") && i + 1 < argc) csv = std::fopen(argv[++i], "w");
    }
    auto context = renderer::HeadlessContext::create();
    if (!context) {
        std::fprintf(stderr, "bench_tracer: %s\n", context.error().message.c_str());
        return 3;
    }
    std::printf("GL: %s\n\n", renderer::describe(context.value()->info()).c_str());
    if (dataset) datasetReport();
    if (error) errorReport(csv);
    if (csv) std::fclose(csv);
    return 0;
}
