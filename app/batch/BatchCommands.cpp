#include "BatchCommands.h"

#include <core/Log.h>
#include <core/Paths.h>
#include <dataset/Catalogue.h>
#include <renderer/HeadlessContext.h>
#include <renderer/ImageIO.h>
#include <renderer/OffscreenRenderer.h>
#include <renderer/SdfRenderer.h>
#include <shaders/SdfSource.h>

#include <renderer/SampleCompute.h>
#include <renderer/VideoWriter.h>
#include <sampling/FieldAudit.h>
#include <sampling/Sampler.h>
#include <sampling/SamplerLibrary.h>

#include <glm/geometric.hpp>
#include <nlohmann/json.hpp>

#include <atomic>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <iostream>
#include <unistd.h>

namespace sdfwb::app {
namespace fs = std::filesystem;

void printError(const std::string& message) { std::fprintf(stderr, "sdfwb: %s\n", message.c_str()); }

namespace {

shaders::IncludeOptions includeOptions() {
    shaders::IncludeOptions options;
    options.libraryRoots = {paths::shaderLibraryRoot(), paths::datasetRoot()};
    return options;
}

void printDiagnostics(const std::vector<shaders::Diagnostic>& diagnostics) {
    for (const shaders::Diagnostic& d : diagnostics) std::fprintf(stderr, "%s\n", shaders::formatDiagnostic(d).c_str());
}

// A one-line progress bar on a terminal's stderr, redrawn at most 10 times a second.
// The shared "open the SDF" step of every command that takes --sdf, in its two halves: first the
// name is resolved (a dataset name or a path; nothing found is a usage error, exit 2, before any
// work), then, after the command's own checks, the file is prepared with its entry point (errors
// are printed with their file and line; the caller exits 1).
std::optional<fs::path> resolveSdf(const std::string& argument) {
    dataset::Catalogue catalogue = dataset::Catalogue::scan(paths::datasetRoot());
    auto path = dataset::resolveSdfArgument(argument, catalogue);
    if (!path) {
        printError("--sdf: " + path.error().message);
        return std::nullopt;
    }
    return *path;
}

std::optional<shaders::PreparedSdf> openSdf(const fs::path& path, const std::string& entry, const std::string& failure) {
    shaders::PreparedSdf sdf = shaders::prepareSdfFile(path, includeOptions(), entry);
    if (sdf.ok()) return sdf;
    printDiagnostics(sdf.diagnostics);
    printError(failure);
    return std::nullopt;
}

class ProgressBar {
public:
    explicit ProgressBar(bool enabled) : m_enabled(enabled && ::isatty(STDERR_FILENO)) {}
    ~ProgressBar() { finish(); }

    void update(std::uint64_t done, std::uint64_t total) {
        if (!m_enabled || total == 0) return;
        auto now = std::chrono::steady_clock::now();
        if (done < total && now - m_lastDraw < std::chrono::milliseconds(100)) return;
        m_lastDraw = now;
        double seconds = std::chrono::duration<double>(now - m_start).count();
        double fraction = double(done) / double(total);
        int filled = int(fraction * 30.0);
        std::string bar(std::size_t(filled), '#');
        bar.append(std::size_t(30 - filled), ' ');
        double rate = seconds > 0.0 ? double(done) / seconds : 0.0;
        std::fprintf(stderr, "\r%5.1f%% [%s] %llu/%llu  %.2f M samples/s ", 100.0 * fraction, bar.c_str(),
                     (unsigned long long)done, (unsigned long long)total, rate / 1e6);
        m_drawn = true;
    }

