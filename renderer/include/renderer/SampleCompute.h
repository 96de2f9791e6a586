#pragma once
// Runs a sampler (a GLSL file defining samplePosition()) composed with an SDF as a compute
// shader, one invocation per sample, and reads the rows back. Needs a current GL 4.3 context
// for every call, including destruction (or call releaseGl() first).

#include <core/Expected.h>
#include <shaders/Diagnostic.h>
#include <shaders/Parameters.h>
#include <shaders/SdfSource.h>
#include <shaders/ShaderComposer.h>

#include <array>
#include <cstdint>
#include <memory>
#include <vector>

namespace sdfwb::meshfield {
struct QueryCounters;
} // namespace sdfwb::meshfield

namespace sdfwb::renderer {

struct SampleUniforms {
    std::uint32_t sampleCount = 0; // N of the whole run
    std::uint64_t seed = 0;
    float time = 0.0f;
    float gradientStep = 1e-3f;       // central-difference step of the written gradient
    float parameters[16] = {};        // u_parameters[4] (vec4s) for program-driven samplers
    float surfaceTolerance = 1e-5f;   // traceRay() (surface, near, metropolis) stops at |f| below this
    bool tetrahedralGradient = false; // written gradient by the tracer's 4-tap scheme, not 6-tap central
    // A mesh's own field writes its exact gradient (from the closest point: one nearest walk and
    // one sign a row); true asks for the six taps of gradientStep instead (a step the user gave).
    bool meshGradientTaps = false;
    // Points given by the caller (3 floats per sample, sampleCount of them, indexed globally), read
    // by the analysis/points.glsl sampler through sdfwb_inputPoint(); null for every other sampler.
    const float* inputPoints = nullptr;
    // Non-zero: inputPoints is one table of this many floats that every chunk reads whole, indexed
    // as its sampler chooses (the mesher's block corners), not 3 floats per sample.
    std::size_t inputTableFloats = 0;
    // The SDF's parameter values (the others keep their initializers' values).
    std::vector<shaders::ParameterSetting> sdfParameters;
};

struct MappedRows {
    const float* positions; // 3 per row (null in the interleaved layout)
    const float* distances;
    const float* gradients;      // 3 per row
    std::uint32_t badRows;       // rows with a NaN or infinity
    const float* rows = nullptr; // interleaved layout: x y z distance gx gy gz per row
};

// Rows with a NaN or infinity among `count` rows (null arrays are skipped), counted on the host:
// what the shader's counter gives, for when it cannot be trusted.
std::uint32_t countNonFiniteRows(const MappedRows& rows, std::uint32_t count);

// How runMapped() leaves a chunk's rows: three arrays, or one array of 7-float rows written so by
// the shader (what .ply stores, so the host copies it to the file as it is).
enum class RowLayout { Separate, Interleaved };

// How runMapped()'s chunks flow through the GL: chosen per driver unless a caller sets them
// (tests and benchmarks). Files are the same bit for bit whatever they are.
struct SamplePipeline {
    // Buffer sets in the ring (3 to SampleCompute::kMaxSlots): chunks on the GPU, the one the host
    // collects, the ones the writer still reads (not `slots`: a Qt macro).
    int sets = 4;
    // Chunks dispatched before the oldest is collected (1 to sets - 2). 0: per driver (1 where the
    // driver runs a dispatch on the CPU before it returns, as llvmpipe does; sets - 2 on a GPU).
    int ahead = 0;
    // -1: per driver (on a GPU: rows computed into GPU memory, then copied by the GPU into mapped
    // host buffers; on llvmpipe: computed into the mapped buffers, read in place). 0: off, 1: on.
    int staging = -1;
};

class SampleCompute {
public:
    // Largest chunk one dispatch may take: past 65,535 work groups of 64 the groups go in two
    // dimensions. 2^25 rows are 896 MiB of rows a buffer set.
    static constexpr std::uint32_t kMaxChunk = 1u << 25;
    // The chunk when a caller leaves it to the driver (0): 2^18 rows where the driver runs shaders
    // on the CPU (a chunk's rows stay in its cache), 2^21 on a GPU: 8 waves of an H200's 270,000
    // resident threads, and 56 MiB a buffer set, so a ring of mapped host buffers stays near
    // 224 MiB (with 2^24 rows a 5e7-row run held 1393 MiB resident on the H200, 2026-11-30).
    static constexpr std::uint32_t kSoftwareChunk = 1u << 18;
    static constexpr std::uint32_t kGpuChunk = 1u << 21;

    SampleCompute();
    ~SampleCompute();
    SampleCompute(const SampleCompute&) = delete;
    SampleCompute& operator=(const SampleCompute&) = delete;

