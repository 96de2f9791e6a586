// A mesh's own field sampled by the GLSL engine (the program a GPU runs) into host memory: issue 46's
// GPU goals (the bunny: 50 M rows/s `rand`, 20 M rows/s `near`, value + exact gradient + winding
// sign), measured the way arrays in memory are filled (sampling::sampleInto, as `sdfwb.sample` and
// `sdfwb.evaluate` do), so no file system or disk sets the pace. For each pattern, rows grouped by
// cell on the GPU (the default) and in the sampler's order (SDFWB_MESH_MORTON=0): the first call
// (the driver's code generation included; the sign lattice only in the first row's, since the
// mesh's query keeps it for the later ones), then the median of 3 calls, the dispatches' and
// copies' GPU time (timer queries) of the median call, and the accuracy of the timed calls' rows
// (each call writes the same rows): over the first rows, the largest distance error against a
// float64 brute force over every triangle, the share of wrong signs against the exact winding
// number (every triangle's solid angle summed) where the true distance exceeds 1e-4, and the
// gradient's angle from the exact one, (p - closest point) / distance times the sign. The
// hierarchy's build time and memory are in the mesh's summary line.
//
//   build/bench/bench_mesh_gpu [MESH [RAND_ROWS [NEAR_ROWS]]]
//       (default: the shared bunny; 10,000,000 rows each on a GPU, 200,000 and 100,000 on llvmpipe)
// SDFWB_MESH_ENGINE is set to gpu: on llvmpipe the same program runs on the CPU (far from a GPU's
// rate, but the path and its accuracy are the GPU's).

#include <meshfield/MeshField.h>
#include <renderer/GlInfo.h>
#include <renderer/HeadlessContext.h>
#include <renderer/SampleCompute.h>
#include <sampling/Sampler.h>
#include <sampling/SamplerLibrary.h>
#include <shaders/SdfSource.h>

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

using namespace sdfwb;
namespace fs = std::filesystem;

