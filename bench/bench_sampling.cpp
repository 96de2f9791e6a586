// Sampling throughput: sdfwb's compute path (llvmpipe on a machine without a GPU) against a fair
// optimised C++ reference doing the same work: the same fields (inlined, no per-call indirection),
// the same points (the samplers' counter-based hash, so both evaluate identical positions and the
// values are compared), the same 6-tap gradient, all hardware threads on contiguous blocks (no
// false sharing), this file built with -O3 -march=native. Each rate is the median of 5 runs, with
// the range. Prints the ratio measured in this run, so the figure means the same on any machine.
//
//   build/bench/bench_sampling [N]      (default N = 4,000,000)

#include <core/Hash.h>
#include <renderer/HeadlessContext.h>
#include <renderer/SampleCompute.h>
#include <sampling/Sampler.h>
#include <sampling/SamplerLibrary.h>

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <thread>
#include <vector>

using namespace sdfwb;

namespace {

// The same three fields in GLSL and in C++.
struct Field {
    const char* name;
    const char* glsl;
};

float box(glm::vec3 p, glm::vec3 b) {
    glm::vec3 q = glm::abs(p) - b;
    return glm::length(glm::max(q, glm::vec3(0.0f))) + std::min(std::max(q.x, std::max(q.y, q.z)), 0.0f);
}

float mandelbulb(glm::vec3 p) {
    glm::vec3 z = p;
    float dr = 1.0f, r = 0.0f;
    for (int i = 0; i < 8; ++i) {
        r = glm::length(z);
        if (r > 2.0f) break;
        float theta = std::acos(std::clamp(z.z / std::max(r, 1e-12f), -1.0f, 1.0f)) * 8.0f;
        float phi = std::atan2(z.y, z.x) * 8.0f;
        dr = std::pow(r, 7.0f) * 8.0f * dr + 1.0f;
        float zr = std::pow(r, 8.0f);
        z = zr * glm::vec3(std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi), std::cos(theta)) + p;
    }
    return 0.5f * std::log(std::max(r, 1e-12f)) * r / dr;
}

float sphere(glm::vec3 p) { return glm::length(p) - 0.5f; }

float csg(glm::vec3 p) {
    float d = std::max(box(p, glm::vec3(0.6f)), -(glm::length(p) - 0.75f));
    float tx = std::sqrt(p.x * p.x + p.z * p.z) - 0.7f;
    return std::min(d, std::sqrt(tx * tx + p.y * p.y) - 0.12f);
}

const Field kFields[] = {
    {"sphere", "float sdf(vec3 p) { return length(p) - 0.5; }\n"},
    {"csg (box - sphere + torus)",
     "float box(vec3 p, vec3 b) { vec3 q = abs(p) - b; return length(max(q, 0.0)) + min(max(q.x, max(q.y, q.z)), 0.0); }\n"
     "float sdf(vec3 p) { float d = max(box(p, vec3(0.6)), -(length(p) - 0.75));\n"
     "  vec2 t = vec2(length(p.xz) - 0.7, p.y); return min(d, length(t) - 0.12); }\n"},
    {"mandelbulb (8 iterations)",
     "float sdf(vec3 p) { vec3 z = p; float dr = 1.0, r = 0.0;\n"
     "  for (int i = 0; i < 8; ++i) { r = length(z); if (r > 2.0) break;\n"
     "    float theta = acos(clamp(z.z / max(r, 1e-12), -1.0, 1.0)) * 8.0; float phi = atan(z.y, z.x) * 8.0;\n"
     "    dr = pow(r, 7.0) * 8.0 * dr + 1.0; float zr = pow(r, 8.0);\n"
     "    z = zr * vec3(sin(theta) * cos(phi), sin(theta) * sin(phi), cos(theta)) + p; }\n"
     "  return 0.5 * log(max(r, 1e-12)) * r / dr; }\n"},
};

double seconds(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// The samplers' counter-based random numbers (shaders/sampling/common.glsl, with the same
// finaliser, core/Hash.h): the reference evaluates exactly the points the rand sampler does.
glm::vec3 randomInCube(std::uint64_t seed, std::uint32_t index) {
    const std::uint32_t seedKey = scramble32(std::uint32_t(seed >> 32) ^ scramble32(std::uint32_t(seed)));
    const std::uint32_t sampleKey = scramble32(index ^ seedKey);
    const std::uint32_t streamKey = scramble32(sampleKey); // stream 0: 0 * 0x9e3779b9 + sampleKey
    const std::uint32_t bits[3] = {scramble32(streamKey), scramble32(streamKey + 0x9e3779b9u),
                                   scramble32(streamKey + 0x3c6ef372u)};
    glm::vec3 p;
    for (int c = 0; c < 3; ++c) p[c] = float(bits[c] >> 8u) * (1.0f / 16777216.0f) * 2.0f - 1.0f;
    return p;
}

// Reference: value + 6-tap gradient at the rand sampler's points; each thread a contiguous block
// of the output. `field` is a callable the compiler inlines. Returns samples per second.
template <class F> double referenceRate(F field, std::size_t n, std::vector<float>& distances, std::vector<float>& gradients) {
    const unsigned threads = std::max(1u, std::thread::hardware_concurrency());
    auto start = std::chrono::steady_clock::now();
    std::vector<std::thread> workers;
    for (unsigned t = 0; t < threads; ++t)
        workers.emplace_back([&, t] {
            const float h = 1e-3f;
            const std::size_t first = n * t / threads, last = n * (t + 1) / threads;
            for (std::size_t i = first; i < last; ++i) {
                const glm::vec3 p = randomInCube(0, std::uint32_t(i));
                distances[i] = field(p);
                gradients[3 * i] = (field(p + glm::vec3(h, 0, 0)) - field(p - glm::vec3(h, 0, 0))) / (2 * h);
                gradients[3 * i + 1] = (field(p + glm::vec3(0, h, 0)) - field(p - glm::vec3(0, h, 0))) / (2 * h);
                gradients[3 * i + 2] = (field(p + glm::vec3(0, 0, h)) - field(p - glm::vec3(0, 0, h))) / (2 * h);
            }
        });
    for (auto& worker : workers) worker.join();
    return double(n) / seconds(start);
}

struct Rates {
    double median, low, high;
};

// Median (and range) of `runs` calls of `measure`, which returns a rate.
template <class M> Rates repeated(M measure, int runs = 5) {
    std::vector<double> rates;
    for (int k = 0; k < runs; ++k) rates.push_back(measure());
    std::sort(rates.begin(), rates.end());
    return {rates[rates.size() / 2], rates.front(), rates.back()};
}

} // namespace

