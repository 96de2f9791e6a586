#include <sampling/Sampler.h>

#include <core/Log.h>

#include <renderer/GlInfo.h>
#include <renderer/SampleCompute.h>

#include "OutputFile.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <condition_variable>
#include <cstdlib>
#include <deque>
#include <iterator>
#include <mutex>
#include <optional>
#include <thread>
#include <vector>
#ifdef __linux__
#include <sched.h>
#endif

namespace sdfwb::sampling {
namespace {

constexpr std::uint32_t kSmallestChunk = 4096;

// Runs the job chunk by chunk, `chunk` rows at a time. `submit(uniforms, first, done, count)`
// starts rows [done, done + count) of this run (global index first) and returns a token;
// `collect(token)` returns them as renderer::MappedRows once they are made; `consume(rows, count,
// token, done)` receives each chunk's rows in order, with the row of this run where they start. Up to `ahead` chunks are
// submitted before the oldest is collected, so a GPU computes the next while the host takes the last.
template <class Submit, class Collect, class Consume>
Expected<SamplingReport> run(const SamplingJob& job, std::uint32_t chunk, int ahead, Submit submit, Collect collect,
                             Consume consume, const ProgressSink& progress) {
    if (auto ok = validate(job); !ok) return ok.error();
    auto start = std::chrono::steady_clock::now();
    SamplingReport report;
    report.firstIndex = job.firstIndex();
    const std::uint64_t rows = job.rows();
    chunk = std::clamp(chunk, 1u, renderer::SampleCompute::kMaxChunk);
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
    struct InFlight {
        std::uint64_t done;
        std::uint32_t count;
        int token;
    };
    std::deque<InFlight> inFlight;
    // Collects the oldest chunk in flight; hands it on unless the run was cancelled.
    auto retire = [&](bool keep) -> Expected<void> {
        const InFlight oldest = inFlight.front();
        inFlight.pop_front();
        Expected<renderer::MappedRows> chunkRows = collect(oldest.token);
        if (!chunkRows) return chunkRows.error();
        if (!keep) return {};
        report.badRows += chunkRows->badRows;
        if (auto ok = consume(*chunkRows, oldest.count, oldest.token, oldest.done); !ok) return ok.error();
        report.rows = oldest.done + oldest.count;
        progress(report.rows, rows);
        return {};
    };
    progress(0, rows);
    for (std::uint64_t submitted = 0; submitted < rows;) {
        if (progress.isCancelled()) {
            report.cancelled = true;
            break;
        }
        while (inFlight.size() >= std::size_t(std::max(ahead, 1)))
            if (auto ok = retire(true); !ok) return ok.error();
        std::uint32_t count = std::uint32_t(std::min<std::uint64_t>(chunk, rows - submitted));
        Expected<int> token = makeError("");
        try {
            token = submit(uniforms, std::uint32_t(report.firstIndex + submitted), submitted, count);
        } catch (const std::bad_alloc&) {
            token = makeError("sampling: out of memory for a chunk of " + std::to_string(count) + " samples (" +
                              std::to_string(std::uint64_t(count) * 28u >> 20) + " MiB on the host)");
        }
        if (!token) {
            // Out of GPU/driver memory (or another failed dispatch): rows depend only on their
            // index, so the same rows can be made in smaller pieces. Halve down to 4096.
            if (count <= kSmallestChunk) return token.error();
            chunk = std::max(kSmallestChunk, count / 2);
            std::string message = token.error().message;
            if (message.rfind("sampling: ", 0) == 0) message.erase(0, 10);
            log::warning("sampling", message + "; continuing in chunks of " + std::to_string(chunk) + " samples");
            continue;
        }
        inFlight.push_back({submitted, count, *token});
        submitted += count;
    }
    while (!inFlight.empty())
        if (auto ok = retire(!report.cancelled); !ok) return ok.error();
    report.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return report;
}

// The chunk a job asks for, or the driver's when it leaves it (0).
std::uint32_t chunkFor(const SamplingJob& job, const renderer::SampleCompute& compute) {
    return job.chunkSize > 0 ? job.chunkSize : compute.preferredChunk();
}

// The cores this process may run on (empty where that cannot be asked).
std::vector<int> allowedCores() {
    std::vector<int> cores;
#ifdef __linux__
    cpu_set_t allowed;
    CPU_ZERO(&allowed);
    if (::sched_getaffinity(0, sizeof allowed, &allowed) == 0)
        for (int cpu = 0; cpu < CPU_SETSIZE; ++cpu)
            if (CPU_ISSET(cpu, &allowed)) cores.push_back(cpu);
#endif
    return cores;
}

// Keeps the calling thread on `core` (a refusal leaves it where it is).
void pinTo(int core) {
#ifdef __linux__
    cpu_set_t one;
    CPU_ZERO(&one);
    CPU_SET(core, &one);
    (void)::sched_setaffinity(0, sizeof one, &one);
#else
    (void)core;
#endif
}

// Writes chunk k while the GL thread computes the next chunks into the other mapped buffer sets
// of the ring (SampleCompute::pipeline().sets): the writer reads the rows where the shader (or the
// GPU's copy) left them. Four slots rather than two absorb the writer's uneven pace (a write that
// waits on the disk), so the GL thread seldom waits for a free slot. The first write error stops
// the run at the next chunk.
//
// Spread (the driver computes on the CPU and the file lies in memory, so writing is copying):
// llvmpipe splits every dispatch into equal shares, one per worker thread (one per core), fixed
// before they start, and the dispatch ends with its slowest share. A writer on one core delays
// that core's worker by all the time it writes while the other cores wait idle at the end: 0.2 of
// 1.2 core-seconds stood idle writing 20 M rows into tmpfs on 2 cores. So the writing goes in
// pieces to writer threads pinned one to a core, which take them in turn: every worker is
// delayed about equally. Otherwise one writer thread writes whole chunks.
class PipelinedWriter {
public:
    PipelinedWriter(SampleWriter& writer, int slots, bool spread) : m_writer(writer), m_slots(slots) {
        const std::vector<int> cores = spread ? allowedCores() : std::vector<int>();
        m_laneCount = cores.size() >= 2 ? std::min<std::size_t>(cores.size(), kPieces) : 1;
        for (std::size_t lane = 0; lane < m_laneCount; ++lane)
            m_lanes.emplace_back([this, lane, core = m_laneCount > 1 ? cores[lane] : -1] {
                if (core >= 0) pinTo(core);
                loop(lane);
            });
    }
    PipelinedWriter(const PipelinedWriter&) = delete;
    PipelinedWriter& operator=(const PipelinedWriter&) = delete;
    ~PipelinedWriter() {
        {
            std::lock_guard lock(m_mutex);
            m_stop = true;
        }
        m_changed.notify_all();
        for (std::thread& lane : m_lanes) lane.join();
    }

