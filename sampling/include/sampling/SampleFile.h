#pragma once
// Sample files: .bin (the paper's Table 2), .npz (NumPy, readable with allow_pickle=False) and
// .ply (binary little-endian, gradient and distance as vertex properties). Writers stream rows in
// chunks into a temporary file beside the target and rename it into place on commit(), so a
// failed or cancelled run leaves no partial file and keeps an existing one. Readers reject corrupt
// files with a message naming the file and what is wrong, and read any row range without loading
// the whole file (except deflate-compressed .npz entries, which are inflated once).

#include <core/Expected.h>
#include <sampling/SampleSet.h>

#include <array>
#include <cstdint>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <string_view>

namespace sdfwb::sampling {

enum class SampleFormat { Bin, Npz, Ply };

const char* formatName(SampleFormat format);
std::optional<SampleFormat> parseFormat(std::string_view name);                // "bin" | "npz" | "ply"
std::optional<SampleFormat> formatFromPath(const std::filesystem::path& path); // by extension

// Where rows came from. .npz stores every field as an array, .ply as header comments; .bin has
// no room for metadata.
struct SampleMetadata {
    std::string sdf; // as the user named it (dataset name or path)
    std::string pattern;
    std::uint64_t seed = 0;
    float time = 0.0f;
    std::uint64_t firstIndex = 0; // global index of the file's first row (non-zero for shards)
    std::uint64_t totalCount = 0; // N of the whole run the rows belong to
    std::string version;          // sdfwb version that wrote the file
    // The SDF's parameter values as a JSON object ({"radius":0.3,"tint":[1,0.5,0]}); empty when
    // it declares none. npz: a `parameters` string array; PLY: a comment; .bin: a JSON sidecar
    // FILE.bin.json with all of this metadata (the paper's .bin has no room for it).
    std::string parameters;
    // A mesh SDF's provenance as a JSON object: file, triangles, closed, sign, normalize, transform
    // (file -> field, column-major 4x4) and the file's bounds ([min xyz, max xyz]); empty for GLSL
    // SDFs. Stored like `parameters` (npz `mesh`, PLY comment, .bin sidecar).
    std::string mesh;
    // A framed GLSL field (--normalize: shaders::PreparedSdf::frame) as a JSON object
    // {"normalize": ..., "centre": [x, y, z], "scale": s}: a row's position p is the field's point
    // centre + scale * p, its distance and gradient the field's divided by scale and as they are.
    // Empty when the field is not framed. Stored like `mesh` (npz `frame`, PLY comment, sidecar).
    std::string frame;
};

// The metadata as one JSON object (the .bin sidecar's content).
std::string metadataJson(const SampleMetadata& metadata);

// Largest row count a format can hold (.bin stores N as uint32).
std::uint64_t maxRows(SampleFormat format);

class SampleWriter {
public:
    struct Options {
        bool forceZip64 = false; // .npz: use ZIP64 records even when not needed (for tests)
    };

    // Opens a temporary file for `rows` rows. Fails before writing anything when rows exceeds
    // maxRows(format) or the folder is not writable.
    static Expected<std::unique_ptr<SampleWriter>> create(const std::filesystem::path& path, SampleFormat format,
                                                          std::uint64_t rows, const SampleMetadata& metadata,
                                                          const Options& options);
    static Expected<std::unique_ptr<SampleWriter>> create(const std::filesystem::path& path, SampleFormat format,
                                                          std::uint64_t rows, const SampleMetadata& metadata) {
        return create(path, format, rows, metadata, Options{});
    }

    // Removes the temporary file unless commit() succeeded.
    virtual ~SampleWriter();

    // Appends the next n rows: 3n positions, n distances, 3n gradients.
    virtual Expected<void> append(const float* positions, const float* distances, const float* gradients, std::size_t n) = 0;

    // The same from one array of 7-float rows (x y z distance gx gy gz). A format that stores rows
    // so (.ply) says so with takesRows() and writes them without rearranging; the others split them.
    virtual bool takesRows() const { return false; }
    virtual Expected<void> appendRows(const float* rows, std::size_t n);

    // Floats to leave before each of the three arrays of the chunk that starts at `firstRow` (below
    // renderer::SampleCompute::kMaxShift), so that each lies in memory at the offset modulo a disk
    // block it has in the file and whole blocks go to the disk without a copy (.bin). None by default.
    virtual std::array<std::uint32_t, 3> arrayShift(std::uint64_t firstRow) const {
        (void)firstRow;
        return {};
    }

    // After exactly `rows` rows: finishes the file, flushes it to disk and renames it into place.
    virtual Expected<void> commit() = 0;

protected:
    SampleWriter() = default;
};

class SampleReader {
public:
    static Expected<std::unique_ptr<SampleReader>> open(const std::filesystem::path& path);
    // The same reader over a file's bytes already in memory (fuzzing, archives); `name` labels
    // the errors as a path would.
    static Expected<std::unique_ptr<SampleReader>> openBytes(std::string bytes, SampleFormat format, const std::string& name);
    virtual ~SampleReader();

    std::uint64_t rows() const { return m_rows; }
    SampleFormat format() const { return m_format; }
    // Metadata when the file carries it (.npz, .ply written by sdfwb).
    const std::optional<SampleMetadata>& metadata() const { return m_metadata; }

    // Reads rows [first, first + n) into the arrays (3n, n, 3n floats); a range past rows() is
    // an error.
    virtual Expected<void> read(std::uint64_t first, std::size_t n, float* positions, float* distances, float* gradients) = 0;

protected:
    SampleReader() = default;
    std::uint64_t m_rows = 0;
    SampleFormat m_format = SampleFormat::Bin;
    std::optional<SampleMetadata> m_metadata;
};

// Whole-file conveniences (the Python module's load/save, tests).
Expected<SampleSet> readSamples(const std::filesystem::path& path, std::optional<SampleMetadata>* metadata = nullptr);
Expected<void> writeSamples(const std::filesystem::path& path, SampleFormat format, const SampleSet& samples,
                            const SampleMetadata& metadata);

// Joins shard files into the file one run would have written. Parts with metadata (.npz, .ply)
// are ordered by their first index and must be contiguous slices of the same run; .bin parts are
// taken in the order given.
struct MergeReport {
    std::uint64_t rows = 0;
    std::size_t parts = 0;
};
Expected<MergeReport> mergeSampleFiles(const std::filesystem::path& output, SampleFormat format,
                                       const std::vector<std::filesystem::path>& parts);

} // namespace sdfwb::sampling
