#pragma once
// Image files through OpenImageIO; the format follows the extension (.png, .jpg, .exr, ...).

#include <core/Expected.h>
#include <renderer/Image.h>

#include <filesystem>

namespace sdfwb::renderer {

// Writes atomically: a temporary file next to `path`, renamed when complete, so a failed write
// leaves no partial file and keeps an existing one.
Expected<void> writeImage(const std::filesystem::path& path, const Image& image);

Expected<Image> readImage(const std::filesystem::path& path);

// True when OpenImageIO can write files with this extension (".png").
bool canWriteImageExtension(const std::string& extension);

} // namespace sdfwb::renderer
