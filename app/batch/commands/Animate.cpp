// `sdfwb --batch animate`: frames over time and/or a turntable into an H.264 MP4.
#include "Common.h"

namespace sdfwb::app {

int runAnimate(const values::AnimateRequest& request, const OutputOptions& output) {
    return runWithGl(request, output, [](const values::AnimateReport& r) {
        std::printf("wrote %s (%d frames at %d fps, %dx%d, H.264; rendering %.2f s, total %.2f s)\n", r.output.c_str(), r.frames,
                    r.framesPerSecond, r.width, r.height, r.renderSeconds, r.seconds);
    });
}

} // namespace sdfwb::app
