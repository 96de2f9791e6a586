// .npz: a ZIP archive of .npy arrays, as numpy.savez writes it (stored, uncompressed entries):
// position (N,3) float32, distance (N,) float32, gradient (N,3) float32, and metadata arrays
// sdf, pattern, version (unicode strings), seed, first_index, total_count (uint64), time (float32).
// Written with fixed timestamps so equal runs give equal bytes; ZIP64 records when sizes need them.

#include "Formats.h"

#include <core/Regex.h>

#include <isa-l/crc.h>
#include <zlib.h>

#include <algorithm>
#include <map>
#include <regex>
#include <vector>

namespace sdfwb::sampling::detail {
namespace {

constexpr std::uint64_t kBlockBytes = 256u << 10; // written and checksummed together

constexpr std::uint32_t kLocalSignature = 0x04034b50;
constexpr std::uint32_t kCentralSignature = 0x02014b50;
constexpr std::uint32_t kEndSignature = 0x06054b50;
constexpr std::uint32_t kZip64EndSignature = 0x06064b50;
constexpr std::uint32_t kZip64LocatorSignature = 0x07064b50;
constexpr std::uint16_t kDosDate = (0 << 9) | (1 << 5) | 1; // 1980-01-01: fixed for reproducible files
constexpr std::uint32_t kMax32 = 0xffffffffu;

// The .npy header padded with spaces so that the array's data, when the header starts at file
// offset `startsAt`, begins at a multiple of `alignment` (64, as numpy writes it, or 4096 so that
// large arrays can go to the disk without a copy: OutputFile::writeDirectAt).
std::string npyHeader(const std::string& descr, const std::string& shape, std::uint64_t startsAt = 0,
                      std::uint64_t alignment = 64) {
    std::string dict = "{'descr': '" + descr + "', 'fortran_order': False, 'shape': " + shape + ", }";
    std::uint64_t total = 10 + dict.size() + 1;
    dict.append(std::size_t((alignment - (startsAt + total) % alignment) % alignment), ' ');
    dict += '\n';
    std::string header = "\x93NUMPY";
    header += '\x01';
    header += '\x00';
    put16(header, std::uint16_t(dict.size()));
    return header + dict;
}

std::u32string utf8ToUtf32(const std::string& text) {
    std::u32string out;
    for (std::size_t i = 0; i < text.size();) {
        unsigned char c = static_cast<unsigned char>(text[i]);
        int length = c < 0x80 ? 1 : (c >> 5) == 6 ? 2 : (c >> 4) == 14 ? 3 : (c >> 3) == 30 ? 4 : 0;
        if (length == 0 || i + std::size_t(length) > text.size()) {
            out += U'\uFFFD';
            ++i;
            continue;
        }
        char32_t code = length == 1 ? c : c & (0x7f >> length);
        bool valid = true;
        for (int k = 1; k < length; ++k) {
            unsigned char next = static_cast<unsigned char>(text[i + std::size_t(k)]);
            if ((next >> 6) != 2) valid = false;
            code = (code << 6) | (next & 0x3f);
        }
        out += valid ? code : U'\uFFFD';
        i += valid ? std::size_t(length) : 1;
    }
    return out;
}

std::string utf32ToUtf8(const std::u32string& text) {
    std::string out;
    for (char32_t c : text) {
        if (c == 0) break; // numpy pads fixed-width strings with NULs
        if (c < 0x80)
            out += char(c);
        else if (c < 0x800) {
            out += char(0xc0 | (c >> 6));
            out += char(0x80 | (c & 0x3f));
        } else if (c < 0x10000) {
            out += char(0xe0 | (c >> 12));
            out += char(0x80 | ((c >> 6) & 0x3f));
            out += char(0x80 | (c & 0x3f));
        } else {
            out += char(0xf0 | (c >> 18));
            out += char(0x80 | ((c >> 12) & 0x3f));
            out += char(0x80 | ((c >> 6) & 0x3f));
            out += char(0x80 | (c & 0x3f));
        }
    }
    return out;
}

// A small array kept in memory (metadata).
struct SmallEntry {
    std::string name;
    std::string bytes; // npy header + data
};

SmallEntry stringArray(const std::string& name, const std::string& value) {
    std::u32string wide = utf8ToUtf32(value);
    if (wide.empty()) wide = U"\0";
    std::string bytes = npyHeader("<U" + std::to_string(wide.size()), "()");
    bytes.append(reinterpret_cast<const char*>(wide.data()), wide.size() * 4);
    return {name, bytes};
}

template <class T> SmallEntry scalarArray(const std::string& name, const char* descr, T value) {
    std::string bytes = npyHeader(descr, "()");
    bytes.append(reinterpret_cast<const char*>(&value), sizeof(T));
    return {name, bytes};
}

struct EntryRecord {
    std::string name;
    std::uint64_t offset = 0; // of the local header
    std::uint64_t size = 0;   // stored = uncompressed
    std::uint32_t crc = 0;
};

std::string localHeader(const EntryRecord& e, bool zip64) {
    std::string out;
    put32(out, kLocalSignature);
    put16(out, zip64 ? 45 : 20);
    put16(out, 0); // flags
    put16(out, 0); // stored
    put16(out, 0); // time
    put16(out, kDosDate);
    put32(out, e.crc);
    put32(out, zip64 ? kMax32 : std::uint32_t(e.size));
    put32(out, zip64 ? kMax32 : std::uint32_t(e.size));
    put16(out, std::uint16_t(e.name.size()));
    put16(out, zip64 ? 20 : 0);
    out += e.name;
    if (zip64) {
        put16(out, 0x0001);
        put16(out, 16);
        put64(out, e.size);
        put64(out, e.size);
    }
    return out;
}

std::string centralHeader(const EntryRecord& e, bool zip64) {
    std::string out;
    put32(out, kCentralSignature);
    put16(out, zip64 ? 45 : 20); // made by
    put16(out, zip64 ? 45 : 20); // needed
    put16(out, 0);
    put16(out, 0);
    put16(out, 0);
    put16(out, kDosDate);
    put32(out, e.crc);
    put32(out, zip64 ? kMax32 : std::uint32_t(e.size));
    put32(out, zip64 ? kMax32 : std::uint32_t(e.size));
    put16(out, std::uint16_t(e.name.size()));
    put16(out, zip64 ? 28 : 0);
    put16(out, 0); // comment
    put16(out, 0); // disk
    put16(out, 0); // internal attributes
    put32(out, 0); // external attributes
    put32(out, zip64 ? kMax32 : std::uint32_t(e.offset));
    out += e.name;
    if (zip64) {
        put16(out, 0x0001);
        put16(out, 24);
        put64(out, e.size);
        put64(out, e.size);
        put64(out, e.offset);
    }
    return out;
}

class NpzWriter final : public SampleWriter {
public:
    NpzWriter(OutputFile file, std::uint64_t rows, const SampleMetadata& metadata, bool forceZip64)
        : m_file(std::move(file)), m_rows(rows) {
        const std::string n = std::to_string(rows);
        const std::string shapes[3] = {"(" + n + ", 3)", "(" + n + ",)", "(" + n + ", 3)"};
        const char* names[3] = {"position.npy", "distance.npy", "gradient.npy"};
        const std::uint64_t rowBytes[3] = {12, 4, 12};
        std::uint64_t bigBytes = 0;
        for (int i = 0; i < 3; ++i) bigBytes += OutputFile::kDirectAlignment + 256 + rowBytes[i] * rows + 128;
        m_zip64 = forceZip64 || bigBytes > 0xfff00000ull;
        // Large arrays start at multiples of 4096 bytes, so the sampler's chunks go to the disk
        // straight from its page-aligned buffers.
        const std::uint64_t alignment = rows >= kDirectFromRows ? OutputFile::kDirectAlignment : 64;
        std::string headers[3];
        std::uint64_t offset = 0;
        for (int i = 0; i < 3; ++i) {
            EntryRecord& e = m_big[i];
            e.name = names[i];
            e.offset = offset;
            headers[i] = npyHeader("<f4", shapes[i], offset + localHeader(e, m_zip64).size(), alignment);
            e.size = headers[i].size() + rowBytes[i] * rows;
            e.crc = std::uint32_t(crc32(0, reinterpret_cast<const Bytef*>(headers[i].data()), uInt(headers[i].size())));
            m_headers[i] = headers[i];
            m_payload[i] = offset + localHeader(e, m_zip64).size() + headers[i].size();
            m_rowBytes[i] = rowBytes[i];
            offset += localHeader(e, m_zip64).size() + e.size;
        }
        m_end = offset;
        m_file.reserve(m_end); // the small entries and the directory are appended after it
        m_small = {stringArray("sdf.npy", metadata.sdf),
                   stringArray("pattern.npy", metadata.pattern),
                   scalarArray<std::uint64_t>("seed.npy", "<u8", metadata.seed),
                   scalarArray<float>("time.npy", "<f4", metadata.time),
                   scalarArray<std::uint64_t>("first_index.npy", "<u8", metadata.firstIndex),
                   scalarArray<std::uint64_t>("total_count.npy", "<u8", metadata.totalCount),
                   stringArray("version.npy", metadata.version)};
        if (!metadata.parameters.empty()) m_small.push_back(stringArray("parameters.npy", metadata.parameters));
        if (!metadata.mesh.empty()) m_small.push_back(stringArray("mesh.npy", metadata.mesh));
        if (!metadata.frame.empty()) m_small.push_back(stringArray("frame.npy", metadata.frame));
    }

