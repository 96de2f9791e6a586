// `sdfwb --batch sample`: N rows of (position, distance, raw gradient) into .bin, .npz or .ply.
#include "Common.h"

namespace sdfwb::app {

int runSample(const values::SampleRequest& request, const OutputOptions& output) {
    return runWithGl(request, output, [](const values::SampleReport& r) {
        if (!r.instances.empty()) {
            std::printf("wrote %zu instances of %s: %llu samples each (%s, seed %llu), index %s, %llu bad rows, %.2f s (%.2f M "
                        "samples/s)\n",
                        r.instances.size(), r.sdf.c_str(), (unsigned long long)r.count, r.pattern.c_str(),
                        (unsigned long long)r.seed, r.index.c_str(), (unsigned long long)r.badRows, r.seconds,
                        r.samplesPerSecond / 1e6);
            for (std::size_t k = 0; k < r.instances.size(); ++k) {
                if (k == 8 && r.instances.size() > 10) {
                    std::printf("  ... (%zu more in the index)\n", r.instances.size() - 9);
                    k = r.instances.size() - 1;
                }
                const values::SampleInstance& i = r.instances[k];
                std::string values;
                for (const auto& v : i.parameters) values += " " + shaders::formatParameterValue(v);
                std::printf("  %s:%s\n", i.output.c_str(), values.c_str());
            }
        } else {
            // A GPU's timer queries: how much of the run the dispatches took (none on llvmpipe).
            char kernel[64] = "";
            if (r.kernelSeconds >= 0.0) std::snprintf(kernel, sizeof kernel, "; GPU kernels %.3f s", r.kernelSeconds);
            std::printf(
                "wrote %s: %llu samples (%s, seed %llu, rows %llu..%llu of %llu), %llu bad rows, %.2f s (%.2f M samples/s)%s\n",
                r.output.c_str(), (unsigned long long)r.rows, r.pattern.c_str(), (unsigned long long)r.seed,
                (unsigned long long)r.firstIndex, (unsigned long long)(r.firstIndex + r.rows), (unsigned long long)r.count,
                (unsigned long long)r.badRows, r.seconds, r.samplesPerSecond / 1e6, kernel);
        }
        if (r.badRows > 0)
            std::fprintf(stderr,
                         "sdfwb: note: %llu rows are NaN/Inf (rays that missed for surface/near, Metropolis chains the driver "
                         "cut short, or a field that is not finite)\n",
                         (unsigned long long)r.badRows);
    });
}

} // namespace sdfwb::app
