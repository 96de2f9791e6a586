// `sdfwb --batch sample` as a user runs it: the paper's --sample form, job files, Ctrl-C, and
// bounded memory for N = 50 million. Runs the real binary without a display (EGL).

#include "common/ChildProcess.h"
#include "common/Scratch.h"

#include <gtest/gtest.h>

#include <array>
#include <chrono>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <functional>
#include <linux/magic.h>
#include <string>
#include <sys/resource.h>
#include <sys/vfs.h>
#include <sys/wait.h>
#include <thread>
#include <unistd.h>
#include <vector>

#include <csignal>
#include <iterator>

#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

namespace fs = std::filesystem;

namespace {

using Result = sdfwb::testing::RunResult;

Result run(const std::string& arguments) { return sdfwb::testing::runCommand(SDFWB_BINARY, arguments); }

// A folder of this test process's own: ctest -j runs the cases of this binary side by side, and a
// case that looks for partial files must not see another case's.
fs::path scratchFolder() { return fs::temp_directory_path() / ("sdfwb-batch-sample-test-" + std::to_string(::getpid())); }

// Nothing is left at the path: a case checks that its run made the file.
fs::path scratch(const std::string& name) {
    const fs::path path = sdfwb::testing::scratchPath("batch-sample", name);
    fs::remove(path);
    return path;
}

bool partialFilesIn(const fs::path& folder) {
    for (const auto& entry : fs::directory_iterator(folder))
        if (entry.path().filename().string().find(".partial-") != std::string::npos) return true;
    return false;
}

// Starts the binary directly (no shell, no DISPLAY); `prepare` runs in the child before exec.
pid_t spawnSdfwb(const std::vector<std::string>& arguments, const std::function<void()>& prepare) {
    pid_t child = fork();
    if (child == 0) {
        unsetenv("DISPLAY");
        prepare();
        std::vector<char*> argv;
        std::string binary = SDFWB_BINARY;
        argv.push_back(binary.data());
        std::vector<std::string> copy = arguments;
        for (std::string& a : copy) argv.push_back(a.data());
        argv.push_back(nullptr);
        execv(binary.c_str(), argv.data());
        _exit(127);
    }
    return child;
}

// Runs the binary directly (no shell) and returns its exit status and peak resident memory.
std::pair<int, long> runMeasured(const std::vector<std::string>& arguments) {
    pid_t child = spawnSdfwb(arguments, [] {});
    int status = 0;
    struct rusage usage {};
    wait4(child, &status, 0, &usage);
    return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, usage.ru_maxrss};
}

// Runs the binary directly with one resource limit set (and SIGXFSZ ignored, so a file-size
// limit turns into failing writes, as a full disk does); returns the exit status and the output.
Result runLimited(const std::vector<std::string>& arguments, int resource, rlim_t limit) {
    int fds[2];
    if (pipe(fds) != 0) return {};
    pid_t child = spawnSdfwb(arguments, [&] {
        dup2(fds[1], 1);
        dup2(fds[1], 2);
        close(fds[0]);
        signal(SIGXFSZ, SIG_IGN);
        struct rlimit value {
            limit, limit
        };
        setrlimit(resource, &value);
    });
    close(fds[1]);
    Result result;
    std::array<char, 4096> buffer;
    ssize_t n;
    while ((n = read(fds[0], buffer.data(), buffer.size())) > 0) result.output.append(buffer.data(), std::size_t(n));
    close(fds[0]);
    int status = 0;
    waitpid(child, &status, 0);
    result.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
    return result;
}

// Hidden temporary files a writer left next to `target` (".full.npz.partial-*", ".full.png.*",
// ".full.partial*.mp4", whatever the writer's pattern).
bool temporariesNextTo(const fs::path& target) {
    for (const auto& entry : fs::directory_iterator(target.parent_path())) {
        const std::string name = entry.path().filename().string();
        if (name.size() > 1 && name[0] == '.' && name.find(target.stem().string()) != std::string::npos) return true;
    }
    return false;
}

