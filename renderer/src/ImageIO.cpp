#include <renderer/ImageIO.h>

#include <OpenImageIO/imageio.h>

#include <cstdio>
#include <random>

namespace sdfwb::renderer {
namespace fs = std::filesystem;

bool canWriteImageExtension(const std::string& extension) {
    std::string ext = extension;
    if (!ext.empty() && ext.front() == '.') ext.erase(0, 1);
    if (ext.empty()) return false;
    auto output = OIIO::ImageOutput::create("probe." + ext);
    return output != nullptr;
}

Expected<void> writeImage(const fs::path& path, const Image& image) {
    if (image.width <= 0 || image.height <= 0 || image.rgba.size() != std::size_t(image.width) * std::size_t(image.height) * 4)
        return makeError(path.string() + ": refusing to write an empty or inconsistent image");
    fs::path folder = path.parent_path().empty() ? fs::path(".") : path.parent_path();
    std::random_device random;
    // Same extension as the target, so OpenImageIO picks the same format.
    fs::path temporary = folder / ("." + path.stem().string() + ".tmp" + std::to_string(random()) + path.extension().string());
    auto output = OIIO::ImageOutput::create(temporary.string());
    if (!output) return makeError(path.string() + ": no image writer for extension '" + path.extension().string() + "' (use .png, .jpg or .exr)");
    bool exr = path.extension() == ".exr";
    // EXR keeps alpha and stores half floats; PNG and JPEG get RGB.
    int channels = exr ? 4 : 3;
    OIIO::ImageSpec spec(image.width, image.height, channels, exr ? OIIO::TypeDesc::HALF : OIIO::TypeDesc::UINT8);
    if (!output->open(temporary.string(), spec)) {
        std::string error = output->geterror();
        std::error_code ec;
        fs::remove(temporary, ec);
        return makeError(path.string() + ": cannot write: " + error);
    }
    std::vector<std::uint8_t> pixels(std::size_t(image.width) * std::size_t(image.height) * std::size_t(channels));
    for (std::size_t i = 0, n = std::size_t(image.width) * std::size_t(image.height); i < n; ++i)
        for (int c = 0; c < channels; ++c) pixels[i * std::size_t(channels) + std::size_t(c)] = image.rgba[i * 4 + std::size_t(c)];
    bool ok = output->write_image(OIIO::TypeDesc::UINT8, pixels.data()) && output->close();
    if (!ok) {
        std::string error = output->geterror();
        std::error_code ec;
        fs::remove(temporary, ec);
        return makeError(path.string() + ": write failed: " + error);
    }
    std::error_code ec;
    fs::rename(temporary, path, ec);
    if (ec) {
        fs::remove(temporary, ec);
        return makeError(path.string() + ": cannot move the finished image into place: " + ec.message());
    }
    return {};
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
    if (spec.nchannels < 3)  // grey: replicate
        for (std::size_t i = 0, n = std::size_t(spec.width) * std::size_t(spec.height); i < n; ++i)
            image.rgba[i * 4 + 1] = image.rgba[i * 4 + 2] = image.rgba[i * 4];
    return image;
}

} // namespace sdfwb::renderer
