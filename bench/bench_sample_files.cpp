// Sampling end to end against its two limits, all measured in this run on the same field, pattern
// and folder:
//   compute  the same sampler dispatched chunk by chunk into the mapped buffer sets sdfwb's
//            pipeline uses (the same GL path), nothing written (what the GL side alone costs);
//   write    the same number of bytes written to a file in the same folder through sdfwb's own
//            writer (the same I/O path: fallocate, direct I/O for whole blocks, fsync, rename),
//            in blocks of one chunk's rows (what the disk alone costs);
//   sdfwb    sampling::sampleToFile, as `sdfwb --batch sample` runs it (compute, format, write,
//            fsync, rename), without process start-up and shader compile.
// A run that overlapped compute and writing perfectly would take max(compute, write); the ratio
// printed is max(compute, write) / sdfwb (1.0 = perfect overlap). Medians of 5 repetitions, each
// measuring the three one after the other (this machine's speed drifts between minutes). Beside
// them the CPU seconds of each (all threads): where sdfwb's exceed compute's plus write's, the
// overlap costs work; where its wall time exceeds that sum over the cores, cores stood idle. The
// ceiling is the best ratio the cores allow: a run must do both parts' CPU work, so on C cores it
// takes at least (compute CPU + write CPU) / C; ceiling = max(compute, write) / max(compute, write,
// that least time).
//
//   build/bench/bench_sample_files [N [FOLDER [PATTERN]]]
//       (default N = 20,000,000, FOLDER = $TMPDIR or /tmp, PATTERN rand and near)
// SDFWB_DIRECT_IO=0 makes sdfwb write through the page cache only (to see what direct I/O gives).

#include <renderer/HeadlessContext.h>
#include <renderer/SampleCompute.h>
#include <sampling/SampleFile.h>
#include <sampling/Sampler.h>
#include <sampling/SamplerLibrary.h>

#include "OutputFile.h" // sampling/src: the writer the sample files use

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <deque>
#include <fcntl.h>
#include <filesystem>
#include <memory>
#include <string>
#include <sys/resource.h>
#include <thread>
#include <unistd.h>
#include <vector>

using namespace sdfwb;
namespace fs = std::filesystem;

