// The paper's .bin: uint32 N, N positions, N distances, N gradients (float32, little-endian).

#include "Formats.h"

#include <array>
#include <bit>

namespace sdfwb::sampling::detail {
namespace {

static_assert(std::endian::native == std::endian::little, "sdfwb writes little-endian files on little-endian hosts only");

class BinWriter final : public SampleWriter {
public:
    BinWriter(OutputFile file, std::uint64_t rows, const SampleMetadata& metadata)
        : m_file(std::move(file)), m_rows(rows), m_metadata(metadata), m_direct(rows >= kDirectFromRows) {
        m_file.reserve(4 + 28 * rows);
    }

    // The paper's layout cannot be aligned (a 4-byte header, arrays of any length), so the rows are:
    // each array of a chunk lands in memory at its file offset modulo a disk block, so that its
    // whole blocks go to the disk directly from there (OutputFile::writeDirectAt).
    std::array<std::uint32_t, 3> arrayShift(std::uint64_t firstRow) const override {
        if (!m_direct) return {};
        const std::uint64_t block = OutputFile::kDirectAlignment;
        return {std::uint32_t(positionsAt(firstRow) % block / 4), std::uint32_t(distancesAt(firstRow) % block / 4),
                std::uint32_t(gradientsAt(firstRow) % block / 4)};
    }

    Expected<void> append(const float* positions, const float* distances, const float* gradients, std::size_t n) override {
        if (m_written + n > m_rows) return makeError(m_file.target().string() + ": more rows than announced");
        if (auto ok = write(positionsAt(m_written), positions, 12 * n); !ok) return ok;
        if (auto ok = write(distancesAt(m_written), distances, 4 * n); !ok) return ok;
        if (auto ok = write(gradientsAt(m_written), gradients, 12 * n); !ok) return ok;
        m_written += n;
        return {};
    }

    Expected<void> commit() override {
        if (m_written != m_rows)
            return makeError(m_file.target().string() + ": " + std::to_string(m_written) + " of " + std::to_string(m_rows) +
                             " rows written");
        const std::uint32_t count = std::uint32_t(m_rows);
        if (auto ok = m_file.writeAt(0, &count, 4); !ok) return ok;
        if (!m_metadata.parameters.empty() || !m_metadata.mesh.empty() ||
            !m_metadata.frame.empty()) { // the sidecar first: a .bin never appears without it
            auto sidecar = OutputFile::create(m_file.target().string() + ".json");
            if (!sidecar) return sidecar.error();
            const std::string text = metadataJson(m_metadata) + "\n";
            if (auto ok = sidecar->writeAt(0, text.data(), text.size()); !ok) return ok;
            if (auto ok = sidecar->commit(); !ok) return ok;
        }
        return m_file.commit();
    }

private:
    std::uint64_t positionsAt(std::uint64_t row) const { return 4 + 12 * row; }
    std::uint64_t distancesAt(std::uint64_t row) const { return 4 + 12 * m_rows + 4 * row; }
    std::uint64_t gradientsAt(std::uint64_t row) const { return 4 + 16 * m_rows + 12 * row; }

    Expected<void> write(std::uint64_t offset, const float* data, std::size_t size) {
        return m_direct ? m_file.writeDirectAt(offset, data, size) : m_file.writeAt(offset, data, size);
    }

    OutputFile m_file;
    std::uint64_t m_rows;
    SampleMetadata m_metadata;
    bool m_direct; // large enough that writing past the page cache pays (kDirectFromRows)
    std::uint64_t m_written = 0;
};

class BinReader final : public SampleReader {
public:
    BinReader(InputFile file, std::uint64_t rows) : m_file(std::move(file)) {
        m_rows = rows;
        m_format = SampleFormat::Bin;
    }

    Expected<void> read(std::uint64_t first, std::size_t n, float* positions, float* distances, float* gradients) override {
        if (first > m_rows || n > m_rows - first)
            return makeError(m_file.name() + ": rows " + std::to_string(first) + "+" + std::to_string(n) + " out of range");
        const std::uint64_t N = m_rows;
        if (auto ok = m_file.readAt(4 + 12 * first, positions, 12 * n); !ok) return ok;
        if (auto ok = m_file.readAt(4 + 12 * N + 4 * first, distances, 4 * n); !ok) return ok;
        return m_file.readAt(4 + 16 * N + 12 * first, gradients, 12 * n);
    }

private:
    InputFile m_file;
};

} // namespace

Expected<std::unique_ptr<SampleWriter>> createBinWriter(OutputFile file, std::uint64_t rows, const SampleMetadata& metadata) {
    return std::unique_ptr<SampleWriter>(new BinWriter(std::move(file), rows, metadata));
}

Expected<std::unique_ptr<SampleReader>> openBinReader(InputFile file) {
    if (file.size() < 4)
        return makeError(file.name() + ": not a .bin sample file: " + std::to_string(file.size()) +
                         " bytes, the header alone needs 4");
    std::uint32_t count = 0;
    if (auto ok = file.readAt(0, &count, 4); !ok) return ok.error();
    const std::uint64_t expected = 4 + 28ull * count;
    if (file.size() != expected)
        return makeError(file.name() + ": file has " + std::to_string(file.size()) + " bytes, but its header says N = " +
                         std::to_string(count) + ", which needs " + std::to_string(expected));
    return std::unique_ptr<SampleReader>(new BinReader(std::move(file), count));
}

} // namespace sdfwb::sampling::detail
