#include "SampleComputeImpl.h"

#include <core/Log.h>
#include <meshfield/MeshQuery.h>
#include <renderer/GlInfo.h>
#include <renderer/SamplingBindings.h>
#include <shaders/DiagnosticParser.h>
#include <shaders/SdfSource.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <regex>
#include <string_view>
#include <unordered_map>

namespace sdfwb::renderer {

std::string glErrorName(GLenum error) {
    switch (error) {
    case GL_OUT_OF_MEMORY:
        return "GL_OUT_OF_MEMORY";
    case GL_INVALID_VALUE:
        return "GL_INVALID_VALUE";
    case GL_INVALID_OPERATION:
        return "GL_INVALID_OPERATION";
    case GL_INVALID_ENUM:
        return "GL_INVALID_ENUM";
    default:
        return "GL error " + std::to_string(error);
    }
}

// The GPU's count of a chunk's non-finite rows, or the rows counted on the host when that count is
// impossible (above the chunk's rows). NVIDIA's driver 580 read back such counts on an H200
// (538976288 for 1e6 `near` rows of a mesh whose rows were all finite); the cause is not known.
std::uint32_t checkedBadRows(const MappedRows& rows, std::uint32_t count) {
    if (rows.badRows <= count) return rows.badRows;
    log::warning("sampling", "the GPU's count of non-finite rows read back " + std::to_string(rows.badRows) + " for " +
                                 std::to_string(count) + " rows; counted them on the host instead");
    return countNonFiniteRows(rows, count);
}

std::uint32_t cubeSide(std::uint64_t count) {
    std::uint64_t n = std::uint64_t(std::cbrt(double(count)));
    while (n * n * n < count) ++n;
    while (n > 1 && (n - 1) * (n - 1) * (n - 1) >= count) --n;
    return std::uint32_t(std::max<std::uint64_t>(n, 1));
}

std::uint32_t squareSide(std::uint64_t count) {
    std::uint64_t n = std::uint64_t(std::sqrt(double(count)));
    while (n * n < count) ++n;
    while (n > 1 && (n - 1) * (n - 1) >= count) --n;
    return std::uint32_t(std::max<std::uint64_t>(n, 1));
}

bool waitFor(GLsync fence) {
    GLbitfield flags = GL_SYNC_FLUSH_COMMANDS_BIT;
    for (;;) {
        const GLenum result = glClientWaitSync(fence, flags, GLuint64(1000000000u));
        if (result == GL_ALREADY_SIGNALED || result == GL_CONDITION_SATISFIED) return true;
        if (result == GL_WAIT_FAILED) return false;
        flags = 0;
    }
}

Expected<void> SampleCompute::Impl::reserve(BufferSet& set, std::uint32_t count, BufferKind kind, bool interleaved) {
    if (count <= set.capacity && interleaved == set.interleaved && kind == set.kind) return {};
    set.reset();
    while (glGetError() != GL_NO_ERROR) {}
    // Mapped arrays, and the GPU arrays they copy, have room for runMapped()'s shift before their rows.
    const GLsizeiptr room = kind != BufferKind::ReadBack && !interleaved ? GLsizeiptr(kMaxShift) * 4 : 0;
    const GLsizeiptr sizes[3] = {GLsizeiptr(count) * (interleaved ? 28 : 12) + room,
                                 interleaved ? 4 : GLsizeiptr(count) * 4 + room, interleaved ? 4 : GLsizeiptr(count) * 12 + room};
    const GLbitfield access = GL_MAP_READ_BIT | GL_MAP_PERSISTENT_BIT | GL_MAP_COHERENT_BIT;
    for (int i = 0; i < 3; ++i) {
        GLuint id = 0;
        glGenBuffers(1, &id);
        set.buffers[i] = GlBuffer(id);
        glBindBuffer(GL_SHADER_STORAGE_BUFFER, id);
        if (kind == BufferKind::Mapped) {
            glBufferStorage(GL_SHADER_STORAGE_BUFFER, sizes[i], nullptr, access);
            set.mapped[i] = static_cast<const float*>(glMapBufferRange(GL_SHADER_STORAGE_BUFFER, 0, sizes[i], access));
        } else if (kind == BufferKind::Device) {
            glBufferStorage(GL_SHADER_STORAGE_BUFFER, sizes[i], nullptr, 0);
        } else {
            glBufferData(GL_SHADER_STORAGE_BUFFER, sizes[i], nullptr, GL_DYNAMIC_READ);
        }
    }
    glBindBuffer(GL_SHADER_STORAGE_BUFFER, 0);
    const GLenum error = glGetError();
    const bool mapped = kind == BufferKind::Mapped;
    if (error != GL_NO_ERROR || (mapped && (!set.mapped[0] || !set.mapped[1] || !set.mapped[2]))) {
        set.reset();
        return makeError("sampling: cannot allocate buffers for " + std::to_string(count) + " samples (" +
                         (error != GL_NO_ERROR ? glErrorName(error) : std::string("mapping failed")) +
                         "); try a smaller --chunk");
    }
    set.capacity = count;
    set.interleaved = interleaved;
    set.kind = kind;
    return {};
}

Expected<void> SampleCompute::Impl::reserveCounts() {
    if (countWords) return {};
    GLint alignment = 16;
    glGetIntegerv(GL_SHADER_STORAGE_BUFFER_OFFSET_ALIGNMENT, &alignment);
    alignment = std::max(alignment, 4);
    const GLsizeiptr words = GLsizeiptr(kCountWords) * 4;
    countStride = (words + alignment - 1) / alignment * alignment;
    const GLsizeiptr size = countStride * (kMaxSlots + 1);
    const GLbitfield access = GL_MAP_READ_BIT | GL_MAP_WRITE_BIT | GL_MAP_PERSISTENT_BIT | GL_MAP_COHERENT_BIT;
    while (glGetError() != GL_NO_ERROR) {}
    GLuint id = 0;
    glGenBuffers(1, &id);
    counts = GlBuffer(id);
    glBindBuffer(GL_SHADER_STORAGE_BUFFER, id);
    glBufferStorage(GL_SHADER_STORAGE_BUFFER, size, nullptr, access);
    countWords = static_cast<std::uint32_t*>(glMapBufferRange(GL_SHADER_STORAGE_BUFFER, 0, size, access));
    glBindBuffer(GL_SHADER_STORAGE_BUFFER, 0);
    if (const GLenum error = glGetError(); error != GL_NO_ERROR || !countWords) {
        counts.reset();
        countWords = nullptr;
        return makeError("sampling: cannot map the count buffer (" +
                         (error != GL_NO_ERROR ? glErrorName(error) : std::string("mapping failed")) + ")");
    }
    std::memset(countWords, 0, std::size_t(size));
    return {};
}

std::uint32_t SampleCompute::Impl::takeCounts(int region) {
    const std::uint32_t* words = countWords + std::size_t(region) * std::size_t(countStride) / 4;
    if (countWalks) {
        counters.nearestNodes += words[1];
        counters.windingNodes += words[2];
        counters.cachedSigns += words[3];
        counters.segmentNodes += words[4];
        counters.crossedSigns += words[5];
    }
    return words[0];
}

void SampleCompute::Impl::finishPending() {
    for (PendingChunk& chunk : pending) {
        if (chunk.fence) waitFor(chunk.fence);
        chunk.dropFence();
        chunk.timer.reset();
        chunk.copyTimer.reset();
        chunk.active = false;
    }
}

SampleCompute::SampleCompute() : m_impl(std::make_unique<Impl>()) {}

SampleCompute::~SampleCompute() {
    m_impl->program.release();
    m_impl->plain.release();
    for (BufferSet& set : m_impl->slots) set.release();
    for (BufferSet& set : m_impl->staging) set.release();
    for (PendingChunk& chunk : m_impl->pending) { // fences: the context is gone
        chunk.timer.release();
        chunk.copyTimer.release();
    }
    m_impl->counts.release();
    m_impl->inputs.release();
    m_impl->sortWords.release();
    m_impl->chainStates.release();
    m_impl->textures.release();
    m_impl->kernelTimer.release();
}

const std::string& SampleCompute::source() const { return m_impl->source; }

const char* SampleCompute::meshEngine() const { return m_impl->engine; }

double SampleCompute::kernelMilliseconds() const { return m_impl->kernelMilliseconds; }

double SampleCompute::copyMilliseconds() const { return m_impl->copyMilliseconds; }

bool SampleCompute::countsMeshWalks() const { return m_impl->countWalks; }

void SampleCompute::addMeshCounters(meshfield::QueryCounters& into) const {
    const meshfield::QueryCounters& c = m_impl->counters;
    into.nearestNodes += c.nearestNodes;
    into.windingNodes += c.windingNodes;
    into.cachedSigns += c.cachedSigns;
    into.crossedSigns += c.crossedSigns;
    into.segmentNodes += c.segmentNodes;
}

std::vector<shaders::Diagnostic> SampleCompute::build(const shaders::PreparedSdf& sdf, const shaders::ShaderPiece& sampler) {
    std::vector<shaders::Diagnostic> diagnostics = sdf.diagnostics;
    if (shaders::hasErrors(diagnostics)) return diagnostics;
    auto pieces = shaders::samplingStagePieces(sampler);
    if (!pieces) return {{"<sdfwb>", 0, 0, shaders::Severity::Error, pieces.error().message}};
    // A mesh's own field on a driver that runs shaders on the CPU anyway: the shader computes the
    // positions (so they are the GPU path's, bit for bit) and the native engine the values.
    std::shared_ptr<const meshfield::MeshQuery> query;
    const char* engine = "";
    if (sdf.mesh) {
        const char* rendererName = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
        const meshfield::MeshEngine chosen = meshfield::chooseMeshEngine(rendererName ? rendererName : "");
        engine = sdf.meshIsTheField ? meshfield::meshEngineName(chosen) : "gpu";
        if (sdf.meshIsTheField && chosen == meshfield::MeshEngine::Cpu) query = meshfield::meshQuery(sdf.mesh);
    }
    shaders::FeatureDefines features;
    // The GLSL engine on a mesh's own field: each chunk's rows grouped by where they lie, on the GPU
    // (Impl::sortRows). SDFWB_MESH_MORTON=0 keeps one pass in the sampler's order (benchmarks).
    // The H200 ran the earlier form, a Morton sort on the host between two programs, slower than
    // one pass (2026-11-30, docs/gpu.md: the bunny's rand 4.9 against 12.2 M rows/s): the host's
    // sort and copies, not the GPU, set its pace.
    const char* morton = std::getenv("SDFWB_MESH_MORTON");
    const bool sortRows = sdf.mesh && sdf.meshIsTheField && !query && !(morton && std::string_view(morton) == "0");
    if (query) features["SDFWB_POSITIONS_ONLY"] = "1";
    // A Metropolis sampler that reads only |f| walks a mesh's own field for its nearest distance alone.
    const std::string samplerCode = shaders::stripComments(sampler.text);
    static const std::regex magnitude(R"(\bconst\s+bool\s+sdfwb_chainReadsMagnitude\s*=\s*true\b)", std::regex::ECMAScript);
    const bool chainMagnitude = sdf.mesh && sdf.meshIsTheField && std::regex_search(samplerCode, magnitude);
    if (chainMagnitude) features["SDFWB_CHAIN_MAGNITUDE"] = "1";
    // The CPU engine's positions-only program computes no sign unless its sampler evaluates the
    // signed field itself (a call of its own, or a Metropolis chain on the signed field): else it
    // is composed without the sign lattice, which is neither built nor uploaded (33^3 took 0.14 s
    // of a 0.65 s run of 200,000 bunny rows on two cores). A field call the patterns below miss
    // stays right, only slower.
    static const std::regex call(R"(\b(sdfwb_sdf|sdfwb_valueAndGradient|sdfwb_meshSdf|sdfwb_meshInside)\s*\()",
                                 std::regex::ECMAScript);
    static const std::regex chain(R"(\bsdfwb_metropolisChain\s*\()", std::regex::ECMAScript);
    const bool lattice =
        !query || std::regex_search(samplerCode, call) || (!chainMagnitude && std::regex_search(samplerCode, chain));
    if (!lattice) features["SDFWB_MESH_NO_LATTICE"] = "1";
    if (sortRows) {
        features["SDFWB_SORT_ROWS"] = "1";
        features["SDFWB_SORT_PARTS"] = std::to_string(Impl::kSortParts) + "u";
    }
    // Benchmarks: the GLSL mesh field counts the nodes its walks visit (a count no driver changes).
    const char* count = std::getenv("SDFWB_MESH_COUNT");
    const bool countWalks = sdf.mesh && !query && count && std::string_view(count) == "1";
    if (countWalks) features["SDFWB_MESH_COUNT"] = "1";
    shaders::ComposedShader composed = shaders::composeSdfShader(sdf, shaders::Stage::Compute, *pieces, features);

    auto start = std::chrono::steady_clock::now();
    CompiledShader compiled = compileShader(GL_COMPUTE_SHADER, composed);
    diagnostics.insert(diagnostics.end(), compiled.diagnostics.begin(), compiled.diagnostics.end());
    if (shaders::hasErrors(diagnostics)) return diagnostics;
    for (shaders::Diagnostic& warning : driverLoopWarnings(sdf, composed)) diagnostics.push_back(std::move(warning));
    std::string log;
    GlProgram program = linkProgram({compiled.shader.id()}, log);
    if (!program) {
        diagnostics.push_back({composed.map.fileName(0), 0, 0, shaders::Severity::Error, "link failed: " + log});
        return diagnostics;
    }
    double milliseconds = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    log::info("sampling", "compiled " + sdf.source.map.fileName(0) + " with " + sampler.name + " in " +
                              std::to_string(int(milliseconds)) + " ms" +
                              (*engine ? std::string("; mesh engine: ") + engine : std::string()));
    // llvmpipe's loop budget (metropolis_chain.glsl): there a chain runs 8 steps a pass, which kept
    // metropolis_curvature's chains uncut on every shared mesh where one pass cut all of them
    // (spot after 41 steps). A GPU's driver has no such budget: one pass. SDFWB_CHAIN_PASS_STEPS
    // sets the steps a pass (0: one pass).
    m_impl->chainSteps = 0;
    if (GLint at = glGetUniformLocation(program.id(), "sdfwb_chainTo"); at >= 0)
        glGetUniformiv(program.id(), at, &m_impl->chainSteps);
    m_impl->chainPassSteps = softwareRasteriser() ? 8 : 0;
    if (const char* steps = std::getenv("SDFWB_CHAIN_PASS_STEPS"); steps && *steps)
        m_impl->chainPassSteps = std::max(0, std::atoi(steps));
    m_impl->program = std::move(program);
    m_impl->locations.clear();
    m_impl->source = std::move(composed.text);
    m_impl->channels = sdf.channels;
    m_impl->mesh = sdf.mesh;
    m_impl->query = std::move(query);
    m_impl->engine = engine;
    m_impl->counters = {};
    m_impl->countWalks = countWalks;
    // llvmpipe's and softpipe's timer queries end before the work they time (0 for a dispatch that
    // took seconds): no kernel time there.
    const bool software = softwareRasteriser();
    m_impl->kernelMilliseconds = software ? -1.0 : 0.0;
    m_impl->copyMilliseconds = software ? -1.0 : 0.0;
    m_impl->sortRows = sortRows;
    if (sortRows) {
        double side = 0.0;
        const glm::dvec3 lo = meshfield::mortonBoxCorner(*sdf.mesh, side);
        m_impl->sortCube[0] = float(lo.x);
        m_impl->sortCube[1] = float(lo.y);
        m_impl->sortCube[2] = float(lo.z);
        m_impl->sortCube[3] = float(side);
    }
    m_impl->pointsSampler = sampler.name == "sdfwb:analysis/points.glsl";
    m_impl->meshLattice = lattice;
    return diagnostics;
}

Expected<void> SampleCompute::Impl::issue(const SampleUniforms& uniforms, std::uint32_t first, std::uint32_t count,
                                          BufferSet& set, bool positions, bool gradients, bool interleaved,
                                          std::array<std::uint32_t, 3> shift, const float* inputRows, int region) {
    if (auto ok = reserveCounts(); !ok) return ok;
    glUseProgram(program.id());
    glUniform1ui(location("sdfwb_sampleCount"), uniforms.sampleCount);
    glUniform2ui(location("sdfwb_seed"), GLuint(uniforms.seed & 0xffffffffu), GLuint(uniforms.seed >> 32));
    glUniform1f(location("sdfwb_gradientStep"), uniforms.gradientStep);
    glUniform1ui(location("sdfwb_cubeSide"), cubeSide(uniforms.sampleCount));
    glUniform1ui(location("sdfwb_squareSide"), squareSide(uniforms.sampleCount));
    if (GLint at = location("sdfwb_time"); at >= 0) glUniform1f(at, uniforms.time);
    for (const char* name : {"g3d_SceneTime", "iTime"}) // declared by the file, or uniforms its macro wraps
        if (GLint at = location(name); at >= 0) glUniform1f(at, uniforms.time);
    // A GPU's long runs take the sign lattice of 65^3 points: the bunny's near rows walk 36 % fewer
    // nodes than with 33^3 (30.7 against 48.1 a row, rand 46.8 against 50.9; counted by the shader
    // on llvmpipe), for 0.8 s of two cores (0.1 s of sixteen) at the first chunk: worth it past a
    // few million rows, not for a DeepSDF-sized 500,000 (the default's 33^3 takes 0.1 s here).
    // A program composed without it (SDFWB_MESH_NO_LATTICE, see build()) gets none.
    textures.meshSignLevel = !meshLattice ? -1 : !softwareRasteriser() && uniforms.sampleCount >= (1u << 22) ? 6 : 0;
    bindSdfTextures(program.id(), textures, channels, mesh);
    if (GLint at = location("sdfwb_parameters"); at >= 0) glUniform4fv(at, 4, uniforms.parameters);
    if (GLint at = location("sdfwb_surfaceTolerance"); at >= 0) glUniform1f(at, uniforms.surfaceTolerance);
    if (GLint at = location("sdfwb_tetrahedralGradient"); at >= 0) glUniform1i(at, uniforms.tetrahedralGradient ? 1 : 0);
    if (GLint at = location("sdfwb_meshGradientTaps"); at >= 0) glUniform1i(at, uniforms.meshGradientTaps ? 1 : 0);
    applyParameters(uniforms.sdfParameters, [this](const char* name) { return location(name); });
    // A target not wanted is skipped by the shader (the gradient's six evaluations included).
    if (GLint at = location("sdfwb_writePosition"); at >= 0) glUniform1i(at, positions ? 1 : 0);
    if (GLint at = location("sdfwb_writeGradient"); at >= 0) glUniform1i(at, gradients ? 1 : 0);
    if (GLint at = location("sdfwb_interleaved"); at >= 0) glUniform1i(at, interleaved ? 1 : 0);
    if (GLint at = location("sdfwb_arrayShift"); at >= 0) glUniform3ui(at, shift[0], shift[1], shift[2]);
    glUniform1ui(location("sdfwb_chunkFirst"), first);
    glUniform1ui(location("sdfwb_chunkCount"), count);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kBindingPositions, set.buffers[0].id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kBindingDistances, set.buffers[1].id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kBindingGradients, set.buffers[2].id());
    // The region's last chunk has finished (its fence was waited on): zeroed through the mapping.
    std::uint32_t* words = countWords + std::size_t(region) * std::size_t(countStride) / 4;
    std::fill(words, words + kCountWords, 0u);
    glBindBufferRange(GL_SHADER_STORAGE_BUFFER, kBindingBadRows, counts.id(), GLintptr(region) * countStride,
                      GLsizeiptr(kCountWords) * 4);
    if (uniforms.inputPoints) {
        if (!inputs) {
            GLuint id = 0;
            glGenBuffers(1, &id);
            inputs = GlBuffer(id);
        }
        glBindBuffer(GL_SHADER_STORAGE_BUFFER, inputs.id());
        if (uniforms.inputTableFloats > 0)
            glBufferData(GL_SHADER_STORAGE_BUFFER, GLsizeiptr(uniforms.inputTableFloats * sizeof(float)), uniforms.inputPoints,
                         GL_STREAM_DRAW);
        else
            glBufferData(GL_SHADER_STORAGE_BUFFER, GLsizeiptr(count) * 12,
                         inputRows ? inputRows : uniforms.inputPoints + 3 * std::size_t(first), GL_STREAM_DRAW);
        glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kBindingInputs, inputs.id());
        glBindBuffer(GL_SHADER_STORAGE_BUFFER, 0);
    }
    // Past 65,535 groups of 64 (the least every driver allows in x), the groups go in rows of
    // gx; sample.comp numbers the invocations across them.
    const std::uint32_t groups = (count + 63u) / 64u;
    const std::uint32_t gx = std::clamp(groups, 1u, 65535u);
    if (auto ok = dispatchChainPasses(count, gx, (groups + gx - 1u) / gx); !ok) {
        glUseProgram(0);
        return ok;
    }
    if (sortRows) {
        if (auto ok = dispatchSorted(count, gx, (groups + gx - 1u) / gx); !ok) {
            glUseProgram(0);
            return ok;
        }
    } else {
        glDispatchCompute(gx, (groups + gx - 1u) / gx, 1);
    }
    glUseProgram(0);
    if (GLenum error = glGetError(); error != GL_NO_ERROR)
        return makeError("sampling: dispatch of " + std::to_string(count) + " samples failed (" + glErrorName(error) +
                         "); try a smaller --chunk");
    return {};
}