    void finish() {
        if (m_drawn) std::fprintf(stderr, "\n");
        m_drawn = false;
    }

private:
    bool m_enabled;
    bool m_drawn = false;
    std::chrono::steady_clock::time_point m_start = std::chrono::steady_clock::now();
    std::chrono::steady_clock::time_point m_lastDraw{};
};

// Ctrl-C cancels the running job cleanly (the writer removes its temporary file).
std::atomic<CancelToken*> g_interruptToken{nullptr};

extern "C" void onInterrupt(int) {
    if (CancelToken* token = g_interruptToken.load()) token->cancel();
}

class InterruptScope {
public:
    explicit InterruptScope(CancelToken& token) {
        g_interruptToken.store(&token);
        m_previousInt = std::signal(SIGINT, onInterrupt);
        m_previousTerm = std::signal(SIGTERM, onInterrupt);
    }
    ~InterruptScope() {
        std::signal(SIGINT, m_previousInt);
        std::signal(SIGTERM, m_previousTerm);
        g_interruptToken.store(nullptr);
    }

private:
    void (*m_previousInt)(int);
    void (*m_previousTerm)(int);
};

} // namespace

int runRender(const RenderJob& job, const OutputOptions& output) {
    auto start = std::chrono::steady_clock::now();
    auto sdfPath = resolveSdf(job.sdf);
    if (!sdfPath) return kExitUsage;
    fs::path outputPath(job.output);
    if (!renderer::canWriteImageExtension(outputPath.extension().string())) {
        printError("--output: '" + job.output + "': unsupported image type '" + outputPath.extension().string() +
                   "' (use .png, .jpg or .exr)");
        return kExitUsage;
    }
    std::error_code ec;
    fs::path folder = outputPath.parent_path().empty() ? fs::path(".") : outputPath.parent_path();
    if (!fs::is_directory(folder, ec)) {
        printError("--output: '" + job.output + "': folder '" + folder.string() + "' does not exist");
        return kExitUsage;
    }

    auto opened = openSdf(*sdfPath, job.entry, "render: " + sdfPath->string() + " has errors; nothing written");
    if (!opened) return kExitFailure;
    const shaders::PreparedSdf& sdf = *opened;
    auto context = renderer::HeadlessContext::create();
    if (!context) {
        printError(context.error().message);
        return kExitNoGl;
    }
    if (auto floor = renderer::precisionFloor(job.camera, job.trace.epsilonScale, job.height); floor.exceeded) {
        char text[256];
        std::snprintf(
            text, sizeof text,
            "below float32 precision: positions are known to %.2g at this camera distance, the hit tolerance is %.2g (expect "
            "surface noise; bring the camera nearer the origin or widen --fov)",
            double(floor.positionFloor), double(floor.hitTolerance));
        log::warning("render", text);
    }
    if (const float distance = glm::length(job.camera.position); distance - 1.05f * std::sqrt(3.0f) > job.camera.farPlane) {
        char text[256];
        std::snprintf(text, sizeof text,
                      "the camera is %.4g from the origin, beyond the far plane (%.4g): the [-1,1]^3 box is out of view, nothing "
                      "will be drawn",
                      double(distance), double(job.camera.farPlane));
        log::warning("render", text);
    }

    renderer::SdfRenderer sdfRenderer;
    (void)sdfRenderer.setTrace(job.trace);
    (void)sdfRenderer.setShading(job.shading);
    (void)sdfRenderer.setPlane(job.plane);
    auto diagnostics = sdfRenderer.setSdf(sdf);
    if (shaders::hasErrors(diagnostics)) {
        printDiagnostics(diagnostics);
        printError("render: the driver rejected " + sdfPath->string() + "; nothing written");
        return kExitFailure;
    }
    renderer::FrameStats stats;
    renderer::Image image;
    {
        renderer::OffscreenRenderer offscreen;
        image = offscreen.render(sdfRenderer, job.width, job.height, job.camera, job.time, &stats);
    }
    sdfRenderer.releaseGl();
    if (auto written = renderer::writeImage(outputPath, image); !written) {
        printError(written.error().message);
        return kExitFailure;
    }
    double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (output.json) {
        nlohmann::json report = {{"output", outputPath.string()},
                                 {"sdf", sdfPath->string()},
                                 {"width", job.width},
                                 {"height", job.height},
                                 {"shading", renderer::shadingModeName(job.shading.mode)},
                                 {"frame_ms", stats.cpuMilliseconds},
                                 {"seconds", seconds},
                                 {"gl_renderer", context.value()->info().renderer}};
        std::cout << report.dump(2) << "\n";
    } else if (!output.quiet) {
        std::printf("wrote %s (%dx%d, %s shading, frame %.1f ms, total %.2f s)\n", outputPath.string().c_str(), job.width,
                    job.height, renderer::shadingModeName(job.shading.mode), stats.cpuMilliseconds, seconds);
    }
    return kExitOk;
}

int runList(const OutputOptions& output) {
    dataset::Catalogue catalogue = dataset::Catalogue::scan(paths::datasetRoot());
    for (const std::string& problem : catalogue.problems()) log::warning("dataset", problem);
    if (output.json) {
        nlohmann::json list = nlohmann::json::array();
        for (const dataset::Entry& entry : catalogue.entries())
            list.push_back({{"name", entry.metadata.name},
                            {"category", entry.metadata.category},
                            {"declared_type", dataset::declaredTypeName(entry.metadata.type)},
                            {"animated", entry.metadata.animated},
                            {"path", entry.path.string()},
                            {"author", entry.metadata.author},
                            {"license", entry.metadata.license},
                            {"notes", entry.metadata.notes}});
        std::cout << list.dump(2) << "\n";
    } else {
        for (const dataset::Entry& entry : catalogue.entries())
            std::printf("%-28s %-13s %-12s %s\n", entry.metadata.name.c_str(), entry.metadata.category.c_str(),
                        dataset::declaredTypeName(entry.metadata.type), entry.metadata.animated ? "animated" : "");
        if (!output.quiet) std::printf("%zu SDFs in %s\n", catalogue.entries().size(), paths::datasetRoot().string().c_str());
    }
    return catalogue.entries().empty() ? kExitFailure : kExitOk;
}

} // namespace sdfwb::app

