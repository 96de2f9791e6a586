#include "SampleComputeImpl.h"

#include <renderer/GlInfo.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <vector>

namespace sdfwb::renderer {

std::uint32_t countNonFiniteRows(const MappedRows& rows, std::uint32_t count) {
    auto finite = [](const float* values, std::size_t n) {
        for (std::size_t i = 0; i < n; ++i)
            if (!std::isfinite(values[i])) return false;
        return true;
    };
    std::uint32_t bad = 0;
    for (std::uint32_t row = 0; row < count; ++row) {
        const bool ok = rows.rows ? finite(rows.rows + 7 * std::size_t(row), 7)
                                  : (!rows.positions || finite(rows.positions + 3 * std::size_t(row), 3)) &&
                                        (!rows.distances || finite(rows.distances + row, 1)) &&
                                        (!rows.gradients || finite(rows.gradients + 3 * std::size_t(row), 3));
        bad += ok ? 0u : 1u;
    }
    return bad;
}

Expected<void> SampleCompute::submitMapped(const SampleUniforms& uniforms, std::uint32_t first, std::uint32_t count, int slot,
                                           RowLayout layout, std::array<std::uint32_t, 3> shift) {
    if (!m_impl->program) return makeError("sampling: no compiled sampler");
    if (count > kMaxChunk)
        return makeError("sampling: chunk of " + std::to_string(count) + " exceeds " + std::to_string(kMaxChunk));
    const int at = slot % m_impl->slotCount();
    PendingChunk& chunk = m_impl->pending[at];
    if (chunk.fence) waitFor(chunk.fence); // a chunk submitted and never collected
    chunk.dropFence();
    chunk.active = false;
    while (glGetError() != GL_NO_ERROR) {}
    const bool interleaved = layout == RowLayout::Interleaved;
    if (interleaved) shift = {};
    for (std::uint32_t floats : shift)
        if (floats >= kMaxShift) return makeError("sampling: array shift of " + std::to_string(floats) + " floats");
    chunk.count = count;
    chunk.interleaved = interleaved;
    chunk.shift = shift;
    chunk.inputs =
        m_impl->query && m_impl->positionsAreInputs(uniforms) ? uniforms.inputPoints + 3 * std::size_t(first) : nullptr;
    if (m_impl->query) chunk.uniforms = uniforms;
    if (chunk.inputs) { // the CPU engine at the caller's points: nothing for the GL to do
        chunk.active = true;
        return {};
    }
    const bool staged = m_impl->staged();
    chunk.staged = staged;
    BufferSet& set = m_impl->slots[at];
    const std::uint32_t rows = std::max(count, 1u);
    if (auto ok = m_impl->reserve(set, rows, staged ? BufferKind::Device : BufferKind::Mapped, interleaved); !ok) return ok;
    if (staged)
        if (auto ok = m_impl->reserve(m_impl->staging[at], rows, BufferKind::Mapped, interleaved); !ok) return ok;
    chunk.issued = std::chrono::steady_clock::now();
    chunk.timer.begin();
    auto ok = m_impl->issue(uniforms, first, count, set, true, true, interleaved, shift, nullptr, at);
    chunk.timer.end();
    if (!ok) return ok;
    if (staged) { // the GPU copies the rows (and the shift before them) into the mapped buffers
        glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
        chunk.copyTimer.begin();
        const GLsizeiptr room = interleaved ? 0 : GLsizeiptr(kMaxShift) * 4;
        const GLsizeiptr sizes[3] = {GLsizeiptr(count) * (interleaved ? 28 : 12) + room,
                                     interleaved ? 0 : GLsizeiptr(count) * 4 + room,
                                     interleaved ? 0 : GLsizeiptr(count) * 12 + room};
        for (int i = 0; i < 3; ++i) {
            if (sizes[i] == 0) continue;
            glBindBuffer(GL_COPY_READ_BUFFER, set.buffers[i].id());
            glBindBuffer(GL_COPY_WRITE_BUFFER, m_impl->staging[at].buffers[i].id());
            glCopyBufferSubData(GL_COPY_READ_BUFFER, GL_COPY_WRITE_BUFFER, 0, 0, sizes[i]);
        }
        chunk.copyTimer.end();
        glBindBuffer(GL_COPY_READ_BUFFER, 0);
        glBindBuffer(GL_COPY_WRITE_BUFFER, 0);
    }
    glMemoryBarrier(GL_CLIENT_MAPPED_BUFFER_BARRIER_BIT);
    chunk.fence = glFenceSync(GL_SYNC_GPU_COMMANDS_COMPLETE, 0);
    glFlush(); // the GPU starts on it now, not at the first wait
    if (GLenum error = glGetError(); error != GL_NO_ERROR || !chunk.fence) {
        chunk.dropFence();
        return makeError("sampling: dispatch of " + std::to_string(count) + " samples failed (" +
                         (error != GL_NO_ERROR ? glErrorName(error) : std::string("no fence")) + "); try a smaller --chunk");
    }
    chunk.active = true;
    return {};
}

Expected<MappedRows> SampleCompute::collectMapped(int slot) {
    const int at = slot % m_impl->slotCount();
    PendingChunk& chunk = m_impl->pending[at];
    if (!chunk.active) return makeError("sampling: nothing was submitted into slot " + std::to_string(slot));
    chunk.active = false;
    const std::uint32_t count = chunk.count;
    const bool interleaved = chunk.interleaved;
    const std::array<std::uint32_t, 3> shift = chunk.shift;
    const float* inputs = chunk.inputs;
    std::uint32_t bad = 0;
    const float* const* mapped = m_impl->slots[at].mapped;
    if (!inputs) {
        const bool done = waitFor(chunk.fence);
        chunk.dropFence();
        if (!done) return makeError("sampling: waiting for the dispatch of " + std::to_string(count) + " samples failed");
        const double wall = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - chunk.issued).count();
        auto add = [](double& total, double milliseconds) {
            total = milliseconds < 0.0 || total < 0.0 ? -1.0 : total + milliseconds;
        };
        add(m_impl->kernelMilliseconds, chunk.timer.milliseconds(wall));
        if (chunk.staged) add(m_impl->copyMilliseconds, chunk.copyTimer.milliseconds(wall));
        bad = m_impl->takeCounts(at);
        if (chunk.staged) mapped = m_impl->staging[at].mapped;
    }
    if (m_impl->query) {
        // The mapping is read-only: the rows are completed in this slot's host arrays, at the
        // same shifts, and the caller reads them there.
        std::vector<float>(&host)[3] = m_impl->hostRows[at];
        if (interleaved) {
            host[0].resize(std::size_t(count) * 7);
            float* base = host[0].data();
            if (inputs)
                for (std::size_t i = 0; i < count; ++i) std::copy(inputs + 3 * i, inputs + 3 * i + 3, base + 7 * i);
            else
                std::copy(mapped[0], mapped[0] + std::size_t(count) * 7, base);
            auto valuesBad = m_impl->evaluateRows(chunk.uniforms, base, 7, base + 3, 7, base + 4, 7, count);
            if (!valuesBad) return valuesBad.error();
            return MappedRows{nullptr, nullptr, nullptr, *valuesBad, base};
        }
        const std::size_t sizes[3] = {std::size_t(count) * 3, count, std::size_t(count) * 3};
        for (int i = 0; i < 3; ++i) host[i].resize(shift[std::size_t(i)] + sizes[i]);
        float* p = host[0].data() + shift[0];
        float* d = host[1].data() + shift[1];
        float* g = host[2].data() + shift[2];
        const float* from = inputs ? inputs : mapped[0] + shift[0];
        std::copy(from, from + sizes[0], p);
        auto valuesBad = m_impl->evaluateRows(chunk.uniforms, p, 3, d, 1, g, 3, count);
        if (!valuesBad) return valuesBad.error();
        return MappedRows{p, d, g, *valuesBad};
    }
    MappedRows rows = interleaved ? MappedRows{nullptr, nullptr, nullptr, bad, mapped[0]}
                                  : MappedRows{mapped[0] + shift[0], mapped[1] + shift[1], mapped[2] + shift[2], bad};
    rows.badRows = checkedBadRows(rows, count);
    return rows;
}