    // The slot the next chunk is computed into, once the writer no longer reads it. Slots are
    // taken in turn, so the chunks still on the GPU (fewer than the slots) are never taken.
    int acquire() {
        const auto start = std::chrono::steady_clock::now();
        std::unique_lock lock(m_mutex);
        m_changed.wait(lock, [&] { return !m_busy[m_next]; });
        m_waitSeconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        const int slot = m_next;
        m_next = (m_next + 1) % m_slots;
        return slot;
    }

    // The GL thread's time waiting in acquire(), and the writers' in their appends (after drain()).
    double waitSeconds() const { return m_waitSeconds; }
    double writeSeconds() {
        std::lock_guard lock(m_mutex);
        return m_writeSeconds;
    }

    // Hands the chunk computed into `slot` to the writer.
    Expected<void> submit(const renderer::MappedRows& rows, std::size_t n, int slot) {
        {
            std::lock_guard lock(m_mutex);
            if (m_error) return *m_error;
            m_busy[slot] = true;
            m_queue.push_back({rows, n, slot});
        }
        m_changed.notify_all();
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
        std::size_t done = 0; // rows appended
    };

    // Pieces a chunk when spread: against whole chunks on one thread, 8 pieces were faster in 28 of
    // 30 paired runs here (median 0.87-0.89 of the time); 4 pieces did as well as 8 (12 of 30
    // faster), 16 lost 28 of 30 to 8 (each hand-over wakes a thread on another core).
    static constexpr std::size_t kPieces = 8;

    // Rows a piece for a chunk of n rows: whole multiples of 1024 rows (4096-byte multiples in
    // every array), so that pieces keep the chunk's alignment for direct I/O.
    std::size_t pieceRows(std::size_t n) const {
        if (m_laneCount == 1) return n;
        return std::max<std::size_t>(1024, (n / kPieces + 1023) / 1024 * 1024);
    }