std::string readAll(const fs::path& path) { return sdfwb::testing::readBytes(path); }

} // namespace

TEST(ResourceLimits, DiskFullFailsCleanlyAndKeepsTheOldFile) {
    const fs::path out = scratch("full.npz");
    { std::ofstream(out) << "the previous results"; }
    // Into /dev/shm too, where the writing goes in pieces to writer threads pinned one to a core.
    const auto memory = sdfwb::testing::memoryScratchPath("batch-sample", "full.npz");
    EXPECT_TRUE(memory.has_value()) << "/dev/shm is not a tmpfs here: the spread writer's failure is not tested";
    std::vector<fs::path> targets;
    for (const char* extension : {".npz", ".bin", ".ply"}) {
        targets.push_back(out.parent_path() / (std::string("full") + extension));
        if (memory) targets.push_back(memory->parent_path() / (std::string("full") + extension));
    }
    for (const fs::path& target : targets) {
        { std::ofstream(target) << "the previous results"; }
        // 64 KiB per file: the writer's first large write fails with EFBIG, as on a full disk.
        Result r =
            runLimited({"--batch", "sample", "--sdf", "sphere", "--pattern", "rand", "-n", "200000", "--output", target.string()},
                       RLIMIT_FSIZE, 64 * 1024);
        EXPECT_EQ(r.exitCode, 1) << r.output;
        EXPECT_NE(r.output.find(target.string()), std::string::npos) << "the message names the file: " << r.output;
        EXPECT_NE(r.output.find("write failed"), std::string::npos) << r.output;
        EXPECT_TRUE(readAll(target) == "the previous results") << target << ": the old file was replaced";
        EXPECT_FALSE(temporariesNextTo(target)) << target;
    }
    if (memory) fs::remove_all(memory->parent_path());
    // A render too: the PNG writer fails, the old image stays.
    const fs::path image = scratch("full.png");
    { std::ofstream(image) << "the previous image"; }
    Result r = runLimited({"--batch", "render", "--sdf", "torus", "--size", "1024x1024", "--output", image.string()},
                          RLIMIT_FSIZE, 4 * 1024);
    EXPECT_EQ(r.exitCode, 1) << r.output;
    EXPECT_NE(r.output.find(image.string()), std::string::npos) << r.output;
    EXPECT_TRUE(readAll(image) == "the previous image") << "the old image was replaced (" << fs::file_size(image) << " bytes)";
    EXPECT_FALSE(temporariesNextTo(image));
    // And an MP4.
    const fs::path video = scratch("full.mp4");
    { std::ofstream(video) << "the previous video"; }
    r = runLimited({"--batch", "animate", "--sdf", "torus", "--size", "320x240", "--seconds", "2", "--turntable", "--output",
                    video.string()},
                   RLIMIT_FSIZE, 20 * 1024);
    EXPECT_EQ(r.exitCode, 1) << r.output;
    EXPECT_NE(r.output.find(video.string()), std::string::npos) << r.output;
    EXPECT_TRUE(readAll(video) == "the previous video");
    EXPECT_FALSE(temporariesNextTo(video));
}

TEST(ResourceLimits, UnwritableOutputIsNamedBeforeAnyWork) {
    // /proc refuses new files even to root; a folder that does not exist refuses them to everyone.
    for (const std::string& target : {std::string("/proc/sdfwb-test.bin"), scratch("no-such-folder").string() + "/x.npz"}) {
        Result r = run("--batch sample --sdf sphere --pattern rand -n 1000 --output " + target);
        EXPECT_NE(r.exitCode, 0) << target;
        EXPECT_NE(r.output.find(target), std::string::npos) << r.output;
        EXPECT_EQ(r.output.find("wrote"), std::string::npos) << r.output;
    }
    Result r = run("--batch render --sdf sphere --size 64x64 --output /proc/sdfwb-test.png");
    EXPECT_NE(r.exitCode, 0);
    EXPECT_NE(r.output.find("/proc/sdfwb-test.png"), std::string::npos) << r.output;
}

