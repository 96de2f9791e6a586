#include <sampling/Sampler.h>

#include <core/Log.h>

#include <renderer/SampleCompute.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <condition_variable>
#include <deque>
#include <iterator>
#include <mutex>
#include <optional>
#include <thread>
#include <vector>

namespace sdfwb::sampling {
namespace {

constexpr std::uint32_t kSmallestChunk = 4096;

// Runs the job chunk by chunk. `dispatch(uniforms, first, done, count)` computes rows [done,
// done + count) of this run (global index first) and returns them as renderer::MappedRows;
// `consume(rows, count)` receives each chunk's rows in order.
template <class Dispatch, class Consume>
Expected<SamplingReport> run(const SamplingJob& job, Dispatch dispatch, Consume consume, const ProgressSink& progress) {
    if (auto ok = validate(job); !ok) return ok.error();
    auto start = std::chrono::steady_clock::now();
    SamplingReport report;
    report.firstIndex = job.firstIndex();
    const std::uint64_t rows = job.rows();
    std::uint32_t chunk = std::min(job.chunkSize, renderer::SampleCompute::kMaxChunk);
    renderer::SampleUniforms uniforms;
    uniforms.sampleCount = std::uint32_t(job.count);
    uniforms.seed = job.seed;
    uniforms.time = job.time;
    uniforms.gradientStep = job.gradientStep;
    uniforms.meshGradientTaps = job.meshGradientTaps;
    std::copy(std::begin(job.parameters), std::end(job.parameters), uniforms.parameters);
    uniforms.surfaceTolerance = job.surfaceTolerance;
    uniforms.inputPoints = job.inputPoints;
    uniforms.inputTableFloats = job.inputTableFloats;
    uniforms.sdfParameters = job.sdfParameters;
    progress(0, rows);
    for (std::uint64_t done = 0; done < rows;) {
        if (progress.isCancelled()) {
            report.cancelled = true;
            break;
        }
        std::uint32_t count = std::uint32_t(std::min<std::uint64_t>(chunk, rows - done));
        Expected<renderer::MappedRows> chunkRows = makeError("");
        try {
            chunkRows = dispatch(uniforms, std::uint32_t(report.firstIndex + done), done, count);
        } catch (const std::bad_alloc&) {
            chunkRows = makeError("sampling: out of memory for a chunk of " + std::to_string(count) + " samples (" +
                                  std::to_string(std::uint64_t(count) * 28u >> 20) + " MiB on the host)");
        }
        if (!chunkRows) {
            // Out of GPU/driver memory (or another failed dispatch): rows depend only on their
            // index, so the same rows can be made in smaller pieces. Halve down to 4096.
            if (count <= kSmallestChunk) return chunkRows.error();
            chunk = std::max(kSmallestChunk, count / 2);
            std::string message = chunkRows.error().message;
            if (message.rfind("sampling: ", 0) == 0) message.erase(0, 10);
            log::warning("sampling", message + "; continuing in chunks of " + std::to_string(chunk) + " samples");
            continue;
        }
        report.badRows += chunkRows->badRows;
        if (auto ok = consume(*chunkRows, count); !ok) return ok.error();
        done += count;
        report.rows = done;
        progress(done, rows);
    }
    report.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return report;
}

// Writes chunk k on its own thread while the GL thread computes the next chunks into the other
// SampleCompute::kSlots mapped buffer sets: the writer reads the rows where the shader wrote them.
// Four slots rather than two absorb the writer's uneven pace (a write that waits on the disk), so
// the GL thread seldom waits for a free slot.
// The first write error stops the run at the next chunk.
class PipelinedWriter {
public:
    explicit PipelinedWriter(SampleWriter& writer) : m_writer(writer), m_thread([this] { loop(); }) {}
    PipelinedWriter(const PipelinedWriter&) = delete;
    PipelinedWriter& operator=(const PipelinedWriter&) = delete;
    ~PipelinedWriter() {
        {
            std::lock_guard lock(m_mutex);
            m_stop = true;
        }
        m_changed.notify_all();
        m_thread.join();
    }

    // The slot the next chunk is computed into, once the writer no longer reads it.
    int nextSlot() {
        const auto start = std::chrono::steady_clock::now();
        std::unique_lock lock(m_mutex);
        m_changed.wait(lock, [&] { return !m_busy[m_next]; });
        m_waitSeconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        return m_next;
    }

    // The GL thread's time waiting in nextSlot(), and the writer's in its appends (after drain()).
    double waitSeconds() const { return m_waitSeconds; }
    double writeSeconds() {
        std::lock_guard lock(m_mutex);
        return m_writeSeconds;
    }

    // Hands the chunk computed into nextSlot() to the writer.
    Expected<void> submit(const renderer::MappedRows& rows, std::size_t n) {
        {
            std::lock_guard lock(m_mutex);
            if (m_error) return *m_error;
            m_busy[m_next] = true;
            m_queue.push_back({rows, n, m_next});
        }
        m_changed.notify_all();
        m_next = (m_next + 1) % renderer::SampleCompute::kSlots;
        return {};
    }

    // Waits until every submitted chunk is written.
    Expected<void> drain() {
        std::unique_lock lock(m_mutex);
        m_changed.wait(lock, [&] {
            return m_queue.empty() && std::none_of(std::begin(m_busy), std::end(m_busy), [](bool busy) { return busy; });
        });
        if (m_error) return *m_error;
        return {};
    }

private:
    struct Chunk {
        renderer::MappedRows rows;
        std::size_t n;
        int slot;
    };