int main(int argc, char** argv) {
    std::size_t n = argc > 1 ? std::size_t(std::atoll(argv[1])) : 4000000;
    auto context = renderer::HeadlessContext::create();
    if (!context) {
        std::fprintf(stderr, "bench_sampling: %s\n", context.error().message.c_str());
        return 3;
    }
    std::printf("sampling throughput, N = %zu per field (Mandelbulb N/8), pattern rand, value + 6-tap gradient; median [min, "
                "max] of 5 runs\n",
                n);
    std::printf("GL: %s; reference: C++/GLM on %u threads, build type %s, this file built with %s\n\n",
                context.value()->info().renderer.c_str(), std::max(1u, std::thread::hardware_concurrency()), SDFWB_BUILD_TYPE,
                SDFWB_BENCH_FLAGS);
    std::printf("| field | sdfwb compute (samples/s) | first dispatch incl. JIT (s) | C++ reference (samples/s) | ratio | f "
                "difference p99 / max |\n");
    std::printf("|---|---|---|---|---|---|\n");
    auto sampler = sampling::findSampler("rand", {});
    int fieldIndex = 0;
    for (const Field& field : kFields) {
        std::size_t fieldN = std::string(field.name).rfind("mandelbulb", 0) == 0 ? n / 8 : n;
        renderer::SampleCompute compute;
        auto diagnostics = compute.build(shaders::prepareSdf(field.glsl, field.name, {}, {}), *sampler);
        if (shaders::hasErrors(diagnostics)) {
            std::fprintf(stderr, "%s\n", shaders::formatDiagnostic(diagnostics[0]).c_str());
            return 1;
        }
        std::vector<float> positions(3 * fieldN), distances(fieldN), gradients(3 * fieldN);
        sampling::SamplingJob warm;
        warm.count = 1024;
        auto jitStart = std::chrono::steady_clock::now();
        (void)sampling::sampleInto(compute, warm, positions.data(), distances.data(), gradients.data(), {});
        double jit = seconds(jitStart);
        sampling::SamplingJob job;
        job.count = fieldN;
        bool failed = false;
        const Rates gpu = repeated([&] {
            auto start = std::chrono::steady_clock::now();
            auto report = sampling::sampleInto(compute, job, positions.data(), distances.data(), gradients.data(), {});
            if (!report) {
                std::fprintf(stderr, "%s\n", report.error().message.c_str());
                failed = true;
            }
            return double(fieldN) / seconds(start);
        });
        if (failed) return 1;
        std::vector<float> cpuDistances(fieldN), cpuGradients(3 * fieldN);
        auto measure = [&](auto f) { return repeated([&] { return referenceRate(f, fieldN, cpuDistances, cpuGradients); }); };
        const Rates cpu = fieldIndex == 0 ? measure(sphere) : fieldIndex == 1 ? measure(csg) : measure(mandelbulb);
        // Same points, same field: the values must agree (up to float differences between the two).
        // (Iterated fractals amplify llvmpipe's acos error: compare them by percentile.)
        std::vector<float> differences;
        for (std::size_t i = 0; i < fieldN; ++i)
            if (std::isfinite(distances[i]) && std::isfinite(cpuDistances[i]))
                differences.push_back(std::abs(distances[i] - cpuDistances[i]));
        std::sort(differences.begin(), differences.end());
        const float p99 = differences.empty() ? 0.0f : differences[differences.size() * 99 / 100];
        const float worst = differences.empty() ? 0.0f : differences.back();
        std::printf("| %s | %.3g [%.3g, %.3g] | %.3f | %.3g [%.3g, %.3g] | %.2f | %.2g / %.2g |\n", field.name, gpu.median,
                    gpu.low, gpu.high, jit, cpu.median, cpu.low, cpu.high, gpu.median / cpu.median, double(p99), double(worst));
        compute.releaseGl();
        ++fieldIndex;
    }
    return 0;
}
