// Sphere tracer benchmark: every dataset SDF at 1280x720 (Gooch shading): time to the
// full-resolution frame, the frame time while moving (at the scale the viewport picks for a 33 ms
// budget), steps per pixel, and, measured in the same run on the same context, the frame time of
// a minimal reference tracer doing the same work: textbook sphere tracing in the same [-1,1]^3 box
// with the same step budget and hit tolerance, a 4-tap normal and the same Gooch formula, drawn
// the same way (the box's far faces as geometry over a cleared background, so both trace the same
// pixels); none of our refinement, retaken normal taps, miss reasons or feature switches. Timings
// are medians of 3 frames after a warm-up frame (shader JIT excluded), draw to glFinish for both.
// Ours settles its program choices first (the fused or separate march, the cone pass, the compute
// tracer: what the viewport does at rest) and its full frame is then measured afresh, so the figure is not the
// timing that won a comparison. Error against run time (hit error, samplers, gradients, audit) is
// `sdfwb --batch bench` (jobs/src/Benchmarks.cpp).
//
//   build/bench/bench_tracer [NAME ...]     (dataset names; default: every SDF)
//   build/bench/bench_tracer --mesh FILE... (meshes as SDFs, normalised to the unit cube as the
//                                            workbench opens them: the walk against the march)
//   SDFWB_CONES=on|off forces the cone pass (default auto: tried at rest, as in the viewport).

#include <core/Paths.h>
#include <dataset/Catalogue.h>
#include <meshfield/MeshField.h>
#include <renderer/GlInfo.h>
#include <renderer/HeadlessContext.h>
#include <renderer/ImageIO.h>
#include <renderer/OffscreenRenderer.h>
#include <renderer/SdfRenderer.h>
#include <shaders/SdfSource.h>
#include <shaders/ShaderComposer.h>

#include <epoxy/gl.h>

#include <glm/ext/matrix_clip_space.hpp>
#include <glm/ext/matrix_transform.hpp>
#include <glm/trigonometric.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <string>
#include <vector>

using namespace sdfwb;

namespace {

double median3(double a, double b, double c) { return std::max(std::min(a, b), std::min(std::max(a, b), c)); }

// Median frame time over 3 frames, after one warm-up frame.
double frameMilliseconds(renderer::OffscreenRenderer& offscreen, renderer::SdfRenderer& sdfRenderer, int width, int height,
                         float scale) {
    renderer::FrameStats stats;
    offscreen.render(sdfRenderer, width, height, values::Camera{}, 0.0f, &stats, scale);
    double t[3];
    for (double& value : t) {
        offscreen.render(sdfRenderer, width, height, values::Camera{}, 0.0f, &stats, scale);
        value = stats.cpuMilliseconds;
    }
    return median3(t[0], t[1], t[2]);
}

using renderer::softwareRasteriser; // the GL on the CPU: its timer queries miss the deferred rasterisation

// The frame's GPU time (a GL_TIME_ELAPSED query around its draws): the median over 50 frames, or
// over the frames that fit in 3 s when they are slower (llvmpipe: at least 5). -1 without timer.
struct GpuFrames {
    double milliseconds = -1.0;
    int frames = 0;
};
GpuFrames gpuFrameMilliseconds(renderer::OffscreenRenderer& offscreen, renderer::SdfRenderer& sdfRenderer, int width,
                               int height) {
    std::vector<double> times;
    const auto start = std::chrono::steady_clock::now();
    while (times.size() < 50 &&
           (times.size() < 5 || std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() < 3.0)) {
        renderer::FrameStats stats;
        offscreen.render(sdfRenderer, width, height, values::Camera{}, 0.0f, &stats, 1.0f);
        if (stats.gpuMilliseconds < 0.0) return {};
        times.push_back(stats.gpuMilliseconds);
    }
    std::sort(times.begin(), times.end());
    return {times[times.size() / 2], int(times.size())};
}

// The reference: the textbook loop, nothing else.
const char* const kReferenceMain = R"(
out vec4 ref_color;
uniform vec2 ref_resolution;
uniform vec3 ref_origin, ref_right, ref_up, ref_forward;
uniform float ref_tanHalfFov;
void main() {
    vec2 ndc = gl_FragCoord.xy / ref_resolution * 2.0 - 1.0;
    vec3 d = normalize(ref_forward + ndc.x * (ref_resolution.x / ref_resolution.y) * ref_tanHalfFov * ref_right + ndc.y * ref_tanHalfFov * ref_up);
    vec3 inv = 1.0 / d;
    vec3 t0 = (vec3(-1.05) - ref_origin) * inv, t1 = (vec3(1.05) - ref_origin) * inv;
    vec3 lo = min(t0, t1), hi = max(t0, t1);
    float t = max(max(max(lo.x, lo.y), lo.z), 0.01), tEnd = min(min(min(hi.x, hi.y), hi.z), 100.0);
    float footprint = 0.5 * 2.0 * ref_tanHalfFov / ref_resolution.y;
    bool hit = false;
    for (int i = 0; i < 256 && t <= tEnd; ++i) {
        float f = sdfwb_sdf(ref_origin + t * d);
        if (abs(f) < footprint * t) { hit = true; break; }
        t += f;
    }
    if (!hit) { ref_color = vec4(0.16, 0.17, 0.19, 1.0); return; }
    vec3 p = ref_origin + t * d;
    float h = footprint * t;
    const vec2 k = vec2(1.0, -1.0);
    vec3 n = normalize(k.xyy * sdfwb_sdf(p + k.xyy * h) + k.yyx * sdfwb_sdf(p + k.yyx * h) + k.yxy * sdfwb_sdf(p + k.yxy * h) + k.xxx * sdfwb_sdf(p + k.xxx * h));
    vec3 light = normalize(vec3(-0.05, 0.87, 0.49));
    vec3 color = mix(vec3(0.12, 0.22, 0.48) + 0.124, vec3(0.85, 0.55, 0.25) + 0.186, 0.5 + 0.5 * dot(n, light));
    color += 0.25 * pow(max(dot(n, normalize(light - d)), 0.0), 40.0) + 0.15 * pow(1.0 - max(dot(n, -d), 0.0), 3.0);
    ref_color = vec4(clamp(color, 0.0, 1.0), 1.0);
}
)";

