// bench: the error-against-run-time report (Benchmarks.h); the plots are drawn by the caller.
#include <jobs/Benchmarks.h>
#include <jobs/Jobs.h>

#include <renderer/GlInfo.h>

namespace sdfwb::jobs {

JobResult<values::BenchReport> run(const values::BenchRequest& request, const ProgressSink& progress) {
    if (auto error = validate(request)) return *error;
    bench::BenchOptions options;
    options.outputDirectory = request.outputDirectory;
    options.repeats = request.repeats;
    options.quick = request.quick;
    options.glDescription = renderer::describe(renderer::queryGlInfo());
    options.commandLine = "sdfwb --batch bench" + std::string(request.quick ? " --quick" : "") + " -o " +
                          request.outputDirectory + " --repeats " + std::to_string(request.repeats);
    auto files = bench::runBenchmarks(options, progress);
    if (!files) return workError(files.error().keyed());
    values::BenchReport report;
    report.markdown = files->markdown.string();
    report.csvDirectory = files->csvDirectory.string();
    report.imageDirectory = files->imageDirectory.string();
    return report;
}

} // namespace sdfwb::jobs
