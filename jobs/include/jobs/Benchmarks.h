#pragma once
// Error against run time, measured in one run on this machine (`sdfwb --batch bench`):
//   tracer     hit error |t - t*| against steps and frame time (plain, over-relaxed, step factor)
//   samplers   distance of surface samples to the true surface, and error of the written f at
//              near samples, against time (surface tolerance 1e-2 .. 1e-6)
//   gradients  6-tap central against 4-tap tetrahedral differences against the step h, compared
//              with analytic gradients (angle and length error), with the time per dispatch
//   audit      the audit's Lipschitz estimate against samples and seconds, for known constants
// The references (exact intersections, distances and gradients, in double) are in References.h.
// A GL 4.3 context must be current on the calling thread.

#include <core/Expected.h>
#include <core/Progress.h>

#include <filesystem>
#include <string>

namespace sdfwb::bench {

struct BenchOptions {
    std::filesystem::path outputDirectory; // benchmarks.md, benchmarks/*.csv, images/bench_*.png
    int repeats = 5;                       // timed repeats per configuration
    bool quick = false;                    // smaller and fewer configurations (tests)
    std::string glDescription;             // the GL renderer, for the report's header
    std::string commandLine;               // how the report was made, for its header
};

struct BenchFiles {
    std::filesystem::path markdown;
    std::filesystem::path csvDirectory;
    std::filesystem::path imageDirectory;
};

// Runs the four benchmarks and writes benchmarks.md and the CSV tables (atomically). The plots
// are made afterwards from the CSVs by bench/plot_benchmarks.py (matplotlib).
Expected<BenchFiles> runBenchmarks(const BenchOptions& options, const ProgressSink& progress);

} // namespace sdfwb::bench