    Expected<void> append(const float* positions, const float* distances, const float* gradients, std::size_t n) override {
        if (m_written + n > m_rows) return makeError(m_file.target().string() + ": more rows than announced");
        const float* data[3] = {positions, distances, gradients};
        for (int i = 0; i < 3; ++i) {
            const unsigned char* cursor = reinterpret_cast<const unsigned char*>(data[i]);
            std::uint64_t offset = m_payload[i] + m_rowBytes[i] * m_written;
            const std::uint64_t bytes = m_rowBytes[i] * n;
            if (OutputFile::directWritable(offset, cursor, bytes)) { // no copy: the CRC reads, the disk takes it
                m_big[i].crc = crc32_gzip_refl(m_big[i].crc, cursor, bytes);
                if (auto ok = m_file.writeDirectAt(offset, cursor, std::size_t(bytes)); !ok) return ok;
                continue;
            }
            // In blocks that stay in the cache between the write's copy and the CRC's read.
            for (std::uint64_t left = bytes; left > 0;) {
                const std::size_t step = std::size_t(std::min<std::uint64_t>(left, kBlockBytes));
                if (auto ok = m_file.writeAt(offset, cursor, step); !ok) return ok;
                m_big[i].crc = crc32_gzip_refl(m_big[i].crc, cursor, step);
                cursor += step;
                offset += step;
                left -= step;
            }
        }
        m_written += n;
        return {};
    }

