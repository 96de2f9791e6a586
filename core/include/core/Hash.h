#pragma once
// The 32-bit integer finaliser the samplers use (shaders/sampling/common.glsl, sdfwb_scramble):
// xorshift-multiply rounds with the "lowbias32" constants of Chris Wellons' hash-prospector search
// (public domain). C++ code that must reproduce the shaders' numbers (the G3D noise texture, the
// sampling benchmark's reference) calls this one.

#include <cstdint>

namespace sdfwb {

constexpr std::uint32_t scramble32(std::uint32_t x) {
    x ^= x >> 16u;
    x *= 0x7feb352du;
    x ^= x >> 15u;
    x *= 0x846ca68bu;
    x ^= x >> 16u;
    return x;
}

} // namespace sdfwb
