// ImageIO.h and VideoWriter.h: forwarders into libsdfwb_media.so (../media/MediaApi.h), loaded the
// first time an image or a video is read or written.

#include "../media/MediaApi.h"

#include <renderer/ImageIO.h>
#include <renderer/VideoWriter.h>

#include <core/Plugins.h>

namespace sdfwb::renderer {
namespace fs = std::filesystem;

namespace {

Expected<const media::Api*> loadApi() {
    auto entry = plugins::symbol(media::kModuleFile, media::kEntryPoint);
    if (!entry) return makeError("image and video files need " + entry.error().message);
    const auto* api = reinterpret_cast<const media::Api* (*)()>(*entry)();
    if (!api || api->abiVersion != media::kAbiVersion)
        return makeError((plugins::folder() / media::kModuleFile).string() +
                         ": built for another version of sdfwb (reinstall or rebuild it)");
    return api;
}

const Expected<const media::Api*>& api() {
    static const Expected<const media::Api*> loaded = loadApi();
    return loaded;
}

} // namespace

Expected<void> writeImage(const fs::path& path, const Image& image) {
    if (!api()) return makeError(path.string() + ": " + api().error().message);
    return (*api())->writeImage(path, image);
}

Expected<void> writeImage(const fs::path& path, const FloatImage& image) {
    if (!api()) return makeError(path.string() + ": " + api().error().message);
    return (*api())->writeFloatImage(path, image);
}

Expected<void> drawLabel(Image& image, const std::string& text) {
    if (!api()) return api().error();
    return (*api())->drawLabel(image, text);
}

Expected<void> drawLabel(FloatImage& image, const std::string& text) {
    if (!api()) return api().error();
    return (*api())->drawFloatLabel(image, text);
}

Expected<FloatImage> readFloatImage(const fs::path& path) {
    if (!api()) return makeError(path.string() + ": " + api().error().message);
    return (*api())->readFloatImage(path);
}

Expected<Image> readImage(const fs::path& path) {
    if (!api()) return makeError(path.string() + ": " + api().error().message);
    return (*api())->readImage(path);
}

Expected<bool> canWriteImageExtension(const std::string& extension) {
    if (!api()) return api().error();
    return (*api())->canWriteImageExtension(extension);
}

struct VideoWriter::Impl {
    std::unique_ptr<media::VideoEncoder> encoder;
};

VideoWriter::VideoWriter() : m_impl(std::make_unique<Impl>()) {}
VideoWriter::~VideoWriter() = default;
int VideoWriter::frames() const { return m_impl->encoder->frames(); }

Expected<std::unique_ptr<VideoWriter>> VideoWriter::open(const fs::path& path, int width, int height, int framesPerSecond,
                                                         const FileMetadata& metadata) {
    if (!api()) return makeError(path.string() + ": " + api().error().message);
    auto encoder = (*api())->openVideo(path, width, height, framesPerSecond, metadata);
    if (!encoder) return encoder.error();
    std::unique_ptr<VideoWriter> writer(new VideoWriter());
    writer->m_impl->encoder = std::move(*encoder);
    return writer;
}

Expected<void> VideoWriter::addFrame(const Image& image) { return m_impl->encoder->addFrame(image); }

Expected<void> VideoWriter::finish() { return m_impl->encoder->finish(); }

} // namespace sdfwb::renderer
