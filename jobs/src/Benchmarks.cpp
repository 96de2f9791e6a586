#include <jobs/Benchmarks.h>

#include "References.h"

#include <core/TextFile.h>
#include <renderer/OffscreenRenderer.h>
#include <renderer/SampleCompute.h>
#include <renderer/SdfRenderer.h>
#include <sampling/FieldAudit.h>
#include <sampling/SamplerLibrary.h>
#include <shaders/SdfSource.h>
#include <values/Camera.h>

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <functional>
#include <string_view>
#include <thread>
#include <vector>

namespace sdfwb::bench {
namespace {

using Clock = std::chrono::steady_clock;

double millisecondsSince(Clock::time_point start) {
    return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

// Median, minimum and maximum of repeated measurements.
struct Spread {
    double median = 0, minimum = 0, maximum = 0;
};
Spread spreadOf(std::vector<double> values) {
    if (values.empty()) return {};
    std::sort(values.begin(), values.end());
    const std::size_t n = values.size();
    const double median = n % 2 ? values[n / 2] : 0.5 * (values[n / 2 - 1] + values[n / 2]);
    return {median, values.front(), values.back()};
}

// q-quantile of values (nearest rank); 0 when empty.
double quantile(std::vector<double> values, double q) {
    if (values.empty()) return 0.0;
    const std::size_t k = std::min(values.size() - 1, std::size_t(q * double(values.size())));
    std::nth_element(values.begin(), values.begin() + std::ptrdiff_t(k), values.end());
    return values[k];
}

std::string format(const char* pattern, auto... values) {
    const int size = std::snprintf(nullptr, 0, pattern, values...);
    std::string text(std::size_t(std::max(size, 0)) + 1, '\0');
    std::snprintf(text.data(), text.size(), pattern, values...);
    text.pop_back();
    return text;
}

// A markdown table cell: a literal | would end the cell.
std::string cell(std::string_view text) {
    std::string escaped;
    for (char c : text) {
        if (c == '|') escaped += '\\';
        escaped += c;
    }
    return escaped;
}

std::string spreadText(const Spread& s, const char* unit = "") {
    return format("%.3g%s [%.3g, %.3g]", s.median, unit, s.minimum, s.maximum);
}

struct BenchShape {
    const char* name;
    const char* glsl;
    Shape shape;
};

const BenchShape kShapes[] = {
    {"sphere", "float sdf(vec3 p) { return length(p) - 0.6; }\n", {Shape::Sphere, 0.6, 0.0}},
    {"torus",
     "float sdf(vec3 p) { vec2 q = vec2(length(p.xz) - 0.6, p.y); return length(q) - 0.25; }\n",
     {Shape::Torus, 0.6, 0.25}},
};

shaders::PreparedSdf prepare(const char* glsl, const char* name) {
    return shaders::prepareSdf(glsl, name, {}, shaders::IncludeOptions{});
}

struct Report {
    std::string markdown;
    std::string csv;
};

// 1. Sphere tracer: |t - t*| at every pixel both hit, against steps and frame time.
Expected<Report> tracerBenchmark(const BenchOptions& options) {
    const int width = options.quick ? 160 : 640, height = options.quick ? 90 : 360;
    struct Method {
        const char* name;
        float relaxation, stepFactor;
        bool cones = false; // the cone pass (a ray per 4x4 tile) first
    };
    const Method methods[] = {{"plain", 1.0f, 1.0f},
                              {"over-relaxed 1.6", 1.6f, 1.0f},
                              {"step factor 0.7", 1.0f, 0.7f},
                              {"plain + cone pass", 1.0f, 1.0f, true}};
    std::vector<float> tolerances =
        options.quick ? std::vector<float>{2.0f, 0.5f} : std::vector<float>{4.0f, 2.0f, 1.0f, 0.5f, 0.25f, 0.1f, 0.05f};
    const values::Camera camera;

    Report report;
    report.csv =
        "sdf,method,epsilon_scale,steps_hits,steps_all,error_p50,error_p99,error_max,missed_pixels,false_hits,hit_pixels,"
        "ms_median,ms_min,ms_max\n";
    report.markdown =
        format("### Sphere tracer: hit error against steps and time\n\n"
               "%dx%d, default camera, step budget 512. Error = |t - t*| along the ray, in scene units, where t* is the "
               "exact first intersection (References.cpp, double precision), over the pixels both hit; \"missed\": pixels "
               "whose exact ray hits and ours does not, \"false hits\": ours hits and the exact ray misses (a ray passing "
               "within the tolerance of the silhouette; in no error column); steps per hit "
               "pixel are means; frame time is the median [min, max] of %d frames after a warm-up frame. The hit "
               "tolerance is in pixels: a hit when |f| < tolerance x the pixel footprint at t. \"plain + cone pass\" "
               "first marches one cone per 4x4 pixels and starts each pixel where its cone stopped (steps count the "
               "pixel's own march; the frame time includes the cone pass).\n\n"
               "| SDF | method | tolerance (px) | steps/hit | error p50 | error p99 | missed | false hits | frame ms |\n"
               "|---|---|---|---|---|---|---|---|---|\n",
               width, height, options.repeats);
    renderer::OffscreenRenderer offscreen;
    for (const BenchShape& shape : kShapes) {
        // The reference intersection of every pixel's ray, as the shader builds it.
        std::vector<double> reference(std::size_t(width) * std::size_t(height), -1.0);
        for (int y = 0; y < height; ++y)
            for (int x = 0; x < width; ++x) {
                const glm::dvec3 direction = values::primaryRayDirection(camera, x, y, width, height);
                if (auto t = intersect(shape.shape, glm::dvec3(camera.position), direction))
                    reference[std::size_t(y * width + x)] = *t;
            }
        for (const Method& method : methods)
            for (float tolerance : tolerances) {
                renderer::SdfRenderer sdfRenderer;
                values::ShadingSettings shading;
                shading.statsOutput = true;
                values::TraceSettings trace;
                trace.overRelaxation = method.relaxation;
                trace.stepFactor = method.stepFactor;
                trace.epsilonScale = tolerance;
                trace.maxSteps = 512;
                trace.cones = method.cones ? values::TraceSettings::Cones::On : values::TraceSettings::Cones::Off;
                (void)sdfRenderer.setShading(shading);
                (void)sdfRenderer.setTrace(trace);
                if (auto d = sdfRenderer.setSdf(prepare(shape.glsl, shape.name)); shaders::hasErrors(d))
                    return makeError("bench: the tracer benchmark's " + std::string(shape.name) + " does not compile");
                renderer::FrameStats frame;
                offscreen.renderStats(sdfRenderer, width, height, camera, 0.0f, &frame); // warm-up (JIT)
                std::vector<double> times;
                std::vector<renderer::OffscreenRenderer::PixelStats> stats;
                for (int r = 0; r < options.repeats; ++r) {
                    stats = offscreen.renderStats(sdfRenderer, width, height, camera, 0.0f, &frame);
                    times.push_back(frame.cpuMilliseconds);
                }
                sdfRenderer.releaseGl();
                std::vector<double> errors;
                double stepsAll = 0, stepsHits = 0;
                long hits = 0, missed = 0, falseHits = 0;
                for (std::size_t i = 0; i < stats.size(); ++i) {
                    stepsAll += stats[i].steps;
                    if (!stats[i].hit()) {
                        missed += reference[i] >= 0.0;
                        continue;
                    }
                    ++hits;
                    falseHits += reference[i] < 0.0;
                    stepsHits += stats[i].steps;
                    if (reference[i] >= 0.0) errors.push_back(std::abs(double(stats[i].t) - reference[i]));
                }
                const Spread ms = spreadOf(times);
                const double p50 = quantile(errors, 0.5), p99 = quantile(errors, 0.99);
                const double worst = errors.empty() ? 0.0 : *std::max_element(errors.begin(), errors.end());
                const double perHit = hits ? stepsHits / double(hits) : 0.0;
                report.csv += format("%s,%s,%g,%.3f,%.3f,%.4g,%.4g,%.4g,%ld,%ld,%ld,%.4g,%.4g,%.4g\n", shape.name, method.name,
                                     double(tolerance), perHit, stepsAll / double(stats.size()), p50, p99, worst, missed,
                                     falseHits, hits, ms.median, ms.minimum, ms.maximum);
                report.markdown += format("| %s | %s | %g | %.1f | %.2e | %.2e | %ld | %ld | %s |\n", shape.name, method.name,
                                          double(tolerance), perHit, p50, p99, missed, falseHits, spreadText(ms).c_str());
            }
    }
    report.markdown += "\n![Sphere tracer: hit error against steps and frame time](images/bench_tracer.png)\n\n";
    return report;
}

// 2. Surface and near samplers: accuracy against time over the surface tolerance.
Expected<Report> samplerBenchmark(const BenchOptions& options) {
    const std::uint32_t count = options.quick ? (1u << 13) : (1u << 18);
    std::vector<float> tolerances =
        options.quick ? std::vector<float>{1e-3f, 1e-5f} : std::vector<float>{1e-2f, 1e-3f, 1e-4f, 1e-5f, 1e-6f};
    Report report;
    report.csv = "sdf,pattern,surface_tolerance,samples,error_p50,error_p99,error_max,bad_rows,ms_median,ms_min,ms_max\n";
    report.markdown = format(
        "### Surface and near samplers: accuracy against time\n\n"
        "%u samples per run; the rays of `surface` and `near` stop when |f| < the surface tolerance "
        "(`--surface-tolerance`, default 1e-5). Error for `surface`: the exact distance of each sample to "
        "the surface; for `near`: | written f - exact signed distance | at the sample. Time: median [min, max] of "
        "%d runs (one dispatch each, read-back included) after a warm-up run.\n\n"
        "| SDF | pattern | tolerance | error p50 | error p99 | bad rows | ms | samples/s |\n|---|---|---|---|---|---|---|---|\n",
        count, options.repeats);
    std::vector<float> positions(3 * std::size_t(count)), distances(count), gradients(3 * std::size_t(count));
    for (const BenchShape& shape : kShapes)
        for (const char* pattern : {"surface", "near"}) {
            renderer::SampleCompute compute;
            auto piece = sampling::findSampler(pattern, {});
            if (!piece) return piece.error();
            if (shaders::hasErrors(compute.build(prepare(shape.glsl, shape.name), *piece)))
                return makeError("bench: the sampler benchmark's " + std::string(shape.name) + " does not compile");
            for (float tolerance : tolerances) {
                renderer::SampleUniforms uniforms;
                uniforms.sampleCount = count;
                uniforms.seed = 11;
                uniforms.surfaceTolerance = tolerance;
                if (auto ok = compute.run(uniforms, 0, count, positions.data(), distances.data(), gradients.data()); !ok)
                    return ok.error();
                std::vector<double> times;
                for (int r = 0; r < options.repeats; ++r) {
                    auto start = Clock::now();
                    if (auto ok = compute.run(uniforms, 0, count, positions.data(), distances.data(), gradients.data()); !ok)
                        return ok.error();
                    times.push_back(millisecondsSince(start));
                }
                std::vector<double> errors;
                std::uint64_t bad = 0;
                for (std::uint32_t i = 0; i < count; ++i) {
                    const glm::dvec3 p(positions[3 * i], positions[3 * i + 1], positions[3 * i + 2]);
                    if (!std::isfinite(distances[i]) || !std::isfinite(p.x)) {
                        ++bad;
                        continue;
                    }
                    const double exact = distance(shape.shape, p);
                    errors.push_back(std::string(pattern) == "surface" ? std::abs(exact)
                                                                       : std::abs(double(distances[i]) - exact));
                }
                const Spread ms = spreadOf(times);
                const double p50 = quantile(errors, 0.5), p99 = quantile(errors, 0.99);
                const double worst = errors.empty() ? 0.0 : *std::max_element(errors.begin(), errors.end());
                report.csv += format("%s,%s,%g,%u,%.4g,%.4g,%.4g,%llu,%.4g,%.4g,%.4g\n", shape.name, pattern, double(tolerance),
                                     count, p50, p99, worst, (unsigned long long)bad, ms.median, ms.minimum, ms.maximum);
                report.markdown +=
                    format("| %s | %s | %g | %.2e | %.2e | %llu | %s | %.3g |\n", shape.name, pattern, double(tolerance), p50,
                           p99, (unsigned long long)bad, spreadText(ms).c_str(), double(count) / (ms.median / 1000.0));
            }
            compute.releaseGl();
        }
    report.markdown += "\n![Samplers: error against time](images/bench_samplers.png)\n\n";
    return report;
}

// 3. Gradients: central (6 taps) and tetrahedral (4 taps) differences against the step.
Expected<Report> gradientBenchmark(const BenchOptions& options) {
    const std::uint32_t count = options.quick ? (1u << 13) : (1u << 18);
    std::vector<float> steps =
        options.quick ? std::vector<float>{1e-2f, 1e-4f}
                      : std::vector<float>{1e-1f, 3e-2f, 1e-2f, 3e-3f, 1e-3f, 3e-4f, 1e-4f, 3e-5f, 1e-5f, 3e-6f, 1e-6f};
    const BenchShape& shape = kShapes[1]; // the torus: curvature 1/0.25 across the tube
    Report report;
    report.csv = "scheme,step,angle_p50_deg,angle_p99_deg,length_error_p50,length_error_p99,ms_median,ms_min,ms_max\n";
    report.markdown =
        format("### Gradients: central against tetrahedral differences, against the step\n\n"
               "%u points near the torus (R 0.6, r 0.25; the `near` pattern: within ~0.005 of the surface), gradient "
               "by 6-tap central differences (the samplers' written gradient) and by the 4-tap tetrahedral scheme (the "
               "tracer's normals), against the analytic gradient (References.cpp). Angle error in degrees, length "
               "error | |g| - 1 |. Time: the same dispatch on `rand` points (cheap positions, so the taps dominate), "
               "median [min, max] of %d runs.\n\n"
               "| scheme | step h | angle p50 (deg) | angle p99 (deg) | length error p50 | length error p99 | ms |\n"
               "|---|---|---|---|---|---|---|\n",
               count, options.repeats);
    std::vector<float> positions(3 * std::size_t(count)), distances(count), gradients(3 * std::size_t(count));
    renderer::SampleCompute nearCompute, randCompute;
    auto nearPiece = sampling::findSampler("near", {});
    auto randPiece = sampling::findSampler("rand", {});
    if (!nearPiece || !randPiece) return makeError("bench: built-in samplers missing");
    if (shaders::hasErrors(nearCompute.build(prepare(shape.glsl, shape.name), *nearPiece)) ||
        shaders::hasErrors(randCompute.build(prepare(shape.glsl, shape.name), *randPiece)))
        return makeError("bench: the gradient benchmark's torus does not compile");
    for (bool tetrahedral : {false, true}) {
        const char* scheme = tetrahedral ? "tetrahedral 4-tap" : "central 6-tap";
        renderer::SampleUniforms uniforms;
        uniforms.sampleCount = count;
        uniforms.seed = 5;
        uniforms.tetrahedralGradient = tetrahedral;
        uniforms.gradientStep = 1e-3f;
        if (auto ok = randCompute.run(uniforms, 0, count, positions.data(), distances.data(), gradients.data()); !ok)
            return ok.error();
        for (float h : steps) {
            uniforms.gradientStep = h;
            // Each step's own time (rand over the same count): the scheme's cost, measured per row
            // rather than once and repeated.
            std::vector<double> times;
            for (int r = 0; r < options.repeats; ++r) {
                auto start = Clock::now();
                if (auto ok = randCompute.run(uniforms, 0, count, positions.data(), distances.data(), gradients.data()); !ok)
                    return ok.error();
                times.push_back(millisecondsSince(start));
            }
            const Spread ms = spreadOf(times);
            if (auto ok = nearCompute.run(uniforms, 0, count, positions.data(), distances.data(), gradients.data()); !ok)
                return ok.error();
            std::vector<double> angles, lengths;
            for (std::uint32_t i = 0; i < count; ++i) {
                const glm::dvec3 p(positions[3 * i], positions[3 * i + 1], positions[3 * i + 2]);
                const glm::dvec3 g(gradients[3 * i], gradients[3 * i + 1], gradients[3 * i + 2]);
                if (!std::isfinite(p.x) || !std::isfinite(g.x) || !std::isfinite(g.y) || !std::isfinite(g.z)) continue;
                const double length = glm::length(g);
                const glm::dvec3 exact = gradient(shape.shape, p);
                const double cosine = length > 0.0 ? std::clamp(glm::dot(g / length, exact), -1.0, 1.0) : -1.0;
                angles.push_back(glm::degrees(std::acos(cosine)));
                lengths.push_back(std::abs(length - 1.0));
            }
            const double a50 = quantile(angles, 0.5), a99 = quantile(angles, 0.99), l50 = quantile(lengths, 0.5),
                         l99 = quantile(lengths, 0.99);
            report.csv += format("%s,%g,%.4g,%.4g,%.4g,%.4g,%.4g,%.4g,%.4g\n", scheme, double(h), a50, a99, l50, l99, ms.median,
                                 ms.minimum, ms.maximum);
            report.markdown += format("| %s | %g | %.2e | %.2e | %.2e | %.2e | %s |\n", scheme, double(h), a50, a99, l50, l99,
                                      spreadText(ms).c_str());
        }
    }
    nearCompute.releaseGl();
    randCompute.releaseGl();
    report.markdown += "\n![Gradients: error against the step and time](images/bench_gradients.png)\n\n";
    return report;
}

// 4. The audit's Lipschitz estimate against samples and seconds, for fields with known constants.
Expected<Report> auditBenchmark(const BenchOptions& options, const ProgressSink& progress) {
    struct Field {
        const char* name;
        const char* glsl;
        double lipschitz; // the true constant over the cube [-1, 1]^3
    };
    // |grad (|p| - 0.5)^3| = 3 (|p| - 0.5)^2, largest at the corners: 3 (sqrt 3 - 0.5)^2.
    const double cubedL = 3.0 * (std::sqrt(3.0) - 0.5) * (std::sqrt(3.0) - 0.5);
    const Field fields[] = {
        {"sphere (L = 1)", "float sdf(vec3 p) { return length(p) - 0.6; }\n", 1.0},
        {"100 x sphere (L = 100)", "float sdf(vec3 p) { return 100.0 * (length(p) - 0.5); }\n", 100.0},
        {"(|p| - 0.5)^3 (L = 4.55)", "float sdf(vec3 p) { float d = length(p) - 0.5; return d * d * d; }\n", cubedL},
    };
    std::vector<std::uint64_t> sampleCounts =
        options.quick ? std::vector<std::uint64_t>{1000, 4000} : std::vector<std::uint64_t>{1000, 4000, 16000, 64000};
    const int seeds = 3; // the (|p| - 0.5)^3 audit takes ~30 s at 64000 (its surface rays crawl)
    Report report;
    report.csv = "sdf,true_lipschitz,samples,ratio_median,ratio_min,ratio_max,max_ratio_median,max_ratio_min,max_ratio_max,"
                 "seconds_median,seconds_min,"
                 "seconds_max\n";
    report.markdown =
        format("### Field audit: Lipschitz estimate against samples and seconds\n\n"
               "`sdfwb --batch audit` (no convergence runs) on fields whose Lipschitz constant over the cube is known. "
               "Ratio = estimate / true constant (the estimate is a lower bound: the 99.9th percentile of difference "
               "quotients), median [min, max] over %d seeds; the largest quotient seen, an upper estimate that is "
               "prone to outliers, likewise; seconds likewise.\n\n"
               "| field | samples | estimate / true | largest quotient / true | seconds |\n|---|---|---|---|---|\n",
               seeds);
    for (const Field& field : fields) {
        for (std::uint64_t samples : sampleCounts) {
            std::vector<double> ratios, maxRatios, seconds;
            for (int seed = 0; seed < seeds; ++seed) {
                if (progress.isCancelled()) return makeError("bench: cancelled");
                sampling::AuditOptions audit;
                audit.samples = samples;
                audit.seed = std::uint64_t(seed) * 7919u;
                audit.convergence = false;
                auto r = sampling::auditField(prepare(field.glsl, field.name), audit, {});
                if (!r) return r.error();
                ratios.push_back(double(r->lipschitz) / field.lipschitz);
                maxRatios.push_back(double(r->lipschitzMax) / field.lipschitz);
                seconds.push_back(r->seconds);
            }
            const Spread ratio = spreadOf(ratios), largest = spreadOf(maxRatios), time = spreadOf(seconds);
            report.csv += format("%s,%.6g,%llu,%.5g,%.5g,%.5g,%.5g,%.5g,%.5g,%.4g,%.4g,%.4g\n", field.name, field.lipschitz,
                                 (unsigned long long)samples, ratio.median, ratio.minimum, ratio.maximum, largest.median,
                                 largest.minimum, largest.maximum, time.median, time.minimum, time.maximum);
            report.markdown += format("| %s | %llu | %s | %s | %s |\n", cell(field.name).c_str(), (unsigned long long)samples,
                                      spreadText(ratio).c_str(), spreadText(largest).c_str(), spreadText(time, " s").c_str());
        }
    }
    report.markdown += "\n![Audit: Lipschitz estimate against samples and time](images/bench_audit.png)\n\n";
    return report;
}

} // namespace

Expected<BenchFiles> runBenchmarks(const BenchOptions& options, const ProgressSink& progress) {
    BenchFiles files;
    files.markdown = options.outputDirectory / "benchmarks.md";
    files.csvDirectory = options.outputDirectory / "benchmarks";
    files.imageDirectory = options.outputDirectory / "images";
    std::error_code ec;
    std::filesystem::create_directories(files.csvDirectory, ec);
    if (ec) return makeError("'" + files.csvDirectory.string() + "': cannot create the folder (" + ec.message() + ")");
    std::filesystem::create_directories(files.imageDirectory, ec);
    if (ec) return makeError("'" + files.imageDirectory.string() + "': cannot create the folder (" + ec.message() + ")");

    const auto start = Clock::now();
    struct Section {
        const char* csvName;
        std::function<Expected<Report>()> run;
    };
    const Section sections[] = {
        {"tracer.csv", [&] { return tracerBenchmark(options); }},
        {"samplers.csv", [&] { return samplerBenchmark(options); }},
        {"gradients.csv", [&] { return gradientBenchmark(options); }},
        {"audit.csv", [&] { return auditBenchmark(options, progress); }},
    };
    std::string body;
    std::uint64_t done = 0;
    for (const Section& section : sections) {
        if (progress.isCancelled()) return makeError("bench: cancelled");
        auto report = section.run();
        if (!report) return report.error();
        if (auto ok = writeFileAtomically(files.csvDirectory / section.csvName, report->csv); !ok) return ok.error();
        body += report->markdown;
        progress(++done, std::size(sections));
    }

    const std::time_t now = std::time(nullptr);
    char date[64];
    std::strftime(date, sizeof date, "%Y-%m-%d %H:%M UTC", std::gmtime(&now));
    std::string markdown = "# Benchmarks: error against run time\n\n";
    markdown += "<!-- Generated by `" + options.commandLine + "`; do not edit by hand. -->\n\n";
    markdown += format("Measured %s in one run of `%s` (%.0f s in all%s) on this machine: %u hardware threads, GL: %s. "
                       "Every time is the median [min, max] of repeated runs in that same run; every error is a distribution "
                       "over pixels or samples (50th and 99th percentiles). The tables are also in benchmarks/*.csv; the plots "
                       "are made from them by bench/plot_benchmarks.py (matplotlib). The references (exact intersections, "
                       "distances, gradients in double precision) are in jobs/src/References.cpp.\n\n",
                       date, options.commandLine.c_str(), millisecondsSince(start) / 1000.0,
                       options.quick ? ", --quick: not for reading" : "", std::thread::hardware_concurrency(),
                       options.glDescription.c_str());
    markdown += body;
    if (auto ok = writeFileAtomically(files.markdown, markdown); !ok) return ok.error();
    return files;
}

} // namespace sdfwb::bench