GLuint compileStage(GLenum type, const std::string& text) {
    GLuint shader = glCreateShader(type);
    const char* source = text.c_str();
    glShaderSource(shader, 1, &source, nullptr);
    glCompileShader(shader);
    GLint ok = 0;
    glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
    if (!ok) {
        glDeleteShader(shader);
        return 0;
    }
    return shader;
}

// Frame time of the reference tracer at width x height (median of 3 after a warm-up), or < 0
// when it does not compile.
double referenceMilliseconds(const shaders::PreparedSdf& sdf, const std::string& name, int width, int height) {
    // The same proxy geometry as ours (tracer/trace.vert with its box switched on).
    auto vertex = shaders::composeBuiltinShader(shaders::Stage::Vertex, "tracer/trace.vert", {});
    auto fragment = shaders::composeSdfShader(sdf, shaders::Stage::Fragment, {{"bench:reference", kReferenceMain}}, {});
    if (!vertex) return -1.0;
    GLuint vs = compileStage(GL_VERTEX_SHADER, vertex->text), fs = compileStage(GL_FRAGMENT_SHADER, fragment.text);
    GLuint program = glCreateProgram();
    if (vs && fs) {
        glAttachShader(program, vs);
        glAttachShader(program, fs);
        glLinkProgram(program);
    }
    GLint linked = 0;
    glGetProgramiv(program, GL_LINK_STATUS, &linked);
    glDeleteShader(vs);
    glDeleteShader(fs);
    if (!linked) {
        glDeleteProgram(program);
        return -1.0;
    }
    GLuint texture = 0, framebuffer = 0, vertexArray = 0;
    glGenTextures(1, &texture);
    glBindTexture(GL_TEXTURE_2D, texture);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, width, height, 0, GL_RGBA, GL_UNSIGNED_BYTE, nullptr);
    glGenFramebuffers(1, &framebuffer);
    glBindFramebuffer(GL_FRAMEBUFFER, framebuffer);
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, texture, 0);
    glGenVertexArrays(1, &vertexArray);
    const values::Camera camera;
    const values::CameraBasis basis = values::cameraBasis(camera);
    // World to clip space of the camera (a textbook perspective; the box lies beyond its near plane).
    const glm::mat4 clip =
        glm::perspective(glm::radians(camera.fovYDegrees), float(width) / float(height), camera.nearPlane, camera.farPlane) *
        glm::lookAt(camera.position, camera.target, camera.up);
    auto frame = [&] {
        const auto start = std::chrono::steady_clock::now();
        glViewport(0, 0, width, height);
        glClearColor(0.16f, 0.17f, 0.19f, 1.0f);
        glClear(GL_COLOR_BUFFER_BIT);
        glUseProgram(program);
        glUniform1i(glGetUniformLocation(program, "sdfwb_proxyBox"), 1);
        glUniformMatrix4fv(glGetUniformLocation(program, "sdfwb_proxyClip"), 1, GL_FALSE, &clip[0][0]);
        glUniform1f(glGetUniformLocation(program, "sdfwb_proxyHalf"), 1.05f * 1.001f);
        glUniform2f(glGetUniformLocation(program, "ref_resolution"), float(width), float(height));
        glUniform3f(glGetUniformLocation(program, "ref_origin"), camera.position.x, camera.position.y, camera.position.z);
        glUniform3f(glGetUniformLocation(program, "ref_right"), basis.right.x, basis.right.y, basis.right.z);
        glUniform3f(glGetUniformLocation(program, "ref_up"), basis.up.x, basis.up.y, basis.up.z);
        glUniform3f(glGetUniformLocation(program, "ref_forward"), basis.forward.x, basis.forward.y, basis.forward.z);
        glUniform1f(glGetUniformLocation(program, "ref_tanHalfFov"), std::tan(camera.fovYDegrees * 3.14159265f / 360.0f));
        glBindVertexArray(vertexArray);
        glEnable(GL_CULL_FACE);
        glCullFace(GL_FRONT);
        glFrontFace(GL_CCW);
        glDrawArrays(GL_TRIANGLES, 0, 36);
        glDisable(GL_CULL_FACE);
        glCullFace(GL_BACK);
        glFinish();
        return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    };
    frame();
    const double a = frame(), b = frame(), c = frame();
    // SDFWB_REFERENCE_IMAGES=FOLDER writes what the reference drew, to look at.
    if (const char* folder = std::getenv("SDFWB_REFERENCE_IMAGES")) {
        renderer::Image image{width, height, std::vector<std::uint8_t>(std::size_t(width) * height * 4), {}};
        glReadPixels(0, 0, width, height, GL_RGBA, GL_UNSIGNED_BYTE, image.rgba.data());
        for (int y = 0; y < height / 2; ++y) // GL rows run bottom up
            std::swap_ranges(image.rgba.begin() + std::ptrdiff_t(y) * width * 4,
                             image.rgba.begin() + std::ptrdiff_t(y + 1) * width * 4,
                             image.rgba.begin() + std::ptrdiff_t(height - 1 - y) * width * 4);
        (void)renderer::writeImage(std::filesystem::path(folder) / (name + ".png"), image);
    }
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glDeleteVertexArrays(1, &vertexArray);
    glDeleteFramebuffers(1, &framebuffer);
    glDeleteTextures(1, &texture);
    glDeleteProgram(program);
    return median3(a, b, c);
}

