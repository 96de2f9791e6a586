// render and animate: one frame request, traced offscreen, written as an image or an MP4.
#include <jobs/Jobs.h>

#include <core/Log.h>
#include <core/TextFile.h>
#include <dataset/Metadata.h>
#include <renderer/FrameScaler.h>
#include <renderer/GlInfo.h>
#include <renderer/ImageIO.h>
#include <renderer/OffscreenRenderer.h>
#include <renderer/SdfRenderer.h>
#include <renderer/ShadertoyPicture.h>
#include <renderer/VideoWriter.h>

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include <chrono>
#include <cmath>
#include <cstdio>

namespace sdfwb::jobs {
namespace {

using Clock = std::chrono::steady_clock;
double secondsSince(Clock::time_point start) { return std::chrono::duration<double>(Clock::now() - start).count(); }

// Warnings about a view that cannot show what the user expects (logged and reported).
std::vector<std::string> viewWarnings(const values::FrameRequest& frame) {
    std::vector<std::string> warnings;
    char text[256];
    if (auto floor = values::precisionFloor(frame.camera, frame.trace.epsilonScale, frame.height); floor.exceeded) {
        std::snprintf(
            text, sizeof text,
            "below float32 precision: positions are known to %.2g at this camera distance, the hit tolerance is %.2g (expect "
            "surface noise; bring the camera nearer the origin or widen --fov)",
            double(floor.positionFloor), double(floor.hitTolerance));
        warnings.push_back(text);
    }
    if (const float distance = glm::length(frame.camera.position); distance - 1.05f * std::sqrt(3.0f) > frame.camera.farPlane) {
        std::snprintf(
            text, sizeof text,
            "the camera is %.4g from the origin, beyond the far plane (%.4g): the [-1,1]^3 box is out of view, nothing will "
            "be drawn",
            double(distance), double(frame.camera.farPlane));
        warnings.push_back(text);
    }
    for (const std::string& warning : warnings) log::warning("render", warning);
    return warnings;
}

// A frame's report header: the SDF's, with the view's warnings first.
void describe(values::SdfHeader& report, const OpenedSdf& sdf, const values::FrameRequest& frame) {
    sdf.describe(report);
    const std::vector<std::string> view = viewWarnings(frame);
    report.warnings.insert(report.warnings.begin(), view.begin(), view.end());
}

// The values a fraction t of the way from `from` to `to` (same parameters, same order): floats and
// vectors linearly, ints rounded, bools switching halfway.
std::vector<shaders::ParameterSetting> interpolateParameters(const std::vector<shaders::ParameterSetting>& from,
                                                             const std::vector<shaders::ParameterSetting>& to, float t) {
    std::vector<shaders::ParameterSetting> out = from;
    for (std::size_t i = 0; i < out.size() && i < to.size(); ++i)
        for (std::size_t k = 0; k < 4; ++k) {
            const float a = from[i].value[k], b = to[i].value[k];
            float v = a + t * (b - a);
            if (out[i].type == shaders::ParameterType::Int) v = std::round(v);
            if (out[i].type == shaders::ParameterType::Bool) v = t < 0.5f ? a : b;
            out[i].value[k] = v;
        }
    return out;
}

// The overlay's text: the metadata block's name, author and license (the file's name without one).
std::string overlayText(const values::FrameRequest& frame, const OpenedSdf& sdf, std::vector<std::string>& warnings) {
    Expected<std::string> text = frame.sdf.source.empty() ? readTextFile(sdf.label) : Expected<std::string>(frame.sdf.source);
    if (text)
        if (auto metadata = dataset::parseMetadata(*text, sdf.label)) return dataset::overlayText(*metadata);
    warnings.push_back("--overlay: " + sdf.label + " has no metadata block; the overlay shows its file name");
    log::warning("render", warnings.back());
    const std::size_t slash = sdf.label.find_last_of('/');
    return slash == std::string::npos ? sdf.label : sdf.label.substr(slash + 1);
}

// Draws the overlay onto a frame (a float or an 8-bit image); a missing font is a warning.
template <class Frame> void drawOverlay(Frame& image, const std::string& text, std::vector<std::string>& warnings) {
    if (auto drawn = renderer::drawLabel(image, text); !drawn) {
        warnings.push_back(drawn.error().message);
        log::warning("render", drawn.error().message);
    }
}

// The tracer set up with the frame's settings and SDF; errors carry the driver's diagnostics.
std::optional<JobError> setUp(renderer::SdfRenderer& tracer, const values::FrameRequest& frame, const OpenedSdf& sdf,
                              const std::string& what) {
    (void)tracer.setTrace(frame.trace);
    (void)tracer.setShading(frame.shading);
    (void)tracer.setPlane(frame.plane);
    tracer.setParameters(sdf.parameters);
    auto diagnostics = tracer.setSdf(sdf.prepared);
    if (!shaders::hasErrors(diagnostics)) return std::nullopt;
    return JobError{Failure::Work, what + ": the driver rejected " + sdf.label + "; nothing written", diagnostics, {}};
}

} // namespace

JobResult<values::RenderReport> run(const values::RenderRequest& request, const ProgressSink&) {
    const auto start = Clock::now();
    if (auto error = validate(request)) return *error;
    auto sdf = openSdf(request.frame.sdf, "render");
    if (!sdf) return sdf.error;
    values::RenderReport report;
    describe(report, *sdf, request.frame);
    const values::FrameRequest& frame = request.frame;
    if (request.shadertoyPicture) {
        // The author's picture: one 8-bit frame from the file's mainImage.
        renderer::ShadertoyPicture picture;
        picture.setParameters(sdf->parameters);
        auto diagnostics = picture.setSdf(sdf->prepared);
        if (shaders::hasErrors(diagnostics))
            return JobError{
                Failure::Work, "render: " + sdf->label + " has no Shadertoy picture to draw; nothing written", diagnostics, {}};
        const auto drawStart = Clock::now();
        renderer::ShadertoyInputs inputs;
        inputs.time = frame.time;
        renderer::Image image = [&] {
            renderer::OffscreenRenderer offscreen;
            return offscreen.renderPicture(picture, frame.width, frame.height, inputs);
        }();
        report.frameMilliseconds = secondsSince(drawStart) * 1e3;
        picture.releaseGl();
        image.metadata = sdf->fileMetadata();
        if (auto written = renderer::writeImage(request.output, image); !written) return workError(written.error().keyed());
        report.output = request.output;
        report.entry = "mainImage";
        report.width = frame.width;
        report.height = frame.height;
        report.shading = "shadertoy picture";
        report.glRenderer = renderer::queryGlInfo().renderer;
        report.seconds = secondsSince(start);
        return report;
    }
    renderer::SdfRenderer tracer;
    if (auto error = setUp(tracer, request.frame, *sdf, "render")) return *error;
    renderer::FrameStats stats;
    const std::string label = frame.overlay ? overlayText(frame, *sdf, report.warnings) : std::string();
    // High-dynamic-range files get the float frame (highlights and backgrounds above 1 kept).
    // One frame (8-bit or float), labelled and written.
    auto renderAndWrite = [&](auto draw) {
        auto image = [&] {
            renderer::OffscreenRenderer offscreen;
            return draw(offscreen);
        }();
        tracer.releaseGl();
        if (!label.empty()) drawOverlay(image, label, report.warnings);
        image.metadata = sdf->fileMetadata();
        return renderer::writeImage(request.output, image);
    };
    const Expected<void> written =
        renderer::isHighDynamicRange(request.output)
            ? renderAndWrite([&](renderer::OffscreenRenderer& o) {
                  return o.renderFloat(tracer, frame.width, frame.height, frame.camera, frame.time, &stats);
              })
            : renderAndWrite([&](renderer::OffscreenRenderer& o) {
                  return o.render(tracer, frame.width, frame.height, frame.camera, frame.time, &stats);
              });
    if (!written) return workError(written.error().keyed());
    report.output = request.output;
    report.width = request.frame.width;
    report.height = request.frame.height;
    report.shading = shaders::shadingModeName(request.frame.shading.mode);
    report.frameMilliseconds = stats.cpuMilliseconds;
    report.glRenderer = renderer::queryGlInfo().renderer;
    report.seconds = secondsSince(start);
    return report;
}

namespace {

// The recorder's event kind as the job model's (values/Requests.h, which names them).
values::MarchEvent marchEvent(renderer::OffscreenRenderer::ProbeEvent::Kind kind) {
    using Event = renderer::OffscreenRenderer::ProbeEvent;
    switch (kind) {
    case Event::Step:
        return values::MarchEvent::Step;
    case Event::RelaxedStep:
        return values::MarchEvent::RelaxedStep;
    case Event::Fallback:
        return values::MarchEvent::Fallback;
    case Event::Hit:
        return values::MarchEvent::Hit;
    case Event::RefineKept:
        return values::MarchEvent::Refine;
    case Event::RefineUndone:
        return values::MarchEvent::RefineUndone;
    case Event::LeftBox:
        return values::MarchEvent::LeftBox;
    case Event::NotFinite:
        return values::MarchEvent::NotFinite;
    case Event::OutOfSteps:
        return values::MarchEvent::OutOfSteps;
    case Event::MissedBox:
        return values::MarchEvent::MissedBox;
    }
    return values::MarchEvent::NotFinite;
}

// The march's events with what follows from them: f, the step each one led to, oversteps.
void describeMarch(values::ProbeReport& report, const renderer::OffscreenRenderer::ProbeTrace& trace, float stepFactor) {
    using Event = renderer::OffscreenRenderer::ProbeEvent;
    const auto& events = trace.events;
    auto evaluates = [](Event::Kind kind) {
        return kind == Event::Step || kind == Event::RelaxedStep || kind == Event::Fallback || kind == Event::Hit ||
               kind == Event::NotFinite;
    };
    for (std::size_t k = 0; k < events.size(); ++k) {
        const Event& e = events[k];
        values::ProbeStep step;
        step.event = marchEvent(e.kind);
        step.t = e.t;
        step.position = e.position;
        step.f = e.d / stepFactor;
        step.gradientLength = e.gradientLength;
        if (e.kind == Event::Step || e.kind == Event::RelaxedStep || e.kind == Event::Fallback) {
            for (std::size_t next = k + 1; next < events.size(); ++next)
                if (evaluates(events[next].kind) || events[next].kind == Event::LeftBox ||
                    events[next].kind == Event::OutOfSteps) {
                    step.step = events[next].t - e.t;
                    // Passed the surface: positive here, negative at the next evaluation (a hit
                    // within the tolerance is the march ending as it should, not an overstep).
                    step.overstep =
                        e.d > 0.0f && evaluates(events[next].kind) && events[next].kind != Event::Hit && events[next].d < 0.0f;
                    break;
                }
        }
        if (step.overstep) ++report.oversteps;
        if (e.kind == Event::Fallback) ++report.fallbacks;
        report.events.push_back(step);
    }
}

} // namespace

JobResult<values::ProbeReport> run(const values::ProbeRequest& request, const ProgressSink&) {
    const auto start = Clock::now();
    if (auto error = validate(request)) return *error;
    auto sdf = openSdf(request.frame.sdf, "probe");
    if (!sdf) return sdf.error;
    values::FrameRequest frame = request.frame;
    frame.shading.statsOutput = true; // the pixel's steps and t, from the same draw
    frame.shading.probe = true;
    renderer::SdfRenderer tracer;
    if (auto error = setUp(tracer, frame, *sdf, "probe")) return *error;
    renderer::OffscreenRenderer::ProbeTrace trace;
    {
        renderer::OffscreenRenderer offscreen;
        trace = offscreen.probe(tracer, frame.width, frame.height, frame.camera, frame.time, request.x, request.y);
    }
    tracer.releaseGl();
    values::ProbeReport report;
    describe(report, *sdf, frame);
    report.width = frame.width;
    report.height = frame.height;
    report.x = request.x;
    report.y = request.y;
    report.origin = frame.camera.position;
    report.direction = glm::vec3(values::primaryRayDirection(frame.camera, request.x, request.y, frame.width, frame.height));
    report.steps = int(trace.pixel.steps);
    report.maxSteps = frame.trace.maxSteps;
    report.stepFactor = frame.trace.stepFactor;
    report.overRelaxation = frame.trace.overRelaxation;
    report.dropped = trace.dropped;
    report.parameters = shaders::valuesOf(sdf->parameters);
    describeMarch(report, trace, frame.trace.stepFactor);
    const float pixelAngle = 2.0f * std::tan(glm::radians(frame.camera.fovYDegrees) * 0.5f) / float(frame.height);
    const float lastT = report.events.empty() ? 0.0f : report.events.back().t;
    char text[320];
    using Stats = renderer::OffscreenRenderer::PixelStats;
    if (trace.pixel.hit()) {
        report.outcome = values::MarchEvent::Hit;
        report.hitT = trace.pixel.t;
        report.hitResidual = trace.pixel.residual;
        report.footprint = frame.trace.epsilonScale * pixelAngle * trace.pixel.t;
        std::snprintf(text, sizeof text,
                      "hit at t = %.6g after %d steps: |f| = %.3g at the refined hit (the tolerance there is %.3g)",
                      double(trace.pixel.t), report.steps, double(trace.pixel.residual), double(report.footprint));
    } else {
        report.footprint = frame.trace.epsilonScale * pixelAngle * lastT;
        float closest = INFINITY, closestT = 0.0f;
        for (const values::ProbeStep& e : report.events)
            if (std::isfinite(e.f) && std::abs(e.f) < closest && e.event != values::MarchEvent::LeftBox &&
                e.event != values::MarchEvent::OutOfSteps) {
                closest = std::abs(e.f);
                closestT = e.t;
            }
        if (!report.events.empty() && report.events.back().event == values::MarchEvent::MissedBox) {
            report.outcome = values::MarchEvent::MissedBox;
            std::snprintf(text, sizeof text, "the ray does not enter the box [-%g, %g]^3 that bounds the shape: nothing to march",
                          double(1.0f + frame.trace.boxMargin), double(1.0f + frame.trace.boxMargin));
        } else if (trace.pixel.t == Stats::kLeftBox) {
            report.outcome = values::MarchEvent::LeftBox;
            std::snprintf(
                text, sizeof text,
                "the ray left the box after %d steps without |f| falling below the tolerance (nearest: |f| = %.3g at t = %.4g)",
                report.steps, double(closest), double(closestT));
        } else if (trace.pixel.t == Stats::kOutOfSteps) {
            report.outcome = values::MarchEvent::OutOfSteps;
            const float lastF = report.events.size() > 1 ? report.events[report.events.size() - 2].f : 0.0f;
            std::snprintf(text, sizeof text,
                          "the step budget of %d ran out at t = %.4g with |f| = %.3g still above the tolerance %.3g (raise "
                          "--max-steps; small steps that do not shrink mean a flat or grazing field)",
                          report.maxSteps, double(lastT), double(std::abs(lastF)), double(report.footprint));
        } else {
            report.outcome = values::MarchEvent::NotFinite;
            const glm::vec3 p = report.events.empty() ? glm::vec3(0.0f) : report.events.back().position;
            std::snprintf(text, sizeof text, "f was NaN or Inf at t = %.4g, position (%.4g, %.4g, %.4g)", double(lastT),
                          double(p.x), double(p.y), double(p.z));
        }
    }
    report.reason = text;
    report.seconds = secondsSince(start);
    return report;
}

JobResult<values::AnimateReport> run(const values::AnimateRequest& request, const ProgressSink& progress) {
    const auto start = Clock::now();
    if (auto error = validate(request)) return *error;
    auto sdf = openSdf(request.frame.sdf, "animate");
    if (!sdf) return sdf.error;
    values::AnimateReport report;
    describe(report, *sdf, request.frame);
    std::vector<shaders::ParameterValue> endValues = request.frame.sdf.params;
    for (const shaders::ParameterValue& value : request.paramsEnd) {
        std::erase_if(endValues, [&](const shaders::ParameterValue& v) { return v.name == value.name; });
        endValues.push_back(value);
    }
    auto end = shaders::resolveParameters(sdf->prepared.parameters, endValues);
    if (!end) return usageError(key("params_end") + ": " + sdf->label + ": " + end.error().message);
    report.warnings.insert(report.warnings.end(), end->warnings.begin(), end->warnings.end());
    const bool keyframed = !request.paramsEnd.empty();
    if (!request.turntable && !sdf->prepared.usesTime() && !keyframed) {
        report.warnings.push_back(sdf->label + " is not animated and --turntable is off: every frame is the same");
        log::warning("animate", report.warnings.back());
    }
    renderer::SdfRenderer tracer;
    if (auto error = setUp(tracer, request.frame, *sdf, "animate")) return *error;
    const values::FrameRequest& frame = request.frame;
    auto writer =
        renderer::VideoWriter::open(request.output, frame.width, frame.height, request.framesPerSecond, sdf->fileMetadata());
    if (!writer) return workError(writer.error().keyed());

    const int frames = std::max(1, int(std::lround(double(request.seconds) * request.framesPerSecond)));
    const std::string label = frame.overlay ? overlayText(frame, *sdf, report.warnings) : std::string();
    {
        renderer::OffscreenRenderer offscreen;
        std::vector<std::string> ignoredWarnings; // the first frame's are reported
        for (int i = 0; i < frames; ++i) {
            if (progress.isCancelled()) break;
            values::Camera camera = frame.camera;
            if (request.turntable) values::orbit(camera, float(2.0 * 3.14159265358979 * i / frames), 0.0f);
            const float time = frame.time + float(i) / float(request.framesPerSecond);
            if (keyframed)
                tracer.setParameters(
                    interpolateParameters(sdf->parameters, end->settings, frames > 1 ? float(i) / float(frames - 1) : 0.0f));
            renderer::FrameStats stats;
            renderer::Image image = offscreen.render(tracer, frame.width, frame.height, camera, time, &stats);
            if (!label.empty()) drawOverlay(image, label, i == 0 ? report.warnings : ignoredWarnings);
            report.renderSeconds += stats.cpuMilliseconds / 1000.0;
            // The viewport's choices at rest, from frame times (the first includes code generation).
            // A changed program generates its code on a tiny frame, so the next frame's time is fair.
            if (i > 0 && tracer.settleMarch(stats.cpuMilliseconds)) {
                renderer::FrameStats warm;
                (void)offscreen.render(tracer, frame.width, frame.height, camera, time, &warm,
                                       renderer::FrameScaler::kTimingScale);
                report.renderSeconds += warm.cpuMilliseconds / 1000.0;
            }
            if (auto ok = (*writer)->addFrame(image); !ok) return workError(ok.error().keyed());
            progress(std::uint64_t(i + 1), std::uint64_t(frames));
        }
    }
    tracer.releaseGl();
    if (progress.isCancelled()) return JobError{Failure::Cancelled, "animate: cancelled; nothing written", {}, {}};
    if (auto ok = (*writer)->finish(); !ok) return workError(ok.error().keyed());
    report.output = request.output;
    report.frames = frames;
    report.framesPerSecond = request.framesPerSecond;
    report.width = frame.width & ~1;
    report.height = frame.height & ~1;
    report.seconds = secondsSince(start);
    return report;
}

} // namespace sdfwb::jobs
