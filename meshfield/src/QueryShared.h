#pragma once
// Helpers MeshQuery.cpp and SignLattice.cpp share (the native engine's internals).

#include <algorithm>
#include <bit>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <thread>

namespace sdfwb::meshfield::detail {

// Points of the sign cache's level `level`: 2^level + 1 a side.
constexpr std::size_t latticePoints(int level) {
    const std::size_t side = (std::size_t(1) << level) + 1;
    return side * side * side;
}

// A float no smaller than `value` (>= 0, or NaN).
inline float roundedUp(double value) {
    const float f = float(value);
    return double(f) < value ? std::bit_cast<float>(std::bit_cast<std::uint32_t>(f) + 1u) : f; // the next float up
}

// `asked` threads, or (0) SDFWB_MESH_THREADS, or every core.
inline unsigned threadCount(unsigned asked) {
    if (asked > 0) return asked;
    if (const char* text = std::getenv("SDFWB_MESH_THREADS")) {
        const int n = std::atoi(text);
        if (n > 0) return unsigned(n);
    }
    return std::max(1u, std::thread::hardware_concurrency());
}

} // namespace sdfwb::meshfield::detail