TEST(ResourceLimits, OutOfMemoryContinuesInSmallerChunksWithTheSameRows) {
    // Reference rows with small chunks, no limit.
    const fs::path reference = scratch("oom-reference.bin");
    const Result first =
        run("--batch sample --sdf sphere --pattern rand -n 4194240 --chunk 65536 --output " + reference.string());
    ASSERT_EQ(first.exitCode, 0) << first.output;
    // A GPU's buffers live in its own memory, where an address-space limit does not reach them
    // (NVIDIA's H200 ran every limit below to the end in one chunk): the premise holds only where
    // the driver keeps them in the process.
    if (first.output.find("llvmpipe") == std::string::npos && first.output.find("softpipe") == std::string::npos)
        GTEST_SKIP() << "the GL driver is a GPU's: an address-space limit does not bind its buffers";
    // One dispatch of 4 194 240 samples needs ~117 MB of buffers in llvmpipe: under an address
    // space limit it fails with GL_OUT_OF_MEMORY. The run halves its chunks and goes on; the rows
    // depend only on their index, so the file is the same. The limit that shows it depends on the
    // process's own footprint (about 0.5 GB smaller since OpenImageIO and FFmpeg load only for
    // images and videos), so a few are tried; none may crash. (Much lower, near 600 MB, Mesa's
    // shader compiler itself runs out and dies of SIGSEGV inside swrast_dri.so: not tried.)
    bool continued = false;
    for (rlim_t megabytes : {700, 750, 800, 680, 850, 900}) {
        const fs::path out = scratch("oom.bin");
        Result r = runLimited({"--batch", "sample", "--sdf", "sphere", "--pattern", "rand", "-n", "4194240", "--chunk", "4194240",
                               "--output", out.string()},
                              RLIMIT_AS, megabytes << 20);
        EXPECT_TRUE(r.exitCode == 0 || r.exitCode == 1 || r.exitCode == 3) << megabytes << " MB: " << r.output;
        if (r.exitCode == 0 && r.output.find("continuing in chunks") != std::string::npos) {
            EXPECT_EQ(readAll(out), readAll(reference)) << megabytes << " MB";
            continued = true;
            break;
        }
    }
    EXPECT_TRUE(continued) << "no address-space limit between 680 and 900 MB made the big dispatch fail and the run continue";
}

// The paper's .bin layout (Table 2): uint32 N, then N positions, N distances, N gradients.
struct BinRows {
    std::vector<float> positions, distances, gradients;
};
BinRows readBin(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    std::uint32_t n = 0;
    in.read(reinterpret_cast<char*>(&n), 4);
    BinRows rows{std::vector<float>(3 * std::size_t(n)), std::vector<float>(n), std::vector<float>(3 * std::size_t(n))};
    in.read(reinterpret_cast<char*>(rows.positions.data()), std::streamsize(rows.positions.size() * 4));
    in.read(reinterpret_cast<char*>(rows.distances.data()), std::streamsize(rows.distances.size() * 4));
    in.read(reinterpret_cast<char*>(rows.gradients.data()), std::streamsize(rows.gradients.size() * 4));
    EXPECT_TRUE(in.good()) << path;
    return rows;
}

float lengthOf(const float* v) { return std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]); }

