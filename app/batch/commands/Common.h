#pragma once
// What every batch command shares: the failure messages and exit codes, a headless GL context,
// and a scope that gives the job a progress bar, "progress" lines and Ctrl-C as cancellation.

#include "../BatchCommands.h"

#include <jobs/JobJson.h>
#include <jobs/Jobs.h>
#include <renderer/HeadlessContext.h>

#include <chrono>
#include <cstdio>
#include <memory>

namespace sdfwb::app {

// Prints the failure (the SDF's diagnostics first, then the message, its keys worded by the
// ErrorTerms in effect: BatchCommands.h) and returns its exit code.
int reportFailure(const jobs::JobError& error);

// Prints a report's JSON on stdout: as it is, or as the worker protocol's report message.
void printReport(const std::string& json, const OutputOptions& output);

// A headless GL context, or null after printing why (the caller exits kExitNoGl).
std::unique_ptr<renderer::HeadlessContext> makeContext();

// While alive: a one-line progress bar on a terminal's stderr (at most 10 redraws a second, not
// with --quiet or --json), progress messages under the worker protocol, and SIGINT/SIGTERM
// cancelling the job through sink().
class JobScope {
public:
    explicit JobScope(const OutputOptions& output);
    ~JobScope();
    JobScope(const JobScope&) = delete;
    JobScope& operator=(const JobScope&) = delete;

    const ProgressSink& sink() const { return m_sink; }
    // Ends the bar's line (before the command prints its report).
    void finish();

private:
    void draw(std::uint64_t done, std::uint64_t total);

    bool m_bar;
    bool m_protocol;
    bool m_drawn = false;
    CancelToken m_cancel;
    ProgressSink m_sink;
    std::chrono::steady_clock::time_point m_start = std::chrono::steady_clock::now();
    std::chrono::steady_clock::time_point m_lastDraw{};
    void (*m_previousInt)(int) = nullptr;
    void (*m_previousTerm)(int) = nullptr;
};

// The common run of a command that needs GL: validate (exit 2 before any work), make the context
// (exit 3), run with a JobScope, then print the report's JSON (--json) or `printText(report)`.
template <class Request, class PrintText>
int runWithGl(const Request& request, const OutputOptions& output, PrintText printText) {
    if (auto error = jobs::validate(request)) return reportFailure(*error);
    auto context = makeContext();
    if (!context) return kExitNoGl;
    JobScope scope(output);
    auto result = jobs::run(request, scope.sink());
    scope.finish();
    if (!result) return reportFailure(result.error);
    if (output.json)
        printReport(jobs::toJson(*result), output);
    else if (!output.quiet)
        printText(*result);
    return kExitOk;
}

} // namespace sdfwb::app
