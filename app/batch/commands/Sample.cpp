// `sdfwb --batch sample`: N rows of (position, distance, raw gradient) into .bin, .npz or .ply.
#include "Common.h"

namespace sdfwb::app {

int runSample(const jobs::SampleRequest& request, const OutputOptions& output) {
    return runWithGl(request, output, [](const jobs::SampleReport& r) {
        std::printf("wrote %s: %llu samples (%s, seed %llu, rows %llu..%llu of %llu), %llu bad rows, %.2f s (%.2f M samples/s)\n",
                    r.output.c_str(), (unsigned long long)r.rows, r.pattern.c_str(), (unsigned long long)r.seed,
                    (unsigned long long)r.firstIndex, (unsigned long long)(r.firstIndex + r.rows), (unsigned long long)r.count,
                    (unsigned long long)r.badRows, r.seconds, r.samplesPerSecond / 1e6);
        if (r.badRows > 0)
            std::fprintf(
                stderr, "sdfwb: note: %llu rows are NaN/Inf (rays that missed for surface/near, or a field that is not finite)\n",
                (unsigned long long)r.badRows);
    });
}

} // namespace sdfwb::app