Expected<MappedRows> SampleCompute::runMapped(const SampleUniforms& uniforms, std::uint32_t first, std::uint32_t count, int slot,
                                              RowLayout layout, std::array<std::uint32_t, 3> shift) {
    if (auto ok = submitMapped(uniforms, first, count, slot, layout, shift); !ok) return ok.error();
    return collectMapped(slot);
}

void SampleCompute::setPipeline(const SamplePipeline& pipeline) {
    m_impl->finishPending();
    m_impl->settings = pipeline;
}

SamplePipeline SampleCompute::pipeline() const {
    SamplePipeline resolved = m_impl->settings;
    resolved.sets = m_impl->slotCount();
    const bool software = softwareRasteriser();
    const int most = resolved.sets - 2;
    resolved.ahead = resolved.ahead > 0 ? std::min(resolved.ahead, most) : software ? 1 : most;
    resolved.staging = m_impl->staged() ? 1 : 0;
    return resolved;
}

std::uint32_t SampleCompute::preferredChunk() const { return softwareRasteriser() ? kSoftwareChunk : kGpuChunk; }

void SampleCompute::releaseGl() {
    m_impl->program.reset();
    m_impl->locations.clear();
    m_impl->plain.reset();
    m_impl->finishPending();
    for (BufferSet& set : m_impl->slots) set.reset();
    for (BufferSet& set : m_impl->staging) set.reset();
    m_impl->counts.reset();
    m_impl->countWords = nullptr;
    m_impl->inputs.reset();
    m_impl->sortWords.reset();
    m_impl->sortCapacity = 0;
    m_impl->chainStates.reset();
    m_impl->chainCapacity = 0;
    m_impl->textures.reset();
    m_impl->kernelTimer.reset();
    m_impl->query.reset();
    for (auto& host : m_impl->hostRows)
        for (std::vector<float>& rows : host) std::vector<float>().swap(rows);
}

