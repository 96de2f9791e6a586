#pragma once
// Image files through OpenImageIO; the format follows the extension (.png, .jpg, .exr, ...).

#include <core/Expected.h>
#include <renderer/Image.h>

#include <filesystem>

namespace sdfwb::renderer {

// Writes atomically: a temporary file next to `path`, renamed when complete, so a failed write
// leaves no partial file and keeps an existing one.
Expected<void> writeImage(const std::filesystem::path& path, const Image& image);

// A float frame: .exr keeps it as half floats (values above 1 kept); other formats get it
// clamped to [0,1] and quantised to 8 bits.
Expected<void> writeImage(const std::filesystem::path& path, const FloatImage& image);

// True when the extension names a high-dynamic-range format (.exr, .hdr): render it in float.
bool isHighDynamicRange(const std::filesystem::path& path);

// Draws `text` (lines split at '\n') in the lower-left corner over a darkened box, in DejaVu Sans
// (fonts-dejavu-core): the name/author/license overlay of exports. Fails, leaving the image as it
// was, when no font file is found.
Expected<void> drawLabel(Image& image, const std::string& text);
Expected<void> drawLabel(FloatImage& image, const std::string& text);

// Any image as float RGBA (EXR values above 1 kept; 8-bit files scaled to [0,1]).
Expected<FloatImage> readFloatImage(const std::filesystem::path& path);

Expected<Image> readImage(const std::filesystem::path& path);

// True when OpenImageIO can write files with this extension (".png").
bool canWriteImageExtension(const std::string& extension);

} // namespace sdfwb::renderer
