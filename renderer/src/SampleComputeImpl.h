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
    SampleUniforms uniforms;       // for the values computed on collection (CPU engine)
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
    bool meshLattice = true; // composed with the GLSL field's sign lattice (SampleCompute::build)
    bool positionsAreInputs(const SampleUniforms& uniforms) const {
        return pointsSampler && uniforms.inputPoints && uniforms.inputTableFloats == 0;
    }
    // The CPU engine's values and gradients at positions this program computed.
    Expected<std::uint32_t> evaluateRows(const SampleUniforms& uniforms, const float* positions, std::size_t positionStride,
                                         float* distances, std::size_t distanceStride, float* gradients,
                                         std::size_t gradientStride, std::uint32_t count) {
        meshfield::RowView rows{positions, positionStride, distances, distanceStride, gradients, gradientStride};
        meshfield::GradientMode mode{!uniforms.meshGradientTaps, uniforms.gradientStep};
        return std::uint32_t(query->evaluate(rows, count, mode, 0, &counters));
    }
    // issue() into run()'s region, then waits for it: the bad rows.
    Expected<std::uint32_t> dispatch(const SampleUniforms& uniforms, std::uint32_t first, std::uint32_t count, BufferSet& set,
                                     bool positions, bool gradients, const float* inputRows = nullptr);
    // A mesh's own field on the GLSL engine: neighbouring invocations whose points lie far apart
    // walk different nodes, so a chunk's rows are evaluated grouped by the cell of a lattice over
    // the mesh's Morton cube they lie in (sample.comp's SDFWB_SORT_ROWS: five dispatches a chunk,
    // all on the GPU) and written back in their own order. SDFWB_MESH_MORTON=0: one pass in the
    // sampler's order.
    bool sortRows = false;
    // Cells an axis: 2^1 .. 2^kMostBits. The cells' counts are added up in kSortParts parts, an
    // invocation each (sample.comp's SDFWB_SORT_PARTS): on a GPU a part's cells are read one
    // after another, so a few long parts would hold up the chunk.
    static constexpr std::uint32_t kMostBits = 6;
    static constexpr std::uint32_t kSortParts = 1024;
    float sortCube[4] = {}; // low corner, side
    GlBuffer sortWords;
    std::uint32_t sortCapacity = 0; // rows
    // The five passes of a chunk of `count` rows dispatched as gx by gy groups (issue()).
    Expected<void> dispatchSorted(std::uint32_t count, std::uint32_t gx, std::uint32_t gy);
    // A Metropolis sampler's chains (sampling/metropolis_chain.glsl): their steps (the initial
    // value of sdfwb_chainTo; 0 for other samplers) and the steps of each pass (0: one pass).
    int chainSteps = 0;
    int chainPassSteps = 0;
    GlBuffer chainStates;
    std::uint32_t chainCapacity = 0; // rows
    // The passes of a chunk's chains before their last, which the chunk's own dispatch runs.
    Expected<void> dispatchChainPasses(std::uint32_t count, std::uint32_t gx, std::uint32_t gy);
};

} // namespace sdfwb::renderer
