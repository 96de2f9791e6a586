#pragma once
// Runs a sampling job in chunks through renderer::SampleCompute (which must be built and whose
// GL context must be current on the calling thread). Rows depend only on (seed, global index),
// so any chunk size and any sharding give the same rows.

#include <core/Expected.h>
#include <core/Progress.h>
#include <sampling/SampleFile.h>
#include <shaders/Parameters.h>

#include <cstdint>
#include <filesystem>
#include <vector>

namespace sdfwb::renderer {
class SampleCompute;
}

namespace sdfwb::sampling {

struct SamplingJob {
    std::uint64_t count = 0; // N of the whole run
    std::uint64_t seed = 0;
    float time = 0.0f;            // for animated SDFs
    std::uint32_t shardIndex = 0; // this run writes slice shardIndex (0-based) of shardCount
    std::uint32_t shardCount = 1;
    std::uint32_t chunkSize = 0;        // samples per dispatch (28 bytes each); 0: the driver's (SampleCompute::preferredChunk)
    float gradientStep = 1e-3f;         // central-difference step of the written gradient
    bool meshGradientTaps = false;      // a mesh's own field: taps of gradientStep, not its exact gradient
    float parameters[16] = {};          // u_parameters for program-driven samplers (plane analysis)
    float surfaceTolerance = 1e-5f;     // |f| at which surface/near/metropolis rays stop (accuracy against time)
    const float* inputPoints = nullptr; // 3 * count floats for the analysis/points.glsl sampler (not owned)
    std::size_t inputTableFloats = 0;   // non-zero: inputPoints is a table every chunk reads whole (analysis/lattice.glsl)
    std::vector<shaders::ParameterSetting> sdfParameters; // the SDF's parameter values (others: defaults)
    // The first sample's index (a stream's batch g of B rows starts at g * B); shards slice after it.
    std::uint64_t indexOffset = 0;

    std::uint64_t firstIndex() const { return indexOffset + count * shardIndex / shardCount; }
    std::uint64_t rows() const { return count * (shardIndex + 1ull) / shardCount - count * shardIndex / shardCount; }
};

// Fails with a message naming the offending value (N, shard, chunk).
Expected<void> validate(const SamplingJob& job);

struct SamplingReport {
    std::uint64_t rows = 0; // rows produced (this shard)
    std::uint64_t firstIndex = 0;
    std::uint64_t badRows = 0; // rows with NaN or Inf anywhere (misses of surface/near, broken fields)
    double seconds = 0.0;
    bool cancelled = false;
    // Where the time went (issue 49): the dispatches' GPU time by timer queries (-1 where the
    // driver's timer cannot be trusted: llvmpipe's runs no later than the dispatch's own call),
    // and for a file the writer thread's time in its appends and the GL thread's time waiting for
    // the writer to free a buffer set.
    double kernelSeconds = -1.0;
    double copySeconds = -1.0; // the GPU's copies of the rows into mapped host buffers (staging), the same way
    double writeSeconds = 0.0;
    double waitSeconds = 0.0;
};

// Writes rows into caller-owned arrays of job.rows() rows (3n, n, 3n floats): no copies. Null
// positions or gradients are not computed (a field-only evaluation skips the gradient's taps).
Expected<SamplingReport> sampleInto(renderer::SampleCompute& compute, const SamplingJob& job, float* positions, float* distances,
                                    float* gradients, const ProgressSink& progress);

// Streams rows into `path` (atomic: nothing appears unless the run completes). A cancelled run
// returns a report with cancelled = true and leaves no file.
Expected<SamplingReport> sampleToFile(renderer::SampleCompute& compute, const SamplingJob& job, const std::filesystem::path& path,
                                      SampleFormat format, const SampleMetadata& metadata, const ProgressSink& progress);

} // namespace sdfwb::sampling
