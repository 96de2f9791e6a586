// .ply, binary little-endian: one vertex per sample with float properties
// x y z distance gx gy gz; run metadata as `comment sdfwb <key> <value>` header lines.

#include "Formats.h"

#include <meshfield/PlyHeader.h>

#include <cstdio>
#include <sstream>
#include <vector>

namespace sdfwb::sampling::detail {
namespace {

constexpr std::size_t kRowBytes = 28;
const char* const kProperties[7] = {"x", "y", "z", "distance", "gx", "gy", "gz"};

std::string singleLine(std::string text) {
    for (char& c : text)
        if (c == '\n' || c == '\r') c = ' ';
    return text;
}

std::string header(std::uint64_t rows, const SampleMetadata& m) {
    char time[32];
    std::snprintf(time, sizeof time, "%.9g", double(m.time));
    std::string out = "ply\nformat binary_little_endian 1.0\n";
    out += "comment sdfwb sdf " + singleLine(m.sdf) + "\n";
    out += "comment sdfwb pattern " + singleLine(m.pattern) + "\n";
    out += "comment sdfwb seed " + std::to_string(m.seed) + "\n";
    out += "comment sdfwb time " + std::string(time) + "\n";
    out += "comment sdfwb first_index " + std::to_string(m.firstIndex) + "\n";
    out += "comment sdfwb total_count " + std::to_string(m.totalCount) + "\n";
    out += "comment sdfwb version " + singleLine(m.version) + "\n";
    if (!m.parameters.empty()) out += "comment sdfwb parameters " + singleLine(m.parameters) + "\n";
    if (!m.mesh.empty()) out += "comment sdfwb mesh " + singleLine(m.mesh) + "\n";
    if (!m.frame.empty()) out += "comment sdfwb frame " + singleLine(m.frame) + "\n";
    out += "element vertex " + std::to_string(rows) + "\n";
    for (const char* property : kProperties) out += std::string("property float ") + property + "\n";
    // Large files: rows start at a multiple of 4096 bytes (a comment line of spaces pads the
    // header), so the sampler's chunks go to the disk straight from its page-aligned buffers
    // (OutputFile::writeDirectAt).
    const std::string end = "end_header\n";
    if (rows >= kDirectFromRows) {
        const std::size_t alignment = OutputFile::kDirectAlignment;
        const std::size_t padded = (out.size() + end.size() + 16 + alignment - 1) / alignment * alignment;
        out += "comment " + std::string(padded - out.size() - end.size() - 9, ' ') + "\n";
    }
    out += end;
    return out;
}

class PlyWriter final : public SampleWriter {
public:
    PlyWriter(OutputFile file, std::uint64_t rows, std::string header)
        : m_file(std::move(file)), m_rows(rows), m_dataOffset(header.size()), m_header(std::move(header)) {
        m_file.reserve(m_dataOffset + kRowBytes * rows);
    }

    Expected<void> append(const float* positions, const float* distances, const float* gradients, std::size_t n) override {
        if (m_written + n > m_rows) return makeError(m_file.target().string() + ": more rows than announced");
        // Interleaved in blocks small enough to stay in the cache until the write copies them.
        constexpr std::size_t kBlockRows = 8192;
        m_buffer.resize(std::min(n, kBlockRows) * 7);
        for (std::size_t first = 0; first < n; first += kBlockRows) {
            const std::size_t count = std::min(kBlockRows, n - first);
            for (std::size_t i = first; i < first + count; ++i) {
                float* row = m_buffer.data() + 7 * (i - first);
                row[0] = positions[3 * i];
                row[1] = positions[3 * i + 1];
                row[2] = positions[3 * i + 2];
                row[3] = distances[i];
                row[4] = gradients[3 * i];
                row[5] = gradients[3 * i + 1];
                row[6] = gradients[3 * i + 2];
            }
            if (auto ok = m_file.writeAt(m_dataOffset + kRowBytes * (m_written + first), m_buffer.data(), kRowBytes * count); !ok)
                return ok;
        }
        m_written += n;
        return {};
    }

    bool takesRows() const override { return true; }

    Expected<void> appendRows(const float* rows, std::size_t n) override {
        if (m_written + n > m_rows) return makeError(m_file.target().string() + ": more rows than announced");
        if (auto ok = m_file.writeDirectAt(m_dataOffset + kRowBytes * m_written, rows, kRowBytes * n); !ok) return ok;
        m_written += n;
        return {};
    }

    Expected<void> commit() override {
        if (m_written != m_rows)
            return makeError(m_file.target().string() + ": " + std::to_string(m_written) + " of " + std::to_string(m_rows) +
                             " rows written");
        if (auto ok = m_file.writeAt(0, m_header.data(), m_header.size()); !ok) return ok;
        return m_file.commit();
    }

private:
    OutputFile m_file;
    std::uint64_t m_rows;
    std::uint64_t m_dataOffset;
    std::string m_header;
    std::vector<float> m_buffer;
    std::uint64_t m_written = 0;
};

class PlyReader final : public SampleReader {
public:
    PlyReader(InputFile file, std::uint64_t rows, std::uint64_t dataOffset, std::size_t stride, const int (&offsets)[7],
              std::optional<SampleMetadata> metadata)
        : m_file(std::move(file)), m_dataOffset(dataOffset), m_stride(stride) {
        m_rows = rows;
        m_format = SampleFormat::Ply;
        m_metadata = std::move(metadata);
        for (int i = 0; i < 7; ++i) m_offsets[i] = offsets[i];
    }