    // Writer thread `lane`: takes every m_laneCount-th piece, in order.
    void loop(std::size_t lane) {
        std::unique_lock lock(m_mutex);
        for (;;) {
            m_changed.wait(lock,
                           [&] { return (m_stop && m_queue.empty()) || (!m_queue.empty() && m_piece % m_laneCount == lane); });
            if (m_queue.empty()) return; // stopping with nothing left
            const Chunk chunk = m_queue.front();
            const std::size_t at = chunk.done, n = std::min(pieceRows(chunk.n), chunk.n - at);
            const bool skip = m_error.has_value();
            lock.unlock();
            Expected<void> ok;
            const auto start = std::chrono::steady_clock::now();
            const renderer::MappedRows& rows = chunk.rows;
            if (!skip)
                ok = rows.rows ? m_writer.appendRows(rows.rows + 7 * at, n)
                               : m_writer.append(rows.positions + 3 * at, rows.distances + at, rows.gradients + 3 * at, n);
            const double took = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
            lock.lock();
            m_writeSeconds += took;
            if (!ok && !m_error) m_error = ok.error();
            ++m_piece;
            if ((m_queue.front().done += n) == chunk.n) {
                m_busy[chunk.slot] = false;
                m_queue.pop_front();
            }
            m_changed.notify_all();
        }
    }

    SampleWriter& m_writer;
    const int m_slots;
    std::size_t m_laneCount = 1;
    bool m_busy[renderer::SampleCompute::kMaxSlots] = {};
    int m_next = 0;              // the slot the GL thread computes into next (its thread only)
    double m_waitSeconds = 0.0;  // GL thread only
    double m_writeSeconds = 0.0; // under m_mutex
    std::deque<Chunk> m_queue;   // the front chunk is being written, piece by piece
    std::size_t m_piece = 0;     // pieces written so far: lane m_piece % m_laneCount writes the next
    std::optional<Error> m_error;
    bool m_stop = false;
    std::mutex m_mutex;
    std::condition_variable m_changed;
    std::vector<std::thread> m_lanes; // last: they start after everything they use
};

} // namespace

Expected<void> validate(const SamplingJob& job) {
    if (job.count == 0) return makeError(key("n") + ": the sample count must be at least 1");
    if (job.count > 0xffffffffull)
        return makeError(
            key("n") + ": " + std::to_string(job.count) +
            " samples exceed the limit of 4294967295 per run (shard larger jobs into several runs with different seeds)");
    if (job.indexOffset + job.count > 0x100000000ull)
        return makeError(key("first_index") + ": " + std::to_string(job.indexOffset) + " + " + std::to_string(job.count) +
                         " samples pass the last sample index 4294967295");
    if (job.shardCount == 0 || job.shardIndex >= job.shardCount)
        return makeError(keys({"shard_index", "shard_count"}) + ": " + std::to_string(job.shardIndex) + "/" +
                         std::to_string(job.shardCount) + " is not a slice (0 <= K < COUNT)");
    if (!(job.gradientStep > 0.0f) || !std::isfinite(job.gradientStep))
        return makeError(key("gradient_step") + ": must be positive");
    if (!(job.surfaceTolerance > 0.0f) || !std::isfinite(job.surfaceTolerance))
        return makeError(key("surface_tolerance") + ": must be positive");
    return {};
}

// The GPU time of a run's dispatches and staging copies (SampleCompute's running totals, read
// before and after it; unset where the driver's timer cannot be trusted).
struct GpuTimes {
    const renderer::SampleCompute& compute;
    double kernel = compute.kernelMilliseconds(), copy = compute.copyMilliseconds();
    void into(SamplingReport& report) const {
        const double kernelAfter = compute.kernelMilliseconds(), copyAfter = compute.copyMilliseconds();
        if (kernel >= 0.0 && kernelAfter >= 0.0) report.kernelSeconds = (kernelAfter - kernel) / 1000.0;
        if (copy >= 0.0 && copyAfter >= 0.0) report.copySeconds = (copyAfter - copy) / 1000.0;
    }
};

// SDFWB_SAMPLE_RING=0: arrays in memory one chunk at a time through SampleCompute::run(), the
// path the ring replaced for them (tests compare the two bit for bit; benchmarks).
bool sampleIntoInOrder() {
    const char* setting = std::getenv("SDFWB_SAMPLE_RING");
    return setting && setting[0] == '0';
}

// Copies each chunk's rows out of the mapped buffers into the caller's arrays, split over
// `threads` threads kept for the whole run: on a GPU a chunk's copy takes a few milliseconds, and
// starting fifteen threads for each would cost a tenth of that. With one thread the caller copies.
class CopyCrew {
public:
    CopyCrew(std::size_t threads, float* positions, float* distances, float* gradients)
        : m_positions(positions), m_distances(distances), m_gradients(gradients) {
        try {
            for (std::size_t k = 1; k < threads; ++k) m_crew.emplace_back([this, k] { loop(k); });
        } catch (...) { // no thread to be had: the ones started end, and the caller hears why
            stop();
            throw;
        }
    }
    CopyCrew(const CopyCrew&) = delete;
    CopyCrew& operator=(const CopyCrew&) = delete;
    ~CopyCrew() { stop(); }