    Expected<void> commit() override {
        if (m_written != m_rows)
            return makeError(m_file.target().string() + ": " + std::to_string(m_written) + " of " + std::to_string(m_rows) +
                             " rows written");
        std::vector<EntryRecord> records(m_big, m_big + 3);
        for (int i = 0; i < 3; ++i) {
            std::string head = localHeader(m_big[i], m_zip64) + m_headers[i];
            if (auto ok = m_file.writeAt(m_big[i].offset, head.data(), head.size()); !ok) return ok;
        }
        std::string tail;
        std::uint64_t offset = m_end;
        for (const SmallEntry& small : m_small) {
            EntryRecord e{small.name, offset + tail.size(), small.bytes.size(),
                          std::uint32_t(crc32(0, reinterpret_cast<const Bytef*>(small.bytes.data()), uInt(small.bytes.size())))};
            tail += localHeader(e, m_zip64) + small.bytes;
            records.push_back(e);
        }
        const std::uint64_t centralOffset = offset + tail.size();
        std::string central;
        for (const EntryRecord& e : records) central += centralHeader(e, m_zip64);
        tail += central;
        if (m_zip64) {
            const std::uint64_t zip64EndOffset = centralOffset + central.size();
            put32(tail, kZip64EndSignature);
            put64(tail, 44);
            put16(tail, 45);
            put16(tail, 45);
            put32(tail, 0);
            put32(tail, 0);
            put64(tail, records.size());
            put64(tail, records.size());
            put64(tail, central.size());
            put64(tail, centralOffset);
            put32(tail, kZip64LocatorSignature);
            put32(tail, 0);
            put64(tail, zip64EndOffset);
            put32(tail, 1);
        }
        put32(tail, kEndSignature);
        put16(tail, 0);
        put16(tail, 0);
        put16(tail, std::uint16_t(records.size()));
        put16(tail, std::uint16_t(records.size()));
        put32(tail, std::uint32_t(std::min<std::uint64_t>(central.size(), kMax32)));
        put32(tail, m_zip64 ? kMax32 : std::uint32_t(centralOffset));
        put16(tail, 0);
        if (auto ok = m_file.writeAt(offset, tail.data(), tail.size()); !ok) return ok;
        return m_file.commit();
    }

private:
    OutputFile m_file;
    std::uint64_t m_rows;
    bool m_zip64 = false;
    EntryRecord m_big[3];
    std::string m_headers[3];
    std::uint64_t m_payload[3] = {};
    std::uint64_t m_rowBytes[3] = {};
    std::uint64_t m_end = 0;
    std::vector<SmallEntry> m_small;
    std::uint64_t m_written = 0;
};

// ---------------------------------------------------------------- reading

struct ZipEntry {
    std::uint16_t method = 0;
    std::uint64_t compressedSize = 0;
    std::uint64_t size = 0;
    std::uint64_t dataOffset = 0;
};

// One .npy array inside the archive: either a byte range of the file (stored) or inflated bytes.
struct NpyArray {
    std::string descr;
    std::vector<std::uint64_t> shape;
    std::uint64_t dataOffset = 0; // in the file, or in `inflated`
    std::uint64_t dataSize = 0;
    std::string inflated; // non-empty for deflated entries
    bool isInflated = false;
};

Expected<std::string> inflateEntry(const InputFile& file, const ZipEntry& entry, const std::string& name) {
    // Deflate cannot expand data more than ~1032:1; a claim beyond that is corrupt.
    if (entry.size > entry.compressedSize * 1100 + 1024 || entry.size > (1ull << 34))
        return makeError(file.name() + ": " + name + ": implausible uncompressed size " + std::to_string(entry.size));
    std::string compressed(std::size_t(entry.compressedSize), '\0');
    if (auto ok = file.readAt(entry.dataOffset, compressed.data(), compressed.size()); !ok) return ok.error();
    std::string out(std::size_t(entry.size), '\0');
    z_stream stream{};
    if (inflateInit2(&stream, -MAX_WBITS) != Z_OK) return makeError(file.name() + ": zlib init failed");
    stream.next_in = reinterpret_cast<Bytef*>(compressed.data());
    stream.avail_in = uInt(compressed.size());
    stream.next_out = reinterpret_cast<Bytef*>(out.data());
    stream.avail_out = uInt(out.size());
    int result = inflate(&stream, Z_FINISH);
    std::uint64_t produced = stream.total_out;
    inflateEnd(&stream);
    if (result != Z_STREAM_END || produced != entry.size) return makeError(file.name() + ": " + name + ": corrupt deflate data");
    return out;
}

Expected<NpyArray> parseNpy(const InputFile& file, const ZipEntry& entry, const std::string& name) {
    NpyArray array;
    std::uint64_t base = entry.dataOffset;
    std::uint64_t available = entry.size;
    if (entry.method == 8) {
        auto inflated = inflateEntry(file, entry, name);
        if (!inflated) return inflated.error();
        array.inflated = std::move(*inflated);
        array.isInflated = true;
        base = 0;
    } else if (entry.method != 0) {
        return makeError(file.name() + ": " + name + ": compression method " + std::to_string(entry.method) +
                         " is not supported");
    } else if (entry.compressedSize != entry.size) {
        return makeError(file.name() + ": " + name + ": stored entry with differing sizes");
    }
    auto readBytes = [&](std::uint64_t offset, void* data, std::size_t size) -> Expected<void> {
        if (offset + size > available) return makeError(file.name() + ": " + name + ": truncated .npy data");
        if (array.isInflated) {
            std::memcpy(data, array.inflated.data() + offset, size);
            return {};
        }
        return file.readAt(base + offset, data, size);
    };
    char prefix[12];
    if (auto ok = readBytes(0, prefix, 10); !ok) return ok.error();
    if (std::memcmp(prefix, "\x93NUMPY", 6) != 0) return makeError(file.name() + ": " + name + ": not a .npy array (bad magic)");
    std::uint64_t headerLength = 0, headerStart = 0;
    if (prefix[6] == 1) {
        headerLength = get<std::uint16_t>(prefix + 8);
        headerStart = 10;
    } else if (prefix[6] == 2 || prefix[6] == 3) {
        if (auto ok = readBytes(0, prefix, 12); !ok) return ok.error();
        headerLength = get<std::uint32_t>(prefix + 8);
        headerStart = 12;
    } else {
        return makeError(file.name() + ": " + name + ": unsupported .npy version " + std::to_string(int(prefix[6])));
    }
    if (headerLength > 65536) return makeError(file.name() + ": " + name + ": .npy header too long");
    std::string header(std::size_t(headerLength), '\0');
    if (auto ok = readBytes(headerStart, header.data(), header.size()); !ok) return ok.error();
    static const std::regex descr(R"('descr'\s*:\s*'([^']*)')", kLinearRegex);
    static const std::regex fortran(R"('fortran_order'\s*:\s*(True|False))", kLinearRegex);
    static const std::regex shape(R"('shape'\s*:\s*\(([^)]*)\))", kLinearRegex);
    std::smatch match;
    if (!std::regex_search(header, match, descr)) return makeError(file.name() + ": " + name + ": .npy header lacks 'descr'");
    array.descr = match[1].str();
    if (!std::regex_search(header, match, fortran))
        return makeError(file.name() + ": " + name + ": .npy header lacks 'fortran_order'");
    if (match[1].str() == "True") return makeError(file.name() + ": " + name + ": Fortran-ordered arrays are not supported");
    if (!std::regex_search(header, match, shape)) return makeError(file.name() + ": " + name + ": .npy header lacks 'shape'");
    std::string dims = match[1].str();
    static const std::regex number(R"(\d+)", kLinearRegex);
    for (auto it = std::sregex_iterator(dims.begin(), dims.end(), number); it != std::sregex_iterator(); ++it) {
        if (it->str().size() > 15) return makeError(file.name() + ": " + name + ": absurd array dimension");
        array.shape.push_back(std::stoull(it->str()));
    }
    array.dataOffset = base + headerStart + headerLength;
    array.dataSize = available - (headerStart + headerLength);
    if (array.isInflated) array.dataOffset = headerStart + headerLength;
    return array;
}

std::uint64_t elementSize(const std::string& descr) {
    if (descr.size() >= 3 && descr[0] == '<' && descr[1] == 'U') {
        try {
            return 4 * std::stoull(descr.substr(2));
        } catch (const std::exception&) { return 0; }
    }
    static const std::map<std::string, std::uint64_t> sizes = {{"<f4", 4}, {"<f8", 8}, {"<u8", 8},
                                                               {"<i8", 8}, {"<u4", 4}, {"<i4", 4}};
    auto it = sizes.find(descr);
    return it == sizes.end() ? 0 : it->second;
}

class NpzReader final : public SampleReader {
public:
    NpzReader(InputFile file, std::uint64_t rows, NpyArray arrays[3], std::optional<SampleMetadata> metadata)
        : m_file(std::move(file)) {
        m_rows = rows;
        m_format = SampleFormat::Npz;
        m_metadata = std::move(metadata);
        for (int i = 0; i < 3; ++i) m_arrays[i] = std::move(arrays[i]);
    }