namespace sdfwb::app {

int runSample(const SampleCommand& command, const OutputOptions& output) {
    auto sdfPath = resolveSdf(command.sdf);
    if (!sdfPath) return kExitUsage;
    auto sampler = sampling::findSampler(command.pattern, sampling::samplerFolders());
    if (!sampler) {
        printError("--pattern: " + sampler.error().message);
        return kExitUsage;
    }
    std::optional<sampling::SampleFormat> format =
        command.format.empty() ? sampling::formatFromPath(command.output) : sampling::parseFormat(command.format);
    if (!format) {
        if (command.format.empty())
            printError("--output: '" + command.output + "': unknown sample file type (use .bin, .npz or .ply, or --format)");
        else
            printError("--format: unknown format '" + command.format + "' (bin, npz, ply)");
        return kExitUsage;
    }
    sampling::SamplingJob job;
    job.count = command.count;
    job.seed = command.seed;
    job.time = command.time;
    job.shardIndex = command.shardIndex;
    job.shardCount = command.shardCount;
    job.chunkSize = command.chunkSize;
    job.gradientStep = command.gradientStep;
    job.surfaceTolerance = command.surfaceTolerance;
    if (auto ok = sampling::validate(job); !ok) {
        printError(ok.error().message);
        return kExitUsage;
    }
    if (job.rows() > sampling::maxRows(*format)) {
        printError("-n: " + std::to_string(job.rows()) + " rows exceed the ." + sampling::formatName(*format) + " limit of " +
                   std::to_string(sampling::maxRows(*format)));
        return kExitUsage;
    }
    std::error_code ec;
    std::filesystem::path outputPath(command.output);
    std::filesystem::path folder = outputPath.parent_path().empty() ? std::filesystem::path(".") : outputPath.parent_path();
    if (!std::filesystem::is_directory(folder, ec)) {
        printError("--output: '" + command.output + "': folder '" + folder.string() + "' does not exist");
        return kExitUsage;
    }

    auto opened = openSdf(*sdfPath, command.entry, "sample: " + sdfPath->string() + " has errors; nothing written");
    if (!opened) return kExitFailure;
    const shaders::PreparedSdf& sdf = *opened;
    auto context = renderer::HeadlessContext::create();
    if (!context) {
        printError(context.error().message);
        return kExitNoGl;
    }
    renderer::SampleCompute compute;
    auto diagnostics = compute.build(sdf, *sampler);
    if (shaders::hasErrors(diagnostics)) {
        printDiagnostics(diagnostics);
        printError("sample: " + sdfPath->string() + " with pattern '" + command.pattern + "' does not compile; nothing written");
        return kExitFailure;
    }

    sampling::SampleMetadata metadata;
    metadata.sdf = command.sdf;
    metadata.pattern = command.pattern;
    metadata.version = SDFWB_VERSION;
    CancelToken cancel;
    ProgressBar bar(!output.quiet && !output.json);
    ProgressSink progress{[&](std::uint64_t done, std::uint64_t total) {
                              bar.update(done, total);
                              if (output.progressLines)
                                  std::fprintf(stderr, "progress %llu %llu\n", (unsigned long long)done,
                                               (unsigned long long)total);
                          },
                          &cancel};
    Expected<sampling::SamplingReport> report = [&] {
        InterruptScope interrupts(cancel);
        return sampling::sampleToFile(compute, job, outputPath, *format, metadata, progress);
    }();
    bar.finish();
    compute.releaseGl();
    if (!report) {
        printError(report.error().message);
        return kExitFailure;
    }
    if (report->cancelled) {
        printError("sample: cancelled after " + std::to_string(report->rows) + " of " + std::to_string(job.rows()) +
                   " samples; nothing written");
        return kExitCancelled;
    }
    double rate = report->seconds > 0.0 ? double(report->rows) / report->seconds : 0.0;
    if (output.json) {
        nlohmann::json json = {{"output", outputPath.string()},
                               {"format", sampling::formatName(*format)},
                               {"sdf", command.sdf},
                               {"pattern", command.pattern},
                               {"n", job.count},
                               {"rows", report->rows},
                               {"first_index", report->firstIndex},
                               {"seed", job.seed},
                               {"time", job.time},
                               {"bad_rows", report->badRows},
                               {"seconds", report->seconds},
                               {"samples_per_second", rate},
                               {"gl_renderer", context.value()->info().renderer}};
        std::cout << json.dump(2) << "\n";
    } else if (!output.quiet) {
        std::printf("wrote %s: %llu samples (%s, seed %llu, rows %llu..%llu of %llu), %llu bad rows, %.2f s (%.2f M samples/s)\n",
                    outputPath.string().c_str(), (unsigned long long)report->rows, command.pattern.c_str(),
                    (unsigned long long)job.seed, (unsigned long long)report->firstIndex,
                    (unsigned long long)(report->firstIndex + report->rows), (unsigned long long)job.count,
                    (unsigned long long)report->badRows, report->seconds, rate / 1e6);
    }
    if (report->badRows > 0 && !output.quiet && !output.json)
        std::fprintf(stderr,
                     "sdfwb: note: %llu rows are NaN/Inf (rays that missed for surface/near, or a field that is not finite)\n",
                     (unsigned long long)report->badRows);
    return kExitOk;
}

int runMerge(const std::string& outputFile, const std::string& formatName, const std::vector<std::string>& parts,
             const OutputOptions& output) {
    std::optional<sampling::SampleFormat> format =
        formatName.empty() ? sampling::formatFromPath(outputFile) : sampling::parseFormat(formatName);
    if (!format) {
        printError(formatName.empty()
                       ? "--output: '" + outputFile + "': unknown sample file type (use .bin, .npz or .ply, or --format)"
                       : "--format: unknown format '" + formatName + "' (bin, npz, ply)");
        return kExitUsage;
    }
    std::vector<std::filesystem::path> paths(parts.begin(), parts.end());
    auto start = std::chrono::steady_clock::now();
    auto report = sampling::mergeSampleFiles(outputFile, *format, paths);
    if (!report) {
        printError(report.error().message);
        return kExitFailure;
    }
    double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (output.json) {
        nlohmann::json json = {{"output", outputFile}, {"rows", report->rows}, {"parts", report->parts}, {"seconds", seconds}};
        std::cout << json.dump(2) << "\n";
    } else if (!output.quiet) {
        std::printf("wrote %s: %llu samples from %zu parts in %.2f s\n", outputFile.c_str(), (unsigned long long)report->rows,
                    report->parts, seconds);
    }
    return kExitOk;
}

} // namespace sdfwb::app