namespace {

// A scratch buffer of the GPU's own (no host access) grown to hold `rows` rows in `bytes`: kept
// while it is large enough, else made anew; a failed allocation leaves it empty and names `what`.
Expected<void> growScratch(GlBuffer& buffer, std::uint32_t& capacity, std::uint32_t rows, GLsizeiptr bytes, const char* what,
                           std::uint32_t count) {
    if (rows <= capacity && buffer) return {};
    GLuint id = 0;
    glGenBuffers(1, &id);
    buffer = GlBuffer(id);
    glBindBuffer(GL_SHADER_STORAGE_BUFFER, id);
    glBufferStorage(GL_SHADER_STORAGE_BUFFER, bytes, nullptr, 0);
    glBindBuffer(GL_SHADER_STORAGE_BUFFER, 0);
    capacity = rows;
    if (const GLenum error = glGetError(); error != GL_NO_ERROR) {
        buffer.reset();
        capacity = 0;
        return makeError("sampling: cannot allocate " + std::string(what) + " for " + std::to_string(count) + " samples (" +
                         glErrorName(error) + "); try a smaller --chunk");
    }
    return {};
}

} // namespace

Expected<void> SampleCompute::Impl::dispatchSorted(std::uint32_t count, std::uint32_t gx, std::uint32_t gy) {
    // About a row a cell over the cube, at most 64 cells an axis: on llvmpipe (the bunny, 200,000
    // rows, median of 3) 64 cells an axis ran rand 1.6x and near 1.7x as fast as one pass, 16 an
    // axis 1.4x and 1.7x. SDFWB_SORT_BITS=1..6 sets the bits an axis.
    std::uint32_t bits = 1;
    while (bits < kMostBits && (std::uint64_t(1) << (3 * (bits + 1))) <= std::uint64_t(count) * 2) ++bits;
    if (const char* forced = std::getenv("SDFWB_SORT_BITS"); forced && *forced)
        bits = std::clamp<std::uint32_t>(std::uint32_t(std::atoi(forced)), 1, kMostBits);
    const GLsizeiptr cellWords = GLsizeiptr(kSortParts) + (GLsizeiptr(1) << (3 * kMostBits));
    if (const GLenum error = glGetError(); error != GL_NO_ERROR) // from issue()'s own calls before this
        return makeError("sampling: dispatch of " + std::to_string(count) + " samples failed (" + glErrorName(error) + ")");
    // Per row: its cell, its slot's row and its position.
    if (auto ok = growScratch(sortWords, sortCapacity, count, (cellWords + GLsizeiptr(count) * 5) * 4, "the sort buffer", count);
        !ok)
        return ok;
    // The last chunk's passes have written and read the buffer before its counts are zeroed (a
    // buffer command after shader writes: the update bit).
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_BUFFER_UPDATE_BARRIER_BIT);
    const GLuint zero = 0;
    glBindBuffer(GL_SHADER_STORAGE_BUFFER, sortWords.id());
    glClearBufferSubData(GL_SHADER_STORAGE_BUFFER, GL_R32UI, GLintptr(kSortParts) * 4, (GLsizeiptr(1) << (3 * bits)) * 4,
                         GL_RED_INTEGER, GL_UNSIGNED_INT, &zero);
    glBindBuffer(GL_SHADER_STORAGE_BUFFER, 0);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kBindingSort, sortWords.id());
    glUniform1ui(location("sdfwb_sortBits"), bits);
    glUniform4fv(location("sdfwb_sortCube"), 1, sortCube);
    glUniform1ui(location("sdfwb_sortCapacity"), sortCapacity);
    for (GLuint pass = 1; pass <= 5; ++pass) {
        glUniform1ui(location("sdfwb_sortPass"), pass);
        if (pass == 2 || pass == 3)
            glDispatchCompute(kSortParts / 64, 1, 1); // an invocation a part of the cells
        else
            glDispatchCompute(gx, gy, 1);
        if (pass < 5) glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
    }
    return {};
}

