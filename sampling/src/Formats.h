#pragma once
// Per-format writers and readers behind SampleWriter/SampleReader. Private to sampling/.

#include "OutputFile.h"

#include <sampling/SampleFile.h>

#include <cstring>
#include <string>

namespace sdfwb::sampling::detail {

Expected<std::unique_ptr<SampleWriter>> createBinWriter(OutputFile file, std::uint64_t rows, const SampleMetadata& metadata);
Expected<std::unique_ptr<SampleReader>> openBinReader(InputFile file);
Expected<std::unique_ptr<SampleWriter>> createNpzWriter(OutputFile file, std::uint64_t rows, const SampleMetadata& metadata,
                                                        bool forceZip64);
Expected<std::unique_ptr<SampleReader>> openNpzReader(InputFile file);
Expected<std::unique_ptr<SampleWriter>> createPlyWriter(OutputFile file, std::uint64_t rows, const SampleMetadata& metadata);
Expected<std::unique_ptr<SampleReader>> openPlyReader(InputFile file);

// Little-endian field helpers (sdfwb builds for little-endian hosts only).
inline void put16(std::string& out, std::uint16_t v) { out.append(reinterpret_cast<const char*>(&v), 2); }
inline void put32(std::string& out, std::uint32_t v) { out.append(reinterpret_cast<const char*>(&v), 4); }
inline void put64(std::string& out, std::uint64_t v) { out.append(reinterpret_cast<const char*>(&v), 8); }
template <class T> T get(const char* data) {
    T value;
    std::memcpy(&value, data, sizeof(T));
    return value;
}

// Rows chunk by chunk when reading: at most this many at a time.
inline constexpr std::size_t kCopyChunkRows = 1u << 20;
// From this many rows, .ply and .npz align their large arrays to 4096 bytes in the file (at most
// 4 KiB of padding per array) so that they can be written past the page cache.
inline constexpr std::uint64_t kDirectFromRows = 65536;

} // namespace sdfwb::sampling::detail
