#pragma once
// A scratch path of the test process's own, for the test files that write files.

#include <filesystem>
#include <linux/magic.h>
#include <optional>
#include <string>
#include <sys/vfs.h>
#include <unistd.h>

namespace sdfwb::testing {

// `name` in a folder of this test process's own under the temporary folder (ctest -j runs a
// binary's cases side by side, and a case that looks for partial files must not see another
// case's), the folder created.
inline std::filesystem::path scratchPath(const std::string& suite, const std::string& name) {
    const std::filesystem::path folder =
        std::filesystem::temp_directory_path() / ("sdfwb-" + suite + "-test-" + std::to_string(::getpid()));
    std::filesystem::create_directories(folder);
    return folder / name;
}

// The same under /dev/shm, where files lie in memory (tmpfs); empty where /dev/shm is not a tmpfs.
inline std::optional<std::filesystem::path> memoryScratchPath(const std::string& suite, const std::string& name) {
    struct statfs system {};
    if (::statfs("/dev/shm", &system) != 0 || system.f_type != TMPFS_MAGIC) return std::nullopt;
    const std::filesystem::path folder =
        std::filesystem::path("/dev/shm") / ("sdfwb-" + suite + "-test-" + std::to_string(::getpid()));
    std::filesystem::create_directories(folder);
    return folder / name;
}

} // namespace sdfwb::testing
