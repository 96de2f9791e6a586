#pragma once
// SampleCompute's private state, shared by its files: SampleCompute.cpp (build, run, dispatch)
// and SampleRing.cpp (the ring of mapped buffer sets). Private to renderer/.

#include <renderer/SampleCompute.h>

#include "GlObjects.h"

#include <meshfield/MeshQuery.h>
#include <renderer/GlInfo.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <string>
#include <unordered_map>

namespace sdfwb::renderer {

std::string glErrorName(GLenum error);

// The GPU's count of a chunk's non-finite rows, or the rows counted on the host when that count is
// impossible (above the chunk's rows). NVIDIA's driver 580 read back such counts on an H200
// (538976288 for 1e6 `near` rows of a mesh whose rows were all finite); the cause is not known.
std::uint32_t checkedBadRows(const MappedRows& rows, std::uint32_t count);

// Positions, distances and gradients of one dispatch, in one of three kinds of memory.
enum class BufferKind {
    ReadBack, // run(): read back with glGetBufferSubData
    Mapped,   // immutable, persistently and coherently mapped: the host reads the rows in place
    Device,   // immutable GPU memory, copied by the GPU into a Mapped set (staging)
};

struct BufferSet {
    GlBuffer buffers[3];
    const float* mapped[3] = {};
    std::uint32_t capacity = 0;
    bool interleaved = false; // buffers[0] holds 7-float rows; the other two are placeholders
    BufferKind kind = BufferKind::ReadBack;

    void reset() {
        for (GlBuffer& buffer : buffers) buffer.reset(); // deleting a buffer unmaps it
        for (const float*& pointer : mapped) pointer = nullptr;
        capacity = 0;
        interleaved = false;
        kind = BufferKind::ReadBack;
    }
    void release() {
        for (GlBuffer& buffer : buffers) buffer.release();
    }
};

// The counts one dispatch adds up (the rows with a non-finite value, then the GLSL mesh walks'
// counts under SDFWB_MESH_COUNT), read by the host through a persistent mapping once the
// dispatch's fence has signalled: no read-back that waits on each chunk.
constexpr int kCountWords = 6;

// A chunk that submitMapped() dispatched and collectMapped() has not yet returned.
struct PendingChunk {
    bool active = false;
    std::uint32_t count = 0;
    bool interleaved = false;
    bool staged = false; // the rows are in the staging set
    std::array<std::uint32_t, 3> shift{};
    const float* inputs = nullptr; // the caller's points (the CPU engine: nothing was dispatched)
    SampleUniforms uniforms;       // for the values computed on collection (CPU engine, values program)
    GLsync fence = nullptr;
    GpuTimer timer;     // the dispatch
    GpuTimer copyTimer; // staging: the GPU's copies into the mapped buffers
    std::chrono::steady_clock::time_point issued;