// Size of the statistics frames (steps per pixel, hits).
constexpr int kStatsWidth = 320, kStatsHeight = 180;

double percentile(std::vector<double> values, double p) {
    if (values.empty()) return 0.0;
    std::sort(values.begin(), values.end());
    return values[std::min(values.size() - 1, std::size_t(p * double(values.size())))];
}

// One row of the cone table: times without and with the cone pass and the hits of both
// statistics frames (kStatsWidth x kStatsHeight, the default camera) compared pixel by pixel.
std::string compareCones(const std::string& name, double without, double with,
                         const std::vector<renderer::OffscreenRenderer::PixelStats>& plain,
                         const std::vector<renderer::OffscreenRenderer::PixelStats>& coned) {
    const double pixelAngle = 2.0 * std::tan(values::Camera{}.fovYDegrees * 3.14159265 / 360.0) / kStatsHeight;
    long changed = 0;
    double stepsPlain = 0.0, stepsConed = 0.0;
    std::vector<double> moved, residualPlain, residualConed;
    for (std::size_t i = 0; i < plain.size() && i < coned.size(); ++i) {
        stepsPlain += plain[i].steps;
        stepsConed += coned[i].steps;
        if (plain[i].hit() != coned[i].hit()) ++changed;
        if (plain[i].hit()) residualPlain.push_back(plain[i].residual / (pixelAngle * plain[i].t));
        if (coned[i].hit()) residualConed.push_back(coned[i].residual / (pixelAngle * coned[i].t));
        if (plain[i].hit() && coned[i].hit()) moved.push_back(std::abs(coned[i].t - plain[i].t) / (pixelAngle * plain[i].t));
    }
    const double n = double(std::max<std::size_t>(plain.size(), 1));
    char row[512];
    std::snprintf(row, sizeof row, "| %s | %.1f | %.1f | %.2f | %.1f / %.1f | %ld of %zu | %.3f / %.2f | %.3f / %.3f |",
                  name.c_str(), without, with, with / without, stepsPlain / n, stepsConed / n, changed, plain.size(),
                  percentile(moved, 0.5), moved.empty() ? 0.0 : percentile(moved, 1.0), percentile(residualPlain, 0.99),
                  percentile(residualConed, 0.99));
    return row;
}

