#pragma once
// Waiting on a child process's output instead of sleeping: read its pipe until a text appears or a
// deadline passes (poll with a timeout, so a silent child cannot hang the test).

#include <chrono>
#include <string>

#include <poll.h>
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

} // namespace sdfwb::testing