namespace sdfwb::app {

int runAnimate(const AnimateJob& job, const OutputOptions& output) {
    auto start = std::chrono::steady_clock::now();
    auto sdfPath = resolveSdf(job.frame.sdf);
    if (!sdfPath) return kExitUsage;
    std::filesystem::path outputPath(job.frame.output);
    if (outputPath.extension() != ".mp4") {
        printError("--output: '" + job.frame.output + "': animations are written as .mp4 (H.264)");
        return kExitUsage;
    }
    if (!(job.seconds > 0.0f) || job.seconds > 3600.0f) {
        printError("--seconds: must be in (0, 3600]");
        return kExitUsage;
    }
    if (job.framesPerSecond < 1 || job.framesPerSecond > 240) {
        printError("--fps: must be 1..240");
        return kExitUsage;
    }
    auto opened = openSdf(*sdfPath, job.frame.entry, "animate: " + sdfPath->string() + " has errors; nothing written");
    if (!opened) return kExitFailure;
    const shaders::PreparedSdf& sdf = *opened;
    if (!job.turntable && !sdf.usesTime() && !output.quiet)
        std::fprintf(stderr, "sdfwb: note: %s is not animated and --turntable is off: every frame is the same\n",
                     sdfPath->string().c_str());
    auto context = renderer::HeadlessContext::create();
    if (!context) {
        printError(context.error().message);
        return kExitNoGl;
    }
    renderer::SdfRenderer sdfRenderer;
    (void)sdfRenderer.setTrace(job.frame.trace);
    (void)sdfRenderer.setShading(job.frame.shading);
    (void)sdfRenderer.setPlane(job.frame.plane);
    auto diagnostics = sdfRenderer.setSdf(sdf);
    if (shaders::hasErrors(diagnostics)) {
        printDiagnostics(diagnostics);
        printError("animate: the driver rejected " + sdfPath->string() + "; nothing written");
        return kExitFailure;
    }
    auto writer = renderer::VideoWriter::open(outputPath, job.frame.width, job.frame.height, job.framesPerSecond);
    if (!writer) {
        printError(writer.error().message);
        return kExitFailure;
    }

    const int frames = std::max(1, int(std::lround(double(job.seconds) * job.framesPerSecond)));
    CancelToken cancel;
    ProgressBar bar(!output.quiet && !output.json);
    double renderSeconds = 0.0;
    {
        InterruptScope interrupts(cancel);
        renderer::OffscreenRenderer offscreen;
        for (int i = 0; i < frames; ++i) {
            if (cancel.isCancelled()) break;
            renderer::Camera camera = job.frame.camera;
            if (job.turntable) renderer::orbit(camera, float(2.0 * 3.14159265358979 * i / frames), 0.0f);
            float time = job.frame.time + float(i) / float(job.framesPerSecond);
            renderer::FrameStats stats;
            renderer::Image image = offscreen.render(sdfRenderer, job.frame.width, job.frame.height, camera, time, &stats);
            renderSeconds += stats.cpuMilliseconds / 1000.0;
            if (auto ok = (*writer)->addFrame(image); !ok) {
                printError(ok.error().message);
                return kExitFailure;
            }
            bar.update(std::uint64_t(i + 1), std::uint64_t(frames));
            if (output.progressLines) std::fprintf(stderr, "progress %d %d\n", i + 1, frames);
        }
    }
    bar.finish();
    sdfRenderer.releaseGl();
    if (cancel.isCancelled()) {
        printError("animate: cancelled; nothing written");
        return kExitCancelled;
    }
    if (auto ok = (*writer)->finish(); !ok) {
        printError(ok.error().message);
        return kExitFailure;
    }
    double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (output.json) {
        nlohmann::json report = {{"output", outputPath.string()},
                                 {"frames", frames},
                                 {"fps", job.framesPerSecond},
                                 {"width", job.frame.width & ~1},
                                 {"height", job.frame.height & ~1},
                                 {"render_seconds", renderSeconds},
                                 {"seconds", seconds}};
        std::cout << report.dump(2) << "\n";
    } else if (!output.quiet) {
        std::printf("wrote %s (%d frames at %d fps, %dx%d, H.264; rendering %.2f s, total %.2f s)\n", outputPath.string().c_str(),
                    frames, job.framesPerSecond, job.frame.width & ~1, job.frame.height & ~1, renderSeconds, seconds);
    }
    return kExitOk;
}

} // namespace sdfwb::app

