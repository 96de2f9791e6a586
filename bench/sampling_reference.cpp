// The C++ reference of bench_sampling (sampling_reference.h). Built twice: SDFWB_REFERENCE_NAME
// names the function, the build adds -ffast-math to one of the two.

#include "sampling_reference.h"

#include <core/Hash.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>

#ifndef SDFWB_REFERENCE_NAME
#error "SDFWB_REFERENCE_NAME names the function this build defines"
#endif

namespace sdfwb::bench {
namespace {

struct Vec3 {
    float x, y, z;
};
inline Vec3 operator+(Vec3 a, Vec3 b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
inline float length(Vec3 p) { return std::sqrt(p.x * p.x + p.y * p.y + p.z * p.z); }

// The samplers' counter-based random numbers (shaders/sampling/common.glsl with core/Hash.h's
// finaliser): the reference evaluates exactly the points the rand sampler does (seed 0).
inline Vec3 randomInCube(std::uint32_t index) {
    constexpr std::uint32_t seedKey = scramble32(0u ^ scramble32(0u));
    const std::uint32_t sampleKey = scramble32(index ^ seedKey);
    const std::uint32_t streamKey = scramble32(sampleKey); // stream 0
    const float scale = 2.0f / 16777216.0f;
    return {float(scramble32(streamKey) >> 8u) * scale - 1.0f, float(scramble32(streamKey + 0x9e3779b9u) >> 8u) * scale - 1.0f,
            float(scramble32(streamKey + 0x3c6ef372u) >> 8u) * scale - 1.0f};
}

struct Sphere {
    float operator()(Vec3 p) const { return length(p) - 0.5f; }
};

struct Csg {
    static float box(Vec3 p, float b) {
        const float qx = std::abs(p.x) - b, qy = std::abs(p.y) - b, qz = std::abs(p.z) - b;
        const float ox = std::max(qx, 0.0f), oy = std::max(qy, 0.0f), oz = std::max(qz, 0.0f);
        return std::sqrt(ox * ox + oy * oy + oz * oz) + std::min(std::max(qx, std::max(qy, qz)), 0.0f);
    }
    float operator()(Vec3 p) const {
        const float d = std::max(box(p, 0.6f), -(length(p) - 0.75f));
        const float tx = std::sqrt(p.x * p.x + p.z * p.z) - 0.7f;
        return std::min(d, std::sqrt(tx * tx + p.y * p.y) - 0.12f);
    }
};

struct Mandelbulb {
    float operator()(Vec3 p) const {
        Vec3 z = p;
        float dr = 1.0f, r = 0.0f;
        for (int i = 0; i < 8; ++i) {
            r = length(z);
            if (r > 2.0f) break;
            const float theta = std::acos(std::clamp(z.z / std::max(r, 1e-12f), -1.0f, 1.0f)) * 8.0f;
            const float phi = std::atan2(z.y, z.x) * 8.0f;
            const float r2 = r * r, r4 = r2 * r2, r7 = r4 * r2 * r;
            dr = r7 * 8.0f * dr + 1.0f;
            const float zr = r7 * r, st = std::sin(theta);
            z = Vec3{zr * st * std::cos(phi), zr * st * std::sin(phi), zr * std::cos(theta)} + p;
        }
        return 0.5f * std::log(std::max(r, 1e-12f)) * r / dr;
    }
};

template <class F> double run(F field, std::size_t n, int threads, float* distances, float* gradients) {
    const auto start = std::chrono::steady_clock::now();
    const std::int64_t count = std::int64_t(n);
    constexpr float h = 1e-3f, inverse = 1.0f / (2.0f * h);
#pragma omp parallel for simd num_threads(threads) schedule(static)
    for (std::int64_t i = 0; i < count; ++i) {
        const Vec3 p = randomInCube(std::uint32_t(i));
        distances[i] = field(p);
        gradients[3 * i] = (field(p + Vec3{h, 0, 0}) - field(p + Vec3{-h, 0, 0})) * inverse;
        gradients[3 * i + 1] = (field(p + Vec3{0, h, 0}) - field(p + Vec3{0, -h, 0})) * inverse;
        gradients[3 * i + 2] = (field(p + Vec3{0, 0, h}) - field(p + Vec3{0, 0, -h})) * inverse;
    }
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

} // namespace

double SDFWB_REFERENCE_NAME(ReferenceField field, std::size_t n, int threads, float* distances, float* gradients) {
    switch (field) {
    case ReferenceField::Sphere:
        return run(Sphere{}, n, threads, distances, gradients);
    case ReferenceField::Csg:
        return run(Csg{}, n, threads, distances, gradients);
    case ReferenceField::Mandelbulb:
        return run(Mandelbulb{}, n, threads, distances, gradients);
    }
    return 0.0;
}

} // namespace sdfwb::bench
