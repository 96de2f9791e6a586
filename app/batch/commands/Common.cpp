#include "Common.h"

#include <jobs/Protocol.h>

#include <algorithm>
#include <atomic>
#include <csignal>
#include <cstdio>
#include <optional>
#include <unistd.h>
#include <utility>
#include <variant>

namespace sdfwb::app {

namespace {
// Under the worker protocol a request's errors are gathered and sent once, at its end, with the
// kind its exit code tells (usage, no GL, cancelled) unless the job said.
std::atomic<bool> g_protocol{false};
std::optional<jobs::JobError> g_pendingError;
KeyTerms g_errorTerms; // empty: the request's own terms
} // namespace

ErrorTerms::ErrorTerms(KeyTerms terms) : m_previous(std::exchange(g_errorTerms, std::move(terms))) {}

ErrorTerms::~ErrorTerms() { g_errorTerms = std::move(m_previous); }

void setProtocolOutput(bool on) { g_protocol.store(on); }

void printError(const std::string& message) {
    if (g_protocol.load()) {
        if (!g_pendingError)
            g_pendingError = jobs::workError(message);
        else
            g_pendingError->message += (g_pendingError->message.empty() ? "" : "; ") + message;
        return;
    }
    std::fprintf(stderr, "sdfwb: %s\n", message.c_str());
}

int endProtocolRequest(int exitCode) {
    if (exitCode != kExitOk) {
        // The kind, decided here once for every reader: the exit code's where it tells one, else the job's.
        jobs::JobError error = g_pendingError.value_or(jobs::JobError{});
        if (exitCode == kExitUsage) error.failure = jobs::Failure::Usage;
        if (exitCode == kExitNoGl) error.failure = jobs::Failure::NoGl;
        if (exitCode == kExitCancelled) error.failure = jobs::Failure::Cancelled;
        if (error.message.empty()) error.message = "failed (exit code " + std::to_string(exitCode) + ")";
        std::printf("%s\n", jobs::errorMessage(error).c_str());
    }
    g_pendingError.reset();
    std::printf("%s\n", jobs::endMessage(exitCode).c_str());
    std::fflush(stdout);
    return exitCode;
}

void printReport(const std::string& json, const OutputOptions& output) {
    std::printf("%s\n", output.protocol ? jobs::reportMessage(json).c_str() : json.c_str());
    std::fflush(stdout);
}

int reportFailure(const jobs::JobError& error) {
    if (g_protocol.load()) {
        g_pendingError = error;
    } else {
        for (const shaders::Diagnostic& d : error.diagnostics) std::fprintf(stderr, "%s\n", shaders::formatDiagnostic(d).c_str());
        printError(g_errorTerms ? worded(error.message, error.keys, g_errorTerms) : error.message);
    }
    switch (error.failure) {
    case jobs::Failure::Usage:
        return kExitUsage;
    case jobs::Failure::Work:
        return kExitFailure;
    case jobs::Failure::NoGl:
        return kExitNoGl;
    case jobs::Failure::Cancelled:
        return kExitCancelled;
    }
    return kExitFailure;
}

std::unique_ptr<renderer::HeadlessContext> makeContext() {
    auto context = renderer::HeadlessContext::create();
    if (!context) {
        printError(context.error().message);
        return nullptr;
    }
    return std::move(*context);
}

namespace {

// Ctrl-C cancels the running job cleanly (the writers remove their temporary files).
std::atomic<CancelToken*> g_interruptToken{nullptr};

extern "C" void onInterrupt(int) {
    if (CancelToken* token = g_interruptToken.load()) token->cancel();
}

} // namespace

JobScope::JobScope(const OutputOptions& output)
    : m_bar(!output.quiet && !output.json && !output.protocol && ::isatty(STDERR_FILENO)),
      m_protocol(output.protocol), m_sink{[this](std::uint64_t done, std::uint64_t total) { draw(done, total); }, &m_cancel} {
    g_interruptToken.store(&m_cancel);
    m_previousInt = std::signal(SIGINT, onInterrupt);
    m_previousTerm = std::signal(SIGTERM, onInterrupt);
}

JobScope::~JobScope() {
    finish();
    std::signal(SIGINT, m_previousInt);
    std::signal(SIGTERM, m_previousTerm);
    g_interruptToken.store(nullptr);
}

void JobScope::draw(std::uint64_t done, std::uint64_t total) {
    if (m_protocol) {
        std::printf("%s\n", jobs::progressMessage(done, total).c_str());
        std::fflush(stdout);
    }
    if (!m_bar || total == 0) return;
    auto now = std::chrono::steady_clock::now();
    if (done < total && now - m_lastDraw < std::chrono::milliseconds(100)) return;
    m_lastDraw = now;
    const double seconds = std::chrono::duration<double>(now - m_start).count();
    const double fraction = double(done) / double(total);
    const int filled = int(fraction * 30.0);
    std::string bar(std::size_t(filled), '#');
    bar.append(std::size_t(30 - filled), ' ');
    const double rate = seconds > 0.0 ? double(done) / seconds : 0.0;
    std::fprintf(stderr, "\r%5.1f%% [%s] %llu/%llu  %.2f M/s ", 100.0 * fraction, bar.c_str(), (unsigned long long)done,
                 (unsigned long long)total, rate / 1e6);
    m_drawn = true;
}

void JobScope::finish() {
    if (m_drawn) std::fprintf(stderr, "\n");
    m_drawn = false;
}

int runRequest(const values::Request& request, const OutputOptions& output) {
    return std::visit(
        [&](const auto& r) -> int {
            using T = std::decay_t<decltype(r)>;
            if constexpr (std::is_same_v<T, values::RenderRequest>)
                return runRender(r, output);
            else if constexpr (std::is_same_v<T, values::AnimateRequest>)
                return runAnimate(r, output);
            else if constexpr (std::is_same_v<T, values::SampleRequest>)
                return runSample(r, output);
            else if constexpr (std::is_same_v<T, values::AuditRequest>)
                return runAudit(r, output);
            else if constexpr (std::is_same_v<T, values::MergeRequest>)
                return runMerge(r, output);
            else if constexpr (std::is_same_v<T, values::ListRequest>)
                return runList(r, output);
            else if constexpr (std::is_same_v<T, values::ParamsRequest>)
                return runParams(r, output);
            else if constexpr (std::is_same_v<T, values::MeshRequest>)
                return runMesh(r, output);
            else if constexpr (std::is_same_v<T, values::EvalRequest>)
                return runEval(r, output);
            else if constexpr (std::is_same_v<T, values::RunRequest>)
                return runRun(r, output);
            else if constexpr (std::is_same_v<T, values::ProbeRequest>)
                return runProbe(r, output);
            else
                return runBench(r, output);
        },
        request);
}

} // namespace sdfwb::app
