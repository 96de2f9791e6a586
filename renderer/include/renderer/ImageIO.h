#pragma once
// Image files through OpenImageIO; the format follows the extension (.png, .jpg, .exr, ...).
// OpenImageIO lives in libsdfwb_media.so, loaded the first time an image is read or written (a
// command that touches no image never loads it); when it cannot be loaded these functions return
// an error that says so.

#include <core/Expected.h>
#include <renderer/Image.h>

#include <cctype>
#include <filesystem>
#include <string>

namespace sdfwb::renderer {

// Writes atomically: a temporary file next to `path`, renamed when complete, so a failed write
// leaves no partial file and keeps an existing one.
Expected<void> writeImage(const std::filesystem::path& path, const Image& image);

// A float frame: .exr keeps it as half floats (values above 1 kept); other formats get it
// clamped to [0,1] and quantised to 8 bits.
Expected<void> writeImage(const std::filesystem::path& path, const FloatImage& image);

// True when the extension names a high-dynamic-range format (.exr, .hdr): render it in float.
inline bool isHighDynamicRange(const std::filesystem::path& path) {
    std::string extension = path.extension().string();
    for (char& c : extension) c = char(std::tolower(static_cast<unsigned char>(c)));
    return extension == ".exr" || extension == ".hdr";
}

// Draws `text` (lines split at '\n') in the lower-left corner over a darkened box, in DejaVu Sans
// (fonts-dejavu-core): the name/author/license overlay of exports. Fails, leaving the image as it
// was, when no font file is found.
Expected<void> drawLabel(Image& image, const std::string& text);
Expected<void> drawLabel(FloatImage& image, const std::string& text);

// Any image as float RGBA (EXR values above 1 kept; 8-bit files scaled to [0,1]).
Expected<FloatImage> readFloatImage(const std::filesystem::path& path);

Expected<Image> readImage(const std::filesystem::path& path);

// True when OpenImageIO can write files with this extension (".png"); an error when the module
// that holds OpenImageIO cannot be loaded.
Expected<bool> canWriteImageExtension(const std::string& extension);

} // namespace sdfwb::renderer