TEST(BatchSample, PaperFormWritesTheBinLayout) {
    fs::path out = scratch("paper.bin");
    Result r = run("--sample rand 1000 sphere " + out.string());
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_EQ(fs::file_size(out), 4u + 28u * 1000u);
    // The dataset's sphere (radius 0.8): each row's distance is |p| - 0.8 and its gradient p / |p|,
    // points inside the cube.
    const BinRows rows = readBin(out);
    ASSERT_EQ(rows.distances.size(), 1000u);
    int wrong = 0;
    for (std::size_t i = 0; i < 1000; ++i) {
        const float* p = &rows.positions[3 * i];
        const float* g = &rows.gradients[3 * i];
        const float radius = lengthOf(p);
        wrong += !(std::abs(p[0]) <= 1.0f && std::abs(p[1]) <= 1.0f && std::abs(p[2]) <= 1.0f);
        wrong += !(std::abs(rows.distances[i] - (radius - 0.8f)) < 1e-5f);
        for (int a = 0; a < 3; ++a) wrong += !(std::abs(g[a] - p[a] / radius) < 2e-3f);
    }
    EXPECT_EQ(wrong, 0);
    fs::path noExtension = scratch("paper_output");
    r = run("--sample grid 27 Sphere " + noExtension.string());
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_EQ(fs::file_size(noExtension), 4u + 28u * 27u) << "the original wrote .bin whatever the name";
}

TEST(BatchSample, BadArgumentsAreNamedAndWriteNothing) {
    fs::path out = scratch("bad.npz");
    struct Case {
        std::string arguments, culprit;
    } cases[] = {{"--sdf sphere --pattern rand -n 0 --output " + out.string(), "-n"},
                 {"--sdf sphere --pattern spiral -n 10 --output " + out.string(), "'spiral'"},
                 {"--sdf sphere --pattern rand -n 10 --output " + out.string() + " --shard 3/3", "--shard"},
                 {"--sdf sphere --pattern rand -n 10 --output " + out.string() + " --shard x", "--shard"},
                 {"--sdf sphere --pattern rand -n 10 --output " + out.string() + " --format hdf5", "--format"},
                 {"--sdf sphere --pattern rand -n 10 --output " + scratch("bad.xyz").string(), ".bin, .npz or .ply"},
                 {"--sdf nowhere --pattern rand -n 10 --output " + out.string(), "'nowhere'"},
                 {"--sdf sphere --pattern rand -n 5000000000 --output " + scratch("big.bin").string(), "limit"},
                 {"--sdf sphere --pattern surface -n 10 --surface-tolerance 0 --output " + out.string(), "--surface-tolerance"}};
    for (const Case& c : cases) {
        Result r = run("--batch sample " + c.arguments);
        EXPECT_EQ(r.exitCode, 2) << c.arguments << "\n" << r.output;
        EXPECT_NE(r.output.find(c.culprit), std::string::npos) << c.arguments << "\n" << r.output;
    }
    EXPECT_FALSE(fs::exists(out));
    EXPECT_FALSE(fs::exists(scratch("big.bin")));
}

TEST(BatchSample, JobFileRunsEveryStepAndStopsAtTheFirstFailure) {
    fs::path job = scratch("jobs.txt");
    fs::path a = scratch("job-a.npz"), b = scratch("job-b.png"), merged = scratch("job-merged.npz");
    fs::path s0 = scratch("job-s0.npz"), s1 = scratch("job-s1.npz");
    std::ofstream(job) << "# sample, render, shard and merge in one file\n"
                       << "sample --sdf torus --pattern surface -n 2000 --output '" << a.string() << "' --quiet\n\n"
                       << "render --sdf box --output " << b.string() << " --size 64x36 --quiet   # a comment\n"
                       << "sample --sdf torus --pattern surface -n 2000 --output " << s0.string() << " --shard 0/2 -q\n"
                       << "sample --sdf torus --pattern surface -n 2000 --output " << s1.string() << " --shard 1/2 -q\n"
                       << "merge --output " << merged.string() << " " << s1.string() << " " << s0.string() << " -q\n";
    Result r = run("--batch " + job.string());
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_TRUE(fs::exists(a) && fs::exists(b));
    std::ifstream left(a, std::ios::binary), right(merged, std::ios::binary);
    std::string leftBytes((std::istreambuf_iterator<char>(left)), {}), rightBytes((std::istreambuf_iterator<char>(right)), {});
    EXPECT_EQ(leftBytes, rightBytes) << "merged shards must equal the single run";

    std::ofstream(job) << "list -q\nsample --sdf torus --pattern rand -n 10 --output " << scratch("never.npz").string()
                       << " --bogus\n";
    r = run("--batch " + job.string());
    EXPECT_EQ(r.exitCode, 2) << r.output;
    EXPECT_NE(r.output.find("jobs.txt:2"), std::string::npos) << r.output;
    std::ofstream(job) << "sample --sdf 'unterminated\n";
    r = run("--batch " + job.string());
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_NE(r.output.find("jobs.txt:1: unterminated"), std::string::npos) << r.output;
    std::ofstream(job) << "rm -rf /tmp/x\n";
    r = run("--batch " + job.string());
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_NE(r.output.find("unknown command 'rm'"), std::string::npos) << r.output;
}