namespace {

// The CSG field: a box minus a sphere, plus a torus.
const char* kField = "float box(vec3 p, vec3 b) { vec3 q = abs(p) - b; return length(max(q, 0.0)) + min(max(q.x, max(q.y, q.z)), "
                     "0.0); }\n"
                     "float sdf(vec3 p) { float d = max(box(p, vec3(0.6)), -(length(p) - 0.75));\n"
                     "  vec2 t = vec2(length(p.xz) - 0.7, p.y); return min(d, length(t) - 0.12); }\n";

// CPU seconds of this process so far, every thread's (the GL driver's, the writer's).
double cpuSeconds() {
    rusage usage{};
    ::getrusage(RUSAGE_SELF, &usage);
    auto at = [](const timeval& t) { return double(t.tv_sec) + double(t.tv_usec) * 1e-6; };
    return at(usage.ru_utime) + at(usage.ru_stime);
}

double seconds(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

double median5(double (&runs)[5]) {
    double sorted[5];
    std::copy(runs, runs + 5, sorted);
    std::sort(sorted, sorted + 5);
    return sorted[2];
}

// Bare compute, through the same GL path as sdfwb: every chunk dispatched into the ring's buffer
// sets in turn (SampleCompute::submitMapped and collectMapped, the layout the format's writer asks
// for, as many chunks ahead as sdfwb keeps), nothing written.
double computeSeconds(renderer::SampleCompute& compute, const sampling::SamplingJob& job, renderer::RowLayout layout) {
    renderer::SampleUniforms uniforms;
    uniforms.sampleCount = std::uint32_t(job.count);
    uniforms.seed = job.seed;
    uniforms.gradientStep = job.gradientStep;
    uniforms.surfaceTolerance = job.surfaceTolerance;
    const renderer::SamplePipeline ring = compute.pipeline();
    const std::uint32_t chunk = job.chunkSize > 0 ? job.chunkSize : compute.preferredChunk();
    auto start = std::chrono::steady_clock::now();
    auto check = [](const auto& ok) {
        if (ok) return;
        std::fprintf(stderr, "bench_sample_files: %s\n", ok.error().message.c_str());
        std::exit(1);
    };
    std::deque<int> inFlight;
    int slot = 0;
    for (std::uint64_t done = 0; done < job.count;) {
        if (inFlight.size() >= std::size_t(ring.ahead)) {
            check(compute.collectMapped(inFlight.front()));
            inFlight.pop_front();
        }
        const std::uint32_t count = std::uint32_t(std::min<std::uint64_t>(chunk, job.count - done));
        check(compute.submitMapped(uniforms, std::uint32_t(done), count, slot, layout));
        inFlight.push_back(slot);
        slot = (slot + 1) % ring.sets;
        done += count;
    }
    for (int pending : inFlight) check(compute.collectMapped(pending));
    return seconds(start);
}

// The disk alone, through sdfwb's own writer (sampling/src/OutputFile.h, the same I/O path as the
// sample files: the size allocated up front, whole 4096-byte blocks past the page cache when
// direct I/O is on, the disk asked to start writing as it goes, fsync, rename): `bytes` written in
// blocks of `block` bytes from one page-aligned buffer; the file is removed afterwards.
// `cpuSpent`: the CPU seconds of the writing (not of the file's removal afterwards).
double writeSeconds(const fs::path& folder, std::uint64_t bytes, std::size_t block, double& cpuSpent) {
    const std::size_t alignment = sampling::detail::OutputFile::kDirectAlignment;
    const std::size_t capacity = (block + alignment - 1) / alignment * alignment;
    std::unique_ptr<char, decltype(&std::free)> data(static_cast<char*>(std::aligned_alloc(alignment, capacity)), &std::free);
    std::memset(data.get(), 'x', capacity);
    const fs::path path = folder / "bench_sample_files.write";
    auto start = std::chrono::steady_clock::now();
    const double cpuStart = cpuSeconds();
    auto file = sampling::detail::OutputFile::create(path);
    if (!file) {
        std::fprintf(stderr, "bench_sample_files: %s\n", file.error().message.c_str());
        std::exit(1);
    }
    file->reserve(bytes);
    for (std::uint64_t done = 0; done < bytes;) {
        const std::size_t size = std::size_t(std::min<std::uint64_t>(block, bytes - done));
        if (auto ok = file->writeDirectAt(done, data.get(), size); !ok) {
            std::fprintf(stderr, "bench_sample_files: %s\n", ok.error().message.c_str());
            std::exit(1);
        }
        done += size;
    }
    if (auto ok = file->commit(); !ok) {
        std::fprintf(stderr, "bench_sample_files: %s\n", ok.error().message.c_str());
        std::exit(1);
    }
    const double elapsed = seconds(start);
    cpuSpent = cpuSeconds() - cpuStart;
    fs::remove(path);
    return elapsed;
}

} // namespace

int main(int argc, char** argv) {
    const std::uint64_t n = argc > 1 ? std::uint64_t(std::atoll(argv[1])) : 20000000;
    const char* tmp = std::getenv("TMPDIR");
    const fs::path folder = argc > 2 ? fs::path(argv[2]) : fs::path(tmp && *tmp ? tmp : "/tmp");
    auto context = renderer::HeadlessContext::create();
    if (!context) {
        std::fprintf(stderr, "bench_sample_files: %s\n", context.error().message.c_str());
        return 3;
    }
    std::printf("sampling end to end, N = %llu rows of the CSG field (box - sphere + torus), into %s; GL: %s; medians of 5 "
                "repetitions\n\n",
                (unsigned long long)n, folder.c_str(), context.value()->info().renderer.c_str());
    std::printf("| pattern | format | file MB | compute s | write s | sdfwb s | sdfwb Msamples/s | max(compute, write) / sdfwb | "
                "ceiling | CPU s: "
                "compute + write / sdfwb | in sdfwb's run: kernel s / copy into host buffers s (GPU timers) / writer busy s / GL "
                "thread waiting for the writer s |\n");
    std::printf("|---|---|---|---|---|---|---|---|---|---|---|\n");
    std::vector<std::string> patterns = {"rand", "near"};
    if (argc > 3) patterns = {argv[3]};
    for (const std::string& pattern : patterns) {
        auto sampler = sampling::findSampler(pattern, {});
        if (!sampler) {
            std::fprintf(stderr, "bench_sample_files: %s\n", sampler.error().message.c_str());
            return 1;
        }
        renderer::SampleCompute compute;
        auto diagnostics = compute.build(shaders::prepareSdf(kField, "csg", {}, {}), *sampler);
        if (shaders::hasErrors(diagnostics)) {
            std::fprintf(stderr, "%s\n", shaders::formatDiagnostic(diagnostics[0]).c_str());
            return 1;
        }
        sampling::SamplingJob job;
        job.count = n;
        sampling::SamplingJob warm = job;
        warm.count = 1u << 16;
        computeSeconds(compute, warm, renderer::RowLayout::Separate); // the driver's code generation, outside every figure
        computeSeconds(compute, warm, renderer::RowLayout::Interleaved);
        for (sampling::SampleFormat format :
             {sampling::SampleFormat::Bin, sampling::SampleFormat::Npz, sampling::SampleFormat::Ply}) {
            const fs::path path = folder / (std::string("bench_sample_files.") + sampling::formatName(format));
            sampling::SampleMetadata metadata;
            metadata.sdf = "csg";
            metadata.pattern = pattern;
            // .ply's writer takes the rows interleaved as the file stores them (the shader writes them so).
            const renderer::RowLayout layout =
                format == sampling::SampleFormat::Ply ? renderer::RowLayout::Interleaved : renderer::RowLayout::Separate;
            // Each repetition computes, writes the file and then the same bytes raw, one after the
            // other, so all three see the machine and the disk in the same state.
            double computeRuns[5], endToEndRuns[5], writeRuns[5], computeCpu[5], endToEndCpu[5], writeCpu[5];
            sampling::SamplingReport reports[5];
            for (int k = 0; k < 5; ++k) {
                ::sync(); // no measurement pays for another's writeback or the last file's removal
                double cpu = cpuSeconds();
                computeRuns[k] = computeSeconds(compute, job, layout);
                computeCpu[k] = cpuSeconds() - cpu;
                cpu = cpuSeconds();
                auto report = sampling::sampleToFile(compute, job, path, format, metadata, {});
                endToEndCpu[k] = cpuSeconds() - cpu;
                if (!report) {
                    std::fprintf(stderr, "bench_sample_files: %s\n", report.error().message.c_str());
                    return 1;
                }
                const std::uint64_t bytes = fs::file_size(path);
                fs::remove(path);
                endToEndRuns[k] = report->seconds;
                reports[k] = *report;
                ::sync();
                writeRuns[k] = writeSeconds(
                    folder, bytes, std::size_t(job.chunkSize > 0 ? job.chunkSize : compute.preferredChunk()) * 28, writeCpu[k]);
                if (k == 0) std::printf("| %s | %s | %.0f ", pattern.c_str(), sampling::formatName(format), double(bytes) / 1e6);
            }
            // The split of the run whose time is the median.
            std::sort(reports, reports + 5, [](const auto& a, const auto& b) { return a.seconds < b.seconds; });
            const sampling::SamplingReport& middle = reports[2];
            char kernel[32] = "-";
            char copy[32] = "-";
            if (middle.kernelSeconds >= 0.0) std::snprintf(kernel, sizeof kernel, "%.3f", middle.kernelSeconds);
            if (middle.copySeconds >= 0.0) std::snprintf(copy, sizeof copy, "%.3f", middle.copySeconds);
            const double computeTime = median5(computeRuns), endToEnd = median5(endToEndRuns), writeTime = median5(writeRuns);
            const double bound = std::max(computeTime, writeTime);
            const double cores = double(std::max(1u, std::thread::hardware_concurrency()));
            const double least = (median5(computeCpu) + median5(writeCpu)) / cores;
            std::printf("| %.3f | %.3f | %.3f | %.1f | %.2f | %.2f | %.2f + %.2f / %.2f | %s / %s / %.3f / %.3f |\n", computeTime,
                        writeTime, endToEnd, double(n) / endToEnd / 1e6, bound / endToEnd, bound / std::max(bound, least),
                        median5(computeCpu), median5(writeCpu), median5(endToEndCpu), kernel, copy, middle.writeSeconds,
                        middle.waitSeconds);
            std::fflush(stdout);
        }
        compute.releaseGl();
    }
    return 0;
}
