#pragma once
// Waiting on a child process's output instead of sleeping: read its pipe until a text appears or a
// deadline passes (poll with a timeout, so a silent child cannot hang the test).

#include <array>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

#include <poll.h>
#include <sys/wait.h>
#include <unistd.h>

namespace sdfwb::testing {

// Reads `fd` until `text` has appeared, the pipe closes (the child ended) or `limit` passes.
// Returns everything read; the caller checks whether it holds `text`.
inline std::string readUntil(int fd, const std::string& text, std::chrono::seconds limit) {
    std::string read;
    const auto deadline = std::chrono::steady_clock::now() + limit;
    while (read.find(text) == std::string::npos && std::chrono::steady_clock::now() < deadline) {
        pollfd readable{fd, POLLIN, 0};
        if (poll(&readable, 1, 1000) <= 0) continue;
        char buffer[512];
        const ssize_t n = ::read(fd, buffer, sizeof buffer);
        if (n <= 0) break;
        read.append(buffer, std::size_t(n));
    }
    return read;
}

// Reads and drops the rest of `fd` until it closes, so a child never blocks on a full pipe.
inline void drain(int fd) {
    char buffer[512];
    while (::read(fd, buffer, sizeof buffer) > 0) {}
}

inline std::string readBytes(const std::filesystem::path& path) {
    std::ifstream in(path, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), {});
}

struct RunResult {
    int exitCode = -1;
    std::string output;         // stdout, then stderr
    std::string standardOutput; // stdout alone: what a caller parses (a sanitizer's exit report goes to stderr)
};

// Runs `binary arguments` through the shell without a display and waits for it to end.
inline RunResult runCommand(const std::string& binary, const std::string& arguments) {
    char errorPath[] = "/tmp/sdfwb-run-stderr-XXXXXX";
    const int errorFile = mkstemp(errorPath);
    RunResult result;
    if (errorFile < 0) return result;
    ::close(errorFile);
    const std::string command = "env -u DISPLAY " + binary + " " + arguments + " 2>" + errorPath;
    FILE* pipe = popen(command.c_str(), "r");
    if (pipe) {
        std::array<char, 4096> buffer;
        while (std::size_t n = std::fread(buffer.data(), 1, buffer.size(), pipe)) result.standardOutput.append(buffer.data(), n);
        const int status = pclose(pipe);
        result.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    }
    result.output = result.standardOutput + readBytes(errorPath);
    std::filesystem::remove(errorPath);
    return result;
}

} // namespace sdfwb::testing
