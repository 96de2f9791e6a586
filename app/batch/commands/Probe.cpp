// `sdfwb --batch probe`: the march debugger from the command line: every step of one pixel's ray.
#include "Common.h"

#include <jobs/JobJson.h>

#include <cstdio>

namespace sdfwb::app {

int runProbe(const values::ProbeRequest& request, const OutputOptions& output) {
    return runWithGl(request, output, [](const values::ProbeReport& r) {
        std::printf("probe %s, pixel (%d, %d) of %dx%d: %s\n", r.sdf.c_str(), r.x, r.y, r.width, r.height, r.reason.c_str());
        std::printf("  ray from (%.4g, %.4g, %.4g) along (%.4f, %.4f, %.4f); step factor %g, over-relaxation %g, budget %d\n",
                    double(r.origin.x), double(r.origin.y), double(r.origin.z), double(r.direction.x), double(r.direction.y),
                    double(r.direction.z), double(r.stepFactor), double(r.overRelaxation), r.maxSteps);
        std::printf("  %5s  %-14s %12s %13s %13s %9s  %s\n", "#", "event", "t", "f", "step", "|grad f|", "position");
        for (std::size_t k = 0; k < r.events.size(); ++k) {
            const values::ProbeStep& e = r.events[k];
            std::printf("  %5zu  %-14s %12.7g %13.6g %13.6g %9.4g  (%.5g, %.5g, %.5g)%s\n", k, values::marchEventName(e.event),
                        double(e.t), double(e.f), double(e.step), double(e.gradientLength), double(e.position.x),
                        double(e.position.y), double(e.position.z), e.overstep ? "  overstep: passed the surface" : "");
        }
        std::printf("  %llu oversteps, %llu fallbacks%s\n", (unsigned long long)r.oversteps, (unsigned long long)r.fallbacks,
                    r.dropped ? " (events past the recorder's capacity were dropped)" : "");
    });
}

} // namespace sdfwb::app