    void dropFence() {
        if (fence) glDeleteSync(fence);
        fence = nullptr;
    }
};

// Waits until `fence` has signalled (the driver is flushed on the first wait). False: the wait failed.
bool waitFor(GLsync fence);

struct SampleCompute::Impl {
    GlProgram program;
    BufferSet plain;              // run(): read back with glGetBufferSubData
    BufferSet slots[kMaxSlots];   // runMapped(): mapped, or on the GPU when staging
    BufferSet staging[kMaxSlots]; // staging: the mapped copies of `slots`
    PendingChunk pending[kMaxSlots];
    SamplePipeline settings; // as set (zeros and -1: per driver)
    // One region of kCountWords uints per slot and one for run(), at a stride the driver's
    // shader-storage offset alignment allows, mapped for good.
    GlBuffer counts;
    std::uint32_t* countWords = nullptr;
    GLsizeiptr countStride = 0;
    GlBuffer inputs;      // caller's points (analysis/points.glsl)
    SdfTextures textures; // g3d_uniformRandom and iChannel0..3, made when the program reads them
    std::array<std::string, shaders::kShadertoyChannels> channels; // the SDF's channel images
    std::shared_ptr<const meshfield::MeshField> mesh;              // a mesh SDF's triangles
    // The native engine for a mesh's own field (null: the GLSL field computes the values).
    std::shared_ptr<const meshfield::MeshQuery> query;
    const char* engine = "";
    meshfield::QueryCounters counters; // the CPU engine's, or the GLSL field's when counting, since build()
    bool countWalks = false;           // the GLSL mesh field counts its walks (SDFWB_MESH_COUNT=1)
    GpuTimer kernelTimer;
    double kernelMilliseconds = 0.0; // since build(); -1 once a timer could not be trusted
    double copyMilliseconds = 0.0;   // the staging copies' GPU time, the same way
    // With the CPU engine, each slot's rows on the host (the mapped buffers are read-only).
    std::vector<float> hostRows[kMaxSlots][3];
    std::string source;
    // Uniform locations, each asked of the driver once per program (issue 49: not per chunk).
    mutable std::unordered_map<std::string, GLint> locations;
    GLint location(const char* name) const {
        auto it = locations.find(name);
        if (it == locations.end()) it = locations.emplace(name, glGetUniformLocation(program.id(), name)).first;
        return it->second;
    }
    Expected<void> reserve(BufferSet& set, std::uint32_t count, BufferKind kind, bool interleaved = false);
    Expected<void> reserveCounts();
    int slotCount() const { return std::clamp(settings.sets, 3, kMaxSlots); }
    bool staged() const { return settings.staging < 0 ? !softwareRasteriser() : settings.staging > 0; }
    // Binds the uniforms and buffers, zeroes count region `region` and dispatches; waits for nothing.
    Expected<void> issue(const SampleUniforms& uniforms, std::uint32_t first, std::uint32_t count, BufferSet& set, bool positions,
                         bool gradients, bool interleaved, std::array<std::uint32_t, 3> shift, const float* inputRows,
                         int region);
    // Region `region`'s counts, once the dispatch that made them has finished: the bad rows.
    std::uint32_t takeCounts(int region);
    void finishPending();
    // The CPU engine's values and gradients at the positions; the rows with a non-finite value.
    // The sampler is analysis/points.glsl: its positions are the caller's points one for one (the
    // mesher's lattice also reads per-sample inputs when B = 0, but those are grid indices).
    bool pointsSampler = false;
    bool positionsAreInputs(const SampleUniforms& uniforms) const {
        return pointsSampler && uniforms.inputPoints && uniforms.inputTableFloats == 0;
    }
    // The values and gradients at positions this program computed: the CPU engine's, or `values`'s.
    Expected<std::uint32_t> evaluateRows(const SampleUniforms& uniforms, const float* positions, std::size_t positionStride,
                                         float* distances, std::size_t distanceStride, float* gradients,
                                         std::size_t gradientStride, std::uint32_t count) {
        if (query) {
            meshfield::RowView rows{positions, positionStride, distances, distanceStride, gradients, gradientStride};
            meshfield::GradientMode mode{!uniforms.meshGradientTaps, uniforms.gradientStep};
            return std::uint32_t(query->evaluate(rows, count, mode, 0, &counters));
        }
        // Contiguous positions go as they are; interleaved rows (.ply) are gathered first.
        std::vector<float> gathered, d(count), g(gradients ? 3 * std::size_t(count) : 0);
        if (positionStride != 3) {
            gathered.resize(3 * std::size_t(count));
            for (std::size_t i = 0; i < count; ++i)
                std::copy(positions + i * positionStride, positions + i * positionStride + 3, &gathered[3 * i]);
        }
        const float* xyz = positionStride == 3 ? positions : gathered.data();
        SampleUniforms at = uniforms;
        at.inputPoints = xyz;
        at.inputTableFloats = 0;
        auto bad = values->run(at, 0, count, nullptr, d.data(), gradients ? g.data() : nullptr);
        if (!bad) return bad;
        // A row whose position is not finite (a sampler's miss) is a NaN row, as on the one-pass path.
        std::uint32_t nonFinite = 0;
        const float nan = std::numeric_limits<float>::quiet_NaN();
        for (std::size_t i = 0; i < count; ++i) {
            const bool placed = std::isfinite(xyz[3 * i]) && std::isfinite(xyz[3 * i + 1]) && std::isfinite(xyz[3 * i + 2]);
            if (!placed) d[i] = nan;
            if (distances) distances[i * distanceStride] = d[i];
            if (gradients) {
                if (!placed) g[3 * i] = g[3 * i + 1] = g[3 * i + 2] = nan;
                std::copy(&g[3 * i], &g[3 * i] + 3, gradients + i * gradientStride);
            }
            const bool finite =
                placed && std::isfinite(d[i]) &&
                (!gradients || (std::isfinite(g[3 * i]) && std::isfinite(g[3 * i + 1]) && std::isfinite(g[3 * i + 2])));
            nonFinite += finite ? 0u : 1u;
        }
        return nonFinite;
    }
    // issue() into run()'s region, then waits for it: the bad rows.
    Expected<std::uint32_t> dispatch(const SampleUniforms& uniforms, std::uint32_t first, std::uint32_t count, BufferSet& set,
                                     bool positions, bool gradients, const float* inputRows = nullptr);
    // The GLSL mesh field at the caller's points (analysis/points.glsl): a mesh's walks diverge
    // less between neighbouring invocations, so the points go up in Morton order over the mesh's
    // box and the results come back to the caller's order. 1.4-1.7x the points/s on llvmpipe's
    // eight lanes (spot, teapot, bunny; 200,000 uniform points); wider GPU lanes gain more.
    bool mortonInputs = false;
    // A mesh's own field on the GPU engine: this program computes the positions, `values` (the
    // same SDF through analysis/points.glsl) the values in Morton order (runSorted).
    std::unique_ptr<SampleCompute> values;
    glm::dvec3 mortonLo{0.0};
    double mortonSide = 0.0;
    Expected<std::uint32_t> runSorted(const SampleUniforms& uniforms, std::uint32_t first, std::uint32_t count, float* positions,
                                      float* distances, float* gradients);
};

} // namespace sdfwb::renderer
