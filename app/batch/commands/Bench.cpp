// `sdfwb --batch bench`: runs the measurements of jobs/Benchmarks.h and writes the report,
// then draws the plots with bench/plot_benchmarks.py (matplotlib), started without a shell.
#include "Common.h"

#include <core/Log.h>
#include <core/Paths.h>
#include <jobs/JobJson.h>
#include <jobs/Protocol.h>

#include <spawn.h>
#include <sys/wait.h>

#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

extern char** environ;

namespace sdfwb::app {
namespace {

// Runs argv[0] (looked up on PATH) with the arguments; returns its exit status, -1 if it could not start.
int runProgram(const std::vector<std::string>& arguments) {
    std::vector<char*> argv;
    for (const std::string& a : arguments) argv.push_back(const_cast<char*>(a.c_str()));
    argv.push_back(nullptr);
    pid_t pid = 0;
    if (posix_spawnp(&pid, argv[0], nullptr, nullptr, argv.data(), environ) != 0) return -1;
    int status = 0;
    if (waitpid(pid, &status, 0) < 0) return -1;
    return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

} // namespace

int runBench(const values::BenchRequest& request, const OutputOptions& output) {
    if (auto error = jobs::validate(request)) return reportFailure(*error);
    auto context = makeContext();
    if (!context) return kExitNoGl;
    const char* names[] = {"sphere tracer", "samplers", "gradients", "audit"};
    if (!output.quiet) std::fprintf(stderr, "bench: %s ...\n", names[0]);
    ProgressSink progress{[&](std::uint64_t done, std::uint64_t total) {
                              if (output.protocol) {
                                  std::printf("%s\n", jobs::progressMessage(done, total).c_str());
                                  std::fflush(stdout);
                              }
                              if (!output.quiet && done < total && done < 4) std::fprintf(stderr, "bench: %s ...\n", names[done]);
                          },
                          nullptr};
    auto result = jobs::run(request, progress);
    if (!result) return reportFailure(result.error);
    values::BenchReport report = *result;
    if (!request.noPlots) {
        const std::filesystem::path script = paths::dataRoot() / "bench" / "plot_benchmarks.py";
        // Debian's interpreter has matplotlib; a pyenv one first on PATH may not.
        const std::string python = std::filesystem::exists("/usr/bin/python3") ? "/usr/bin/python3" : "python3";
        int status = runProgram({python, script.string(), report.csvDirectory, report.imageDirectory});
        if (status != 0) {
            printError("bench: the plots were not made ('" + python + " " + script.string() + "' " +
                       (status < 0 ? std::string("could not start") : "exited with " + std::to_string(status)) +
                       "; it needs python3-matplotlib); the tables are in " + report.markdown);
            return kExitFailure;
        }
        report.plotted = true;
    }
    if (output.json)
        printReport(jobs::toJson(report), output);
    else if (!output.quiet)
        std::printf("wrote %s (tables in %s, plots in %s)\n", report.markdown.c_str(), report.csvDirectory.c_str(),
                    report.imageDirectory.c_str());
    return kExitOk;
}

} // namespace sdfwb::app