namespace {

double seconds(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

struct Accuracy {
    double distance = 0.0;   // largest |f - true distance|
    double wrongSigns = 0.0; // share of rows beyond 1e-4 of the surface whose sign is wrong
    double angleP99 = 0.0;   // gradient angle from the exact one, degrees (rows beyond 1e-4)
    double angleMax = 0.0;
    std::size_t rows = 0;
};

// The truth at `count` rows, by brute force over every triangle in double precision.
Accuracy accuracyOf(const meshfield::MeshField& field, const float* positions, const float* distances, const float* gradients,
                    std::size_t count) {
    const meshfield::TriangleMesh& mesh = field.mesh;
    std::vector<double> errors(count), angles(count, -1.0);
    std::vector<int> wrong(count, -1);
#pragma omp parallel for schedule(dynamic, 8)
    for (std::size_t i = 0; i < count; ++i) {
        const glm::dvec3 p(positions[3 * i], positions[3 * i + 1], positions[3 * i + 2]);
        double nearest = INFINITY;
        glm::dvec3 closest(0.0);
        for (std::size_t t = 0; t < mesh.triangleCount(); ++t) {
            const glm::dvec3 a(mesh.vertices[mesh.indices[3 * t]]), b(mesh.vertices[mesh.indices[3 * t + 1]]),
                c(mesh.vertices[mesh.indices[3 * t + 2]]);
            const glm::dvec3 q = meshfield::closestPointOnTriangle(p, a, b, c);
            if (const double d = glm::length(p - q); d < nearest) nearest = d, closest = q;
        }
        const bool inside = field.windingExact(p) > 0.5; // every triangle's solid angle, no hierarchy
        const double truth = inside ? -nearest : nearest;
        errors[i] = std::abs(double(distances[i]) - truth);
        if (nearest <= 1e-4) continue;
        wrong[i] = (distances[i] < 0.0f) != inside ? 1 : 0;
        if (!gradients) continue;
        const glm::dvec3 exact = (p - closest) / nearest * (inside ? -1.0 : 1.0);
        const glm::dvec3 g(gradients[3 * i], gradients[3 * i + 1], gradients[3 * i + 2]);
        const double cosine = glm::dot(exact, g) / std::max(1e-300, glm::length(g));
        angles[i] = std::acos(std::clamp(cosine, -1.0, 1.0)) * 180.0 / M_PI;
    }
    Accuracy accuracy;
    accuracy.rows = count;
    for (double e : errors) accuracy.distance = std::max(accuracy.distance, e);
    std::size_t far = 0, signs = 0;
    for (int w : wrong)
        if (w >= 0) ++far, signs += std::size_t(w);
    accuracy.wrongSigns = far ? double(signs) / double(far) : 0.0;
    std::vector<double> measured;
    for (double a : angles)
        if (a >= 0.0) measured.push_back(a);
    std::sort(measured.begin(), measured.end());
    if (!measured.empty()) {
        accuracy.angleP99 = measured[std::min(measured.size() - 1, measured.size() * 99 / 100)];
        accuracy.angleMax = measured.back();
    }
    return accuracy;
}

std::string milliseconds(double secondsOrNegative) {
    if (secondsOrNegative < 0.0) return "-";
    char text[32];
    std::snprintf(text, sizeof text, "%.1f ms", secondsOrNegative * 1e3);
    return text;
}

} // namespace

int main(int argc, char** argv) {
    const char* shared = std::getenv("SDFWB_SHARED_DIR");
    const fs::path meshPath =
        argc > 1 ? fs::path(argv[1]) : fs::path(shared && *shared ? shared : "../shared") / "data/meshes/stanford-bunny.obj";
    ::setenv("SDFWB_MESH_ENGINE", "gpu", 1);
    auto context = renderer::HeadlessContext::create();
    if (!context) {
        std::fprintf(stderr, "bench_mesh_gpu: %s\n", context.error().message.c_str());
        return 3;
    }
    const bool software = renderer::softwareRasteriser();
    const std::size_t randRows = argc > 2 ? std::size_t(std::atoll(argv[2])) : software ? 200000 : 10000000;
    const std::size_t nearRows = argc > 3 ? std::size_t(std::atoll(argv[3])) : software ? 100000 : 10000000;
    meshfield::MeshFieldOptions options;
    options.normalize = meshfield::Normalization::UnitCube;
    auto field = meshfield::loadMeshField(meshPath, options);
    if (!field) {
        std::fprintf(stderr, "bench_mesh_gpu: %s\n", field.error().message.c_str());
        return 1;
    }
    const meshfield::MeshField& mesh = **field;
    std::printf("mesh SDF sampling on the GLSL engine into host memory: %s, normalised to the unit cube, winding-number sign, "
                "value + exact gradient\n\n",
                meshPath.filename().c_str());
    std::printf("- GL: %s\n", context.value()->info().renderer.c_str());
    std::printf("- %s\n", mesh.summary().c_str());
    std::printf("- first call: the driver's code generation included, the sign lattice in the first row's only (the mesh's "
                "query keeps it for the later rows)\n");
    std::printf("- accuracy over the first 1000 rows (all, where fewer) of the timed calls (each writes the same rows) against "
                "a float64 brute force over every triangle; wrong signs and gradient angles where the true distance exceeds "
                "1e-4\n\n");
    std::printf("| pattern | rows | order | first call (s) | rows/s (median of 3) [min, max] | kernels (GPU timer) | copies (GPU "
                "timer) | rows/s of the kernels alone | bad rows | distance error max | wrong signs | gradient angle p99 / "
                "max (deg) | goal | met |\n");
    std::printf("|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n");
    std::string verdicts;
    for (const char* pattern : {"rand", "near"}) {
        const std::size_t rows = std::string(pattern) == "rand" ? randRows : nearRows;
        const double goal = std::string(pattern) == "rand" ? 50e6 : 20e6;
        auto sampler = sampling::findSampler(pattern, {});
        if (!sampler) {
            std::fprintf(stderr, "bench_mesh_gpu: %s\n", sampler.error().message.c_str());
            return 1;
        }
        std::vector<float> positions(3 * rows), distances(rows), gradients(3 * rows);
        for (const char* order : {"sorted by cell", "sampler's order"}) {
            const bool sorted = order[0] == 's' && order[1] == 'o';
            ::setenv("SDFWB_MESH_MORTON", sorted ? "1" : "0", 1);
            renderer::SampleCompute compute;
            const auto buildStart = std::chrono::steady_clock::now();
            auto diagnostics = compute.build(shaders::prepareMeshSdf(*field, meshPath, {}, {}), *sampler);
            if (shaders::hasErrors(diagnostics)) {
                std::fprintf(stderr, "%s\n", shaders::formatDiagnostic(diagnostics[0]).c_str());
                return 1;
            }
            sampling::SamplingJob job;
            job.count = rows;
            auto call = [&]() -> Expected<sampling::SamplingReport> {
                return sampling::sampleInto(compute, job, positions.data(), distances.data(), gradients.data(), {});
            };
            if (auto first = call(); !first) {
                std::fprintf(stderr, "bench_mesh_gpu: %s\n", first.error().message.c_str());
                return 1;
            }
            const double firstCall = seconds(buildStart);
            std::vector<std::pair<double, sampling::SamplingReport>> runs;
            for (int k = 0; k < 3; ++k) {
                const auto start = std::chrono::steady_clock::now();
                auto report = call();
                if (!report) {
                    std::fprintf(stderr, "bench_mesh_gpu: %s\n", report.error().message.c_str());
                    return 1;
                }
                runs.emplace_back(double(rows) / seconds(start), *report);
            }
            std::sort(runs.begin(), runs.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
            const sampling::SamplingReport& middle = runs[1].second;
            compute.releaseGl();
            const Accuracy accuracy =
                accuracyOf(mesh, positions.data(), distances.data(), gradients.data(), std::min<std::size_t>(rows, 1000));
            char kernelRate[32] = "-";
            if (middle.kernelSeconds > 0.0)
                std::snprintf(kernelRate, sizeof kernelRate, "%.3g", double(rows) / middle.kernelSeconds);
            const bool met = !software && runs[1].first >= goal;
            std::printf(
                "| %s | %zu | %s | %.2f | %.3g [%.3g, %.3g] | %s | %s | %s | %llu | %.2g | %.2f %% | %.2f / %.2f | %.0f M "
                "rows/s | %s |\n",
                pattern, rows, order, firstCall, runs[1].first, runs[0].first, runs[2].first,
                milliseconds(middle.kernelSeconds).c_str(), milliseconds(middle.copySeconds).c_str(), kernelRate,
                (unsigned long long)middle.badRows, accuracy.distance, accuracy.wrongSigns * 100.0, accuracy.angleP99,
                accuracy.angleMax, goal / 1e6,
                software ? "no GPU"
                : met    ? "yes"
                         : "**no**");
            std::fflush(stdout);
            char verdict[256];
            std::snprintf(verdict, sizeof verdict, "- %s, %s: %.3g rows/s against a goal of %.0f M rows/s on a GPU: %s\n",
                          pattern, order, runs[1].first, goal / 1e6,
                          software ? "not a GPU (llvmpipe), no verdict"
                          : met    ? "met"
                                   : "**not met**");
            verdicts += verdict;
        }
    }
    ::unsetenv("SDFWB_MESH_MORTON");
    std::printf("\n%s", verdicts.c_str());
    return 0;
}