// The settled program's full frame drawn by the fragment tracer and by the compute tracer (both
// forced): medians of 3 frames to glFinish, on a GPU the GPU time too, and, for accuracy, how
// many pixels of the two pictures differ. The renderer's tracer choice is reset afterwards.
std::string tracerComparison(renderer::OffscreenRenderer& offscreen, renderer::SdfRenderer& sdfRenderer) {
    values::TraceSettings trace = sdfRenderer.trace();
    const values::TraceSettings saved = trace;
    double cpu[2] = {0.0, 0.0}, gpu[2] = {-1.0, -1.0};
    renderer::Image pictures[2];
    const values::TraceSettings::Tracer tracers[2] = {values::TraceSettings::Tracer::Fragment,
                                                      values::TraceSettings::Tracer::Compute};
    for (int k = 0; k < 2; ++k) {
        trace.tracer = tracers[k];
        (void)sdfRenderer.setTrace(trace);
        pictures[k] = offscreen.render(sdfRenderer, 1280, 720, values::Camera{}, 0.0f);
        cpu[k] = frameMilliseconds(offscreen, sdfRenderer, 1280, 720, 1.0f);
        if (!softwareRasteriser()) gpu[k] = gpuFrameMilliseconds(offscreen, sdfRenderer, 1280, 720).milliseconds;
    }
    (void)sdfRenderer.setTrace(saved);
    // Pixels whose colour differs, and by how much at most (a channel's 0-255 step): a compiler's
    // rounding moves a channel by one or two, a different hit by far more.
    long differing = 0;
    int most = 0;
    for (std::size_t i = 0; i + 3 < pictures[0].rgba.size() && pictures[0].rgba.size() == pictures[1].rgba.size(); i += 4) {
        differing += !std::equal(&pictures[0].rgba[i], &pictures[0].rgba[i] + 3, &pictures[1].rgba[i]);
        for (int c = 0; c < 3; ++c) most = std::max(most, std::abs(int(pictures[0].rgba[i + c]) - int(pictures[1].rgba[i + c])));
    }
    char cell[192];
    if (gpu[0] >= 0.0 && gpu[1] >= 0.0)
        std::snprintf(cell, sizeof cell, "%.1f / %.1f (GPU %.3f / %.3f); %ld px differ, by at most %d", cpu[0], cpu[1], gpu[0],
                      gpu[1], differing, most);
    else
        std::snprintf(cell, sizeof cell, "%.1f / %.1f; %ld px differ, by at most %d", cpu[0], cpu[1], differing, most);
    return cell;
}

shaders::IncludeOptions includeOptions() {
    shaders::IncludeOptions options;
    options.libraryRoots = {paths::shaderLibraryRoot(), paths::datasetRoot()};
    return options;
}