    // Rows [0, n) of `rows` to rows [at, at + n) of the arrays; returns when all are copied.
    void copy(const renderer::MappedRows& rows, std::size_t n, std::uint64_t at) {
        const std::size_t parts = std::min(m_crew.size() + 1, std::max<std::size_t>(1, n / 65536));
        {
            std::lock_guard lock(m_mutex);
            m_rows = rows;
            m_count = n;
            m_at = at;
            m_parts = parts;
            m_left = parts - 1;
            ++m_round;
        }
        if (parts > 1) m_start.notify_all();
        part(0);
        std::unique_lock lock(m_mutex);
        m_done.wait(lock, [&] { return m_left == 0; });
    }

private:
    void stop() {
        {
            std::lock_guard lock(m_mutex);
            m_stop = true;
        }
        m_start.notify_all();
        for (std::thread& thread : m_crew) thread.join();
    }
    void part(std::size_t k) {
        const std::size_t begin = m_count * k / m_parts, end = m_count * (k + 1) / m_parts;
        std::copy(m_rows.positions + 3 * begin, m_rows.positions + 3 * end, m_positions + 3 * (m_at + begin));
        std::copy(m_rows.distances + begin, m_rows.distances + end, m_distances + m_at + begin);
        std::copy(m_rows.gradients + 3 * begin, m_rows.gradients + 3 * end, m_gradients + 3 * (m_at + begin));
    }
    void loop(std::size_t k) {
        std::uint64_t seen = 0;
        for (;;) {
            {
                std::unique_lock lock(m_mutex);
                m_start.wait(lock, [&] { return m_stop || m_round != seen; });
                if (m_stop) return;
                seen = m_round;
                if (k >= m_parts) continue; // a small chunk: fewer parts than threads
            }
            part(k); // the fields are not written again before m_left reaches 0
            std::lock_guard lock(m_mutex);
            if (--m_left == 0) m_done.notify_one();
        }
    }