Expected<CopyRate> measureCopyToHost(std::size_t bytes, int repeats) {
    while (glGetError() != GL_NO_ERROR) {}
    GLuint ids[2] = {0, 0};
    glGenBuffers(2, ids);
    GlBuffer device(ids[0]), host(ids[1]);
    glBindBuffer(GL_COPY_READ_BUFFER, device.id());
    glBufferStorage(GL_COPY_READ_BUFFER, GLsizeiptr(bytes), nullptr, 0);
    glBindBuffer(GL_COPY_WRITE_BUFFER, host.id());
    const GLbitfield access = GL_MAP_READ_BIT | GL_MAP_PERSISTENT_BIT | GL_MAP_COHERENT_BIT;
    glBufferStorage(GL_COPY_WRITE_BUFFER, GLsizeiptr(bytes), nullptr, access | GL_CLIENT_STORAGE_BIT);
    const void* mapped = glMapBufferRange(GL_COPY_WRITE_BUFFER, 0, GLsizeiptr(bytes), access);
    if (const GLenum error = glGetError(); error != GL_NO_ERROR || !mapped) {
        glBindBuffer(GL_COPY_READ_BUFFER, 0);
        glBindBuffer(GL_COPY_WRITE_BUFFER, 0);
        return makeError("copy rate: cannot allocate two buffers of " + std::to_string(bytes) + " bytes (" +
                         (error != GL_NO_ERROR ? glErrorName(error) : std::string("mapping failed")) + ")");
    }
    std::vector<double> timed, walls;
    GpuTimer timer;
    for (int k = 0; k <= repeats; ++k) {
        const auto start = std::chrono::steady_clock::now();
        timer.begin();
        glCopyBufferSubData(GL_COPY_READ_BUFFER, GL_COPY_WRITE_BUFFER, 0, 0, GLsizeiptr(bytes));
        timer.end();
        GLsync fence = glFenceSync(GL_SYNC_GPU_COMMANDS_COMPLETE, 0);
        glClientWaitSync(fence, GL_SYNC_FLUSH_COMMANDS_BIT, GLuint64(60) * 1000000000u);
        glDeleteSync(fence);
        const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        const double milliseconds = timer.milliseconds(wall * 1e3 + 1.0);
        if (k == 0) continue; // the warm-up: first touches of the pages
        walls.push_back(double(bytes) / wall);
        if (milliseconds > 0.0 && !softwareRasteriser()) timed.push_back(double(bytes) / (milliseconds * 1e-3));
    }
    timer.reset();
    glBindBuffer(GL_COPY_WRITE_BUFFER, host.id());
    glUnmapBuffer(GL_COPY_WRITE_BUFFER);
    glBindBuffer(GL_COPY_READ_BUFFER, 0);
    glBindBuffer(GL_COPY_WRITE_BUFFER, 0);
    auto median = [](std::vector<double>& v) {
        std::sort(v.begin(), v.end());
        return v.empty() ? -1.0 : v[v.size() / 2];
    };
    CopyRate rate;
    rate.wallBytesPerSecond = median(walls);
    rate.timerBytesPerSecond = median(timed);
    return rate;
}

} // namespace sdfwb::renderer
