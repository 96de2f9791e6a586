// Security: sampler names stay inside their folders (symlinks included), job files run no
// commands, and the batch path opens no network socket. (Include escapes: tests/shaders.)

#include <sampling/SamplerLibrary.h>

#include "common/ChildProcess.h"
#include "common/NetworkSockets.h"

#include <gtest/gtest.h>

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <thread>

#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

using namespace sdfwb;
namespace fs = std::filesystem;

namespace {

// What `ldd FILE` prints: the shared libraries FILE loads when it loads.
std::string sharedLibraries(const std::string& file) {
    FILE* pipe = popen(("ldd " + file).c_str(), "r");
    std::string libraries;
    char buffer[8192];
    while (std::size_t n = std::fread(buffer, 1, sizeof buffer, pipe)) libraries.append(buffer, n);
    pclose(pipe);
    return libraries;
}

fs::path freshFolder(const std::string& name) {
    fs::path folder = fs::temp_directory_path() / ("sdfwb-security-" + name + "-" + std::to_string(::getpid()));
    fs::remove_all(folder);
    fs::create_directories(folder);
    return folder;
}

int runSdfwb(const std::string& arguments, std::string* output = nullptr) {
    FILE* pipe = popen(("env -u DISPLAY " + std::string(SDFWB_BINARY) + " " + arguments + " 2>&1").c_str(), "r");
    char buffer[4096];
    std::string text;
    while (std::size_t n = std::fread(buffer, 1, sizeof buffer, pipe)) text.append(buffer, n);
    int status = pclose(pipe);
    if (output) *output = text;
    return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

} // namespace

TEST(Security, SamplerNamesCannotLeaveTheirFolderThroughASymlink) {
    fs::path root = freshFolder("samplers");
    fs::create_directories(root / "samplers");
    fs::create_directories(root / "elsewhere");
    const char* sampler = "bool samplePosition(uint index, out vec3 position) { position = vec3(0.0); return true; }\n";
    std::ofstream(root / "elsewhere" / "secret.glsl") << sampler;
    std::ofstream(root / "samplers" / "mine.glsl") << sampler;
    fs::create_symlink(root / "elsewhere" / "secret.glsl", root / "samplers" / "escape.glsl");
    EXPECT_TRUE(sampling::findSampler("mine", {root / "samplers"}).hasValue());
    auto escaped = sampling::findSampler("escape", {root / "samplers"});
    ASSERT_FALSE(escaped.hasValue());
    EXPECT_NE(escaped.error().message.find("outside the sampler folder"), std::string::npos) << escaped.error().message;
    fs::remove_all(root);
}

TEST(Security, JobFilesRunNoCommands) {
    fs::path folder = freshFolder("jobs");
    const fs::path marker = folder / "marker";
    const std::string lines[] = {"list $(touch " + marker.string() + ")", "list `touch " + marker.string() + "`",
                                 "list; touch " + marker.string(), "list | touch " + marker.string(),
                                 "list && touch " + marker.string()};
    for (const std::string& line : lines) {
        fs::path job = folder / "job.txt";
        std::ofstream(job) << line << "\n";
        std::string output;
        int code = runSdfwb("--batch " + job.string(), &output);
        EXPECT_EQ(code, 2) << line << "\n" << output; // the extra words are unknown arguments of `list`
        EXPECT_NE(output.find("job.txt:1"), std::string::npos) << output;
        EXPECT_FALSE(fs::exists(marker)) << "a job file ran a command: " << line;
    }
    fs::remove_all(folder);
}

TEST(Security, BatchRunsOpenNoNetworkSocket) {
    // A sampling run long enough to look at its sockets while it works.
    // Its sockets are read once it reports progress (its GL context is up and it is sampling), and
    // only while it still runs.
    fs::path folder = freshFolder("sockets");
    int fds[2];
    ASSERT_EQ(pipe(fds), 0);
    pid_t child = fork();
    if (child == 0) {
        unsetenv("DISPLAY");
        dup2(fds[1], 1);
        close(fds[0]);
        execl(SDFWB_BINARY, SDFWB_BINARY, "--batch", "sample", "--sdf", "mandelbulb", "--pattern", "surface", "-n", "2000000",
              "--chunk", "16384", "--protocol", "--output", (folder / "out.npz").c_str(), static_cast<char*>(nullptr));
        _exit(127);
    }
    close(fds[1]);
    const std::string messages = sdfwb::testing::readUntil(fds[0], "{\"progress\":", std::chrono::seconds(120));
    ASSERT_NE(messages.find("{\"progress\":"), std::string::npos) << "no progress message within 120 s:\n" << messages;
    int status = 0;
    ASSERT_EQ(waitpid(child, &status, WNOHANG), 0) << "the run ended before its sockets were read";
    auto sockets = sdfwb::testing::networkSockets(std::to_string(child));
    kill(child, SIGTERM);
    sdfwb::testing::drain(fds[0]);
    close(fds[0]);
    waitpid(child, &status, 0);
    EXPECT_TRUE(sockets.empty()) << sockets.front();
    // The batch binary loads no Qt, OpenImageIO or FFmpeg at start (they come with its modules,
    // core/Plugins.h), and neither it nor the workbench module links Qt's networking.
    const std::string binary = sharedLibraries(SDFWB_BINARY);
    EXPECT_NE(binary.find("libepoxy"), std::string::npos) << "ldd output looks wrong:\n" << binary;
    for (const char* name : {"libQt6", "libOpenImageIO", "libavcodec"})
        EXPECT_EQ(binary.find(name), std::string::npos) << SDFWB_BINARY << " links " << name << ":\n" << binary;
    EXPECT_NE(sharedLibraries(SDFWB_PLUGIN_DIR "/libsdfwb_media.so").find("libOpenImageIO"), std::string::npos);
#ifdef SDFWB_WITH_GUI
    const std::string workbench = sharedLibraries(SDFWB_PLUGIN_DIR "/libsdfwb_workbench.so");
    EXPECT_NE(workbench.find("libQt6Widgets"), std::string::npos) << "ldd output looks wrong:\n" << workbench;
    EXPECT_EQ(workbench.find("libQt6Network"), std::string::npos);
#endif
    // (libcurl and libssl come with the media module's FFmpeg and OpenImageIO, unused.)
    fs::remove_all(folder);
}
