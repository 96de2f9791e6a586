#pragma once
// N samples of a field: position, distance and the raw (unnormalised) gradient, stored as the
// paper's .bin file lays them out: all positions, then all distances, then all gradients.

#include <cstdint>
#include <vector>

namespace sdfwb::sampling {

struct SampleSet {
    std::vector<float> positions; // 3N: x0 y0 z0 x1 ...
    std::vector<float> distances; // N
    std::vector<float> gradients; // 3N, raw: |gradient| shows the Lipschitz behaviour

    std::size_t size() const { return distances.size(); }
    void resize(std::size_t n) {
        positions.resize(3 * n);
        distances.resize(n);
        gradients.resize(3 * n);
    }
};

} // namespace sdfwb::sampling