TEST(BatchSample, CtrlCLeavesNoPartialFile) {
    fs::path out = scratch("interrupted.npz");
    // Long enough to be interrupted: 200 M metropolis samples would take minutes. Ctrl-C comes once
    // the run has sent its first progress message (so the output file is being written), not
    // after a guessed delay; the child must still be running then.
    int fds[2];
    ASSERT_EQ(pipe(fds), 0);
    pid_t child = spawnSdfwb({"--batch", "sample", "--sdf", "torus", "--pattern", "metropolis", "-n", "200000000", "--output",
                              out.string(), "--chunk", "65536", "--protocol"},
                             [&] {
                                 dup2(fds[1], 1);
                                 close(fds[0]);
                             });
    close(fds[1]);
    const std::string messages = sdfwb::testing::readUntil(fds[0], "{\"progress\":", std::chrono::seconds(120));
    ASSERT_NE(messages.find("{\"progress\":"), std::string::npos) << "no progress message within 120 s:\n" << messages;
    int status = 0;
    ASSERT_EQ(waitpid(child, &status, WNOHANG), 0) << "the child ended before Ctrl-C";
    kill(child, SIGINT);
    sdfwb::testing::drain(fds[0]);
    close(fds[0]);
    waitpid(child, &status, 0);
    const int exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    EXPECT_EQ(exitCode, 130);
    EXPECT_FALSE(fs::exists(out));
    EXPECT_FALSE(partialFilesIn(out.parent_path()));
}

TEST(BatchSample, FiftyMillionSamplesStayUnder512MiB) {
    fs::path out = scratch("fifty-million.bin");
    auto [exitCode, peakKiB] = runMeasured(
        {"--batch", "sample", "--sdf", "sphere", "--pattern", "rand", "-n", "50000000", "--output", out.string(), "--quiet"});
    ASSERT_EQ(exitCode, 0);
    EXPECT_EQ(fs::file_size(out), 4u + 28u * 50000000u);
    EXPECT_LT(peakKiB, 512 * 1024) << "peak resident memory " << peakKiB / 1024 << " MiB";
    std::printf("peak resident memory for N = 5e7: %ld MiB\n", peakKiB / 1024);
    fs::remove(out);
}

TEST(BatchAnimate, WritesAnH264Mp4WithTheRightFrames) {
    fs::path out = scratch("turntable.mp4");
    Result r =
        run("--batch animate --sdf torus --output " + out.string() + " --size 161x91 --seconds 1 --fps 12 --turntable --quiet");
    ASSERT_EQ(r.exitCode, 0) << r.output;
    Result probe;
    {
        std::string command =
            "ffprobe -v error -count_frames -show_entries stream=codec_name,width,height,nb_read_frames -of csv=p=0 " +
            out.string();
        FILE* pipe = popen(command.c_str(), "r");
        std::array<char, 256> buffer{};
        while (std::size_t n = std::fread(buffer.data(), 1, buffer.size(), pipe)) probe.output.append(buffer.data(), n);
        probe.exitCode = pclose(pipe);
    }
    EXPECT_EQ(probe.output, "h264,160,90,12\n") << "odd sizes round down to even for 4:2:0";

    Result wrongType = run("--batch animate --sdf torus --output " + scratch("clip.avi").string());
    EXPECT_EQ(wrongType.exitCode, 2);
    EXPECT_NE(wrongType.output.find(".mp4"), std::string::npos) << wrongType.output;
    EXPECT_FALSE(fs::exists(scratch("clip.avi")));
}

