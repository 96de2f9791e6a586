// `sdfwb --batch animate`: frames over time and/or a turntable into an H.264 MP4.
#include "Common.h"

#include <jobs/JobJson.h>

#include <cstdio>

namespace sdfwb::app {

int runAnimate(const jobs::AnimateRequest& request, const OutputOptions& output) {
    if (auto error = jobs::validate(request)) return reportFailure(*error);
    auto context = makeContext();
    if (!context) return kExitNoGl;
    JobScope scope(output);
    auto result = jobs::run(request, scope.sink());
    scope.finish();
    if (!result) return reportFailure(result.error);
    const jobs::AnimateReport& r = *result;
    if (output.json)
        std::printf("%s\n", jobs::toJson(r).c_str());
    else if (!output.quiet)
        std::printf("wrote %s (%d frames at %d fps, %dx%d, H.264; rendering %.2f s, total %.2f s)\n", r.output.c_str(), r.frames,
                    r.framesPerSecond, r.width, r.height, r.renderSeconds, r.seconds);
    return kExitOk;
}

} // namespace sdfwb::app
