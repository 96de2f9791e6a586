// Sampling throughput: sdfwb's compute path (llvmpipe on a machine without a GPU) against a
// reference written the obvious way in C++ (scalar GLM, all hardware threads), for the same
// fields, pattern (rand) and gradient (6-tap central differences). Prints samples per second and
// the ratio measured in this run, so the figure means the same on any machine.
//
//   build/bench/bench_sampling [N]      (default N = 4,000,000)

#include <renderer/HeadlessContext.h>
#include <renderer/SampleCompute.h>
#include <sampling/Sampler.h>
#include <sampling/SamplerLibrary.h>

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <random>
#include <thread>
#include <vector>

using namespace sdfwb;

namespace {

// The same three fields in GLSL and in C++.
struct Field {
    const char* name;
    const char* glsl;
    std::function<float(glm::vec3)> cpp;
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

const Field kFields[] = {
    {"sphere", "float sdf(vec3 p) { return length(p) - 0.5; }\n", [](glm::vec3 p) { return glm::length(p) - 0.5f; }},
    {"csg (box - sphere + torus)",
     "float box(vec3 p, vec3 b) { vec3 q = abs(p) - b; return length(max(q, 0.0)) + min(max(q.x, max(q.y, q.z)), 0.0); }\n"
     "float sdf(vec3 p) { float d = max(box(p, vec3(0.6)), -(length(p) - 0.75));\n"
     "  vec2 t = vec2(length(p.xz) - 0.7, p.y); return min(d, length(t) - 0.12); }\n",
     [](glm::vec3 p) {
         float d = std::max(box(p, glm::vec3(0.6f)), -(glm::length(p) - 0.75f));
         float tx = std::sqrt(p.x * p.x + p.z * p.z) - 0.7f;
         return std::min(d, std::sqrt(tx * tx + p.y * p.y) - 0.12f);
     }},
    {"mandelbulb (8 iterations)",
     "float sdf(vec3 p) { vec3 z = p; float dr = 1.0, r = 0.0;\n"
     "  for (int i = 0; i < 8; ++i) { r = length(z); if (r > 2.0) break;\n"
     "    float theta = acos(clamp(z.z / max(r, 1e-12), -1.0, 1.0)) * 8.0; float phi = atan(z.y, z.x) * 8.0;\n"
     "    dr = pow(r, 7.0) * 8.0 * dr + 1.0; float zr = pow(r, 8.0);\n"
     "    z = zr * vec3(sin(theta) * cos(phi), sin(theta) * sin(phi), cos(theta)) + p; }\n"
     "  return 0.5 * log(max(r, 1e-12)) * r / dr; }\n",
     mandelbulb},
};

double seconds(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// Reference: value + 6-tap gradient at uniform random points, split over all hardware threads.
double referenceRate(const Field& field, std::size_t n) {
    unsigned threads = std::max(1u, std::thread::hardware_concurrency());
    std::vector<float> distances(n), gradients(3 * n);
    auto start = std::chrono::steady_clock::now();
    std::vector<std::thread> workers;
    for (unsigned t = 0; t < threads; ++t)
        workers.emplace_back([&, t] {
            std::mt19937 random(t);
            std::uniform_real_distribution<float> uniform(-1.0f, 1.0f);
            const float h = 1e-3f;
            for (std::size_t i = t; i < n; i += threads) {
                glm::vec3 p(uniform(random), uniform(random), uniform(random));
                distances[i] = field.cpp(p);
                gradients[3 * i] = (field.cpp(p + glm::vec3(h, 0, 0)) - field.cpp(p - glm::vec3(h, 0, 0))) / (2 * h);
                gradients[3 * i + 1] = (field.cpp(p + glm::vec3(0, h, 0)) - field.cpp(p - glm::vec3(0, h, 0))) / (2 * h);
                gradients[3 * i + 2] = (field.cpp(p + glm::vec3(0, 0, h)) - field.cpp(p - glm::vec3(0, 0, h))) / (2 * h);
            }
        });
    for (auto& worker : workers) worker.join();
    return double(n) / seconds(start);
}

} // namespace

int main(int argc, char** argv) {
    std::size_t n = argc > 1 ? std::size_t(std::atoll(argv[1])) : 4000000;
    auto context = renderer::HeadlessContext::create();
    if (!context) {
        std::fprintf(stderr, "bench_sampling: %s\n", context.error().message.c_str());
        return 3;
    }
    std::printf("sampling throughput, N = %zu per field, pattern rand, value + 6-tap gradient\n", n);
    std::printf("GL: %s; reference: scalar C++/GLM on %u threads\n\n", context.value()->info().renderer.c_str(),
                std::max(1u, std::thread::hardware_concurrency()));
    std::printf("| field | sdfwb compute (samples/s) | first dispatch incl. JIT (s) | C++ reference (samples/s) | ratio |\n");
    std::printf("|---|---|---|---|---|\n");
    auto sampler = sampling::findSampler("rand", {});
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
        auto start = std::chrono::steady_clock::now();
        auto report = sampling::sampleInto(compute, job, positions.data(), distances.data(), gradients.data(), {});
        double gpuRate = double(fieldN) / seconds(start);
        if (!report) {
            std::fprintf(stderr, "%s\n", report.error().message.c_str());
            return 1;
        }
        double cpuRate = referenceRate(field, fieldN);
        std::printf("| %s | %.3g | %.3f | %.3g | %.2f |\n", field.name, gpuRate, jit, cpuRate, gpuRate / cpuRate);
        compute.releaseGl();
    }
    return 0;
}