// Issue 14: foreign code through every batch command, --entry, and the audit's flags in JSON and text.
TEST(BatchForeign, EntryOnEveryCommandAndFlagsInTheReports) {
    const fs::path shadertoy = scratch("toy.glsl");
    std::ofstream(shadertoy) << "#define EPS 0.001\nfloat hash(float n) { return fract(sin(n) * 43758.5453); }\n"
                                "vec2 map(vec3 p) { return vec2(length(p) - 0.5, 1.0); }\n"
                                "float shape(vec3 p, float t) { return min(1.0, 1.9 * (length(p) - 0.4 - 0.05 * sin(t))); }\n";
    // map() is found by convention; --entry picks another function on every command.
    fs::path out = scratch("toy.npz");
    Result r = run("--batch sample --sdf " + shadertoy.string() + " --pattern near -n 2000 --output " + out.string());
    ASSERT_EQ(r.exitCode, 0) << r.output;
    const fs::path shapeBin = scratch("toy_shape.bin");
    r = run("--batch sample --sdf " + shadertoy.string() + " --entry shape --time 1 --pattern rand -n 100 --output " +
            shapeBin.string());
    ASSERT_EQ(r.exitCode, 0) << r.output;
    // The rows are shape()'s at t = 1, not map()'s.
    const BinRows shapeRows = readBin(shapeBin);
    ASSERT_EQ(shapeRows.distances.size(), 100u);
    int notShape = 0;
    for (std::size_t i = 0; i < 100; ++i) {
        const float expected = std::min(1.0f, 1.9f * (lengthOf(&shapeRows.positions[3 * i]) - 0.4f - 0.05f * std::sin(1.0f)));
        notShape += !(std::abs(shapeRows.distances[i] - expected) < 1e-4f);
    }
    EXPECT_EQ(notShape, 0);
    // A render with --entry shape draws what a file whose sdf() is shape() draws, not map()'s picture.
    // (scratch() removes the file it names: each is named once.)
    const fs::path alone = scratch("shape_alone.glsl"), alonePng = scratch("alone.png"), mapPng = scratch("map.png"),
                   shapePng = scratch("toy.png");
    std::ofstream(alone) << "float sdf(vec3 p, float t) { return min(1.0, 1.9 * (length(p) - 0.4 - 0.05 * sin(t))); }\n";
    ASSERT_EQ(run("--batch render --sdf " + alone.string() + " --size 64x48 --output " + alonePng.string()).exitCode, 0);
    ASSERT_EQ(run("--batch render --sdf " + shadertoy.string() + " --size 64x48 --output " + mapPng.string()).exitCode, 0);
    r = run("--batch render --sdf " + shadertoy.string() + " --entry shape --size 64x48 --output " + shapePng.string());
    ASSERT_EQ(r.exitCode, 0) << r.output;
    ASSERT_GT(fs::file_size(shapePng), 100u);
    EXPECT_EQ(readAll(shapePng), readAll(alonePng)) << "--entry shape did not draw shape()";
    EXPECT_NE(readAll(shapePng), readAll(mapPng)) << "--entry shape drew map()";
    r = run("--batch animate --sdf " + shadertoy.string() + " --entry shape --size 64x48 --seconds 0.2 --fps 10 --output " +
            scratch("toy.mp4").string());
    ASSERT_EQ(r.exitCode, 0) << r.output;
    r = run("--batch audit --sdf " + shadertoy.string() + " --entry shape --samples 5000 --json --quiet");
    ASSERT_EQ(r.exitCode, 0) << r.output;
    const std::size_t json = r.output.find('{');
    ASSERT_NE(json, std::string::npos) << r.output;
    const std::string report = r.output.substr(json);
    EXPECT_NE(report.find("\"verdict\": \"truncated\""), std::string::npos) << report;
    EXPECT_NE(report.find("\"flag\": \"non-conservative\""), std::string::npos) << report;
    EXPECT_NE(report.find("\"flag\": \"truncated\""), std::string::npos) << report;
    EXPECT_NE(report.find("\"entry\": \"shape\""), std::string::npos) << report;
    r = run("--batch audit --sdf " + shadertoy.string() + " --entry shape --samples 5000");
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_NE(r.output.find("  truncated          the field stops growing at 1"), std::string::npos) << r.output;
    // Bad entries: named, exit 2 (usage) before any work; a missing one: the file's diagnostic, exit non-zero.
    for (const char* entry : {"main", "sdfwb_sdf", "9lives", "a.b"}) {
        r = run("--batch sample --sdf " + shadertoy.string() + " --entry " + entry + " --pattern rand -n 10 --output " +
                out.string());
        EXPECT_EQ(r.exitCode, 2) << entry << "\n" << r.output;
        EXPECT_NE(r.output.find("--entry"), std::string::npos) << r.output;
    }
    r = run("--batch audit --sdf " + shadertoy.string() + " --entry nothere");
    EXPECT_NE(r.exitCode, 0);
    EXPECT_NE(r.output.find("entry point 'nothere' not found"), std::string::npos) << r.output;
    r = run("--batch audit --sdf " + shadertoy.string() + " --truncation-reach 0");
    EXPECT_EQ(r.exitCode, 2) << r.output;
    EXPECT_NE(r.output.find("--truncation-reach"), std::string::npos) << r.output;
}