Expected<void> SampleCompute::Impl::dispatchChainPasses(std::uint32_t count, std::uint32_t gx, std::uint32_t gy) {
    if (chainSteps <= 0) return {};
    const GLint from = location("sdfwb_chainFrom");
    const GLint to = location("sdfwb_chainTo");
    const bool passes = chainPassSteps > 0 && chainPassSteps <= chainSteps;
    // One pass keeps no states, but the block the program declares gets a buffer all the same.
    const std::uint32_t rows = passes ? count : 1u;
    if (const GLenum error = glGetError(); error != GL_NO_ERROR) // from issue()'s own calls before this
        return makeError("sampling: dispatch of " + std::to_string(count) + " samples failed (" + glErrorName(error) + ")");
    // Two uvec4 a row.
    if (auto ok = growScratch(chainStates, chainCapacity, rows, GLsizeiptr(rows) * 32, "the chains' states", count); !ok)
        return ok;
    if (passes) glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT); // the last chunk's passes are done with the states
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kBindingChain, chainStates.id());
    int first = -1; // the first state is step -1
    for (; passes && first + chainPassSteps < chainSteps; first += chainPassSteps) {
        glUniform1i(from, first);
        glUniform1i(to, first + chainPassSteps);
        glDispatchCompute(gx, gy, 1);
        glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
    }
    glUniform1i(from, first);
    glUniform1i(to, chainSteps);
    return {};
}

