#pragma once
// The paper's .bin format (Table 2): uint32 N, then N float32 positions (xyz), N float32
// distances, N float32 gradients (xyz); little-endian; 4 + 28 N bytes in all.

#include <core/Expected.h>
#include <sampling/SampleSet.h>

#include <filesystem>
#include <string>

namespace sdfwb::sampling {

// Largest N the format can hold (uint32 count).
inline constexpr std::uint64_t kBinMaxSamples = 0xffffffffull;

// Serialises to bytes; fails when N exceeds kBinMaxSamples.
Expected<std::string> encodeBin(const SampleSet& samples);

// Parses bytes; `name` labels errors ("out.bin: file has 100 bytes, but N = 7 needs 200").
Expected<SampleSet> decodeBin(const std::string& bytes, const std::string& name);

// Atomic write (temporary file + rename) and read.
Expected<void> writeBin(const std::filesystem::path& path, const SampleSet& samples);
Expected<SampleSet> readBin(const std::filesystem::path& path);

} // namespace sdfwb::sampling