    float* m_positions;
    float* m_distances;
    float* m_gradients;
    std::vector<std::thread> m_crew;
    std::mutex m_mutex;
    std::condition_variable m_start, m_done;
    renderer::MappedRows m_rows{};
    std::size_t m_count = 0, m_parts = 1, m_left = 0;
    std::uint64_t m_at = 0, m_round = 0;
    bool m_stop = false;
};

// The copying threads of sampleInto's ring: every core on a GPU, one where the driver computes on
// the cores (they are busy with the next chunk), SDFWB_COPY_THREADS=N where set (tests); no more
// than a chunk has parts of 65,536 rows.
std::size_t copyThreads(std::uint64_t rows, std::uint32_t chunk) {
    std::size_t threads = renderer::softwareRasteriser() ? 1 : std::max(1u, std::thread::hardware_concurrency());
    if (const char* forced = std::getenv("SDFWB_COPY_THREADS"); forced && std::atoi(forced) > 0)
        threads = std::size_t(std::atoi(forced));
    return std::min<std::size_t>(threads, std::max<std::uint64_t>(1, std::min<std::uint64_t>(rows, chunk) / 65536));
}

// Every array asked for: the ring, as a file takes its rows (chunks computed ahead, each read
// where the shader or the GPU's copy left it once its fence has signalled), copied out here.
Expected<SamplingReport> sampleIntoRing(renderer::SampleCompute& compute, const SamplingJob& job, float* positions,
                                        float* distances, float* gradients, const ProgressSink& progress) {
    const renderer::SamplePipeline ring = compute.pipeline();
    CopyCrew crew(copyThreads(job.rows(), chunkFor(job, compute)), positions, distances, gradients);
    int next = 0; // a chunk is consumed before its slot comes round again (ahead <= sets - 2)
    auto submit = [&](const renderer::SampleUniforms& uniforms, std::uint32_t first, std::uint64_t,
                      std::uint32_t count) -> Expected<int> {
        const int slot = next;
        if (auto ok = compute.submitMapped(uniforms, first, count, slot); !ok) return ok.error();
        next = (next + 1) % ring.sets;
        return slot;
    };
    auto collect = [&](int slot) { return compute.collectMapped(slot); };
    auto consume = [&](const renderer::MappedRows& rows, std::size_t n, int, std::uint64_t done) -> Expected<void> {
        crew.copy(rows, n, done);
        return {};
    };
    const GpuTimes times{compute};
    auto report = run(job, chunkFor(job, compute), ring.ahead, submit, collect, consume, progress);
    if (report) times.into(*report);
    return report;
}

Expected<SamplingReport> sampleInto(renderer::SampleCompute& compute, const SamplingJob& job, float* positions, float* distances,
                                    float* gradients, const ProgressSink& progress) {
    if (positions && gradients && !sampleIntoInOrder())
        return sampleIntoRing(compute, job, positions, distances, gradients, progress);
    // One chunk at a time, each finished before the next (the rows go to the caller's arrays).
    std::uint32_t lastBad = 0;
    auto submit = [&](const renderer::SampleUniforms& uniforms, std::uint32_t first, std::uint64_t done,
                      std::uint32_t count) -> Expected<int> {
        auto bad = compute.run(uniforms, first, count, positions ? positions + 3 * done : nullptr, distances + done,
                               gradients ? gradients + 3 * done : nullptr);
        if (!bad) return bad.error();
        lastBad = *bad;
        return 0;
    };
    auto collect = [&](int) -> Expected<renderer::MappedRows> {
        return renderer::MappedRows{nullptr, nullptr, nullptr, lastBad};
    };
    auto consume = [](const renderer::MappedRows&, std::size_t, int, std::uint64_t) -> Expected<void> { return {}; };
    const GpuTimes times{compute};
    auto report = run(job, chunkFor(job, compute), 1, submit, collect, consume, progress);
    if (report) times.into(*report);
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
    const renderer::SamplePipeline ring = compute.pipeline();
    // The writer spreads its copying over the cores when the driver computes on them and the file
    // lies in memory; into a file on a disk it mostly waits for the disk, in writes best kept
    // large. SDFWB_SPREAD_WRITER=0 keeps it where the scheduler puts it (for benchmarks).
    const char* setting = std::getenv("SDFWB_SPREAD_WRITER");
    const bool spread =
        renderer::softwareRasteriser() && detail::OutputFile::inMemory(path.parent_path()) && !(setting && setting[0] == '0');
    PipelinedWriter pipeline(**writer, ring.sets, spread);
    const renderer::RowLayout layout = (*writer)->takesRows() ? renderer::RowLayout::Interleaved : renderer::RowLayout::Separate;
    auto submit = [&](const renderer::SampleUniforms& uniforms, std::uint32_t first, std::uint64_t done,
                      std::uint32_t count) -> Expected<int> {
        const int slot = pipeline.acquire();
        if (auto ok = compute.submitMapped(uniforms, first, count, slot, layout, (*writer)->arrayShift(done)); !ok)
            return ok.error();
        return slot;
    };
    auto collect = [&](int slot) { return compute.collectMapped(slot); };
    auto consume = [&](const renderer::MappedRows& rows, std::size_t n, int slot, std::uint64_t) {
        return pipeline.submit(rows, n, slot);
    };
    const GpuTimes times{compute};
    const std::uint32_t chunk = chunkFor(job, compute);
    log::info("sampling", "chunks of " + std::to_string(std::min<std::uint64_t>(chunk, job.rows())) + " rows, " +
                              std::to_string(ring.ahead) + " on the GPU ahead of the one collected, a ring of " +
                              std::to_string(ring.sets) + (ring.staging ? " (copied into mapped host buffers)" : ""));
    auto report = run(job, chunk, ring.ahead, submit, collect, consume, progress);
    if (auto ok = pipeline.drain(); !ok) return ok.error();
    if (!report) return report;
    times.into(*report);
    report->writeSeconds = pipeline.writeSeconds();
    report->waitSeconds = pipeline.waitSeconds();
    if (!report->cancelled)
        if (auto ok = (*writer)->commit(); !ok) return ok.error();
    // End to end: the last chunk's writing and the flush to disk included.
    report->seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return report; // a cancelled writer is dropped here: its temporary file is removed
}

} // namespace sdfwb::sampling
