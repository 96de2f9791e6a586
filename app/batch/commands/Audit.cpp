// `sdfwb --batch audit`: the field audit (verdict, every finding, figures), or one plane's readouts.
#include "Common.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

namespace sdfwb::app {
namespace {

void printFlags(const std::vector<values::AuditFlag>& flags) {
    if (flags.empty()) std::printf("  findings           none (no NaN/Inf, jump, plateau or |grad f| > 1.05 found)\n");
    for (const values::AuditFlag& f : flags) {
        std::printf("  %-18s %s\n", values::findingName(f.finding), f.evidence.c_str());
        if (f.examples.empty()) continue;
        std::printf("  %-18s", "");
        for (std::size_t k = 0; k < f.examples.size() && k < 4; ++k)
            std::printf(" (%.4g, %.4g, %.4g)", f.examples[k].x, f.examples[k].y, f.examples[k].z);
        std::printf("%s\n", f.examples.size() > 4 ? " ... (all in --json)" : "");
    }
}

std::string truncation(const std::optional<float>& distance) { return distance ? std::to_string(*distance) : "none"; }

void printPlane(const values::AuditJobReport& report) {
    const values::PlaneReadout& r = *report.readout;
    const values::PlaneSpec& p = *report.plane;
    std::printf("plane %.3g,%.3g,%.3g,%.3g of %s: %llu points (%dx%d grid), %.3f s\n", p.normal.x, p.normal.y, p.normal.z,
                p.offset, report.sdf.c_str(), (unsigned long long)r.points, r.resolution, r.resolution, r.seconds);
    std::printf("  value range        [%.4g, %.4g]\n", r.minimum, r.maximum);
    std::printf("  |grad f|           max %.4g, 99th percentile %.4g; %.2f %% of the plane above 1\n", r.lipschitzMax,
                r.lipschitz99, 100.0 * r.shareAboveOne);
    std::printf("  safe step factor   %.4g\n", r.safeStepFactor);
    std::printf("  truncation         %s\n", truncation(r.truncationDistance).c_str());
    std::printf("  discontinuities    %llu points\n  NaN/Inf            %llu points\n", (unsigned long long)r.discontinuities,
                (unsigned long long)r.nanCount);
    printFlags(r.flags);
}

std::string valuesText(const std::vector<shaders::ParameterValue>& values) {
    std::string text;
    for (const shaders::ParameterValue& v : values) text += (text.empty() ? "" : " ") + shaders::formatParameterValue(v);
    return text;
}

// One line per instance with a bar of its Lipschitz estimate ('|' marks L = 1: bars past it are
// not conservative): where along the family the field stops being safe to trace, at a glance.
void printFamily(const values::AuditJobReport& report) {
    std::printf("%s: %zu instances\n", report.sdf.c_str(), report.family.size());
    float largest = 2.0f;
    std::size_t width = 10;
    for (const values::AuditInstance& i : report.family) {
        largest = std::max(largest, std::isfinite(i.lipschitz) ? i.lipschitz : 0.0f);
        width = std::max(width, valuesText(i.parameters).size());
    }
    constexpr int kBar = 32;
    const int one = int(std::lround(kBar / largest));
    std::printf("  %-*s  %-16s %9s  %-*s  %7s  %s\n", int(width), "parameters", "verdict", "L", kBar + 1, "L (| = 1)", "seconds",
                "flags");
    double total = 0.0;
    for (const values::AuditInstance& i : report.family) {
        const int filled = std::isfinite(i.lipschitz) ? int(std::lround(std::min(i.lipschitz, largest) / largest * kBar)) : 0;
        std::string bar(std::size_t(kBar + 1), ' ');
        for (int k = 0; k < filled; ++k) bar[std::size_t(k)] = '#';
        bar[std::size_t(one)] = '|';
        std::string flags;
        for (values::Finding f : i.flags) flags += (flags.empty() ? "" : ",") + std::string(values::findingName(f));
        std::printf("  %-*s  %-16s %9.4g  %s  %7.2f  %s\n", int(width), valuesText(i.parameters).c_str(),
                    values::findingName(i.verdict), i.lipschitz, bar.c_str(), i.seconds, flags.empty() ? "-" : flags.c_str());
        total += i.seconds;
    }
    std::printf("  %.2f s in all\n", total);
}

void printVolume(const values::AuditJobReport& report) {
    const values::AuditReport& r = *report.volume;
    std::printf("%s: %s\n  %s\n\n", report.sdf.c_str(), values::findingName(r.verdict), r.reason.c_str());
    printFlags(r.flags);
    std::printf("\n");
    std::printf("  Lipschitz estimate   %.4g (a lower bound of the true constant; largest quotient seen %.4g, spread %.2g)\n",
                r.lipschitz, r.lipschitzMax, r.lipschitzUncertainty);
    std::printf("  safe step factor     %.4g\n", r.safeStepFactor);
    std::printf("  truncation           %s\n", truncation(r.truncationDistance).c_str());
    std::printf("  NaN/Inf fraction     %.3g +- %.2g\n", r.nanFraction, r.nanFractionError);
    std::printf("  discontinuities      %llu points (%.3g %%)\n", (unsigned long long)r.discontinuities,
                100.0 * r.discontinuityShare);
    std::printf("  eikonal error        mean %.3g, 95th percentile %.3g (near the surface)\n", r.eikonalMean, r.eikonalP95);
    std::printf("  exactness            | |f| - true distance |: 99th percentile %.3g, max %.3g; true distance known to +-%.2g\n",
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

} // namespace

int runAudit(const values::AuditRequest& request, const OutputOptions& output) {
    return runWithGl(request, output, [](const values::AuditJobReport& r) {
        if (!r.family.empty())
            printFamily(r);
        else if (r.readout)
            printPlane(r);
        else
            printVolume(r);
        if (r.family.empty() && !r.parameters.empty())
            std::printf("  parameters           %s\n", valuesText(r.parameters).c_str());
    });
}

} // namespace sdfwb::app
