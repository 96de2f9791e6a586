// `sdfwb --batch run MANIFEST`: many shapes in one run, each item in a child process, recorded in
// a status file (resumable; failures isolated), sliced by --rank/--world-size.
#include "Common.h"

#include <jobs/JobJson.h>

#include <cstdio>

namespace sdfwb::app {

namespace {

std::string megabytes(std::uint64_t bytes) {
    char text[32];
    if (bytes < 1000000)
        std::snprintf(text, sizeof text, "%.1f kB", double(bytes) / 1e3);
    else
        std::snprintf(text, sizeof text, "%.1f MB", double(bytes) / 1e6);
    return text;
}

} // namespace

int runRun(const values::RunRequest& request, const OutputOptions& output) {
    if (auto error = jobs::validate(request)) return reportFailure(*error);
    const bool text = !output.json && !output.quiet;
    JobScope scope(OutputOptions{true, false, output.protocol}); // Ctrl-C cancels; no bar over the item lines
    auto result = jobs::run(request, scope.sink(), [&](const values::RunItemReport& r) {
        const bool failed = r.status == values::ItemStatus::Failed || r.status == values::ItemStatus::Timeout;
        if (!text && !(output.quiet && failed)) return;
        std::string outcome = values::itemStatusName(r.status);
        if (r.status == values::ItemStatus::Skipped)
            outcome += " (done before)";
        else if (r.status == values::ItemStatus::Done && !request.list)
            outcome += " in " + std::to_string(int(r.seconds * 1000.0 + 0.5)) + " ms, " + megabytes(r.bytes);
        else if (!r.error.empty())
            outcome += ": " + r.error;
        std::FILE* stream = text ? stdout : stderr;
        std::fprintf(stream, "[%llu] line %d %s %s -> %s: %s\n", (unsigned long long)r.index, r.line, r.task.c_str(),
                     r.sdf.c_str(), r.output.c_str(), outcome.c_str());
        std::fflush(stream);
    });
    scope.finish();
    if (!result) return reportFailure(result.error);
    const values::RunReport& r = *result;
    if (output.json) {
        printReport(jobs::toJson(r), output);
    } else if (text && !request.list) {
        std::printf("run %s (rank %u of %u): %llu of %llu items; %llu done, %llu skipped (done before), %llu failed in %.1f s: "
                    "%.0f shapes/hour, %s written (%.1f MB/s); status in %s\n",
                    r.manifest.c_str(), r.rank, r.worldSize, (unsigned long long)r.selected, (unsigned long long)r.items,
                    (unsigned long long)r.done, (unsigned long long)r.skipped, (unsigned long long)r.failed, r.seconds,
                    r.shapesPerHour, megabytes(r.bytesWritten).c_str(),
                    r.seconds > 0 ? double(r.bytesWritten) / 1e6 / r.seconds : 0.0, r.status.c_str());
    }
    return r.failed > 0 ? kExitFailure : kExitOk;
}

} // namespace sdfwb::app