void datasetReport(const std::vector<std::string>& names) {
    dataset::Catalogue catalogue = dataset::Catalogue::scan(paths::datasetRoot());
    std::printf("| SDF | full-resolution frame (ms) | GPU time a frame (ms; frames) | march | reference tracer (ms) | ours / "
                "reference | moving: scale | moving frame (ms) | steps/pixel (all) | steps/pixel (hits) | fragment / compute "
                "tracer (ms) |\n");
    std::printf("|---|---|---|---|---|---|---|---|---|---|---|\n");
    renderer::OffscreenRenderer offscreen;
    std::vector<double> ratios, movingFrames;
    std::vector<std::string> coneRows;
    for (const dataset::Entry& entry : catalogue.entries()) {
        if (!names.empty() && std::find(names.begin(), names.end(), entry.metadata.name) == names.end()) continue;
        renderer::SdfRenderer sdfRenderer;
        values::ShadingSettings shading;
        shading.mode = shaders::ShadingMode::Gooch;
        (void)sdfRenderer.setShading(shading);
        if (const char* forced = std::getenv("SDFWB_CONES"))
            if (auto cones = values::parseCones(forced)) {
                values::TraceSettings trace;
                trace.cones = *cones;
                (void)sdfRenderer.setTrace(trace);
            }
        const shaders::PreparedSdf prepared = shaders::prepareSdfFile(entry.path, includeOptions());
        auto diagnostics = sdfRenderer.setSdf(prepared);
        if (shaders::hasErrors(diagnostics)) {
            std::printf("| %s | does not compile | | | | | | | | | |\n", entry.metadata.name.c_str());
            continue;
        }
        double full = frameMilliseconds(offscreen, sdfRenderer, 1280, 720, 1.0f);
        // What the viewport shows at rest: a long SDF's fused march is traded for the separate
        // one when that draws its full frame faster, then the cone pass is tried the same way
        // (SdfRenderer::settleMarch).
        while (sdfRenderer.settleMarch(full)) full = frameMilliseconds(offscreen, sdfRenderer, 1280, 720, 1.0f);
        // Measured afresh with the settled program: the timing that won a comparison is biased low.
        full = frameMilliseconds(offscreen, sdfRenderer, 1280, 720, 1.0f);
        const bool fused = sdfRenderer.fusedMarch(), cones = sdfRenderer.conePass(), compute = sdfRenderer.computeTracer();
        const GpuFrames gpu = softwareRasteriser() ? GpuFrames{} : gpuFrameMilliseconds(offscreen, sdfRenderer, 1280, 720);
        const std::string gpuCell =
            gpu.frames > 0 ? std::to_string(gpu.milliseconds).substr(0, 6) + "; " + std::to_string(gpu.frames) : "-";
        const double reference = referenceMilliseconds(prepared, entry.metadata.name, 1280, 720);
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
        auto stats = offscreen.renderStats(sdfRenderer, kStatsWidth, kStatsHeight, values::Camera{}, 0.0f);
        if (cones) {
            // What the cone pass gained, and what it did to the hits: the same program without it.
            values::TraceSettings trace = sdfRenderer.trace();
            trace.cones = values::TraceSettings::Cones::Off;
            (void)sdfRenderer.setTrace(trace);
            auto plain = offscreen.renderStats(sdfRenderer, kStatsWidth, kStatsHeight, values::Camera{}, 0.0f);
            shading.statsOutput = false;
            (void)sdfRenderer.setShading(shading);
            coneRows.push_back(compareCones(entry.metadata.name, frameMilliseconds(offscreen, sdfRenderer, 1280, 720, 1.0f), full,
                                            plain, stats));
        }
        double steps = 0.0, hitSteps = 0.0;
        long hits = 0;
        for (const auto& pixel : stats) {
            steps += pixel.steps;
            if (pixel.t >= 0.0f) {
                hitSteps += pixel.steps;
                ++hits;
            }
        }
        if (reference > 0.0) ratios.push_back(full / reference);
        movingFrames.push_back(moving);
        shading.statsOutput = false;
        (void)sdfRenderer.setShading(shading);
        const std::string tracers = tracerComparison(offscreen, sdfRenderer);
        std::printf("| %s | %.1f | %s | %s%s%s | %.1f | %.2f | %.0f %% | %.1f | %.1f | %.1f | %s |\n",
                    entry.metadata.name.c_str(), full, gpuCell.c_str(), fused ? "fused" : "separate", cones ? " + cones" : "",
                    compute ? ", compute tracer" : "", reference, reference > 0.0 ? full / reference : 0.0, scale * 100.0f,
                    moving, steps / double(stats.size()), hits ? hitSteps / double(hits) : 0.0, tracers.c_str());
        std::fflush(stdout);
        sdfRenderer.releaseGl();
    }
    std::printf("\n");
    if (softwareRasteriser())
        std::printf("GPU time: \"-\" on this driver: llvmpipe's timer queries time the commands' recording, not the "
                    "rasterisation it defers to glFinish, so the frame's time is the CPU column's.\n\n");
    if (!coneRows.empty()) {
        std::printf("Where the cone pass was kept: the full-resolution frame without and with it, and what it did to the "
                    "hits (320x180 statistics frames of the same program): pixels whose ray hit in one and not in the "
                    "other, the hit distance's change where both hit, and |f| at the hits, in pixel footprints "
                    "(|f| / (pixel angle x t); the hit tolerance is 0.5).\n\n"
                    "| SDF | without (ms) | with (ms) | with / without | steps/pixel without / with | hit changed | "
                    "\\|t change\\| p50 / max (footprints) | \\|f\\| p99 without / with (footprints) |\n"
                    "|---|---|---|---|---|---|---|---|\n");
        for (const std::string& row : coneRows) std::printf("%s\n", row.c_str());
        std::printf("\n");
    }
    if (ratios.empty()) return;
    std::sort(ratios.begin(), ratios.end());
    std::sort(movingFrames.begin(), movingFrames.end());
    std::printf("Summary over %zu SDFs: full-resolution frame / reference tracer: median %.2f (range %.2f to %.2f); "
                "moving frames %.1f to %.1f ms (median %.1f).\n",
                ratios.size(), ratios[ratios.size() / 2], ratios.front(), ratios.back(), movingFrames.front(),
                movingFrames.back(), movingFrames[movingFrames.size() / 2]);
}

