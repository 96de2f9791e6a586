#pragma once
// Images in memory, top row first (as image files store them): 8-bit RGBA for PNG/JPEG and the
// screen, float RGBA for high-dynamic-range files (EXR), where values above 1 are kept.

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

namespace sdfwb::renderer {

// Text written into an image or video file beside its pixels, as (key, value) pairs: PNG text
// chunks, EXR header attributes, MP4 metadata tags.
using FileMetadata = std::vector<std::pair<std::string, std::string>>;

struct Image {
    int width = 0;
    int height = 0;
    std::vector<std::uint8_t> rgba; // width * height * 4 bytes
    FileMetadata metadata;

    const std::uint8_t* pixel(int x, int y) const {
        return rgba.data() + (std::size_t(y) * std::size_t(width) + std::size_t(x)) * 4;
    }
};

struct FloatImage {
    int width = 0;
    int height = 0;
    std::vector<float> rgba; // width * height * 4 floats, linear values as the shader wrote them
    FileMetadata metadata;

    const float* pixel(int x, int y) const { return rgba.data() + (std::size_t(y) * std::size_t(width) + std::size_t(x)) * 4; }
};

} // namespace sdfwb::renderer
