// The plane readout: f on a grid over a plane through the box at three difference steps, its
// slopes, jumps, plateaus and NaNs, as findings with examples (the workbench's plane view and
// `--batch audit --plane`).

#include <sampling/FieldAudit.h>

#include "AuditRunner.h"

#include <sampling/AuditStatistics.h>

#include <glm/geometric.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <limits>
#include <utility>
#include <vector>

namespace sdfwb::sampling {
namespace {

using detail::finiteRow;
using detail::gradientLength;
using detail::Runner;
using detail::secondsSince;

// What the scan of the grid collects besides the readout's own figures.
struct PlaneScan {
    std::vector<float> slopes; // |grad f| at the middle step, at every finite point in the box
    std::uint64_t positive = 0, above = 0;
    std::vector<float> flat, jumps;
    std::vector<glm::vec3> flatPoints, jumpPoints, nanPoints;
    std::vector<std::pair<float, glm::vec3>> steep;
};

// The grid's points in the box: the readout's range, slopes and histogram, and what the findings need.
PlaneScan scanPlane(const SampleSet (&sets)[3], int resolution, float side, values::PlaneReadout& readout) {
    readout.histogram.assign(41, 0);
    readout.minimum = std::numeric_limits<float>::infinity();
    readout.maximum = -std::numeric_limits<float>::infinity();
    PlaneScan scan;
    auto pointAt = [](const SampleSet& set, std::size_t i) {
        return glm::vec3(set.positions[3 * i], set.positions[3 * i + 1], set.positions[3 * i + 2]);
    };
    for (std::size_t i = 0; i < sets[1].size(); ++i) {
        const float* p = &sets[1].positions[3 * i];
        if (std::max({std::abs(p[0]), std::abs(p[1]), std::abs(p[2])}) > 1.0f) continue;
        ++readout.points;
        if (!finiteRow(sets[1], i) || !finiteRow(sets[0], i)) {
            ++readout.nanCount;
            scan.nanPoints.push_back(glm::vec3(p[0], p[1], p[2]));
            continue;
        }
        float f = sets[1].distances[i];
        readout.minimum = std::min(readout.minimum, f);
        readout.maximum = std::max(readout.maximum, f);
        float slope = gradientLength(sets[1], i);
        scan.slopes.push_back(slope);
        scan.above += slope > 1.02f;
        if (slope > 1.05f) scan.steep.push_back({slope, pointAt(sets[1], i)});
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
            if (difference > 1.5f * spacing * std::max(slope, 0.1f) + 1e-5f) {
                ++readout.discontinuities;
                scan.jumps.push_back(difference - spacing * slope);
                scan.jumpPoints.push_back(0.5f * (pointAt(sets[2], i) + pointAt(sets[2], neighbour)));
            }
        }
        if (f > 0.0f) {
            ++scan.positive;
            if (coarse < 0.02f) {
                scan.flat.push_back(f);
                scan.flatPoints.push_back(pointAt(sets[1], i));
            }
        }
    }
    if (scan.slopes.empty()) {
        readout.minimum = readout.maximum = 0.0f;
    } else {
        readout.lipschitzMax = *std::max_element(scan.slopes.begin(), scan.slopes.end());
        readout.lipschitz99 = percentile(scan.slopes, 0.99);
        readout.shareAboveOne = double(scan.above) / double(scan.slopes.size());
    }
    if (scan.positive > 0 && double(scan.flat.size()) > 0.02 * double(scan.positive)) {
        float plateau = percentile(scan.flat, 0.05);
        if (plateau > 0.01f) readout.truncationDistance = plateau; // as in the volume audit
    }
    readout.safeStepFactor = 1.0f / std::max(readout.lipschitzMax, 1.0f);
    return scan;
}

// The findings, as the volume audit's (most severe first).
void addPlaneFlags(PlaneScan& scan, values::PlaneReadout& readout) {
    // Examples spread over the grid, not the first rows of it.
    auto spread = [](std::vector<glm::vec3>& points) {
        if (points.size() <= values::kMaxExamples) return;
        std::vector<glm::vec3> chosen;
        for (std::size_t k = 0; k < values::kMaxExamples; ++k)
            chosen.push_back(points[k * (points.size() - 1) / (values::kMaxExamples - 1)]);
        points = std::move(chosen);
    };
    spread(scan.nanPoints);
    spread(scan.jumpPoints);
    spread(scan.flatPoints);
    char text[256];
    if (readout.nanCount > 0) {
        values::AuditFlag flag{values::Finding::Nan,
                               "",
                               0.0f,
                               0.0f,
                               0.0f,
                               double(readout.nanCount) / double(std::max<std::uint64_t>(readout.points, 1)),
                               readout.nanCount,
                               scan.nanPoints};
        std::snprintf(text, sizeof text, "%llu of %llu plane points give NaN or Inf", (unsigned long long)readout.nanCount,
                      (unsigned long long)readout.points);
        flag.evidence = text;
        readout.flags.push_back(std::move(flag));
    }
    if (!scan.jumps.empty()) {
        values::AuditFlag flag{values::Finding::Discontinuous,
                               "",
                               percentile(scan.jumps, 0.5),
                               *std::max_element(scan.jumps.begin(), scan.jumps.end()),
                               0.0f,
                               double(scan.jumps.size()) / double(std::max<std::size_t>(scan.slopes.size(), 1)),
                               scan.jumps.size(),
                               scan.jumpPoints};
        std::snprintf(text, sizeof text, "f jumps by %.3g (median; largest %.3g) between %llu pairs of neighbouring grid points",
                      double(flag.value), double(flag.maximum), (unsigned long long)flag.count);
        flag.evidence = text;
        readout.flags.push_back(std::move(flag));
    }
    if (readout.truncationDistance) {
        values::AuditFlag flag{values::Finding::Truncated,
                               "",
                               *readout.truncationDistance,
                               percentile(scan.flat, 0.95),
                               0.0f,
                               double(scan.flat.size()) / double(scan.positive),
                               scan.flat.size(),
                               scan.flatPoints};
        std::snprintf(text, sizeof text,
                      "the field stops growing at about %.4g: |grad f| < 0.02 on %.3g %% of the plane outside the shape",
                      double(flag.value), 100.0 * flag.share);
        flag.evidence = text;
        readout.flags.push_back(std::move(flag));
    }
    if (readout.lipschitz99 > 1.05f) {
        std::sort(scan.steep.begin(), scan.steep.end(), [](const auto& a, const auto& b) { return a.first > b.first; });
        values::AuditFlag flag{values::Finding::NonConservative,
                               "",
                               readout.lipschitz99,
                               readout.lipschitzMax,
                               0.0f,
                               readout.shareAboveOne,
                               scan.steep.size(),
                               {}};
        for (std::size_t k = 0; k < scan.steep.size() && k < values::kMaxExamples; ++k)
            flag.examples.push_back(scan.steep[k].second);
        std::snprintf(text, sizeof text, "|grad f| reaches %.4g (99th percentile; largest %.4g) on the plane: step factor %.3g",
                      double(flag.value), double(flag.maximum), double(readout.safeStepFactor));
        flag.evidence = text;
        readout.flags.push_back(std::move(flag));
    }
}

} // namespace

Expected<values::PlaneReadout> analysePlane(const shaders::PreparedSdf& sdf, glm::vec3 normal, float offset, int resolution,
                                            float time, const std::vector<shaders::ParameterSetting>& sdfParameters,
                                            std::vector<shaders::Diagnostic>* diagnostics) {
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
    if (auto ok = runner.build(sdf, "analysis/plane_grid.glsl", sdfParameters, diagnostics); !ok) return ok.error();
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

    values::PlaneReadout readout;
    readout.resolution = resolution;
    PlaneScan scan = scanPlane(sets, resolution, side, readout);
    addPlaneFlags(scan, readout);
    readout.seconds = secondsSince(start);
    return readout;
}

} // namespace sdfwb::sampling