namespace sdfwb::app {

int runAudit(const AuditCommand& command, const OutputOptions& output) {
    auto sdfPath = resolveSdf(command.sdf);
    if (!sdfPath) return kExitUsage;
    if (command.samples < 64 || command.samples > 100000000) {
        printError("--samples: must be 64..100000000");
        return kExitUsage;
    }
    auto opened = openSdf(*sdfPath, command.entry, "audit: " + sdfPath->string() + " has errors");
    if (!opened) return kExitFailure;
    const shaders::PreparedSdf& sdf = *opened;
    auto context = renderer::HeadlessContext::create();
    if (!context) {
        printError(context.error().message);
        return kExitNoGl;
    }
    // Every finding with its evidence: JSON objects, and text lines.
    auto flagsJson = [](const std::vector<sampling::AuditFlag>& flags) {
        nlohmann::json list = nlohmann::json::array();
        for (const sampling::AuditFlag& f : flags) {
            nlohmann::json examples = nlohmann::json::array();
            for (const glm::vec3& e : f.examples) examples.push_back({e.x, e.y, e.z});
            nlohmann::json item = {
                {"flag", f.name}, {"evidence", f.evidence}, {"share", f.share}, {"count", f.count}, {"examples", examples}};
            for (const auto& [name, value] : sampling::namedFigures(f)) item[name] = value;
            list.push_back(std::move(item));
        }
        return list;
    };
    auto printFlags = [](const std::vector<sampling::AuditFlag>& flags) {
        if (flags.empty()) std::printf("  findings           none (no NaN/Inf, jump, plateau or |grad f| > 1.05 found)\n");
        for (const sampling::AuditFlag& f : flags) {
            std::printf("  %-18s %s\n", f.name.c_str(), f.evidence.c_str());
            if (!f.examples.empty()) {
                std::printf("  %-18s", "");
                for (std::size_t k = 0; k < f.examples.size() && k < 4; ++k)
                    std::printf(" (%.4g, %.4g, %.4g)", f.examples[k].x, f.examples[k].y, f.examples[k].z);
                std::printf("%s\n", f.examples.size() > 4 ? " ... (all in --json)" : "");
            }
        }
    };

    if (command.plane) {
        glm::vec3 normal(command.planeNormal[0], command.planeNormal[1], command.planeNormal[2]);
        auto readout = sampling::analysePlane(sdf, normal, command.planeOffset, command.resolution, command.time);
        if (!readout) {
            printError(readout.error().message);
            return kExitFailure;
        }
        const sampling::PlaneReadout& r = *readout;
        if (output.json) {
            nlohmann::json json = {
                {"sdf", sdfPath->string()},
                {"plane", {normal.x, normal.y, normal.z, command.planeOffset}},
                {"resolution", r.resolution},
                {"points", r.points},
                {"minimum", r.minimum},
                {"maximum", r.maximum},
                {"lipschitz_max", r.lipschitzMax},
                {"lipschitz_p99", r.lipschitz99},
                {"share_above_one", r.shareAboveOne},
                {"truncation_distance", r.truncationDistance ? nlohmann::json(*r.truncationDistance) : nlohmann::json(nullptr)},
                {"discontinuities", r.discontinuities},
                {"nan_count", r.nanCount},
                {"histogram", r.histogram},
                {"histogram_bin_width", 0.05},
                {"safe_step_factor", r.safeStepFactor},
                {"flags", flagsJson(r.flags)},
                {"entry", sdf.signature.entry},
                {"seconds", r.seconds}};
            std::cout << json.dump(2) << "\n";
        } else if (!output.quiet) {
            std::printf("plane %.3g,%.3g,%.3g,%.3g of %s: %llu points (%dx%d grid), %.3f s\n", normal.x, normal.y, normal.z,
                        command.planeOffset, sdfPath->string().c_str(), (unsigned long long)r.points, r.resolution, r.resolution,
                        r.seconds);
            std::printf("  value range        [%.4g, %.4g]\n", r.minimum, r.maximum);
            std::printf("  |grad f|           max %.4g, 99th percentile %.4g; %.2f %% of the plane above 1\n", r.lipschitzMax,
                        r.lipschitz99, 100.0 * r.shareAboveOne);
            std::printf("  safe step factor   %.4g\n", r.safeStepFactor);
            std::printf("  truncation         %s\n",
                        r.truncationDistance ? std::to_string(*r.truncationDistance).c_str() : "none");
            std::printf("  discontinuities    %llu points\n  NaN/Inf            %llu points\n",
                        (unsigned long long)r.discontinuities, (unsigned long long)r.nanCount);
            printFlags(r.flags);
        }
        return kExitOk;
    }

    CancelToken cancel;
    ProgressBar bar(!output.quiet && !output.json);
    sampling::AuditOptions options;
    options.samples = command.samples;
    options.seed = command.seed;
    options.time = command.time;
    options.probeDistance = command.probeDistance;
    Expected<sampling::AuditReport> report = [&] {
        InterruptScope interrupts(cancel);
        return sampling::auditField(
            sdf, options, ProgressSink{[&](std::uint64_t done, std::uint64_t total) { bar.update(done, total); }, &cancel});
    }();
    bar.finish();
    if (cancel.isCancelled()) {
        printError("audit: cancelled");
        return kExitCancelled;
    }
    if (!report) {
        printError(report.error().message);
        return kExitFailure;
    }
    const sampling::AuditReport& r = *report;
    if (output.json) {
        nlohmann::json scales = nlohmann::json::array();
        for (const auto& q : r.scales)
            scales.push_back({{"scale", q.step}, {"p50", q.p50}, {"p99", q.p99}, {"p999", q.p999}, {"max", q.max}});
        nlohmann::json convergence = nlohmann::json::array();
        for (const auto& c : r.convergence)
            convergence.push_back(
                {{"samples", c.samples}, {"lipschitz", c.lipschitz}, {"exactness_p99", c.exactnessP99}, {"seconds", c.seconds}});
        nlohmann::json json = {
            {"sdf", sdfPath->string()},
            {"verdict", r.verdict},
            {"reason", r.reason},
            {"lipschitz", r.lipschitz},
            {"lipschitz_max", r.lipschitzMax},
            {"lipschitz_uncertainty", r.lipschitzUncertainty},
            {"safe_step_factor", r.safeStepFactor},
            {"truncation_distance", r.truncationDistance ? nlohmann::json(*r.truncationDistance) : nlohmann::json(nullptr)},
            {"nan_fraction", r.nanFraction},
            {"nan_fraction_error", r.nanFractionError},
            {"discontinuities", r.discontinuities},
            {"discontinuity_share", r.discontinuityShare},
            {"eikonal_error_mean", r.eikonalMean},
            {"eikonal_error_p95", r.eikonalP95},
            {"surface_points", r.surfacePoints},
            {"surface_spacing", r.surfaceSpacing},
            {"exactness_error_p99", r.exactnessP99},
            {"exactness_error_max", r.exactnessMax},
            {"overestimate_share", r.overestimateShare},
            {"surface_gradient", r.surfaceGradient},
            {"noise_floor", r.noiseFloor},
            {"samples", r.samples},
            {"scales", scales},
            {"convergence", convergence},
            {"flags", flagsJson(r.flags)},
            {"entry", sdf.signature.entry},
            {"probe_distance", options.probeDistance},
            {"seconds", r.seconds}};
        std::cout << json.dump(2) << "\n";
    } else if (!output.quiet) {
        std::printf("%s: %s\n  %s\n\n", sdfPath->string().c_str(), r.verdict.c_str(), r.reason.c_str());
        printFlags(r.flags);
        std::printf("\n");
        std::printf("  Lipschitz estimate   %.4g (a lower bound of the true constant; largest quotient seen %.4g, spread %.2g)\n",
                    r.lipschitz, r.lipschitzMax, r.lipschitzUncertainty);
        std::printf("  safe step factor     %.4g\n", r.safeStepFactor);
        std::printf("  truncation           %s\n", r.truncationDistance ? std::to_string(*r.truncationDistance).c_str() : "none");
        std::printf("  NaN/Inf fraction     %.3g +- %.2g\n", r.nanFraction, r.nanFractionError);
        std::printf("  discontinuities      %llu points (%.3g %%)\n", (unsigned long long)r.discontinuities,
                    100.0 * r.discontinuityShare);
        std::printf("  eikonal error        mean %.3g, 95th percentile %.3g (near the surface)\n", r.eikonalMean, r.eikonalP95);
        std::printf(
            "  exactness            | |f| - true distance |: 99th percentile %.3g, max %.3g; true distance known to +-%.2g\n",
            r.exactnessP99, r.exactnessMax, r.surfaceSpacing);
        std::printf("                       (%llu surface points, k-d tree); %.3g %% of points overestimate it\n",
                    (unsigned long long)r.surfacePoints, 100.0 * r.overestimateShare);
        std::printf("  |grad f| at surface  %.3g (median; 1 for a distance, ~0 when the gradient vanishes there)\n",
                    r.surfaceGradient);
        std::printf("  precision floor      %.2g (rounding noise in f; float32 spacing at |p| = 1 is 1.2e-07)\n", r.noiseFloor);
        std::printf("\n  difference quotients |Df|      p50      p99    p99.9      max\n");
        for (const auto& q : r.scales)
            std::printf("    at scale %-8.2g        %8.4f %8.4f %8.4f %8.4f\n", q.step, q.p50, q.p99, q.p999, q.max);
        std::printf("\n  error against run time: samples   Lipschitz   exactness p99   seconds\n");
        for (const auto& c : r.convergence)
            std::printf("                          %9llu   %9.4f   %13.3g   %7.2f\n", (unsigned long long)c.samples, c.lipschitz,
                        c.exactnessP99, c.seconds);
    }
    return kExitOk;
}

} // namespace sdfwb::app