    void loop() {
        std::unique_lock lock(m_mutex);
        for (;;) {
            m_changed.wait(lock, [&] { return m_stop || !m_queue.empty(); });
            if (m_queue.empty()) return; // stopping with nothing left
            const Chunk chunk = m_queue.front();
            m_queue.pop_front();
            const bool skip = m_error.has_value();
            lock.unlock();
            Expected<void> ok;
            const auto start = std::chrono::steady_clock::now();
            if (!skip)
                ok = chunk.rows.rows ? m_writer.appendRows(chunk.rows.rows, chunk.n)
                                     : m_writer.append(chunk.rows.positions, chunk.rows.distances, chunk.rows.gradients, chunk.n);
            const double took = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
            lock.lock();
            m_writeSeconds += took;
            if (!ok && !m_error) m_error = ok.error();
            m_busy[chunk.slot] = false;
            m_changed.notify_all();
        }
    }

    SampleWriter& m_writer;
    bool m_busy[renderer::SampleCompute::kSlots] = {};
    int m_next = 0;              // the slot the GL thread computes into next (its thread only)
    double m_waitSeconds = 0.0;  // GL thread only
    double m_writeSeconds = 0.0; // under m_mutex
    std::deque<Chunk> m_queue;
    std::optional<Error> m_error;
    bool m_stop = false;
    std::mutex m_mutex;
    std::condition_variable m_changed;
    std::thread m_thread; // last: starts after everything it uses
};

} // namespace

Expected<void> validate(const SamplingJob& job) {
    if (job.count == 0) return makeError("'n': the sample count must be at least 1");
    if (job.count > 0xffffffffull)
        return makeError(
            "-n: " + std::to_string(job.count) +
            " samples exceed the limit of 4294967295 per run (shard larger jobs into several runs with different seeds)");
    if (job.indexOffset + job.count > 0x100000000ull)
        return makeError("first_index: " + std::to_string(job.indexOffset) + " + " + std::to_string(job.count) +
                         " samples pass the last sample index 4294967295");
    if (job.shardCount == 0 || job.shardIndex >= job.shardCount)
        return makeError("'shard_index', 'shard_count': " + std::to_string(job.shardIndex) + "/" +
                         std::to_string(job.shardCount) + " is not a slice (0 <= K < COUNT)");
    if (job.chunkSize == 0) return makeError("--chunk: must be at least 1");
    if (!(job.gradientStep > 0.0f) || !std::isfinite(job.gradientStep)) return makeError("'gradient_step': must be positive");
    if (!(job.surfaceTolerance > 0.0f) || !std::isfinite(job.surfaceTolerance))
        return makeError("'surface_tolerance': must be positive");
    return {};
}

Expected<SamplingReport> sampleInto(renderer::SampleCompute& compute, const SamplingJob& job, float* positions, float* distances,
                                    float* gradients, const ProgressSink& progress) {
    auto dispatch = [&](const renderer::SampleUniforms& uniforms, std::uint32_t first, std::uint64_t done,
                        std::uint32_t count) -> Expected<renderer::MappedRows> {
        auto bad = compute.run(uniforms, first, count, positions ? positions + 3 * done : nullptr, distances + done,
                               gradients ? gradients + 3 * done : nullptr);
        if (!bad) return bad.error();
        return renderer::MappedRows{nullptr, nullptr, nullptr, *bad};
    };
    auto consume = [](const renderer::MappedRows&, std::size_t) -> Expected<void> { return {}; };
    const double kernelBefore = compute.kernelMilliseconds();
    auto report = run(job, dispatch, consume, progress);
    const double kernelAfter = compute.kernelMilliseconds();
    if (report && kernelBefore >= 0.0 && kernelAfter >= 0.0) report->kernelSeconds = (kernelAfter - kernelBefore) / 1000.0;
    return report;
}

Expected<SamplingReport> sampleToFile(renderer::SampleCompute& compute, const SamplingJob& job, const std::filesystem::path& path,
                                      SampleFormat format, const SampleMetadata& metadata, const ProgressSink& progress) {
    if (auto ok = validate(job); !ok) return ok.error();
    const auto start = std::chrono::steady_clock::now();
    SampleMetadata full = metadata;
    full.seed = job.seed;
    full.time = job.time;
    full.firstIndex = job.firstIndex();
    full.totalCount = job.count;
    auto writer = SampleWriter::create(path, format, job.rows(), full);
    if (!writer) return writer.error();
    PipelinedWriter pipeline(**writer);
    const renderer::RowLayout layout = (*writer)->takesRows() ? renderer::RowLayout::Interleaved : renderer::RowLayout::Separate;
    auto dispatch = [&](const renderer::SampleUniforms& uniforms, std::uint32_t first, std::uint64_t done, std::uint32_t count) {
        return compute.runMapped(uniforms, first, count, pipeline.nextSlot(), layout, (*writer)->arrayShift(done));
    };
    auto consume = [&](const renderer::MappedRows& rows, std::size_t n) { return pipeline.submit(rows, n); };
    const double kernelBefore = compute.kernelMilliseconds();
    auto report = run(job, dispatch, consume, progress);
    if (auto ok = pipeline.drain(); !ok) return ok.error();
    if (!report) return report;
    const double kernelAfter = compute.kernelMilliseconds();
    if (kernelBefore >= 0.0 && kernelAfter >= 0.0) report->kernelSeconds = (kernelAfter - kernelBefore) / 1000.0;
    report->writeSeconds = pipeline.writeSeconds();
    report->waitSeconds = pipeline.waitSeconds();
    if (!report->cancelled)
        if (auto ok = (*writer)->commit(); !ok) return ok.error();
    // End to end: the last chunk's writing and the flush to disk included.
    report->seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return report; // a cancelled writer is dropped here: its temporary file is removed
}

} // namespace sdfwb::sampling