    // Composes and compiles SDF + sampler; diagnostics name the user's files.
    std::vector<shaders::Diagnostic> build(const shaders::PreparedSdf& sdf, const shaders::ShaderPiece& sampler);

    // Samples global indices [first, first + count) into the given arrays (3*count, count,
    // 3*count floats). count <= kMaxChunk. Fails on GL errors (e.g. out of memory) with a message.
    // Null positions or gradients are neither written nor read back (no gradient evaluations).
    // Returns the number of rows with a NaN or infinity in a written value (counted on the GPU).
    Expected<std::uint32_t> run(const SampleUniforms& uniforms, std::uint32_t first, std::uint32_t count, float* positions,
                                float* distances, float* gradients);

    // The same rows (all three arrays), left where the shader (or the GPU's copy) wrote them:
    // buffer set `slot` (0 to pipeline().sets - 1) stays mapped, so nothing is copied on the host.
    // submitMapped() dispatches and returns at once; collectMapped() waits for that slot's fence
    // and returns its rows, valid until the next submitMapped() into the same slot, releaseGl() or
    // destruction. Several slots let chunks be computed while earlier ones are written out.
    // runMapped() is the two in one call.
    // In the separate layout, `shift` puts each array that many floats (below kMaxShift) after the
    // start of its page-aligned buffer: a file writer that asks so finds each array at the same
    // offset modulo a disk block as in its file, and can hand whole blocks to the disk directly.
    static constexpr int kMaxSlots = 8;
    static constexpr std::uint32_t kMaxShift = 1024;
    Expected<void> submitMapped(const SampleUniforms& uniforms, std::uint32_t first, std::uint32_t count, int slot,
                                RowLayout layout = RowLayout::Separate, std::array<std::uint32_t, 3> shift = {});
    Expected<MappedRows> collectMapped(int slot);
    Expected<MappedRows> runMapped(const SampleUniforms& uniforms, std::uint32_t first, std::uint32_t count, int slot,
                                   RowLayout layout = RowLayout::Separate, std::array<std::uint32_t, 3> shift = {});

    // The ring's settings: what was set, with what the driver chooses filled in (after build()).
    // Setting it waits for every chunk still on the GPU.
    void setPipeline(const SamplePipeline& pipeline);
    SamplePipeline pipeline() const;
    // kSoftwareChunk or kGpuChunk, by the driver of the current context.
    std::uint32_t preferredChunk() const;

    // The composed compute source (for tests and the log).
    const std::string& source() const;

    // "cpu" when build() chose the native CPU engine for a mesh's own field (the shader then
    // computes positions only, and meshfield::MeshQuery the values and gradients on every core),
    // "gpu" for a mesh field on the GL device, "" for any other SDF. See meshfield::chooseMeshEngine.
    const char* meshEngine() const;
    // The CPU engine's work since build(): hierarchy nodes its walks visited and how its rows got
    // their signs (meshfield::QueryCounters), a count that does not depend on the driver. The GLSL
    // field's when SDFWB_MESH_COUNT=1 was set at build() (nearest and winding nodes, and signs the
    // lattice gave, per field evaluation); zero otherwise.
    bool countsMeshWalks() const;
    // The GPU time of this program's dispatches since build(), by timer queries (the five
    // passes of a chunk sorted by cell included); -1 when a dispatch's timer read more than the
    // wall time around it.
    double kernelMilliseconds() const;
    // The GPU time of the staging copies into mapped host buffers since build() (0 without
    // staging; -1 where the driver's timer cannot be trusted, as kernelMilliseconds()).
    double copyMilliseconds() const;
    void addMeshCounters(meshfield::QueryCounters& into) const;

    void releaseGl();

private:
    struct Impl;
    std::unique_ptr<Impl> m_impl;
};

// The ceiling for rows a GPU hands back (issue 49): `bytes` copied by the GPU (glCopyBufferSubData)
// from GPU memory into a persistently mapped host buffer, `repeats` times after one warm-up copy;
// the median rate in bytes/s by the GPU's timer (-1 where the timer cannot be trusted) and by the
// wall clock up to the copy's fence. Fails with a message when the buffers cannot be had.
struct CopyRate {
    double timerBytesPerSecond = -1.0;
    double wallBytesPerSecond = 0.0;
};
Expected<CopyRate> measureCopyToHost(std::size_t bytes, int repeats = 5);

// Smallest n with n^3 >= count, and with n^2 >= count (exact integer arithmetic).
std::uint32_t cubeSide(std::uint64_t count);
std::uint32_t squareSide(std::uint64_t count);

} // namespace sdfwb::renderer