Expected<std::uint32_t> SampleCompute::Impl::dispatch(const SampleUniforms& uniforms, std::uint32_t first, std::uint32_t count,
                                                      BufferSet& set, bool positions, bool gradients, const float* inputRows) {
    const auto dispatched = std::chrono::steady_clock::now();
    kernelTimer.begin();
    auto ok = issue(uniforms, first, count, set, positions, gradients, false, {}, inputRows, kMaxSlots);
    kernelTimer.end();
    if (!ok) return ok.error();
    glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT | GL_CLIENT_MAPPED_BUFFER_BARRIER_BIT);
    GLsync fence = glFenceSync(GL_SYNC_GPU_COMMANDS_COMPLETE, 0);
    const bool done = fence && waitFor(fence);
    if (fence) glDeleteSync(fence);
    if (!done) return makeError("sampling: waiting for the dispatch of " + std::to_string(count) + " samples failed");
    const double kernel = kernelTimer.milliseconds(
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - dispatched).count());
    kernelMilliseconds = kernel < 0.0 || kernelMilliseconds < 0.0 ? -1.0 : kernelMilliseconds + kernel;
    return takeCounts(kMaxSlots);
}

Expected<std::uint32_t> SampleCompute::run(const SampleUniforms& uniforms, std::uint32_t first, std::uint32_t count,
                                           float* positions, float* distances, float* gradients) {
    if (!m_impl->program) return makeError("sampling: no compiled sampler");
    if (count == 0) return 0u;
    if (count > kMaxChunk)
        return makeError("sampling: chunk of " + std::to_string(count) + " exceeds " + std::to_string(kMaxChunk));
    while (glGetError() != GL_NO_ERROR) {}
    if (m_impl->query && m_impl->positionsAreInputs(uniforms)) { // analysis/points.glsl: no GL work at all
        const float* in = uniforms.inputPoints + 3 * std::size_t(first);
        if (positions) std::copy(in, in + 3 * std::size_t(count), positions);
        return m_impl->evaluateRows(uniforms, in, 3, distances, 1, gradients, 3, count);
    }
    if (auto ok = m_impl->reserve(m_impl->plain, count, BufferKind::ReadBack); !ok) return ok.error();
    std::vector<float> scratch;
    if (m_impl->query && !positions) { // the engine needs the positions even where the caller does not
        scratch.resize(std::size_t(count) * 3);
        positions = scratch.data();
    }
    auto bad = m_impl->dispatch(uniforms, first, count, m_impl->plain, positions, gradients);
    if (!bad) return bad;
    if (m_impl->query) {
        glBindBuffer(GL_SHADER_STORAGE_BUFFER, m_impl->plain.buffers[0].id());
        glGetBufferSubData(GL_SHADER_STORAGE_BUFFER, 0, GLsizeiptr(count) * 12, positions);
        glBindBuffer(GL_SHADER_STORAGE_BUFFER, 0);
        if (GLenum error = glGetError(); error != GL_NO_ERROR)
            return makeError("sampling: reading back " + std::to_string(count) + " positions failed (" + glErrorName(error) +
                             ")");
        return m_impl->evaluateRows(uniforms, positions, 3, distances, 1, gradients, 3, count);
    }
    float* targets[3] = {positions, distances, gradients};
    const GLsizeiptr sizes[3] = {GLsizeiptr(count) * 12, GLsizeiptr(count) * 4, GLsizeiptr(count) * 12};
    for (int i = 0; i < 3; ++i) {
        if (!targets[i]) continue;
        glBindBuffer(GL_SHADER_STORAGE_BUFFER, m_impl->plain.buffers[i].id());
        glGetBufferSubData(GL_SHADER_STORAGE_BUFFER, 0, sizes[i], targets[i]);
    }
    glBindBuffer(GL_SHADER_STORAGE_BUFFER, 0);
    if (GLenum error = glGetError(); error != GL_NO_ERROR)
        return makeError("sampling: reading back " + std::to_string(count) + " samples failed (" + glErrorName(error) + ")");
    return checkedBadRows(MappedRows{positions, distances, gradients, *bad}, count);
}

} // namespace sdfwb::renderer
