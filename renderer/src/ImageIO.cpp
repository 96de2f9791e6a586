#include <renderer/ImageIO.h>

#include <core/TextFile.h>

#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/imageio.h>

#include <cstdio>

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
    auto output = OIIO::ImageOutput::create(path.string());
    if (!output)
        return makeError(path.string() + ": no image writer for extension '" + path.extension().string() +
                         "' (use .png, .jpg or .exr)");
    if (!output->supports("ioproxy"))
        return makeError(path.string() + ": the image writer for '" + path.extension().string() +
                         "' cannot encode to memory (use .png, .jpg or .exr)");
    bool exr = path.extension() == ".exr";
    // EXR keeps alpha and stores half floats; PNG and JPEG get RGB.
    int channels = exr ? 4 : 3;
    OIIO::ImageSpec spec(image.width, image.height, channels, exr ? OIIO::TypeDesc::HALF : OIIO::TypeDesc::UINT8);
    // Encode into memory, then write the bytes atomically (temporary file, every write checked,
    // fsync, rename): the image libraries do not all report a failed write (libpng ignores a
    // full disk), and a half-written file must never replace a good one.
    std::vector<unsigned char> encoded;
    OIIO::Filesystem::IOVecOutput memory(encoded);
    if (!output->set_ioproxy(&memory) || !output->open(path.string(), spec))
        return makeError(path.string() + ": cannot encode: " + output->geterror());
    std::vector<std::uint8_t> pixels(std::size_t(image.width) * std::size_t(image.height) * std::size_t(channels));
    for (std::size_t i = 0, n = std::size_t(image.width) * std::size_t(image.height); i < n; ++i)
        for (int c = 0; c < channels; ++c)
            pixels[i * std::size_t(channels) + std::size_t(c)] = image.rgba[i * 4 + std::size_t(c)];
    if (!(output->write_image(OIIO::TypeDesc::UINT8, pixels.data()) && output->close()))
        return makeError(path.string() + ": cannot encode: " + output->geterror());
    output.reset();
    if (auto ok = writeFileAtomically(path, std::string_view(reinterpret_cast<const char*>(encoded.data()), encoded.size())); !ok)
        return ok.error();
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
    if (spec.nchannels < 3) // grey: replicate
        for (std::size_t i = 0, n = std::size_t(spec.width) * std::size_t(spec.height); i < n; ++i)
            image.rgba[i * 4 + 1] = image.rgba[i * 4 + 2] = image.rgba[i * 4];
    return image;
}

} // namespace sdfwb::renderer
