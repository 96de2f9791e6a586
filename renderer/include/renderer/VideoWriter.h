#pragma once
// Writes frames to an MP4 file (H.264 through the FFmpeg libraries, libx264 when present).
// The file is written under a temporary name beside the target and renamed by finish(); a writer
// destroyed before finish() removes it, so a failed export leaves no partial video.

#include <core/Expected.h>
#include <renderer/Image.h>

#include <filesystem>
#include <memory>

namespace sdfwb::renderer {

class VideoWriter {
public:
    // width and height are rounded down to even numbers (4:2:0 chroma needs them even); `metadata`
    // goes into the file's tags.
    static Expected<std::unique_ptr<VideoWriter>> open(const std::filesystem::path& path, int width, int height,
                                                       int framesPerSecond, const FileMetadata& metadata = {});
    ~VideoWriter();
    VideoWriter(const VideoWriter&) = delete;
    VideoWriter& operator=(const VideoWriter&) = delete;

    // Frames must have the size given to open(); they are scaled otherwise.
    Expected<void> addFrame(const Image& frame);
    Expected<void> finish();
    int frames() const;

private:
    VideoWriter();
    struct Impl;
    std::unique_ptr<Impl> m_impl;
};

} // namespace sdfwb::renderer
