#include <sampling/BinFormat.h>

#include <core/TextFile.h>

#include <bit>
#include <cstring>

namespace sdfwb::sampling {
namespace {

static_assert(std::endian::native == std::endian::little, "sdfwb writes .bin files on little-endian hosts only");
static_assert(sizeof(float) == 4);

void append(std::string& out, const void* data, std::size_t bytes) {
    out.append(static_cast<const char*>(data), bytes);
}

} // namespace

Expected<std::string> encodeBin(const SampleSet& samples) {
    const std::uint64_t n = samples.size();
    if (n > kBinMaxSamples) return makeError(".bin: " + std::to_string(n) + " samples exceed the format's uint32 limit of " + std::to_string(kBinMaxSamples));
    if (samples.positions.size() != 3 * n || samples.gradients.size() != 3 * n)
        return makeError(".bin: inconsistent sample arrays");
    std::string out;
    out.reserve(4 + 28 * n);
    const std::uint32_t count = std::uint32_t(n);
    append(out, &count, 4);
    append(out, samples.positions.data(), 12 * n);
    append(out, samples.distances.data(), 4 * n);
    append(out, samples.gradients.data(), 12 * n);
    return out;
}

Expected<SampleSet> decodeBin(const std::string& bytes, const std::string& name) {
    if (bytes.size() < 4) return makeError(name + ": not a .bin sample file: " + std::to_string(bytes.size()) + " bytes, the header alone needs 4");
    std::uint32_t count = 0;
    std::memcpy(&count, bytes.data(), 4);
    const std::uint64_t expected = 4 + 28ull * count;
    if (bytes.size() != expected)
        return makeError(name + ": file has " + std::to_string(bytes.size()) + " bytes, but its header says N = " + std::to_string(count) +
                         ", which needs " + std::to_string(expected));
    SampleSet samples;
    samples.resize(count);
    const char* data = bytes.data() + 4;
    std::memcpy(samples.positions.data(), data, 12ull * count);
    std::memcpy(samples.distances.data(), data + 12ull * count, 4ull * count);
    std::memcpy(samples.gradients.data(), data + 16ull * count, 12ull * count);
    return samples;
}

Expected<void> writeBin(const std::filesystem::path& path, const SampleSet& samples) {
    auto bytes = encodeBin(samples);
    if (!bytes) return makeError(path.string() + ": " + bytes.error().message);
    return writeFileAtomically(path, *bytes);
}

Expected<SampleSet> readBin(const std::filesystem::path& path) {
    auto bytes = readTextFile(path);
    if (!bytes) return bytes.error();
    return decodeBin(*bytes, path.string());
}

} // namespace sdfwb::sampling
