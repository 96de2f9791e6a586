// Image files through OpenImageIO: the image half of libsdfwb_media.so (see MediaApi.h).
#include "MediaApi.h"

#include <renderer/ImageIO.h>

#include <core/TextFile.h>

#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imagebufalgo.h>
#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>

namespace sdfwb::renderer::media {
namespace fs = std::filesystem;

bool canWriteImageExtension(const std::string& extension) {
    std::string ext = extension;
    if (!ext.empty() && ext.front() == '.') ext.erase(0, 1);
    if (ext.empty()) return false;
    auto output = OIIO::ImageOutput::create("probe." + ext);
    return output != nullptr;
}

namespace {

// Encodes `channels` of each RGBA pixel (`pixels` holds 4 per pixel, of type `source`) into memory
// with the writer the extension picks, then writes the bytes atomically (temporary file, every
// write checked, fsync, rename): the image libraries do not all report a failed write (libpng
// ignores a full disk), and a half-written file must never replace a good one.
Expected<void> encodeAndWrite(const fs::path& path, int width, int height, OIIO::TypeDesc source, const void* pixels,
                              std::size_t pixelCount, const FileMetadata& metadata) {
    if (width <= 0 || height <= 0 || pixelCount != std::size_t(width) * std::size_t(height))
        return makeError(path.string() + ": refusing to write an empty or inconsistent image");
    auto output = OIIO::ImageOutput::create(path.string());
    if (!output)
        return makeError(path.string() + ": no image writer for extension '" + path.extension().string() +
                         "' (use .png, .jpg or .exr)");
    if (!output->supports("ioproxy"))
        return makeError(path.string() + ": the image writer for '" + path.extension().string() +
                         "' cannot encode to memory (use .png, .jpg or .exr)");
    // EXR keeps alpha and stores half floats, Radiance .hdr RGB floats; PNG and JPEG get 8-bit RGB.
    const bool exr = path.extension() == ".exr";
    const int channels = exr ? 4 : 3;
    const OIIO::TypeDesc stored = exr                        ? OIIO::TypeDesc::HALF
                                  : isHighDynamicRange(path) ? OIIO::TypeDesc::FLOAT
                                                             : OIIO::TypeDesc::UINT8;
    OIIO::ImageSpec spec(width, height, channels, stored);
    for (const auto& [key, value] : metadata) spec.attribute(key, value);
    std::vector<unsigned char> encoded;
    OIIO::Filesystem::IOVecOutput memory(encoded);
    if (!output->set_ioproxy(&memory) || !output->open(path.string(), spec))
        return makeError(path.string() + ": cannot encode: " + output->geterror());
    // The first `channels` of every 4: strides let the writer skip alpha without a copy.
    const OIIO::stride_t pixelStride = OIIO::stride_t(4 * source.size());
    if (!(output->write_image(source, pixels, pixelStride) && output->close()))
        return makeError(path.string() + ": cannot encode: " + output->geterror());
    output.reset();
    if (auto ok = writeFileAtomically(path, std::string_view(reinterpret_cast<const char*>(encoded.data()), encoded.size())); !ok)
        return ok.error();
    return {};
}

} // namespace

Expected<void> writeImage(const fs::path& path, const Image& image) {
    if (image.rgba.size() != std::size_t(image.width) * std::size_t(image.height) * 4)
        return makeError(path.string() + ": refusing to write an empty or inconsistent image");
    return encodeAndWrite(path, image.width, image.height, OIIO::TypeDesc::UINT8, image.rgba.data(), image.rgba.size() / 4,
                          image.metadata);
}

Expected<void> writeImage(const fs::path& path, const FloatImage& image) {
    if (image.rgba.size() != std::size_t(image.width) * std::size_t(image.height) * 4)
        return makeError(path.string() + ": refusing to write an empty or inconsistent image");
    if (isHighDynamicRange(path))
        return encodeAndWrite(path, image.width, image.height, OIIO::TypeDesc::FLOAT, image.rgba.data(), image.rgba.size() / 4,
                              image.metadata);
    // 8-bit formats: what the screen would show (clamped), rounded.
    Image quantised{image.width, image.height, std::vector<std::uint8_t>(image.rgba.size()), image.metadata};
    for (std::size_t i = 0; i < image.rgba.size(); ++i)
        quantised.rgba[i] = std::uint8_t(std::lround(std::clamp(image.rgba[i], 0.0f, 1.0f) * 255.0f));
    return media::writeImage(path, quantised);
}

namespace {

std::string labelFont() {
    for (const char* path : {"/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf", "/usr/share/fonts/TTF/DejaVuSans.ttf",
                             "/usr/share/fonts/dejavu/DejaVuSans.ttf"})
        if (std::filesystem::is_regular_file(path)) return path;
    return {};
}

// The label over `buffer`, whose pixels stay where they are (a wrapped caller's array).
Expected<void> drawLabelInto(OIIO::ImageBuf& buffer, const std::string& text) {
    const std::string font = labelFont();
    if (font.empty()) return makeError("label: no DejaVuSans.ttf found (install fonts-dejavu-core)");
    const int height = buffer.spec().height, width = buffer.spec().width;
    const int size = std::clamp(height / 40, 9, 48), lineHeight = size * 5 / 4, margin = size / 2;
    std::vector<std::string> lines;
    for (std::size_t start = 0; start <= text.size();) {
        const std::size_t end = std::min(text.find('\n', start), text.size());
        if (end > start) lines.push_back(text.substr(start, end - start));
        start = end + 1;
    }
    if (lines.empty()) return {};
    int textWidth = 0;
    for (const std::string& line : lines)
        textWidth = std::max(textWidth, OIIO::ImageBufAlgo::text_size(line, size, font).width());
    const int boxHeight = int(lines.size()) * lineHeight + margin;
    const OIIO::ROI box(margin, std::min(width, 3 * margin + textWidth), std::max(0, height - margin - boxHeight),
                        height - margin);
    const float dim[4] = {0.45f, 0.45f, 0.45f, 1.0f};
    if (!OIIO::ImageBufAlgo::mul(buffer, buffer, dim, box)) return makeError("label: " + buffer.geterror());
    const float white[4] = {0.92f, 0.92f, 0.92f, 1.0f};
    for (std::size_t i = 0; i < lines.size(); ++i) {
        const int baseline = box.ybegin + margin / 2 + int(i + 1) * lineHeight - (lineHeight - size);
        if (!OIIO::ImageBufAlgo::render_text(buffer, 2 * margin, baseline, lines[i], size, font, white))
            return makeError("label: " + buffer.geterror());
    }
    return {};
}

} // namespace

Expected<void> drawLabel(Image& image, const std::string& text) {
    OIIO::ImageBuf buffer(OIIO::ImageSpec(image.width, image.height, 4, OIIO::TypeDesc::UINT8), image.rgba.data());
    return drawLabelInto(buffer, text);
}

Expected<void> drawLabel(FloatImage& image, const std::string& text) {
    OIIO::ImageBuf buffer(OIIO::ImageSpec(image.width, image.height, 4, OIIO::TypeDesc::FLOAT), image.rgba.data());
    return drawLabelInto(buffer, text);
}

Expected<FloatImage> readFloatImage(const fs::path& path) {
    auto input = OIIO::ImageInput::open(path.string());
    if (!input) return makeError(path.string() + ": cannot read image: " + OIIO::geterror());
    const OIIO::ImageSpec& spec = input->spec();
    const std::size_t pixels = std::size_t(spec.width) * std::size_t(spec.height);
    std::vector<float> raw(pixels * std::size_t(spec.nchannels));
    if (!input->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::FLOAT, raw.data()))
        return makeError(path.string() + ": cannot decode image: " + input->geterror());
    FloatImage image{spec.width, spec.height, std::vector<float>(pixels * 4, 1.0f), {}};
    for (std::size_t i = 0; i < pixels; ++i)
        for (int c = 0; c < 4; ++c)
            if (c < spec.nchannels)
                image.rgba[i * 4 + std::size_t(c)] = raw[i * std::size_t(spec.nchannels) + std::size_t(c)];
            else if (c < 3)
                image.rgba[i * 4 + std::size_t(c)] = raw[i * std::size_t(spec.nchannels)]; // grey
    return image;
}

