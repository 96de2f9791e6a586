#pragma once
// The image and video functions of libsdfwb_media.so, the module that holds OpenImageIO and the
// FFmpeg libraries. The renderer loads it the first time a command reads or writes an image or a
// video (src/Media.cpp), so a command that does neither never loads those libraries (about 250 of
// the 285 shared libraries sdfwb needs, and most of its start-up time).
//
// Both sides are built by the same build from the same headers; kAbiVersion changes whenever this
// table does, and the loader refuses a module of another version.

#include <core/Expected.h>
#include <renderer/Image.h>

#include <filesystem>
#include <memory>
#include <string>

namespace sdfwb::renderer::media {

inline constexpr int kAbiVersion = 2;
inline constexpr const char* kModuleFile = "libsdfwb_media.so";
inline constexpr const char* kEntryPoint = "sdfwb_media_api";

// One MP4 being written (VideoWriter's engine).
class VideoEncoder {
public:
    virtual ~VideoEncoder() = default;
    virtual Expected<void> addFrame(const Image& frame) = 0;
    virtual Expected<void> finish() = 0;
    virtual int frames() const = 0;
};

struct Api {
    int abiVersion;
    Expected<void> (*writeImage)(const std::filesystem::path&, const Image&);
    Expected<void> (*writeFloatImage)(const std::filesystem::path&, const FloatImage&);
    Expected<void> (*drawLabel)(Image&, const std::string&);
    Expected<void> (*drawFloatLabel)(FloatImage&, const std::string&);
    Expected<FloatImage> (*readFloatImage)(const std::filesystem::path&);
    Expected<Image> (*readImage)(const std::filesystem::path&);
    bool (*canWriteImageExtension)(const std::string&);
    Expected<std::unique_ptr<VideoEncoder>> (*openVideo)(const std::filesystem::path&, int width, int height, int framesPerSecond,
                                                         const FileMetadata&);
};

// The module's functions, defined in ImageFiles.cpp and VideoEncoder.cpp.
Expected<void> writeImage(const std::filesystem::path& path, const Image& image);
Expected<void> writeImage(const std::filesystem::path& path, const FloatImage& image);
Expected<void> drawLabel(Image& image, const std::string& text);
Expected<void> drawLabel(FloatImage& image, const std::string& text);
Expected<FloatImage> readFloatImage(const std::filesystem::path& path);
Expected<Image> readImage(const std::filesystem::path& path);
bool canWriteImageExtension(const std::string& extension);
Expected<std::unique_ptr<VideoEncoder>> openVideo(const std::filesystem::path& path, int width, int height, int framesPerSecond,
                                                  const FileMetadata& metadata);

} // namespace sdfwb::renderer::media
