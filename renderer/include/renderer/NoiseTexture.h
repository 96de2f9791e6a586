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

// Shadertoy's iChannel noise: the same texture arranged as Shadertoy's "RGBA Noise" textures are,
// green the red channel and alpha the blue one moved by (37, 17) texels (G(x, y) = R(x - 37, y - 17)),
// so the classic texture-based 3D value noise, which reads slices z and z + 1 in one fetch at
// xy + (37, 17) z, is continuous. Red and blue are noiseTexels()'.
constexpr int kShadertoyNoiseShiftX = 37;
constexpr int kShadertoyNoiseShiftY = 17;
std::vector<std::uint8_t> shadertoyNoiseTexels();

} // namespace sdfwb::renderer