    Expected<void> read(std::uint64_t first, std::size_t n, float* positions, float* distances, float* gradients) override {
        if (first > m_rows || n > m_rows - first) return makeError(m_file.name() + ": rows out of range");
        float* targets[3] = {positions, distances, gradients};
        const std::uint64_t rowBytes[3] = {12, 4, 12};
        for (int i = 0; i < 3; ++i) {
            const NpyArray& array = m_arrays[i];
            std::uint64_t offset = array.dataOffset + rowBytes[i] * first;
            std::size_t size = std::size_t(rowBytes[i] * n);
            if (array.isInflated)
                std::memcpy(targets[i], array.inflated.data() + offset, size);
            else if (auto ok = m_file.readAt(offset, targets[i], size); !ok)
                return ok;
        }
        return {};
    }

private:
    InputFile m_file;
    NpyArray m_arrays[3];
};

} // namespace

Expected<std::unique_ptr<SampleWriter>> createNpzWriter(OutputFile file, std::uint64_t rows, const SampleMetadata& metadata,
                                                        bool forceZip64) {
    return std::unique_ptr<SampleWriter>(new NpzWriter(std::move(file), rows, metadata, forceZip64));
}

namespace {

// The archive's entries by name, from its central directory (ZIP64 records read); errors name the file.
Expected<std::map<std::string, ZipEntry>> readZipDirectory(const InputFile& file) {
    const std::string& name = file.name();
    if (file.size() < 22) return makeError(name + ": not an .npz file (too small for a ZIP archive)");
    std::size_t tailSize = std::size_t(std::min<std::uint64_t>(file.size(), 65536 + 22));
    std::string tail(tailSize, '\0');
    std::uint64_t tailStart = file.size() - tailSize;
    if (auto ok = file.readAt(tailStart, tail.data(), tail.size()); !ok) return ok.error();
    std::size_t end = std::string::npos;
    for (std::size_t i = tail.size() - 22 + 1; i-- > 0;)
        if (get<std::uint32_t>(tail.data() + i) == kEndSignature) {
            end = i;
            break;
        }
    if (end == std::string::npos) return makeError(name + ": not an .npz file (no ZIP end record)");
    std::uint64_t entries = get<std::uint16_t>(tail.data() + end + 10);
    std::uint64_t centralSize = get<std::uint32_t>(tail.data() + end + 12);
    std::uint64_t centralOffset = get<std::uint32_t>(tail.data() + end + 16);
    if (end >= 20 && get<std::uint32_t>(tail.data() + end - 20) == kZip64LocatorSignature) {
        std::uint64_t zip64End = get<std::uint64_t>(tail.data() + end - 20 + 8);
        char record[56];
        if (auto ok = file.readAt(zip64End, record, sizeof record); !ok) return ok.error();
        if (get<std::uint32_t>(record) != kZip64EndSignature) return makeError(name + ": corrupt ZIP64 end record");
        entries = get<std::uint64_t>(record + 32);
        centralSize = get<std::uint64_t>(record + 40);
        centralOffset = get<std::uint64_t>(record + 48);
    }
    if (entries > 4096 || centralSize > (1u << 24) || centralOffset > file.size() || centralSize > file.size() - centralOffset)
        return makeError(name + ": corrupt ZIP central directory (" + std::to_string(entries) + " entries at " +
                         std::to_string(centralOffset) + ")");
    std::string central(std::size_t(centralSize), '\0');
    if (auto ok = file.readAt(centralOffset, central.data(), central.size()); !ok) return ok.error();

    std::map<std::string, ZipEntry> found;
    std::size_t cursor = 0;
    for (std::uint64_t i = 0; i < entries; ++i) {
        if (cursor + 46 > central.size() || get<std::uint32_t>(central.data() + cursor) != kCentralSignature)
            return makeError(name + ": corrupt ZIP central directory entry " + std::to_string(i));
        const char* h = central.data() + cursor;
        ZipEntry entry;
        std::uint16_t flags = get<std::uint16_t>(h + 8);
        entry.method = get<std::uint16_t>(h + 10);
        entry.compressedSize = get<std::uint32_t>(h + 20);
        entry.size = get<std::uint32_t>(h + 24);
        std::uint16_t nameLength = get<std::uint16_t>(h + 28), extraLength = get<std::uint16_t>(h + 30),
                      commentLength = get<std::uint16_t>(h + 32);
        std::uint64_t localOffset = get<std::uint32_t>(h + 42);
        if (cursor + 46 + nameLength + extraLength + commentLength > central.size())
            return makeError(name + ": corrupt ZIP central directory");
        std::string entryName(h + 46, nameLength);
        // ZIP64 extra: the 64-bit values of the fields that hold 0xffffffff, in order.
        for (std::size_t e = 0; e + 4 <= extraLength;) {
            const char* extra = h + 46 + nameLength + e;
            std::uint16_t id = get<std::uint16_t>(extra), size = get<std::uint16_t>(extra + 2);
            if (e + 4 + size > extraLength) break;
            if (id == 0x0001) {
                std::size_t k = 4;
                auto next = [&](std::uint64_t& field) {
                    if (field == kMax32 && k + 8 <= std::size_t(size) + 4) {
                        field = get<std::uint64_t>(extra + k);
                        k += 8;
                    }
                };
                next(entry.size);
                next(entry.compressedSize);
                next(localOffset);
            }
            e += 4 + size;
        }
        cursor += 46 + nameLength + extraLength + commentLength;
        if (flags & 1) return makeError(name + ": " + entryName + " is encrypted");
        char local[30];
        if (auto ok = file.readAt(localOffset, local, sizeof local); !ok) return ok.error();
        if (get<std::uint32_t>(local) != kLocalSignature) return makeError(name + ": " + entryName + ": corrupt local header");
        entry.dataOffset = localOffset + 30 + get<std::uint16_t>(local + 26) + get<std::uint16_t>(local + 28);
        if (entry.dataOffset > file.size() || entry.compressedSize > file.size() - entry.dataOffset)
            return makeError(name + ": " + entryName + ": data runs past the end of the file");
        found[entryName] = entry;
    }
    return found;
}

// The three sample arrays (position, distance, gradient) into `arrays`: their row count.
Expected<std::uint64_t> readSampleArrays(const InputFile& file, const std::map<std::string, ZipEntry>& found,
                                         NpyArray (&arrays)[3]) {
    const std::string& name = file.name();
    const char* required[3] = {"position", "distance", "gradient"};
    std::uint64_t rows = 0;
    for (int i = 0; i < 3; ++i) {
        auto it = found.find(std::string(required[i]) + ".npy");
        if (it == found.end())
            return makeError(name + ": no '" + required[i] + "' array (expected position, distance, gradient)");
        auto array = parseNpy(file, it->second, required[i]);
        if (!array) return array.error();
        if (array->descr != "<f4")
            return makeError(name + ": '" + required[i] + "' has dtype '" + array->descr + "'; float32 ('<f4') expected");
        bool vector = i != 1;
        if (array->shape.size() != (vector ? 2u : 1u) || (vector && array->shape[1] != 3))
            return makeError(name + ": '" + required[i] + "' has the wrong shape (expected " + (vector ? "(N, 3)" : "(N,)") +
                             ")");
        if (i == 0)
            rows = array->shape[0];
        else if (array->shape[0] != rows)
            return makeError(name + ": '" + required[i] + "' has " + std::to_string(array->shape[0]) + " rows, 'position' has " +
                             std::to_string(rows));
        if (rows > array->dataSize / (vector ? 12 : 4)) return makeError(name + ": '" + required[i] + "' is truncated");
        arrays[i] = std::move(*array);
    }
    return rows;
}

// The run's metadata arrays, where there are any; malformed metadata is ignored rather than
// failing the data.
std::optional<SampleMetadata> readNpzMetadata(const InputFile& file, const std::map<std::string, ZipEntry>& found) {
    SampleMetadata metadata;
    bool any = false;
    auto readSmall = [&](const char* key, std::string& bytes, std::string& descr) -> bool {
        auto it = found.find(std::string(key) + ".npy");
        if (it == found.end() || it->second.size > 4096) return false;
        auto array = parseNpy(file, it->second, key);
        if (!array || !array->shape.empty()) return false;
        std::uint64_t size = elementSize(array->descr);
        if (size == 0 || size > array->dataSize || size > 4096) return false;
        bytes.resize(std::size_t(size));
        if (array->isInflated)
            std::memcpy(bytes.data(), array->inflated.data() + array->dataOffset, bytes.size());
        else if (!file.readAt(array->dataOffset, bytes.data(), bytes.size()))
            return false;
        descr = array->descr;
        any = true;
        return true;
    };
    auto readString = [&](const char* key, std::string& out) {
        std::string bytes, descr;
        if (!readSmall(key, bytes, descr) || descr.rfind("<U", 0) != 0) return;
        std::u32string wide(bytes.size() / 4, U'\0');
        std::memcpy(wide.data(), bytes.data(), wide.size() * 4);
        out = utf32ToUtf8(wide);
    };
    auto readUnsigned = [&](const char* key, std::uint64_t& out) {
        std::string bytes, descr;
        if (readSmall(key, bytes, descr) && (descr == "<u8" || descr == "<i8")) out = get<std::uint64_t>(bytes.data());
    };
    readString("sdf", metadata.sdf);
    readString("pattern", metadata.pattern);
    readString("version", metadata.version);
    readString("parameters", metadata.parameters);
    readString("mesh", metadata.mesh);
    readString("frame", metadata.frame);
    readUnsigned("seed", metadata.seed);
    readUnsigned("first_index", metadata.firstIndex);
    readUnsigned("total_count", metadata.totalCount);
    {
        std::string bytes, descr;
        if (readSmall("time", bytes, descr)) {
            if (descr == "<f4")
                metadata.time = get<float>(bytes.data());
            else if (descr == "<f8")
                metadata.time = float(get<double>(bytes.data()));
        }
    }
    if (!any) return std::nullopt;
    return metadata;
}

} // namespace

Expected<std::unique_ptr<SampleReader>> openNpzReader(InputFile file) {
    auto found = readZipDirectory(file);
    if (!found) return found.error();
    NpyArray arrays[3];
    auto rows = readSampleArrays(file, *found, arrays);
    if (!rows) return rows.error();
    std::optional<SampleMetadata> metadata = readNpzMetadata(file, *found);
    return std::unique_ptr<SampleReader>(new NpzReader(std::move(file), *rows, arrays, std::move(metadata)));
}

} // namespace sdfwb::sampling::detail
