// ImageIO.h and VideoWriter.h: forwarders into libsdfwb_media.so (../media/MediaApi.h), loaded the
// first time an image or a video is read or written.

#include "../media/MediaApi.h"

#include <renderer/ImageIO.h>
#include <renderer/VideoWriter.h>

#include <core/Log.h>
#include <core/Plugins.h>

#include <png.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <csetjmp>
#include <cstdio>
#include <cstring>
#include <unistd.h>

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

// Without the module: .png through libpng (8-bit RGBA, as Image holds it), said once in the log.
bool pngWithoutModule(const fs::path& path) {
    if (api()) return false;
    std::string extension = path.extension().string();
    std::transform(extension.begin(), extension.end(), extension.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    if (extension != ".png") return false;
    static const bool said = [] {
        log::info("media", "image files: .png through libpng only (" + api().error().message + ")");
        return true;
    }();
    (void)said;
    return true;
}

Expected<Image> readPng(const fs::path& path) {
    png_image png{};
    png.version = PNG_IMAGE_VERSION;
    if (!png_image_begin_read_from_file(&png, path.c_str()))
        return makeError(path.string() + ": cannot read the PNG file (" + png.message + ")");
    png.format = PNG_FORMAT_RGBA;
    Image image;
    image.width = int(png.width);
    image.height = int(png.height);
    image.rgba.resize(PNG_IMAGE_SIZE(png));
    if (!png_image_finish_read(&png, nullptr, image.rgba.data(), 0, nullptr)) {
        png_image_free(&png);
        return makeError(path.string() + ": cannot read the PNG file (" + png.message + ")");
    }
    return image;
}

// libpng's part of writePng: false when it reported an error (its longjmp lands here, in a frame
// that holds nothing to clobber).
bool encodePng(png_structp png, png_infop info, FILE* file, const Image& image, std::vector<png_text>& texts, std::uint8_t* row) {
    if (setjmp(png_jmpbuf(png)) != 0) return false;
    png_init_io(png, file);
    png_set_IHDR(png, info, png_uint_32(image.width), png_uint_32(image.height), 8, PNG_COLOR_TYPE_RGB, PNG_INTERLACE_NONE,
                 PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
    if (!texts.empty()) png_set_text(png, info, texts.data(), int(texts.size()));
    png_write_info(png, info);
    for (int y = 0; y < image.height; ++y) {
        const std::uint8_t* pixel = image.rgba.data() + std::size_t(y) * std::size_t(image.width) * 4;
        for (std::size_t x = 0; x < std::size_t(image.width); ++x)
            for (std::size_t c = 0; c < 3; ++c) row[x * 3 + c] = pixel[x * 4 + c];
        png_write_row(png, row);
    }
    png_write_end(png, info);
    return true;
}

// 8-bit RGB as the module writes a .png (alpha dropped), the metadata as text chunks; written
// beside the target, flushed and renamed over it: never a half-written file.
Expected<void> writePng(const fs::path& path, const Image& image) {
    if (image.width <= 0 || image.height <= 0 || image.rgba.size() != std::size_t(image.width) * std::size_t(image.height) * 4)
        return makeError(path.string() + ": refusing to write an empty or inconsistent image");
    const fs::path partial = path.string() + ".partial";
    FILE* file = std::fopen(partial.c_str(), "wb");
    if (!file) return makeError(path.string() + ": cannot write the PNG file (" + std::strerror(errno) + ")");
    std::vector<std::uint8_t> row(std::size_t(image.width) * 3);
    std::vector<png_text> texts(image.metadata.size());
    for (std::size_t i = 0; i < texts.size(); ++i) {
        texts[i].compression = PNG_TEXT_COMPRESSION_NONE;
        texts[i].key = const_cast<char*>(image.metadata[i].first.c_str());
        texts[i].text = const_cast<char*>(image.metadata[i].second.c_str());
        texts[i].text_length = image.metadata[i].second.size();
    }
    png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, nullptr, nullptr, nullptr);
    png_infop info = png ? png_create_info_struct(png) : nullptr;
    bool written = png && info && encodePng(png, info, file, image, texts, row.data());
    png_destroy_write_struct(&png, &info);
    written = written && std::fflush(file) == 0 && ::fsync(fileno(file)) == 0;
    written = std::fclose(file) == 0 && written;
    std::error_code error;
    if (written) fs::rename(partial, path, error);
    if (!written || error) {
        std::error_code ignored;
        fs::remove(partial, ignored);
        return makeError(path.string() + ": cannot write the PNG file" + (error ? " (" + error.message() + ")" : std::string()));
    }
    return {};
}

} // namespace

Expected<void> writeImage(const fs::path& path, const Image& image) {
    if (pngWithoutModule(path)) return writePng(path, image);
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
    if (pngWithoutModule(path)) return readPng(path);
    if (!api()) return makeError(path.string() + ": " + api().error().message);
    return (*api())->readImage(path);
}

Expected<bool> canWriteImageExtension(const std::string& extension) {
    if (pngWithoutModule(fs::path("image" + extension))) return true;
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
