// `sdfwb --batch render`: one frame into an image file.
#include "Common.h"

namespace sdfwb::app {

int runRender(const values::RenderRequest& request, const OutputOptions& output) {
    return runWithGl(request, output, [](const values::RenderReport& r) {
        std::printf("wrote %s (%dx%d, %s shading, frame %.1f ms, total %.2f s)\n", r.output.c_str(), r.width, r.height,
                    r.shading.c_str(), r.frameMilliseconds, r.seconds);
    });
}

} // namespace sdfwb::app
