#pragma once
// Whole-file text I/O with messages that name the file. Writes are atomic: a temporary file in
// the same folder is written, flushed to disk and renamed over the target.

#include <core/Expected.h>

#include <filesystem>
#include <string>
#include <string_view>

namespace sdfwb {

Expected<std::string> readTextFile(const std::filesystem::path& path);

// Writes `bytes` to `path` atomically (temp file + fsync + rename). On failure the old file,
// if any, is untouched and no temporary file is left behind.
Expected<void> writeFileAtomically(const std::filesystem::path& path, std::string_view bytes);

} // namespace sdfwb
