#include <sampling/SampleFile.h>

#include "Formats.h"

#include <algorithm>
#include <cstdio>
#include <vector>

namespace sdfwb::sampling {
namespace fs = std::filesystem;

const char* formatName(SampleFormat format) {
    switch (format) {
    case SampleFormat::Bin:
        return "bin";
    case SampleFormat::Npz:
        return "npz";
    case SampleFormat::Ply:
        return "ply";
    }
    return "?";
}

std::optional<SampleFormat> parseFormat(std::string_view name) {
    for (SampleFormat format : {SampleFormat::Bin, SampleFormat::Npz, SampleFormat::Ply})
        if (name == formatName(format)) return format;
    return std::nullopt;
}

std::optional<SampleFormat> formatFromPath(const fs::path& path) {
    std::string extension = path.extension().string();
    if (extension.size() < 2) return std::nullopt;
    for (char& c : extension) c = char(std::tolower(static_cast<unsigned char>(c)));
    return parseFormat(extension.substr(1));
}

namespace {

std::string jsonString(const std::string& text) {
    std::string out = "\"";
    for (unsigned char c : text) {
        if (c == '"' || c == '\\') {
            out += '\\';
            out += char(c);
        } else if (c < 0x20) {
            char escaped[8];
            std::snprintf(escaped, sizeof escaped, "\\u%04x", unsigned(c));
            out += escaped;
        } else {
            out += char(c);
        }
    }
    return out + "\"";
}

} // namespace

std::string metadataJson(const SampleMetadata& m) {
    char time[32];
    std::snprintf(time, sizeof time, "%.9g", double(m.time));
    return "{\"sdf\": " + jsonString(m.sdf) + ", \"pattern\": " + jsonString(m.pattern) +
           ", \"seed\": " + std::to_string(m.seed) + ", \"time\": " + time +
           ", \"first_index\": " + std::to_string(m.firstIndex) + ", \"total_count\": " + std::to_string(m.totalCount) +
           ", \"version\": " + jsonString(m.version) +
           ", \"parameters\": " + (m.parameters.empty() ? std::string("{}") : m.parameters) +
           (m.mesh.empty() ? std::string() : ", \"mesh\": " + m.mesh) +
           (m.frame.empty() ? std::string() : ", \"frame\": " + m.frame) + "}";
}

std::uint64_t maxRows(SampleFormat format) {
    switch (format) {
    case SampleFormat::Bin:
        return 0xffffffffull; // N is a uint32
    case SampleFormat::Npz:
    case SampleFormat::Ply:
        return 0xffffffffull; // sdfwb indexes samples with 32 bits on the GPU
    }
    return 0;
}

SampleWriter::~SampleWriter() = default;

Expected<void> SampleWriter::appendRows(const float* rows, std::size_t n) {
    SampleSet block;
    for (std::size_t first = 0; first < n; first += detail::kCopyChunkRows) {
        const std::size_t count = std::min(detail::kCopyChunkRows, n - first);
        block.resize(count);
        for (std::size_t i = 0; i < count; ++i) {
            const float* row = rows + 7 * (first + i);
            std::copy(row, row + 3, block.positions.data() + 3 * i);
            block.distances[i] = row[3];
            std::copy(row + 4, row + 7, block.gradients.data() + 3 * i);
        }
        if (auto ok = append(block.positions.data(), block.distances.data(), block.gradients.data(), count); !ok) return ok;
    }
    return {};
}
SampleReader::~SampleReader() = default;

Expected<std::unique_ptr<SampleWriter>> SampleWriter::create(const fs::path& path, SampleFormat format, std::uint64_t rows,
                                                             const SampleMetadata& metadata, const Options& options) {
    if (rows > maxRows(format))
        return makeError(path.string() + ": " + std::to_string(rows) + " rows exceed the ." + formatName(format) + " limit of " +
                         std::to_string(maxRows(format)));
    auto file = detail::OutputFile::create(path);
    if (!file) return file.error();
    switch (format) {
    case SampleFormat::Bin:
        return detail::createBinWriter(std::move(*file), rows, metadata);
    case SampleFormat::Npz:
        return detail::createNpzWriter(std::move(*file), rows, metadata, options.forceZip64);
    case SampleFormat::Ply:
        return detail::createPlyWriter(std::move(*file), rows, metadata);
    }
    return makeError("sampling: unknown format");
}

Expected<std::unique_ptr<SampleReader>> SampleReader::open(const fs::path& path) {
    auto format = formatFromPath(path);
    if (!format)
        return makeError(path.string() + ": unknown sample file type '" + path.extension().string() + "' (.bin, .npz or .ply)");
    auto file = detail::InputFile::open(path);
    if (!file) return file.error();
    switch (*format) {
    case SampleFormat::Bin:
        return detail::openBinReader(std::move(*file));
    case SampleFormat::Npz:
        return detail::openNpzReader(std::move(*file));
    case SampleFormat::Ply:
        return detail::openPlyReader(std::move(*file));
    }
    return makeError("sampling: unknown format");
}

Expected<std::unique_ptr<SampleReader>> SampleReader::openBytes(std::string bytes, SampleFormat format, const std::string& name) {
    detail::InputFile file = detail::InputFile::fromBytes(name, std::move(bytes));
    switch (format) {
    case SampleFormat::Bin:
        return detail::openBinReader(std::move(file));
    case SampleFormat::Npz:
        return detail::openNpzReader(std::move(file));
    case SampleFormat::Ply:
        return detail::openPlyReader(std::move(file));
    }
    return makeError("sampling: unknown format");
}

Expected<SampleSet> readSamples(const fs::path& path, std::optional<SampleMetadata>* metadata) {
    auto reader = SampleReader::open(path);
    if (!reader) return reader.error();
    SampleSet samples;
    samples.resize(std::size_t((*reader)->rows()));
    if (auto ok =
            (*reader)->read(0, samples.size(), samples.positions.data(), samples.distances.data(), samples.gradients.data());
        !ok)
        return ok.error();
    if (metadata) *metadata = (*reader)->metadata();
    return samples;
}

Expected<void> writeSamples(const fs::path& path, SampleFormat format, const SampleSet& samples, const SampleMetadata& metadata) {
    if (samples.positions.size() != 3 * samples.size() || samples.gradients.size() != 3 * samples.size())
        return makeError(path.string() + ": inconsistent sample arrays");
    auto writer = SampleWriter::create(path, format, samples.size(), metadata);
    if (!writer) return writer.error();
    if (auto ok = (*writer)->append(samples.positions.data(), samples.distances.data(), samples.gradients.data(), samples.size());
        !ok)
        return ok;
    return (*writer)->commit();
}

Expected<MergeReport> mergeSampleFiles(const fs::path& output, SampleFormat format, const std::vector<fs::path>& parts) {
    if (parts.empty()) return makeError("merge: no input files");
    std::vector<std::unique_ptr<SampleReader>> readers;
    for (const fs::path& part : parts) {
        if (fs::exists(output) && fs::exists(part) && fs::equivalent(output, part))
            return makeError("merge: output '" + output.string() + "' is also an input");
        auto reader = SampleReader::open(part);
        if (!reader) return reader.error();
        readers.push_back(std::move(*reader));
    }
    // Order by first index when every part says where it belongs; check they tile one run.
    bool allHaveMetadata = std::all_of(readers.begin(), readers.end(), [](const auto& r) { return r->metadata().has_value(); });
    std::vector<std::size_t> order(readers.size());
    for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
    std::uint64_t total = 0;
    for (const auto& reader : readers) total += reader->rows();
    SampleMetadata merged;
    if (allHaveMetadata) {
        std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
            return readers[a]->metadata()->firstIndex < readers[b]->metadata()->firstIndex;
        });
        const SampleMetadata& first = *readers[order[0]]->metadata();
        std::uint64_t expected = 0;
        for (std::size_t i : order) {
            const SampleMetadata& m = *readers[i]->metadata();
            const std::string& name = parts[i].string();
            if (m.sdf != first.sdf || m.pattern != first.pattern || m.seed != first.seed || m.time != first.time ||
                m.totalCount != first.totalCount || m.mesh != first.mesh || m.frame != first.frame)
                return makeError("merge: " + name +
                                 " belongs to a different run (sdf, pattern, seed, time, N, mesh options or frame differ from " +
                                 parts[order[0]].string() + ")");
            if (m.firstIndex != expected)
                return makeError("merge: " + name + " starts at sample " + std::to_string(m.firstIndex) + ", expected " +
                                 std::to_string(expected) + " (a shard is missing or repeated)");
            expected += readers[i]->rows();
        }
        if (expected != first.totalCount)
            return makeError("merge: the parts hold " + std::to_string(expected) + " of the run's " +
                             std::to_string(first.totalCount) + " samples (a shard is missing)");
        merged = first;
        merged.firstIndex = 0;
    } else {
        merged.totalCount = total;
    }
    auto writer = SampleWriter::create(output, format, total, merged);
    if (!writer) return writer.error();
    SampleSet buffer;
    for (std::size_t i : order) {
        SampleReader& reader = *readers[i];
        for (std::uint64_t done = 0; done < reader.rows();) {
            std::size_t count = std::size_t(std::min<std::uint64_t>(detail::kCopyChunkRows, reader.rows() - done));
            buffer.resize(count);
            if (auto ok = reader.read(done, count, buffer.positions.data(), buffer.distances.data(), buffer.gradients.data());
                !ok)
                return ok.error();
            if (auto ok = (*writer)->append(buffer.positions.data(), buffer.distances.data(), buffer.gradients.data(), count);
                !ok)
                return ok.error();
            done += count;
        }
    }
    if (auto ok = (*writer)->commit(); !ok) return ok.error();
    return MergeReport{total, parts.size()};
}

} // namespace sdfwb::sampling
