#include <sampling/Sampler.h>

#include <core/Log.h>

#include <renderer/SampleCompute.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <iterator>
#include <vector>

namespace sdfwb::sampling {
namespace {

std::uint64_t countBadRows(const float* positions, const float* distances, const float* gradients, std::size_t n) {
    std::uint64_t bad = 0;
    for (std::size_t i = 0; i < n; ++i) {
        bool finite = std::isfinite(distances[i]);
        for (int c = 0; c < 3 && finite; ++c)
            finite = (!positions || std::isfinite(positions[3 * i + std::size_t(c)])) &&
                     (!gradients || std::isfinite(gradients[3 * i + std::size_t(c)]));
        bad += !finite;
    }
    return bad;
}

constexpr std::uint32_t kSmallestChunk = 4096;

// Runs the job chunk by chunk; `consume` receives each chunk's rows in order.
template <class Target, class Consume>
Expected<SamplingReport> run(renderer::SampleCompute& compute, const SamplingJob& job, Target target, Consume consume,
                             const ProgressSink& progress) {
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
        float *positions = nullptr, *distances = nullptr, *gradients = nullptr;
        Expected<void> ok;
        try {
            auto pointers = target(done, count);
            positions = pointers.positions;
            distances = pointers.distances;
            gradients = pointers.gradients;
            ok = compute.run(uniforms, std::uint32_t(report.firstIndex + done), count, positions, distances, gradients);
        } catch (const std::bad_alloc&) {
            ok = makeError("sampling: out of memory for a chunk of " + std::to_string(count) + " samples (" +
                           std::to_string(std::uint64_t(count) * 28u >> 20) + " MiB on the host)");
        }
        if (!ok) {
            // Out of GPU/driver memory (or another failed dispatch): rows depend only on their
            // index, so the same rows can be made in smaller pieces. Halve down to 4096.
            if (count <= kSmallestChunk) return ok.error();
            chunk = std::max(kSmallestChunk, count / 2);
            std::string message = ok.error().message;
            if (message.rfind("sampling: ", 0) == 0) message.erase(0, 10);
            log::warning("sampling", message + "; continuing in chunks of " + std::to_string(chunk) + " samples");
            continue;
        }
        report.badRows += countBadRows(positions, distances, gradients, count);
        if (auto ok = consume(positions, distances, gradients, count); !ok) return ok.error();
        done += count;
        report.rows = done;
        progress(done, rows);
    }
    report.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return report;
}

struct Pointers {
    float* positions;
    float* distances;
    float* gradients;
};

} // namespace

Expected<void> validate(const SamplingJob& job) {
    if (job.count == 0) return makeError("-n: the sample count must be at least 1");
    if (job.count > 0xffffffffull)
        return makeError(
            "-n: " + std::to_string(job.count) +
            " samples exceed the limit of 4294967295 per run (shard larger jobs into several runs with different seeds)");
    if (job.indexOffset + job.count > 0x100000000ull)
        return makeError("first_index: " + std::to_string(job.indexOffset) + " + " + std::to_string(job.count) +
                         " samples pass the last sample index 4294967295");
    if (job.shardCount == 0 || job.shardIndex >= job.shardCount)
        return makeError("--shard: " + std::to_string(job.shardIndex) + "/" + std::to_string(job.shardCount) +
                         " is not a slice (0 <= K < COUNT)");
    if (job.chunkSize == 0) return makeError("--chunk: must be at least 1");
    if (!(job.gradientStep > 0.0f) || !std::isfinite(job.gradientStep)) return makeError("--gradient-step: must be positive");
    if (!(job.surfaceTolerance > 0.0f) || !std::isfinite(job.surfaceTolerance))
        return makeError("--surface-tolerance: must be positive");
    return {};
}

Expected<SamplingReport> sampleInto(renderer::SampleCompute& compute, const SamplingJob& job, float* positions, float* distances,
                                    float* gradients, const ProgressSink& progress) {
    auto target = [&](std::uint64_t done, std::uint32_t) {
        return Pointers{positions ? positions + 3 * done : nullptr, distances + done, gradients ? gradients + 3 * done : nullptr};
    };
    auto consume = [](const float*, const float*, const float*, std::size_t) -> Expected<void> { return {}; };
    return run(compute, job, target, consume, progress);
}

Expected<SamplingReport> sampleToFile(renderer::SampleCompute& compute, const SamplingJob& job, const std::filesystem::path& path,
                                      SampleFormat format, const SampleMetadata& metadata, const ProgressSink& progress) {
    if (auto ok = validate(job); !ok) return ok.error();
    SampleMetadata full = metadata;
    full.seed = job.seed;
    full.time = job.time;
    full.firstIndex = job.firstIndex();
    full.totalCount = job.count;
    auto writer = SampleWriter::create(path, format, job.rows(), full);
    if (!writer) return writer.error();
    std::vector<float> positions, distances, gradients;
    auto target = [&](std::uint64_t, std::uint32_t count) {
        for (std::vector<float>* v : {&positions, &distances, &gradients}) {
            const std::size_t size = (v == &distances ? 1 : 3) * std::size_t(count);
            v->resize(size);
            if (v->capacity() > 2 * size) v->shrink_to_fit(); // after a failed larger chunk: give the memory back
        }
        return Pointers{positions.data(), distances.data(), gradients.data()};
    };
    auto consume = [&](const float* p, const float* d, const float* g, std::size_t n) { return (*writer)->append(p, d, g, n); };
    auto report = run(compute, job, target, consume, progress);
    if (!report) return report;
    if (!report->cancelled)
        if (auto ok = (*writer)->commit(); !ok) return ok.error();
    return report; // a cancelled writer is dropped here: its temporary file is removed
}

} // namespace sdfwb::sampling