    Expected<void> read(std::uint64_t first, std::size_t n, float* positions, float* distances, float* gradients) override {
        if (first > m_rows || n > m_rows - first) return makeError(m_file.name() + ": rows out of range");
        std::vector<char> buffer;
        for (std::size_t done = 0; done < n;) {
            std::size_t count = std::min(kCopyChunkRows, n - done);
            buffer.resize(count * m_stride);
            if (auto ok = m_file.readAt(m_dataOffset + (first + done) * m_stride, buffer.data(), buffer.size()); !ok) return ok;
            for (std::size_t i = 0; i < count; ++i) {
                const char* row = buffer.data() + i * m_stride;
                std::size_t r = done + i;
                positions[3 * r] = get<float>(row + m_offsets[0]);
                positions[3 * r + 1] = get<float>(row + m_offsets[1]);
                positions[3 * r + 2] = get<float>(row + m_offsets[2]);
                distances[r] = get<float>(row + m_offsets[3]);
                gradients[3 * r] = get<float>(row + m_offsets[4]);
                gradients[3 * r + 1] = get<float>(row + m_offsets[5]);
                gradients[3 * r + 2] = get<float>(row + m_offsets[6]);
            }
            done += count;
        }
        return {};
    }

private:
    InputFile m_file;
    std::uint64_t m_dataOffset;
    std::size_t m_stride;
    int m_offsets[7];
};

// `comment sdfwb <key> <value>` header lines into the metadata; false: a malformed value.
bool readMetadataComment(const std::string& comment, SampleMetadata& metadata, std::string& key, std::string& value) {
    std::istringstream words(comment);
    std::string tag;
    words >> tag >> key;
    std::getline(words >> std::ws, value);
    try {
        if (key == "sdf")
            metadata.sdf = value;
        else if (key == "pattern")
            metadata.pattern = value;
        else if (key == "seed")
            metadata.seed = std::stoull(value);
        else if (key == "time")
            metadata.time = std::stof(value);
        else if (key == "first_index")
            metadata.firstIndex = std::stoull(value);
        else if (key == "total_count")
            metadata.totalCount = std::stoull(value);
        else if (key == "version")
            metadata.version = value;
        else if (key == "parameters")
            metadata.parameters = value;
        else if (key == "mesh")
            metadata.mesh = value;
        else if (key == "frame")
            metadata.frame = value;
    } catch (const std::exception&) { return false; }
    return true;
}

} // namespace

Expected<std::unique_ptr<SampleWriter>> createPlyWriter(OutputFile file, std::uint64_t rows, const SampleMetadata& metadata) {
    return std::unique_ptr<SampleWriter>(new PlyWriter(std::move(file), rows, header(rows, metadata)));
}

Expected<std::unique_ptr<SampleReader>> openPlyReader(InputFile file) {
    // The header is text up to "end_header"; 64 KiB is far more than any sane header. It is read
    // by the one PLY header parser (meshfield/PlyHeader.h).
    std::string head(std::size_t(std::min<std::uint64_t>(file.size(), 65536)), '\0');
    if (auto ok = file.readAt(0, head.data(), head.size()); !ok) return ok.error();
    const std::string& name = file.name();
    if (head.rfind("ply\n", 0) != 0) return makeError(name + ": not a PLY file (no 'ply' magic line)");
    auto header = meshfield::parsePlyHeader(head, name);
    if (!header) return header.error();
    if (header->format != "binary_little_endian")
        return makeError(name + ": PLY format '" + header->format + "' is not supported (binary_little_endian only)");
    if (header->elements.empty() || header->elements[0].name != "vertex")
        return makeError(name + ": the PLY file's first element must be 'vertex' (" +
                         (header->elements.empty() ? std::string("it has none") : "'" + header->elements[0].name + "'") + ")");
    const meshfield::PlyElement& vertex = header->elements[0];
    std::size_t stride = 0;
    int offsets[7] = {-1, -1, -1, -1, -1, -1, -1};
    for (const meshfield::PlyProperty& property : vertex.properties) {
        if (property.isList()) return makeError(name + ": list properties in the vertex element are not supported");
        for (int i = 0; i < 7; ++i)
            if (property.name == kProperties[i]) {
                if (property.type != meshfield::PlyType::Float32)
                    return makeError(name + ": PLY vertex property '" + property.name + "' must be float");
                offsets[i] = int(stride);
            }
        stride += std::size_t(meshfield::plySize(property.type));
    }
    for (int i = 0; i < 7; ++i)
        if (offsets[i] < 0) return makeError(name + ": PLY vertices lack the float property '" + kProperties[i] + "'");
    SampleMetadata metadata;
    bool hasMetadata = false;
    for (const std::string& comment : header->comments) {
        if (comment.rfind("sdfwb ", 0) != 0) continue;
        hasMetadata = true;
        std::string key, value;
        if (!readMetadataComment(comment, metadata, key, value))
            return makeError(name + ": malformed sdfwb " + key + " value '" + value + "' in the PLY header");
    }
    const std::uint64_t rows = vertex.count, dataOffset = header->bodyOffset;
    if (stride == 0 || dataOffset > file.size() || rows > (file.size() - dataOffset) / stride)
        return makeError(name + ": " + std::to_string(rows) + " vertices of " + std::to_string(stride) +
                         " bytes do not fit in the file's " + std::to_string(file.size() - std::min(dataOffset, file.size())) +
                         " bytes of data");
    std::optional<SampleMetadata> found;
    if (hasMetadata) found = metadata;
    return std::unique_ptr<SampleReader>(new PlyReader(std::move(file), rows, dataOffset, stride, offsets, std::move(found)));
}

} // namespace sdfwb::sampling::detail
