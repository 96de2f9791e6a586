#pragma once
// What every batch command shares: the failure messages and exit codes, a headless GL context,
// and a scope that gives the job a progress bar, "progress" lines and Ctrl-C as cancellation.

#include "../BatchCommands.h"

#include <jobs/Jobs.h>
#include <renderer/HeadlessContext.h>

#include <chrono>
#include <memory>

namespace sdfwb::app {

// Prints the failure (the SDF's diagnostics first) and returns its exit code.
int reportFailure(const jobs::JobError& error);

// A headless GL context, or null after printing why (the caller exits kExitNoGl).
std::unique_ptr<renderer::HeadlessContext> makeContext();

// While alive: a one-line progress bar on a terminal's stderr (at most 10 redraws a second, not
// with --quiet or --json), "progress DONE TOTAL" lines with --progress-lines, and SIGINT/SIGTERM
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
    bool m_lines;
    bool m_drawn = false;
    CancelToken m_cancel;
    ProgressSink m_sink;
    std::chrono::steady_clock::time_point m_start = std::chrono::steady_clock::now();
    std::chrono::steady_clock::time_point m_lastDraw{};
    void (*m_previousInt)(int) = nullptr;
    void (*m_previousTerm)(int) = nullptr;
};

} // namespace sdfwb::app
