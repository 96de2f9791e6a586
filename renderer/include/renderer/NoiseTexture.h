#pragma once
// The noise texture behind the G3D dialect's `uniform sampler2D g3d_uniformRandom`: 256 x 256
// RGBA8 texels of independent uniform values, made from a hash of the texel index, so every run
// and every machine sees the same texture. GL-free: the GL side lives in the renderer's sources.

#include <cstdint>
#include <vector>

namespace sdfwb::renderer {

constexpr int kNoiseTextureSize = 256;

// kNoiseTextureSize^2 texels, 4 bytes each (R, G, B, A), rows from v = 0 up.
std::vector<std::uint8_t> noiseTexels();

} // namespace sdfwb::renderer
