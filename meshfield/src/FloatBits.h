#pragma once
// A uint32 stored in a float slot of the node arrays the GPU reads (kNodeFloats, kWideNodeFloats),
// bit for bit.

#include <bit>
#include <cstdint>

namespace sdfwb::meshfield::detail {

inline float asFloat(std::uint32_t bits) { return std::bit_cast<float>(bits); }
inline std::uint32_t asBits(float value) { return std::bit_cast<std::uint32_t>(value); }

} // namespace sdfwb::meshfield::detail
