// Counts a .bin sample file's rows whose position, distance or gradient is not finite, on the
// host, by the bits (an all-ones exponent), as the sampler's shader counts them on the GPU: the
// check of the GPU's bad-row count (issue 49) in scripts/device_check.
//
//   build/bench/count_bad_rows FILE.bin      prints "ROWS rows, BAD bad rows"; exit 1 on a bad file
//
// .bin (docs/sampling.md): uint32 N, N x 3 float32 positions, N float32 distances, N x 3 float32
// gradients, little-endian.

#include <cstdint>
#include <cstdio>
#include <cstring>
#include <vector>

namespace {

bool finite(const float* values, int count) {
    for (int k = 0; k < count; ++k) {
        std::uint32_t bits = 0;
        std::memcpy(&bits, &values[k], sizeof bits);
        if ((bits & 0x7f800000u) == 0x7f800000u) return false;
    }
    return true;
}

} // namespace

int main(int argc, char** argv) {
    if (argc != 2) {
        std::fprintf(stderr, "usage: count_bad_rows FILE.bin\n");
        return 2;
    }
    std::FILE* file = std::fopen(argv[1], "rb");
    if (!file) {
        std::fprintf(stderr, "count_bad_rows: %s: cannot open\n", argv[1]);
        return 1;
    }
    std::uint32_t rows = 0;
    bool ok = std::fread(&rows, sizeof rows, 1, file) == 1;
    std::vector<float> positions(std::size_t(rows) * 3), distances(rows), gradients(std::size_t(rows) * 3);
    ok = ok && std::fread(positions.data(), sizeof(float), positions.size(), file) == positions.size();
    ok = ok && std::fread(distances.data(), sizeof(float), distances.size(), file) == distances.size();
    ok = ok && std::fread(gradients.data(), sizeof(float), gradients.size(), file) == gradients.size();
    const bool trailing = std::fgetc(file) != EOF;
    std::fclose(file);
    if (!ok || trailing) {
        std::fprintf(stderr, "count_bad_rows: %s: not a .bin of %u rows (4 + 28 x %u bytes)\n", argv[1], rows, rows);
        return 1;
    }
    std::uint64_t bad = 0;
    for (std::size_t row = 0; row < rows; ++row)
        bad += !(finite(&positions[row * 3], 3) && finite(&distances[row], 1) && finite(&gradients[row * 3], 3));
    std::printf("%u rows, %llu bad rows\n", rows, static_cast<unsigned long long>(bad));
    return 0;
}
