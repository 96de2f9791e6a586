#pragma once
// A scratch path of the test process's own, for the test files that write files.

#include <filesystem>
#include <string>
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

} // namespace sdfwb::testing
