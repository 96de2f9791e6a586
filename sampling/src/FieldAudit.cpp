#include <sampling/FieldAudit.h>
#include <sampling/FieldEvaluator.h>

#include "AuditRunner.h"

#include <renderer/SampleCompute.h>
#include <sampling/AuditStatistics.h>
#include <sampling/SampleSet.h>
#include <sampling/Sampler.h>
#include <sampling/SamplerLibrary.h>

#include <glm/geometric.hpp>

#include <nanoflann.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <optional>

namespace sdfwb::sampling {
namespace {

using detail::finiteRow;
using detail::gradientLength;
using detail::Runner;
using detail::secondsSince;

// Points (xyz triples) for nanoflann.
struct PointCloud {
    const std::vector<float>& points;
    std::size_t kdtree_get_point_count() const { return points.size() / 3; }
    float kdtree_get_pt(std::size_t i, std::size_t d) const { return points[3 * i + d]; }
    template <class Box> bool kdtree_get_bbox(Box&) const { return false; }
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
    if (auto ok = runner.build(sdf, "analysis/noise_lines.glsl", options.parameters); !ok) return ok.error();
    SamplingJob job;
    const std::uint64_t runs = std::clamp<std::uint64_t>(samples / 16, 64, 8192);
    job.count = runs * kRun;
    job.seed = options.seed + 2;
    job.time = options.time;
    job.parameters[0] = kSpacing;
    auto rows = runner.run(job);
    if (!rows) return rows.error();
    std::vector<float> floors;
    for (std::uint64_t r = 0; r < runs; ++r) {
        const float floor = quadraticResidualStep(rows->distances.data() + r * kRun, kRun);
        if (std::isfinite(floor)) floors.push_back(floor);
    }
    return floors.empty() ? 0.0f : percentile(floors, 0.5);
}

// f and its gradient at `points` (xyz triples), through the one field evaluator.
Expected<SampleSet> evaluateAt(const shaders::PreparedSdf& sdf, const AuditOptions& options, const std::vector<float>& points,
                               float gradientStep) {
    FieldEvaluator field;
    for (const auto& d : field.build(sdf))
        if (d.severity == shaders::Severity::Error) return makeError("audit: " + shaders::formatDiagnostic(d));
    SampleSet out;
    out.resize(points.size() / 3);
    out.positions = points;
    FieldSettings settings;
    settings.time = options.time;
    settings.gradientStep = gradientStep;
    settings.parameters = options.parameters;
    auto report = field.evaluate(points.data(), out.size(), out.distances.data(), out.gradients.data(), settings);
    if (!report) return report.error();
    return out;
}

struct JumpCandidate {
    glm::vec3 position;
    glm::vec3 across; // unit: the gradient's direction at the step that saw the jump, which crosses it
    float step;       // that difference step: the jump lies within about this distance
};

// Confirms and measures jumps by line searches across each candidate: 64 points over 3 steps along
// `across` find the largest rise; 64 points across that one interval must show (at least half of)
// the same rise. A continuous field's rise shrinks with the interval (even an infinitely steep one
// like sqrt near 0 shrinks 8-fold here); a jump does not. Rises within 4x the noise floor are
// rounding. Examples are the midpoints of the final intervals: on the jump, within 1/63 of it.
Expected<values::AuditFlag> measureJumps(const shaders::PreparedSdf& sdf, const AuditOptions& options,
                                         const std::vector<JumpCandidate>& candidates, float noiseFloor) {
    constexpr int kLine = 64;
    values::AuditFlag flag;
    flag.finding = values::Finding::Discontinuous;
    const std::size_t used = std::min<std::size_t>(candidates.size(), 1024);
    std::vector<float> points;
    auto line = [&](glm::vec3 from, glm::vec3 to) {
        for (int k = 0; k < kLine; ++k) {
            glm::vec3 q = from + (to - from) * (float(k) / float(kLine - 1));
            points.insert(points.end(), {q.x, q.y, q.z});
        }
    };
    for (std::size_t c = 0; c < used; ++c) {
        const float reach = 1.5f * candidates[c].step;
        line(candidates[c].position - reach * candidates[c].across, candidates[c].position + reach * candidates[c].across);
    }
    auto coarse = evaluateAt(sdf, options, points, 1e-3f);
    if (!coarse) return coarse.error();
    struct Interval {
        glm::vec3 from, to;
        float rise;
    };
    std::vector<Interval> intervals;
    const float floor = 4.0f * noiseFloor + 1e-5f;
    for (std::size_t c = 0; c < used; ++c) {
        auto [rise, k] = largestStep(&coarse->distances[std::size_t(kLine) * c], kLine);
        if (!(rise > floor)) continue;
        const float* p = &points[3 * (std::size_t(kLine) * c + std::size_t(k))];
        intervals.push_back({glm::vec3(p[0], p[1], p[2]), glm::vec3(p[3], p[4], p[5]), rise});
    }
    if (intervals.empty()) return flag;
    points.clear();
    for (const Interval& interval : intervals) line(interval.from, interval.to);
    auto fine = evaluateAt(sdf, options, points, 1e-3f);
    if (!fine) return fine.error();
    std::vector<float> jumps;
    for (std::size_t c = 0; c < intervals.size(); ++c) {
        auto [rise, k] = largestStep(&fine->distances[std::size_t(kLine) * c], kLine);
        if (!(rise > floor) || rise < 0.5f * intervals[c].rise) continue;
        jumps.push_back(rise);
        const float* p = &points[3 * (std::size_t(kLine) * c + std::size_t(k))];
        if (flag.examples.size() < values::kMaxExamples)
            flag.examples.push_back(0.5f * (glm::vec3(p[0], p[1], p[2]) + glm::vec3(p[3], p[4], p[5])));
    }
    flag.count = jumps.size();
    if (!jumps.empty()) {
        flag.value = percentile(jumps, 0.5);
        flag.maximum = *std::max_element(jumps.begin(), jumps.end());
    }
    return flag;
}

// Probes along rays from surface points outward (along the normalised gradient), at distances
// growing quadratically from 0.01 to options.truncationReach. A ray ends on a plateau when, from
// some probe on, f stays put (changes by less than 0.02 per unit of distance, up to noise) at a
// positive value: the field has stopped growing. Returns a "truncated" flag whose count is the
// number of rays that end on one (0: none).
Expected<values::AuditFlag> traceTruncationRays(const shaders::PreparedSdf& sdf, const AuditOptions& options,
                                                const SampleSet& surface, float noiseFloor) {
    values::AuditFlag flag;
    flag.finding = values::Finding::Truncated;
    constexpr int kProbes = 32;
    const float reach = std::max(options.truncationReach, 0.1f);
    float distances[kProbes];
    for (int k = 0; k < kProbes; ++k)
        distances[k] = 0.01f + (reach - 0.01f) * float(k * k) / float((kProbes - 1) * (kProbes - 1));
    std::vector<float> points;
    std::vector<glm::vec3> origins, normals;
    for (std::size_t i = 0; i < surface.size() && origins.size() < 2048; ++i) {
        if (!finiteRow(surface, i)) continue;
        glm::vec3 g(surface.gradients[3 * i], surface.gradients[3 * i + 1], surface.gradients[3 * i + 2]);
        if (!(glm::length(g) > 1e-6f)) continue;
        origins.push_back(glm::vec3(surface.positions[3 * i], surface.positions[3 * i + 1], surface.positions[3 * i + 2]));
        normals.push_back(glm::normalize(g));
    }
    if (origins.empty()) return flag;
    for (std::size_t r = 0; r < origins.size(); ++r)
        for (float d : distances) {
            glm::vec3 q = origins[r] + d * normals[r];
            points.insert(points.end(), {q.x, q.y, q.z});
        }
    auto values = evaluateAt(sdf, options, points, 1e-3f);
    if (!values) return values.error();
    std::vector<float> plateauValues, starts;
    for (std::size_t r = 0; r < origins.size(); ++r) {
        const float* f = &values->distances[std::size_t(kProbes) * r];
        const int first = plateauStart(f, distances, kProbes, 8.0f * noiseFloor + 1e-6f);
        if (first < 0) continue;
        plateauValues.push_back(f[kProbes - 1]);
        starts.push_back(distances[first]);
        if (flag.examples.size() < values::kMaxExamples) flag.examples.push_back(origins[r] + distances[first] * normals[r]);
    }
    flag.count = plateauValues.size();
    flag.share = double(plateauValues.size()) / double(origins.size());
    if (!plateauValues.empty()) {
        flag.value = percentile(plateauValues, 0.5);
        flag.maximum = *std::max_element(plateauValues.begin(), plateauValues.end());
        flag.start = percentile(starts, 0.5);
        char text[320];
        std::snprintf(
            text, sizeof text,
            "the field stops growing at %.4g: %llu of %llu rays probed outward from the surface (to distance %.3g) end on a "
            "plateau (|f| changes < 0.02 per unit) that starts %.3g from the surface (median)",
            double(flag.value), (unsigned long long)flag.count, (unsigned long long)origins.size(), double(reach),
            double(flag.start));
        flag.evidence = text;
    }
    return flag;
}

// The audit at one sample count (no convergence runs).
} // namespace

values::AuditFlag signUncertainty(const meshfield::MeshField& mesh, const SampleSet& points, std::size_t limit) {
    values::AuditFlag flag;
    flag.finding = values::Finding::SignUncertain;
    const std::size_t n = std::min(points.size(), limit);
    std::vector<float> ambiguous;
    for (std::size_t i = 0; i < n; ++i) {
        const glm::dvec3 p(points.positions[3 * i], points.positions[3 * i + 1], points.positions[3 * i + 2]);
        const double w = mesh.winding(p);
        if (std::abs(w - 0.5) >= kSignUncertainBand) continue;
        ambiguous.push_back(float(w));
        if (flag.examples.size() < values::kMaxExamples) flag.examples.push_back(glm::vec3(p));
    }
    flag.count = ambiguous.size();
    flag.share = n ? double(flag.count) / double(n) : 0.0;
    if (flag.count == 0) return flag;
    std::sort(ambiguous.begin(), ambiguous.end());
    flag.value = ambiguous[ambiguous.size() / 2];
    char text[320];
    std::snprintf(text, sizeof text,
                  "%.3g %% of random points (%llu of %zu) have a winding number between %.2g and %.2g (median %.2f): the mesh "
                  "is open or overlaps itself there, so inside or outside is a guess (sign %s)",
                  100.0 * flag.share, (unsigned long long)flag.count, n, 0.5 - kSignUncertainBand, 0.5 + kSignUncertainBand,
                  double(flag.value), meshfield::signName(mesh.options.sign));
    flag.evidence = text;
    return flag;
}

namespace {

// The audit's samples: random and near-surface points at each of the three difference steps, and
// surface points (drawn with seed + 1, independent of the query points).
struct AuditPasses {
    std::uint64_t n = 0;
    std::vector<SampleSet> random, near;
    SampleSet surface;
};

std::uint64_t countNonFinite(const SampleSet& set) {
    std::uint64_t bad = 0;
    for (std::size_t i = 0; i < set.size(); ++i) bad += !finiteRow(set, i);
    return bad;
}

// Rounding noise with steps of q (the precision floor) moves a quotient over `step` by about
// q / step, and its tails (the 99.9th percentile; each tap rounds on its own) by up to ~3 q /
// step: that much is taken off, so a far-from-the-origin field is judged by its shape, not its
// noise. For a field computed near the origin q ~ 1e-7 and nothing changes.
float noiseSlope(const values::AuditReport& report, std::size_t s) { return 3.0f * report.noiseFloor / report.scales[s].step; }

// Draws every pass (7 progress steps) and measures the precision floor.
Expected<AuditPasses> drawPasses(const shaders::PreparedSdf& sdf, const AuditOptions& options, const ProgressSink& progress,
                                 values::AuditReport& report) {
    AuditPasses p;
    p.n = report.samples;
    Runner randomRunner, nearRunner, surfaceRunner;
    if (auto ok = randomRunner.build(sdf, "rand", options.parameters, options.diagnostics); !ok) return ok.error();
    if (auto ok = nearRunner.build(sdf, "near", options.parameters); !ok) return ok.error();
    if (auto ok = surfaceRunner.build(sdf, "surface", options.parameters); !ok) return ok.error();

    SamplingJob job;
    job.count = p.n;
    job.seed = options.seed;
    job.time = options.time;
    int step = 0;
    const int totalSteps = 7;
    for (float h : Scales::kSteps) {
        job.gradientStep = h;
        auto r = randomRunner.run(job);
        if (!r) return r.error();
        p.random.push_back(std::move(*r));
        progress(std::uint64_t(++step), totalSteps);
        auto m = nearRunner.run(job);
        if (!m) return m.error();
        p.near.push_back(std::move(*m));
        progress(std::uint64_t(++step), totalSteps);
        if (progress.isCancelled()) return makeError("audit: cancelled");
    }
    job.gradientStep = 1e-3f;
    job.seed = options.seed + 1; // surface points independent of the query points
    auto surface = surfaceRunner.run(job);
    if (!surface) return surface.error();
    p.surface = std::move(*surface);
    progress(std::uint64_t(++step), totalSteps);
    auto noise = measureNoiseFloor(sdf, options, p.n);
    if (!noise) return noise.error();
    report.noiseFloor = *noise;

    return p;
}

// The share of NaN or Inf rows (random points, middle step), and the difference quotients'
// percentiles: between consecutive random points (scale ~1) and at each step.
void measureQuotients(const AuditPasses& p, values::AuditReport& report) {
    const std::uint64_t bad = countNonFinite(p.random[1]);
    report.nanFraction = double(bad) / double(p.n);
    report.nanFractionError =
        std::sqrt(std::max(report.nanFraction * (1.0 - report.nanFraction), 1.0 / double(p.n)) / double(p.n));
    // Difference quotients: central differences at three scales (random and near-surface points)
    // and the quotient between consecutive random points (scale ~1).
    std::vector<float> perScale[3];
    for (int s = 0; s < 3; ++s)
        for (const SampleSet* set : {&p.random[std::size_t(s)], &p.near[std::size_t(s)]})
            for (std::size_t i = 0; i < set->size(); ++i)
                if (finiteRow(*set, i)) perScale[s].push_back(gradientLength(*set, i));
    std::vector<float> wide;
    for (std::size_t i = 0; i + 1 < p.n; i += 2) {
        if (!finiteRow(p.random[1], i) || !finiteRow(p.random[1], i + 1)) continue;
        glm::vec3 a(p.random[1].positions[3 * i], p.random[1].positions[3 * i + 1], p.random[1].positions[3 * i + 2]);
        glm::vec3 b(p.random[1].positions[3 * i + 3], p.random[1].positions[3 * i + 4], p.random[1].positions[3 * i + 5]);
        float distance = glm::length(a - b);
        if (distance > 1e-3f) wide.push_back(std::abs(p.random[1].distances[i] - p.random[1].distances[i + 1]) / distance);
    }
    auto summarise = [](float scale, const std::vector<float>& values) {
        values::QuotientScale q;
        q.step = scale;
        q.p50 = percentile(values, 0.5);
        q.p99 = percentile(values, 0.99);
        q.p999 = percentile(values, 0.999);
        q.max = values.empty() ? 0.0f : *std::max_element(values.begin(), values.end());
        return q;
    };
    report.scales.push_back(summarise(1.0f, wide));
    for (int s = 0; s < 3; ++s) report.scales.push_back(summarise(2.0f * Scales::kSteps[s], perScale[s]));
}

// Discontinuities: points whose quotient grows as the step shrinks, confirmed by line searches
// (measureJumps). The flag, when any jump is confirmed; report.discontinuities counts the points.
Expected<std::optional<values::AuditFlag>> findDiscontinuities(const shaders::PreparedSdf& sdf, const AuditOptions& options,
                                                               const AuditPasses& p, values::AuditReport& report) {
    std::optional<values::AuditFlag> discontinuous;
    // Discontinuities: the quotient grows as the step shrinks (a jump of J gives J / 2h), at
    // points within the finest step of the jump.
    std::uint64_t tested = 0;
    std::vector<JumpCandidate> candidates;
    std::uint64_t suspects = 0; // points whose quotient at a coarser step outgrows the finest one
    for (const std::vector<SampleSet>* sets : {&p.random, &p.near})
        for (std::size_t i = 0; i < p.n; ++i) {
            if (!finiteRow((*sets)[0], i) || !finiteRow((*sets)[1], i) || !finiteRow((*sets)[2], i)) continue;
            ++tested;
            const float q[3] = {gradientLength((*sets)[0], i), gradientLength((*sets)[1], i), gradientLength((*sets)[2], i)};
            const glm::vec3 position((*sets)[0].positions[3 * i], (*sets)[0].positions[3 * i + 1],
                                     (*sets)[0].positions[3 * i + 2]);
            // Within the finest step of a jump: that quotient is J / 2h, far above the coarse one.
            if (q[2] > 3.0f * std::max(q[0], 0.1f) && q[2] > 2.0f && q[2] > q[0] + noiseSlope(report, 3)) {
                ++report.discontinuities;
                const float* g = &(*sets)[2].gradients[3 * i];
                candidates.push_back({position, glm::vec3(g[0], g[1], g[2]) / q[2], 2.0f * Scales::kSteps[2]});
                continue;
            }
            // Within a coarser step of a jump (100 times more points): that quotient outgrows the finest.
            for (int s = 0; s < 2; ++s)
                if (q[s] > 3.0f * std::max(q[2], 0.1f) + noiseSlope(report, std::size_t(s) + 1) && q[s] > 2.0f) {
                    ++suspects;
                    const float* g = &(*sets)[std::size_t(s)].gradients[3 * i];
                    if (candidates.size() < 4096)
                        candidates.push_back({position, glm::vec3(g[0], g[1], g[2]) / q[s], 2.0f * Scales::kSteps[s]});
                    break;
                }
        }
    report.discontinuityShare = tested ? double(report.discontinuities) / double(tested) : 0.0;
    if (!candidates.empty()) {
        auto jumps = measureJumps(sdf, options, candidates, report.noiseFloor);
        if (!jumps) return jumps.error();
        if (jumps->count > 0) {
            discontinuous = std::move(*jumps);
            discontinuous->share = double(discontinuous->count) / double(std::max<std::uint64_t>(tested, 1));
            char text[320];
            std::snprintf(
                text, sizeof text,
                "f jumps by %.3g (median; largest %.3g): %llu jumps confirmed by line searches from %llu of %llu probed points "
                "whose difference quotients grow as the step shrinks (largest %.3g at scale 0.02, %.3g at 0.0002)",
                double(discontinuous->value), double(discontinuous->maximum), (unsigned long long)discontinuous->count,
                (unsigned long long)(report.discontinuities + suspects), (unsigned long long)tested, double(report.scales[1].max),
                double(report.scales[3].max));
            discontinuous->evidence = text;
        }
    }

    return discontinuous;
}

// The Lipschitz estimate, from points a jump does not explain: near a jump of J the quotient at
// step h is J / 2h while at the finest step it is the field's slope; a steep but continuous field
// has the same quotient at every step. The quotient between distant points is used only when
// no jump was found (across a jump it is J / distance). Flags non-conservative fields.
void estimateLipschitz(const AuditPasses& p, bool discontinuous, values::AuditReport& report) {
    std::vector<float> unaffected[2];
    std::vector<std::pair<float, glm::vec3>> steepest;
    std::uint64_t above = 0, counted = 0;
    for (const std::vector<SampleSet>* sets : {&p.random, &p.near})
        for (std::size_t i = 0; i < p.n; ++i) {
            if (!finiteRow((*sets)[0], i) || !finiteRow((*sets)[1], i) || !finiteRow((*sets)[2], i)) continue;
            const float q0 = gradientLength((*sets)[0], i), q1 = gradientLength((*sets)[1], i),
                        q2 = gradientLength((*sets)[2], i);
            const float allowed = 1.5f * q2 + noiseSlope(report, 3) + 0.05f;
            if (q0 > allowed || q1 > allowed) continue;                // a jump within the coarser steps
            if (q2 > 3.0f * std::max(q0, 0.1f) && q2 > 2.0f) continue; // a jump within the finest step
            // Beside a jump, a small one (where the two sides nearly agree) still lifts the
            // coarser quotients a little: there the per-point estimate takes the smaller.
            unaffected[0].push_back(
                discontinuous ? std::min(q0 - noiseSlope(report, 1), q1 - noiseSlope(report, 2)) + noiseSlope(report, 1) : q0);
            unaffected[1].push_back(q1);
            ++counted;
            if (std::min(q0, q1) > 1.05f + noiseSlope(report, 2)) {
                ++above;
                steepest.push_back({q1, glm::vec3((*sets)[1].positions[3 * i], (*sets)[1].positions[3 * i + 1],
                                                  (*sets)[1].positions[3 * i + 2])});
            }
        }
    report.lipschitz = percentile(unaffected[0], 0.999) - noiseSlope(report, 1);
    if (!discontinuous) report.lipschitz = std::max(report.lipschitz, percentile(unaffected[1], 0.999) - noiseSlope(report, 2));
    if (!discontinuous) report.lipschitz = std::max(report.lipschitz, report.scales[0].p999 - noiseSlope(report, 0));
    report.lipschitzMax = std::max({report.scales[0].max, report.scales[1].max, report.scales[2].max});
    report.lipschitzUncertainty = report.lipschitzMax - report.lipschitz;
    report.safeStepFactor = 1.0f / std::max(report.lipschitz, 1.0f);
    if (report.lipschitz > 1.05f) {
        values::AuditFlag flag;
        flag.finding = values::Finding::NonConservative;
        flag.value = report.lipschitz;
        flag.maximum = report.lipschitzMax;
        flag.count = above;
        flag.share = counted ? double(above) / double(counted) : 0.0;
        std::sort(steepest.begin(), steepest.end(), [](const auto& a, const auto& b) { return a.first > b.first; });
        for (std::size_t k = 0; k < steepest.size() && k < values::kMaxExamples; ++k) flag.examples.push_back(steepest[k].second);
        char text[256];
        std::snprintf(
            text, sizeof text,
            "|grad f| reaches %.4g > 1 (99.9th percentile; largest %.4g) at %.3g %% of probed points: sphere tracing needs a "
            "step factor of %.3g",
            double(report.lipschitz), double(report.lipschitzMax), 100.0 * flag.share, double(report.safeStepFactor));
        flag.evidence = text;
        report.flags.push_back(std::move(flag));
    }
}

// Truncation: a field that stops growing away from its surface.
Expected<void> findTruncation(const shaders::PreparedSdf& sdf, const AuditOptions& options, const AuditPasses& p,
                              values::AuditReport& report) {
    // Truncation: outside points where the field has stopped growing, in the cube...
    std::uint64_t positive = 0;
    std::vector<float> flatValues;
    std::vector<glm::vec3> flatPoints;
    for (std::size_t i = 0; i < p.n; ++i) {
        if (!finiteRow(p.random[0], i) || p.random[0].distances[i] <= 0.0f) continue;
        ++positive;
        if (gradientLength(p.random[0], i) < 0.02f) {
            flatValues.push_back(p.random[0].distances[i]);
            if (flatPoints.size() < values::kMaxExamples)
                flatPoints.push_back(
                    glm::vec3(p.random[0].positions[3 * i], p.random[0].positions[3 * i + 1], p.random[0].positions[3 * i + 2]));
        }
    }
    // ...and along rays from the surface outward, to options.truncationReach: a plateau that lies
    // mostly beyond the cube shows there.
    auto plateau = traceTruncationRays(sdf, options, p.surface, report.noiseFloor);
    if (!plateau) return plateau.error();
    // A truncated field saturates at a distance well off the surface; flat spots that hug the
    // zero set (fractal estimators vanish near their set) are not truncation.
    if (plateau->count > 0 && plateau->share >= 0.05 && plateau->value > 0.01f) {
        report.truncationDistance = plateau->value;
        report.flags.push_back(std::move(*plateau));
    } else if (positive > 0 && double(flatValues.size()) > 0.02 * double(positive) && percentile(flatValues, 0.05) > 0.01f) {
        values::AuditFlag flag;
        flag.finding = values::Finding::Truncated;
        flag.value = percentile(flatValues, 0.05);
        flag.maximum = percentile(flatValues, 0.95);
        flag.count = flatValues.size();
        flag.share = double(flatValues.size()) / double(positive);
        flag.examples = flatPoints;
        char text[256];
        std::snprintf(text, sizeof text,
                      "the field stops growing at about %.4g: |grad f| < 0.02 at %.3g %% of the cube's outside points",
                      double(flag.value), 100.0 * flag.share);
        flag.evidence = text;
        report.truncationDistance = flag.value;
        report.flags.push_back(std::move(flag));
    }
    return {};
}

// Eikonal error near the surface, and exactness: |f| against the distance to the nearest of a
// dense set of surface points.
void measureExactness(const AuditPasses& p, values::AuditReport& report) {
    // Eikonal error near the surface.
    std::vector<float> eikonal;
    for (std::size_t i = 0; i < p.n; ++i)
        if (finiteRow(p.near[1], i)) eikonal.push_back(std::abs(gradientLength(p.near[1], i) - 1.0f));
    if (!eikonal.empty()) {
        double sum = 0.0;
        for (float e : eikonal) sum += e;
        report.eikonalMean = float(sum / double(eikonal.size()));
        report.eikonalP95 = percentile(eikonal, 0.95);
    }

    // Exactness: |f| against the distance to the nearest of a dense set of surface points.
    std::vector<float> surfacePoints;
    for (std::size_t i = 0; i < p.surface.size(); ++i)
        if (finiteRow(p.surface, i))
            for (int c = 0; c < 3; ++c) surfacePoints.push_back(p.surface.positions[3 * i + std::size_t(c)]);
    report.surfacePoints = surfacePoints.size() / 3;
    {
        std::vector<float> lengths;
        for (std::size_t i = 0; i < p.surface.size(); ++i)
            if (finiteRow(p.surface, i)) lengths.push_back(gradientLength(p.surface, i));
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
        for (const SampleSet* set : {&p.random[1], &p.near[1]})
            for (std::size_t i = 0; i < p.n; ++i) {
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
}

// NaN / Inf, with where.
void flagNonFinite(const AuditPasses& p, values::AuditReport& report) {
    const std::uint64_t bad = countNonFinite(p.random[1]);
    if (bad > 0) {
        values::AuditFlag flag;
        flag.finding = values::Finding::Nan;
        flag.count = bad;
        flag.share = report.nanFraction;
        for (std::size_t i = 0; i < p.n && flag.examples.size() < values::kMaxExamples; ++i)
            if (!finiteRow(p.random[1], i))
                flag.examples.push_back(
                    glm::vec3(p.random[1].positions[3 * i], p.random[1].positions[3 * i + 1], p.random[1].positions[3 * i + 2]));
        char text[160];
        std::snprintf(text, sizeof text, "%.3g %% of random points (%llu of %llu) give NaN or Inf", 100.0 * report.nanFraction,
                      (unsigned long long)bad, (unsigned long long)p.n);
        flag.evidence = text;
        report.flags.push_back(std::move(flag));
    }
}

// Orders the flags, most severe first, and gives the verdict: the most severe finding
// (no-surface ranks below discontinuities, above the rest), else exact or conservative.
void settleVerdict(const AuditPasses& p, values::AuditReport& report) {
    float minimum = INFINITY, maximum = -INFINITY;
    for (std::size_t i = 0; i < p.n; ++i)
        if (std::isfinite(p.random[1].distances[i])) {
            minimum = std::min(minimum, p.random[1].distances[i]);
            maximum = std::max(maximum, p.random[1].distances[i]);
        }
    const bool hasSignChange = minimum <= 0.0f && maximum >= 0.0f;

    // Most severe first: the verdict is the first.
    static const values::Finding severity[] = {values::Finding::Nan, values::Finding::Discontinuous, values::Finding::Truncated,
                                               values::Finding::NonConservative};
    std::stable_sort(report.flags.begin(), report.flags.end(), [](const values::AuditFlag& a, const values::AuditFlag& b) {
        auto rank = [](values::Finding finding) {
            return std::find(std::begin(severity), std::end(severity), finding) - std::begin(severity);
        };
        return rank(a.finding) < rank(b.finding);
    });

    // The verdict: the most severe finding (no-surface ranks below discontinuities, above the rest).
    // The nearest surface sample overestimates the true distance by up to about the sample spacing.
    const float exactTolerance = 3.0f * report.surfaceSpacing + 2e-3f;
    char text[256];
    const values::AuditFlag* worst = report.flags.empty() ? nullptr : &report.flags.front();
    if (worst && (worst->finding == values::Finding::Nan || worst->finding == values::Finding::Discontinuous)) {
        report.verdict = worst->finding;
        report.reason = worst->evidence;
    } else if (report.surfacePoints == 0 && !hasSignChange) {
        report.verdict = values::Finding::NoSurface;
        std::snprintf(text, sizeof text, "f never changes sign (%.4g to %.4g over %llu points) and no ray finds a surface",
                      double(minimum), double(maximum), (unsigned long long)p.n);
        report.reason = text;
    } else if (worst) {
        report.verdict = worst->finding;
        report.reason = worst->evidence;
    } else if (report.surfacePoints < 16) {
        report.verdict = values::Finding::Conservative;
        std::snprintf(text, sizeof text, "1-Lipschitz, but too few surface points (%llu) to test exactness",
                      (unsigned long long)report.surfacePoints);
        report.reason = text;
    } else if (report.exactnessP99 <= exactTolerance && report.exactnessMax <= 2.0f * exactTolerance) {
        report.verdict = values::Finding::Exact;
        std::snprintf(text, sizeof text,
                      "|f| matches the distance to the surface within %.2g (99th percentile; sampling allows %.2g)",
                      double(report.exactnessP99), double(exactTolerance));
        report.reason = text;
    } else {
        report.verdict = values::Finding::Conservative;
        std::snprintf(
            text, sizeof text,
            "1-Lipschitz and |f| underestimates the distance (error 99th percentile %.2g, max %.2g; exact allows %.2g, %.2g)",
            double(report.exactnessP99), double(report.exactnessMax), double(exactTolerance), double(2.0f * exactTolerance));
        report.reason = text;
    }
    for (std::size_t k = 1; k < report.flags.size(); ++k)
        report.reason += std::string("; also ") + findingName(report.flags[k].finding) + ": " + report.flags[k].evidence;
}

// Findings beside the verdict: a mesh's uncertain sign, and warnings that go with any verdict.
void addFindingsBesideTheVerdict(const shaders::PreparedSdf& sdf, const AuditPasses& p, values::AuditReport& report) {
    char text[256];
    // A mesh's sign where its winding number is no clear inside or outside: a finding beside the
    // verdict (the field's distances may still be exact).
    if (sdf.mesh) {
        values::AuditFlag flag = signUncertainty(*sdf.mesh, p.random[1]);
        if (flag.count > 0) {
            report.reason += std::string("; also ") + findingName(flag.finding) + ": " + flag.evidence;
            report.flags.push_back(std::move(flag));
        }
    }
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
}

Expected<values::AuditReport> auditOnce(const shaders::PreparedSdf& sdf, const AuditOptions& options,
                                        const ProgressSink& progress) {
    auto start = std::chrono::steady_clock::now();
    values::AuditReport report;
    report.samples = std::max<std::uint64_t>(options.samples, 64);
    auto passes = drawPasses(sdf, options, progress, report);
    if (!passes) return passes.error();
    measureQuotients(*passes, report);
    auto discontinuous = findDiscontinuities(sdf, options, *passes, report);
    if (!discontinuous) return discontinuous.error();
    estimateLipschitz(*passes, discontinuous->has_value(), report);
    if (auto ok = findTruncation(sdf, options, *passes, report); !ok) return ok.error();
    if (*discontinuous) report.flags.push_back(std::move(**discontinuous));
    measureExactness(*passes, report);
    flagNonFinite(*passes, report);
    settleVerdict(*passes, report);
    addFindingsBesideTheVerdict(sdf, *passes, report);
    report.seconds = secondsSince(start);
    return report;
}

} // namespace

Expected<values::AuditReport> auditField(const shaders::PreparedSdf& sdf, const AuditOptions& options,
                                         const ProgressSink& progress) {
    if (!sdf.ok()) return makeError("audit: the SDF has errors");
    std::vector<values::ConvergencePoint> convergence;
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

} // namespace sdfwb::sampling
