#pragma once
// Images in memory, top row first (as image files store them): 8-bit RGBA for PNG/JPEG and the
// screen, float RGBA for high-dynamic-range files (EXR), where values above 1 are kept.

#include <cstdint>
#include <vector>

namespace sdfwb::renderer {

struct Image {
    int width = 0;
    int height = 0;
    std::vector<std::uint8_t> rgba; // width * height * 4 bytes

    const std::uint8_t* pixel(int x, int y) const {
        return rgba.data() + (std::size_t(y) * std::size_t(width) + std::size_t(x)) * 4;
    }
};

struct FloatImage {
    int width = 0;
    int height = 0;
    std::vector<float> rgba; // width * height * 4 floats, linear values as the shader wrote them

    const float* pixel(int x, int y) const { return rgba.data() + (std::size_t(y) * std::size_t(width) + std::size_t(x)) * 4; }
};

} // namespace sdfwb::renderer