// llvmpipe ends every loop after 65535 iterations without an error: a loop that runs longer is
// named at its file and line on standard error (docs/stability.md). On another driver nothing is
// said. The renderer comes from the run's own JSON report.
TEST(BatchSample, ALoopLlvmpipeWouldCutShortIsWarnedAtItsLine) {
    const fs::path sdf = scratch("long_loop.glsl");
    std::ofstream(sdf) << "// 0.5 / 200000 added 200000 times: -0.5 at the origin\n"
                          "float sdf(vec3 p) {\n"
                          "    float s = 0.0;\n"
                          "    for (int i = 0; i < 200000; ++i) s += 0.5 / 200000.0;\n"
                          "    return length(p) - s;\n"
                          "}\n";
    Result r = run("--batch sample --sdf " + sdf.string() + " --pattern rand -n 1000 --json --output " +
                   scratch("long_loop.npz").string());
    ASSERT_EQ(r.exitCode, 0) << r.output;
    const bool llvmpipe = r.output.find("\"gl_renderer\": \"llvmpipe") != std::string::npos ||
                          r.output.find("\"gl_renderer\":\"llvmpipe") != std::string::npos;
    const std::string where = sdf.string() + ":4:";
    if (llvmpipe) {
        EXPECT_NE(r.output.find(where), std::string::npos) << r.output;
        EXPECT_NE(r.output.find("200000 times"), std::string::npos) << r.output;
        EXPECT_NE(r.output.find("65535"), std::string::npos) << r.output;
    } else {
        EXPECT_EQ(r.output.find("65535"), std::string::npos) << r.output;
    }
    // The same field with its loop split in two (400 x 500) draws no warning anywhere.
    std::ofstream(sdf) << "float sdf(vec3 p) {\n"
                          "    float s = 0.0;\n"
                          "    for (int i = 0; i < 400; ++i) for (int j = 0; j < 500; ++j) s += 0.5 / 200000.0;\n"
                          "    return length(p) - s;\n"
                          "}\n";
    r = run("--batch sample --sdf " + sdf.string() + " --pattern rand -n 1000 --json --output " +
            scratch("long_loop.npz").string());
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_EQ(r.output.find("65535"), std::string::npos) << r.output;
}
