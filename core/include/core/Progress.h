#pragma once
// Progress reporting and cancellation for long jobs. Jobs take a ProgressSink, poll
// isCancelled() between chunks and return "cancelled" as a value; threads belong to the caller.

#include <atomic>
#include <cstdint>
#include <functional>

namespace sdfwb {

// Shared between the thread that runs a job and the one that may cancel it. Thread-safe.
class CancelToken {
public:
    void cancel() { m_cancelled.store(true, std::memory_order_relaxed); }
    bool isCancelled() const { return m_cancelled.load(std::memory_order_relaxed); }

private:
    std::atomic<bool> m_cancelled{false};
};

// Called from the job's thread with work done so far out of total (same unit, e.g. samples).
using ProgressFunction = std::function<void(std::uint64_t done, std::uint64_t total)>;

struct ProgressSink {
    ProgressFunction report;             // may be empty
    const CancelToken* cancel = nullptr; // may be null: not cancellable

    void operator()(std::uint64_t done, std::uint64_t total) const {
        if (report) report(done, total);
    }
    bool isCancelled() const { return cancel && cancel->isCancelled(); }
};

} // namespace sdfwb
