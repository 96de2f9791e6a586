// `sdfwb --batch render`: one frame into an image file.
#include "Common.h"

#include <jobs/JobJson.h>

#include <cstdio>

namespace sdfwb::app {

int runRender(const jobs::RenderRequest& request, const OutputOptions& output) {
    if (auto error = jobs::validate(request)) return reportFailure(*error);
    auto context = makeContext();
    if (!context) return kExitNoGl;
    JobScope scope(output);
    auto result = jobs::run(request, scope.sink());
    scope.finish();
    if (!result) return reportFailure(result.error);
    const jobs::RenderReport& r = *result;
    if (output.json)
        std::printf("%s\n", jobs::toJson(r).c_str());
    else if (!output.quiet)
        std::printf("wrote %s (%dx%d, %s shading, frame %.1f ms, total %.2f s)\n", r.output.c_str(), r.width, r.height,
                    r.shading.c_str(), r.frameMilliseconds, r.seconds);
    return kExitOk;
}

} // namespace sdfwb::app