// Frames of a mesh's own field: the picture as the workbench draws it (one walk of the hierarchy
// a pixel, SdfRenderer's default) against the sphere tracer on the same field
// (SDFWB_MESH_TRACE=march), in the same run. Accuracy beside each time: pixels whose hit or miss
// differ and the angle between their normals (normals shading, read back from the picture) where
// both hit; the walk's normal is the face's, the march's the taps' across a pixel's footprint.
// Then the walk with the cutting plane shown and clipping, and with ambient occlusion.
void meshReport(const std::vector<std::string>& files) {
    std::printf(
        "| mesh | triangles | march 320x240 (ms) | walk 320x240 (ms) | walk / march | hit differs (pixels) | "
        "normal angle p50 / p99 (degrees) | walk 1280x720 (ms) | moving: scale, frame (ms) | + plane (ms) | plane field (ms) | "
        "+ AO (ms) |\n");
    std::printf("|---|---|---|---|---|---|---|---|---|---|---|---|\n");
    renderer::OffscreenRenderer offscreen;
    meshfield::MeshFieldOptions options;
    options.normalize = meshfield::Normalization::UnitCube;
    constexpr int kW = 320, kH = 240;
    constexpr double kGoalMilliseconds = 100.0; // issue 46: a mesh's frame at 320x240 on llvmpipe
    double worstWalk = 0.0, worstMarch = 0.0;
    std::string worstName;
    for (const std::string& file : files) {
        const shaders::PreparedSdf prepared = shaders::prepareMeshFile(file, options);
        if (shaders::hasErrors(prepared.diagnostics)) {
            std::printf("| %s | does not load: %s |\n", file.c_str(), prepared.diagnostics[0].message.c_str());
            continue;
        }
        double planeField = 0.0;
        float movingScale = 1.0f;
        double moving = 0.0;
        auto picture = [&](bool walk, values::ShadingSettings shading, const values::CuttingPlane& plane, int width, int height,
                           renderer::Image* image) {
            if (walk)
                unsetenv("SDFWB_MESH_TRACE");
            else
                setenv("SDFWB_MESH_TRACE", "march", 1);
            renderer::SdfRenderer sdfRenderer;
            (void)sdfRenderer.setShading(shading);
            (void)sdfRenderer.setPlane(plane);
            auto diagnostics = sdfRenderer.setSdf(prepared);
            double ms = -1.0;
            if (!shaders::hasErrors(diagnostics)) {
                ms = frameMilliseconds(offscreen, sdfRenderer, width, height, 1.0f);
                if (image) *image = offscreen.render(sdfRenderer, width, height, values::Camera{}, 0.0f);
                if (plane.enabled) planeField = sdfRenderer.planeFieldMilliseconds();
                if (walk && !plane.enabled && !shading.ambientOcclusion && width == 1280) {
                    // The viewport's rule while the camera moves (as datasetReport).
                    float scale = std::clamp(float(std::sqrt(0.8 * 33.0 / ms)), 0.1f, 1.0f);
                    for (int frame = 0; frame < 6; ++frame) {
                        movingScale = scale;
                        moving = frameMilliseconds(offscreen, sdfRenderer, width, height, scale);
                        scale = std::clamp(0.5f * (scale + scale * float(std::sqrt(0.8 * 33.0 / moving))), 0.1f, 1.0f);
                    }
                }
            }
            sdfRenderer.releaseGl();
            unsetenv("SDFWB_MESH_TRACE");
            return ms;
        };
        values::ShadingSettings normals;
        normals.mode = shaders::ShadingMode::Normals;
        renderer::Image walked, marched;
        const double march = picture(false, normals, {}, kW, kH, &marched);
        const double walk = picture(true, normals, {}, kW, kH, &walked);
        // The background is (0.16, 0.17, 0.19); a normal's colour is n * 0.5 + 0.5.
        auto background = [](const std::uint8_t* rgba) {
            return std::abs(rgba[0] - 41) <= 1 && std::abs(rgba[1] - 43) <= 1 && std::abs(rgba[2] - 48) <= 1;
        };
        long differ = 0;
        std::vector<double> angles;
        for (int y = 0; y < kH && !walked.rgba.empty() && !marched.rgba.empty(); ++y)
            for (int x = 0; x < kW; ++x) {
                const std::uint8_t *a = walked.pixel(x, y), *b = marched.pixel(x, y);
                if (background(a) != background(b)) {
                    ++differ;
                    continue;
                }
                if (background(a)) continue;
                glm::vec3 na = glm::vec3(a[0], a[1], a[2]) / 127.5f - 1.0f, nb = glm::vec3(b[0], b[1], b[2]) / 127.5f - 1.0f;
                if (glm::length(na) < 0.5f || glm::length(nb) < 0.5f) continue;
                angles.push_back(std::acos(std::clamp(double(glm::dot(glm::normalize(na), glm::normalize(nb))), -1.0, 1.0)) *
                                 180.0 / 3.14159265358979);
            }
        values::ShadingSettings gooch;
        gooch.mode = shaders::ShadingMode::Gooch;
        const double full = picture(true, gooch, {}, 1280, 720, nullptr);
        values::CuttingPlane plane;
        plane.enabled = true;
        plane.normal = {0.0f, 0.0f, 1.0f};
        const double withPlane = picture(true, gooch, plane, 1280, 720, nullptr);
        values::ShadingSettings occluded = gooch;
        occluded.ambientOcclusion = true;
        const double withAo = picture(true, occluded, {}, 1280, 720, nullptr);
        if (const char* folder = std::getenv("SDFWB_REFERENCE_IMAGES")) {
            const std::string stem = std::filesystem::path(file).stem().string();
            (void)renderer::writeImage(std::filesystem::path(folder) / (stem + "-walk.png"), walked);
            (void)renderer::writeImage(std::filesystem::path(folder) / (stem + "-march.png"), marched);
        }
        if (walk > worstWalk) worstWalk = walk, worstName = std::filesystem::path(file).filename().string();
        worstMarch = std::max(worstMarch, march);
        std::printf("| %s | %zu | %.1f | %.1f | %.3f | %ld of %d | %.2f / %.2f | %.1f | %.0f %%, %.1f | %.1f | %.0f | %.1f |\n",
                    std::filesystem::path(file).filename().string().c_str(),
                    prepared.mesh ? prepared.mesh->mesh.triangleCount() : std::size_t(0), march, walk, walk / march, differ,
                    kW * kH, percentile(angles, 0.5), percentile(angles, 0.99), full, movingScale * 100.0f, moving, withPlane,
                    planeField, withAo);
        std::fflush(stdout);
    }
    if (worstName.empty()) return;
    std::printf("\nGoal: at most %.0f ms a frame at 320x240 for every mesh. The walk's slowest: %.1f ms (%s): %s. "
                "The march's slowest: %.1f ms.\n",
                kGoalMilliseconds, worstWalk, worstName.c_str(), worstWalk <= kGoalMilliseconds ? "met" : "NOT met", worstMarch);
}

} // namespace

int main(int argc, char** argv) {
    auto context = renderer::HeadlessContext::create();
    if (!context) {
        std::fprintf(stderr, "bench_tracer: %s\n", context.error().message.c_str());
        return 3;
    }
    std::printf("GL: %s\n\n", renderer::describe(context.value()->info()).c_str());
    std::vector<std::string> arguments(argv + 1, argv + argc);
    if (!arguments.empty() && arguments.front() == "--mesh")
        meshReport(std::vector<std::string>(arguments.begin() + 1, arguments.end()));
    else
        datasetReport(arguments);
    return 0;
}
