// Fuzzes the .bin, .npz and .ply readers (sampling/src/{Bin,Npz,Ply}File.cpp) through
// SampleReader::openBytes, the in-memory twin of SampleReader::open. Every input is offered to
// all three readers, so the corpus holds real files. A reader must reject a corrupt file with a
// message naming it, and a file it accepts must read back every row and refuse ranges past the end.

#include <sampling/SampleFile.h>

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <string>
#include <vector>

using namespace sdfwb::sampling;

namespace {

const std::string kName = "fuzz-input";

void require(bool condition, const char* what) {
    if (!condition) {
        std::fprintf(stderr, "fuzz_sample_files: contract broken: %s\n", what);
        std::abort();
    }
}

void readEverything(SampleReader& reader) {
    const std::uint64_t rows = reader.rows();
    constexpr std::size_t kChunk = 4096;
    std::vector<float> positions(3 * kChunk), distances(kChunk), gradients(3 * kChunk);
    for (std::uint64_t first = 0; first < rows; first += kChunk) {
        std::size_t n = std::size_t(std::min<std::uint64_t>(kChunk, rows - first));
        auto ok = reader.read(first, n, positions.data(), distances.data(), gradients.data());
        require(ok.hasValue(), "an accepted file failed to read its own rows");
    }
    // Ranges past the end, including ones whose end overflows, are errors, not reads.
    const std::uint64_t past[][2] = {{rows, 1},
                                     {rows + 1, 0},
                                     {std::numeric_limits<std::uint64_t>::max(), 2},
                                     {std::numeric_limits<std::uint64_t>::max() / 4, 8}};
    for (const auto& range : past) {
        auto ok = reader.read(range[0], std::size_t(range[1]), positions.data(), distances.data(), gradients.data());
        require(!ok.hasValue(), "a range past the last row was read");
    }
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string bytes(reinterpret_cast<const char*>(data), size);
    for (SampleFormat format : {SampleFormat::Bin, SampleFormat::Npz, SampleFormat::Ply}) {
        auto reader = SampleReader::openBytes(bytes, format, kName);
        if (!reader) {
            require(reader.error().message.rfind(kName + ":", 0) == 0, "an error message does not start with the file name");
            continue;
        }
        require((*reader)->format() == format, "the reader reports another format");
        readEverything(**reader);
    }
    return 0;
}