Expected<Image> readImage(const fs::path& path) {
    auto input = OIIO::ImageInput::open(path.string());
    if (!input) return makeError(path.string() + ": cannot read image: " + OIIO::geterror());
    const OIIO::ImageSpec& spec = input->spec();
    Image image;
    image.width = spec.width;
    image.height = spec.height;
    std::vector<std::uint8_t> pixels(std::size_t(spec.width) * std::size_t(spec.height) * std::size_t(spec.nchannels));
    if (!input->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::UINT8, pixels.data()))
        return makeError(path.string() + ": cannot decode image: " + input->geterror());
    image.rgba.assign(std::size_t(spec.width) * std::size_t(spec.height) * 4, 255);
    for (std::size_t i = 0, n = std::size_t(spec.width) * std::size_t(spec.height); i < n; ++i)
        for (int c = 0; c < std::min(spec.nchannels, 4); ++c)
            image.rgba[i * 4 + std::size_t(c)] = pixels[i * std::size_t(spec.nchannels) + std::size_t(c)];
    if (spec.nchannels < 3) // grey: replicate
        for (std::size_t i = 0, n = std::size_t(spec.width) * std::size_t(spec.height); i < n; ++i)
            image.rgba[i * 4 + 1] = image.rgba[i * 4 + 2] = image.rgba[i * 4];
    return image;
}

} // namespace sdfwb::renderer::media
