#include <sampling/FieldAudit.h>

#include <renderer/SampleCompute.h>
#include <sampling/SampleSet.h>
#include <sampling/Sampler.h>
#include <sampling/SamplerLibrary.h>

#include <glm/geometric.hpp>

#include <nanoflann.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>

namespace sdfwb::sampling {
namespace {

double secondsSince(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

float percentile(std::vector<float> values, double q) {
    if (values.empty()) return 0.0f;
    std::size_t k = std::min(values.size() - 1, std::size_t(q * double(values.size() - 1) + 0.5));
    std::nth_element(values.begin(), values.begin() + long(k), values.end());
    return values[k];
}

bool finiteRow(const SampleSet& s, std::size_t i) {
    if (!std::isfinite(s.distances[i])) return false;
    for (int c = 0; c < 3; ++c)
        if (!std::isfinite(s.positions[3 * i + std::size_t(c)]) || !std::isfinite(s.gradients[3 * i + std::size_t(c)])) return false;
    return true;
}

float gradientLength(const SampleSet& s, std::size_t i) {
    return std::sqrt(s.gradients[3 * i] * s.gradients[3 * i] + s.gradients[3 * i + 1] * s.gradients[3 * i + 1] +
                     s.gradients[3 * i + 2] * s.gradients[3 * i + 2]);
}

// A compiled sampler that can be run with several gradient steps over the same points.
class Runner {
public:
    Expected<void> build(const shaders::PreparedSdf& sdf, const std::string& pattern) {
        auto piece = pattern.rfind("analysis/", 0) == 0 ? shaders::builtinPiece(pattern) : findSampler(pattern, {});
        if (!piece) return piece.error();
        auto diagnostics = m_compute.build(sdf, *piece);
        if (shaders::hasErrors(diagnostics)) {
            for (const auto& d : diagnostics)
                if (d.severity == shaders::Severity::Error) return makeError("audit: " + shaders::formatDiagnostic(d));
        }
        return {};
    }
    Expected<SampleSet> run(const SamplingJob& job) {
        SampleSet out;
        out.resize(std::size_t(job.count));
        auto report = sampleInto(m_compute, job, out.positions.data(), out.distances.data(), out.gradients.data(), {});
        if (!report) return report.error();
        return out;
    }
    ~Runner() { m_compute.releaseGl(); }

private:
    renderer::SampleCompute m_compute;
};

// Points (xyz triples) for nanoflann.
struct PointCloud {
    const std::vector<float>& points;
    std::size_t kdtree_get_point_count() const { return points.size() / 3; }
    float kdtree_get_pt(std::size_t i, std::size_t d) const { return points[3 * i + d]; }
    template <class Box>
    bool kdtree_get_bbox(Box&) const { return false; }
};
using KdTree = nanoflann::KDTreeSingleIndexAdaptor<nanoflann::L2_Simple_Adaptor<float, PointCloud>, PointCloud, 3>;

struct Scales {
    static constexpr float kSteps[3] = {1e-2f, 1e-3f, 1e-4f};
};

// Rounding noise in f: along short straight runs of 16 points (spacing 1e-3, 0.015 long) a
// smooth field is a quadratic up to terms far below float32 noise; the residual of a least-squares
// quadratic is the noise. For uniform rounding with step q the residual's RMS is q / sqrt(12), so
// the floor reported is sqrt(12) x RMS: the rounding step of the values, median over the runs
// (runs that cross a crease or an edge are the minority and do not move the median).
Expected<float> measureNoiseFloor(const shaders::PreparedSdf& sdf, const AuditOptions& options, std::uint64_t samples) {
    constexpr int kRun = 16;
    constexpr float kSpacing = 1e-3f;
    Runner runner;
    if (auto ok = runner.build(sdf, "analysis/noise_lines.glsl"); !ok) return ok.error();
    SamplingJob job;
    const std::uint64_t runs = std::clamp<std::uint64_t>(samples / 16, 64, 8192);
    job.count = runs * kRun;
    job.seed = options.seed + 2;
    job.time = options.time;
    job.parameters[0] = kSpacing;
    auto rows = runner.run(job);
    if (!rows) return rows.error();
    // Least squares on x = -7.5 .. 7.5 (symmetric, so the linear term decouples): fit the
    // constant + quadratic by their 2x2 normal equations, the slope on its own.
    double sx2 = 0, sx4 = 0;
    for (int k = 0; k < kRun; ++k) {
        double x = k - (kRun - 1) / 2.0;
        sx2 += x * x;
        sx4 += x * x * x * x;
    }
    std::vector<float> floors;
    for (std::uint64_t r = 0; r < runs; ++r) {
        const float* f = rows->distances.data() + r * kRun;
        bool finite = true;
        double s0 = 0, s1 = 0, s2 = 0;
        for (int k = 0; k < kRun; ++k) {
            finite = finite && std::isfinite(f[k]);
            double x = k - (kRun - 1) / 2.0;
            s0 += f[k];
            s1 += x * f[k];
            s2 += x * x * f[k];
        }
        if (!finite) continue;
        const double det = kRun * sx4 - sx2 * sx2;
        const double a = (s0 * sx4 - s2 * sx2) / det, c = (kRun * s2 - sx2 * s0) / det, b = s1 / sx2;
        double residual = 0;
        for (int k = 0; k < kRun; ++k) {
            double x = k - (kRun - 1) / 2.0;
            double e = f[k] - (a + b * x + c * x * x);
            residual += e * e;
        }
        floors.push_back(float(std::sqrt(12.0 * residual / (kRun - 3))));
    }
    return floors.empty() ? 0.0f : percentile(floors, 0.5);
}

// The audit at one sample count (no convergence runs).
Expected<AuditReport> auditOnce(const shaders::PreparedSdf& sdf, const AuditOptions& options, const ProgressSink& progress) {
    auto start = std::chrono::steady_clock::now();
    const std::uint64_t n = std::max<std::uint64_t>(options.samples, 64);
    AuditReport report;
    report.samples = n;
    Runner randomRunner, nearRunner, surfaceRunner;
    if (auto ok = randomRunner.build(sdf, "rand"); !ok) return ok.error();
    if (auto ok = nearRunner.build(sdf, "near"); !ok) return ok.error();
    if (auto ok = surfaceRunner.build(sdf, "surface"); !ok) return ok.error();

    SamplingJob job;
    job.count = n;
    job.seed = options.seed;
    job.time = options.time;
    std::vector<SampleSet> random, near;
    int step = 0;
    const int totalSteps = 7;
    for (float h : Scales::kSteps) {
        job.gradientStep = h;
        auto r = randomRunner.run(job);
        if (!r) return r.error();
        random.push_back(std::move(*r));
        progress(std::uint64_t(++step), totalSteps);
        auto m = nearRunner.run(job);
        if (!m) return m.error();
        near.push_back(std::move(*m));
        progress(std::uint64_t(++step), totalSteps);
        if (progress.isCancelled()) return makeError("audit: cancelled");
    }
    job.gradientStep = 1e-3f;
    job.seed = options.seed + 1;  // surface points independent of the query points
    auto surface = surfaceRunner.run(job);
    if (!surface) return surface.error();
    progress(std::uint64_t(++step), totalSteps);
    auto noise = measureNoiseFloor(sdf, options, n);
    if (!noise) return noise.error();
    report.noiseFloor = *noise;

    // NaN / Inf: over random points, at the middle scale.
    std::uint64_t bad = 0;
    for (std::size_t i = 0; i < n; ++i) bad += !finiteRow(random[1], i);
    report.nanFraction = double(bad) / double(n);
    report.nanFractionError = std::sqrt(std::max(report.nanFraction * (1.0 - report.nanFraction), 1.0 / double(n)) / double(n));

    // Difference quotients: central differences at three scales (random and near-surface points)
    // and the quotient between consecutive random points (scale ~1).
    std::vector<float> perScale[3];
    for (int s = 0; s < 3; ++s)
        for (const SampleSet* set : {&random[std::size_t(s)], &near[std::size_t(s)]})
            for (std::size_t i = 0; i < set->size(); ++i)
                if (finiteRow(*set, i)) perScale[s].push_back(gradientLength(*set, i));
    std::vector<float> wide;
    for (std::size_t i = 0; i + 1 < n; i += 2) {
        if (!finiteRow(random[1], i) || !finiteRow(random[1], i + 1)) continue;
        glm::vec3 a(random[1].positions[3 * i], random[1].positions[3 * i + 1], random[1].positions[3 * i + 2]);
        glm::vec3 b(random[1].positions[3 * i + 3], random[1].positions[3 * i + 4], random[1].positions[3 * i + 5]);
        float distance = glm::length(a - b);
        if (distance > 1e-3f) wide.push_back(std::abs(random[1].distances[i] - random[1].distances[i + 1]) / distance);
    }
    auto summarise = [](float scale, const std::vector<float>& values) {
        QuotientScale q;
        q.step = scale;
        q.p50 = percentile(values, 0.5);
        q.p99 = percentile(values, 0.99);
        q.p999 = percentile(values, 0.999);
        q.max = values.empty() ? 0.0f : *std::max_element(values.begin(), values.end());
        return q;
    };
    report.scales.push_back(summarise(1.0f, wide));
    for (int s = 0; s < 3; ++s) report.scales.push_back(summarise(2.0f * Scales::kSteps[s], perScale[s]));
    // Estimate from the scales float32 resolves well (the smallest step is noisier and is kept
    // for the discontinuity test).
    // Rounding noise with steps of q (the precision floor) moves a quotient over `step` by about
    // q / step, and its tails (the 99.9th percentile; each tap rounds on its own) by up to ~3 q /
    // step: that much is taken off, so a far-from-the-origin field is judged by its shape, not its
    // noise. For a field computed near the origin q ~ 1e-7 and nothing changes.
    auto noiseSlope = [&](std::size_t s) { return 3.0f * report.noiseFloor / report.scales[s].step; };
    report.lipschitz = std::max({report.scales[0].p999 - noiseSlope(0), report.scales[1].p999 - noiseSlope(1),
                                 report.scales[2].p999 - noiseSlope(2)});
    report.lipschitzMax = std::max({report.scales[0].max, report.scales[1].max, report.scales[2].max});
    report.lipschitzUncertainty = report.lipschitzMax - report.lipschitz;
    report.safeStepFactor = 1.0f / std::max(report.lipschitz, 1.0f);

    // Discontinuities: the quotient grows as the step shrinks (a jump of J gives J / 2h).
    std::uint64_t tested = 0;
    for (const std::vector<SampleSet>* sets : {&random, &near})
        for (std::size_t i = 0; i < n; ++i) {
            if (!finiteRow((*sets)[0], i) || !finiteRow((*sets)[2], i)) continue;
            ++tested;
            float coarse = gradientLength((*sets)[0], i), fine = gradientLength((*sets)[2], i);
            if (fine > 3.0f * std::max(coarse, 0.1f) && fine > 2.0f && fine > coarse + noiseSlope(3)) ++report.discontinuities;
        }
    report.discontinuityShare = tested ? double(report.discontinuities) / double(tested) : 0.0;

    // Truncation: outside points where the field has stopped growing.
    std::uint64_t positive = 0;
    std::vector<float> flatValues;
    for (std::size_t i = 0; i < n; ++i) {
        if (!finiteRow(random[0], i) || random[0].distances[i] <= 0.0f) continue;
        ++positive;
        if (gradientLength(random[0], i) < 0.02f) flatValues.push_back(random[0].distances[i]);
    }
    // A truncated field saturates at a distance well off the surface; flat spots that hug the
    // zero set (fractal estimators vanish near their set) are not truncation.
    if (positive > 0 && double(flatValues.size()) > 0.02 * double(positive)) {
        float plateau = percentile(flatValues, 0.05);
        if (plateau > 0.01f) report.truncationDistance = plateau;
    }

    // Eikonal error near the surface.
    std::vector<float> eikonal;
    for (std::size_t i = 0; i < n; ++i)
        if (finiteRow(near[1], i)) eikonal.push_back(std::abs(gradientLength(near[1], i) - 1.0f));
    if (!eikonal.empty()) {
        double sum = 0.0;
        for (float e : eikonal) sum += e;
        report.eikonalMean = float(sum / double(eikonal.size()));
        report.eikonalP95 = percentile(eikonal, 0.95);
    }

    // Exactness: |f| against the distance to the nearest of a dense set of surface points.
    std::vector<float> surfacePoints;
    for (std::size_t i = 0; i < surface->size(); ++i)
        if (finiteRow(*surface, i))
            for (int c = 0; c < 3; ++c) surfacePoints.push_back(surface->positions[3 * i + std::size_t(c)]);
    report.surfacePoints = surfacePoints.size() / 3;
    {
        std::vector<float> lengths;
        for (std::size_t i = 0; i < surface->size(); ++i)
            if (finiteRow(*surface, i)) lengths.push_back(gradientLength(*surface, i));
        report.surfaceGradient = lengths.empty() ? 0.0f : percentile(lengths, 0.5);
    }
    std::vector<float> errors;
    std::uint64_t over = 0;
    if (report.surfacePoints >= 16) {
        PointCloud cloud{surfacePoints};
        KdTree tree(3, cloud, nanoflann::KDTreeSingleIndexAdaptorParams(16));
        tree.buildIndex();
        double spacing = 0.0;
        std::size_t counted = 0;
        for (std::size_t i = 0; i < report.surfacePoints; i += std::max<std::size_t>(1, report.surfacePoints / 4096)) {
            std::uint32_t indices[2];
            float distances[2];
            nanoflann::KNNResultSet<float, std::uint32_t> result(2);
            result.init(indices, distances);
            tree.findNeighbors(result, &surfacePoints[3 * i], nanoflann::SearchParams(16));
            spacing += std::sqrt(distances[1]);
            ++counted;
        }
        report.surfaceSpacing = float(spacing / double(std::max<std::size_t>(counted, 1)));
        const float tolerance = 1.5f * report.surfaceSpacing + 1e-4f;
        for (const SampleSet* set : {&random[1], &near[1]})
            for (std::size_t i = 0; i < n; ++i) {
                if (!finiteRow(*set, i)) continue;
                std::uint32_t index;
                float squared;
                nanoflann::KNNResultSet<float, std::uint32_t> result(1);
                result.init(&index, &squared);
                tree.findNeighbors(result, &set->positions[3 * i], nanoflann::SearchParams(16));
                float trueDistance = std::sqrt(squared);
                float value = std::abs(set->distances[i]);
                errors.push_back(std::abs(value - trueDistance));
                if (value > trueDistance + tolerance) ++over;
            }
        report.exactnessP99 = percentile(errors, 0.99);
        report.exactnessMax = errors.empty() ? 0.0f : *std::max_element(errors.begin(), errors.end());
        report.overestimateShare = errors.empty() ? 0.0 : double(over) / double(errors.size());
    }

    // A jump of height J shows as J / (2h) at step h: the largest quotient grows tenfold per scale.
    // A Lipschitz field's largest quotient stays put (up to float noise at the finest scale).
    const bool jumpGrowth = report.scales[3].max > 2.0f && report.scales[3].max - noiseSlope(3) > 3.0f * report.scales[1].max &&
                            report.scales[2].max - noiseSlope(2) > 1.5f * report.scales[1].max;

    float minimum = INFINITY, maximum = -INFINITY;
    for (std::size_t i = 0; i < n; ++i)
        if (std::isfinite(random[1].distances[i])) {
            minimum = std::min(minimum, random[1].distances[i]);
            maximum = std::max(maximum, random[1].distances[i]);
        }
    const bool hasSignChange = minimum <= 0.0f && maximum >= 0.0f;

    // The verdict, most serious first.
    // The nearest surface sample overestimates the true distance by up to about the sample spacing.
    const float exactTolerance = 3.0f * report.surfaceSpacing + 2e-3f;
    char text[256];
    if (report.nanFraction > 0.0) {
        report.verdict = "nan";
        std::snprintf(text, sizeof text, "%.3g %% of random points give NaN or Inf", 100.0 * report.nanFraction);
    } else if (report.discontinuityShare > 5e-4 || jumpGrowth) {
        report.verdict = "discontinuous";
        std::snprintf(text, sizeof text,
                      "difference quotients grow as the step shrinks (largest %.3g at scale 0.02, %.3g at 0.002, %.3g at 0.0002; %llu points)",
                      double(report.scales[1].max), double(report.scales[2].max), double(report.scales[3].max),
                      (unsigned long long)report.discontinuities);
    } else if (report.surfacePoints == 0 && !hasSignChange) {
        report.verdict = "no-surface";
        std::snprintf(text, sizeof text, "f never changes sign (%.4g to %.4g over %llu points) and no ray finds a surface", double(minimum),
                      double(maximum), (unsigned long long)n);
    } else if (report.truncationDistance) {
        report.verdict = "truncated";
        std::snprintf(text, sizeof text, "the field stops growing at about %.4g (|grad f| < 0.02 there)", double(*report.truncationDistance));
    } else if (report.lipschitz > 1.05f) {
        report.verdict = "non-conservative";
        std::snprintf(text, sizeof text, "|grad f| reaches %.4g > 1: sphere tracing needs a step factor of %.3g", double(report.lipschitz),
                      double(report.safeStepFactor));
    } else if (report.surfacePoints < 16) {
        report.verdict = "conservative";
        std::snprintf(text, sizeof text, "1-Lipschitz, but too few surface points (%llu) to test exactness",
                      (unsigned long long)report.surfacePoints);
    } else if (report.exactnessP99 <= exactTolerance && report.exactnessMax <= 2.0f * exactTolerance) {
        report.verdict = "exact";
        std::snprintf(text, sizeof text, "|f| matches the distance to the surface within %.2g (99th percentile; sampling allows %.2g)",
                      double(report.exactnessP99), double(exactTolerance));
    } else {
        report.verdict = "conservative";
        std::snprintf(text, sizeof text, "1-Lipschitz and |f| underestimates the distance (error 99th percentile %.2g, max %.2g; exact allows %.2g, %.2g)",
                      double(report.exactnessP99), double(report.exactnessMax), double(exactTolerance), double(2.0f * exactTolerance));
    }
    report.reason = text;
    // Warnings that go with any verdict.
    if (report.surfacePoints >= 16 && report.surfaceGradient < 0.1f) {
        std::snprintf(text, sizeof text,
                      "; |grad f| vanishes at the surface (median %.2g): hits and surface samples with a small |f| can still lie "
                      "|f| / |grad f| away from it",
                      double(report.surfaceGradient));
        report.reason += text;
    }
    if (report.noiseFloor > 1e-5f) {
        std::snprintf(text, sizeof text,
                      "; float32 precision floor: f carries rounding noise of %.2g (large coordinates in the SDF's arithmetic), "
                      "so features, hit tolerances and sample distances below that are noise",
                      double(report.noiseFloor));
        report.reason += text;
    }
    report.seconds = secondsSince(start);
    return report;
}

} // namespace

Expected<AuditReport> auditField(const shaders::PreparedSdf& sdf, const AuditOptions& options, const ProgressSink& progress) {
    if (!sdf.ok()) return makeError("audit: the SDF has errors");
    std::vector<ConvergencePoint> convergence;
    if (options.convergence) {
        for (std::uint64_t divisor : {16u, 4u}) {
            AuditOptions smaller = options;
            smaller.samples = std::max<std::uint64_t>(options.samples / divisor, 64);
            auto partial = auditOnce(sdf, smaller, ProgressSink{nullptr, progress.cancel});
            if (!partial) return partial;
            convergence.push_back({partial->samples, partial->lipschitz, partial->exactnessP99, partial->seconds});
        }
    }
    auto report = auditOnce(sdf, options, progress);
    if (!report) return report;
    convergence.push_back({report->samples, report->lipschitz, report->exactnessP99, report->seconds});
    report->convergence = std::move(convergence);
    return report;
}

Expected<PlaneReadout> analysePlane(const shaders::PreparedSdf& sdf, glm::vec3 normal, float offset, int resolution, float time) {
    auto start = std::chrono::steady_clock::now();
    if (glm::length(normal) <= 0.0f) return makeError("plane: the normal must not be zero");
    if (resolution < 2 || resolution > 4096) return makeError("plane: resolution must be 2..4096");
    normal = glm::normalize(normal);
    // An orthonormal basis of the plane, and a square that covers its intersection with the box.
    glm::vec3 helper = std::abs(normal.x) < 0.9f ? glm::vec3(1, 0, 0) : glm::vec3(0, 1, 0);
    glm::vec3 u = glm::normalize(glm::cross(normal, helper));
    glm::vec3 v = glm::cross(normal, u);
    const float side = 2.0f * std::sqrt(3.0f);
    glm::vec3 origin = normal * offset - 0.5f * side * (u + v);

    Runner runner;
    if (auto ok = runner.build(sdf, "analysis/plane_grid.glsl"); !ok) return ok.error();
    SamplingJob job;
    job.count = std::uint64_t(resolution) * std::uint64_t(resolution);
    job.time = time;
    const float parameters[12] = {origin.x, origin.y, origin.z, side, u.x, u.y, u.z, 0, v.x, v.y, v.z, 0};
    std::copy(std::begin(parameters), std::end(parameters), job.parameters);
    SampleSet sets[3];
    const float steps[3] = {1e-2f, 1e-3f, 1e-4f};
    for (int s = 0; s < 3; ++s) {
        job.gradientStep = steps[s];
        auto result = runner.run(job);
        if (!result) return result.error();
        sets[s] = std::move(*result);
    }

    PlaneReadout readout;
    readout.resolution = resolution;
    readout.histogram.assign(41, 0);
    readout.minimum = std::numeric_limits<float>::infinity();
    readout.maximum = -std::numeric_limits<float>::infinity();
    std::vector<float> slopes;
    std::uint64_t positive = 0, above = 0;
    std::vector<float> flat;
    for (std::size_t i = 0; i < sets[1].size(); ++i) {
        const float* p = &sets[1].positions[3 * i];
        if (std::max({std::abs(p[0]), std::abs(p[1]), std::abs(p[2])}) > 1.0f) continue;
        ++readout.points;
        if (!finiteRow(sets[1], i) || !finiteRow(sets[0], i)) {
            ++readout.nanCount;
            continue;
        }
        float f = sets[1].distances[i];
        readout.minimum = std::min(readout.minimum, f);
        readout.maximum = std::max(readout.maximum, f);
        float slope = gradientLength(sets[1], i);
        slopes.push_back(slope);
        above += slope > 1.02f;
        readout.histogram[std::min<std::size_t>(40, std::size_t(slope / 0.05f + 0.5f))]++;
        float coarse = gradientLength(sets[0], i);
        // A jump between grid neighbours that the local slope cannot explain: for a continuous
        // field |f(a) - f(b)| <= |grad f| * spacing (to first order).
        const std::size_t n = std::size_t(resolution);
        const float spacing = side / float(resolution);
        for (std::size_t neighbour : {i + 1, i + n}) {
            if ((neighbour == i + 1 && (i + 1) % n == 0) || neighbour >= sets[2].size() || !finiteRow(sets[2], neighbour) ||
                !finiteRow(sets[2], i))
                continue;
            // The finest step sees the slope on either side of a jump, not the jump itself.
            float slope = std::max(gradientLength(sets[2], i), gradientLength(sets[2], neighbour));
            float difference = std::abs(sets[2].distances[neighbour] - sets[2].distances[i]);
            if (difference > 1.5f * spacing * std::max(slope, 0.1f) + 1e-5f) ++readout.discontinuities;
        }
        if (f > 0.0f) {
            ++positive;
            if (coarse < 0.02f) flat.push_back(f);
        }
    }
    if (slopes.empty()) {
        readout.minimum = readout.maximum = 0.0f;
    } else {
        readout.lipschitzMax = *std::max_element(slopes.begin(), slopes.end());
        readout.lipschitz99 = percentile(slopes, 0.99);
        readout.shareAboveOne = double(above) / double(slopes.size());
    }
    if (positive > 0 && double(flat.size()) > 0.02 * double(positive)) {
        float plateau = percentile(flat, 0.05);
        if (plateau > 0.01f) readout.truncationDistance = plateau;  // as in the volume audit
    }
    readout.safeStepFactor = 1.0f / std::max(readout.lipschitzMax, 1.0f);
    readout.seconds = secondsSince(start);
    return readout;
}

} // namespace sdfwb::sampling
