#pragma once
// An 8-bit RGBA image in memory, top row first (as image files store it).

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

} // namespace sdfwb::renderer
