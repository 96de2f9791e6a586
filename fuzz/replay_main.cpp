// Replays fuzz inputs through a harness without libFuzzer: the normal (gcc) build links each
// harness with this main into a test that feeds it every file of its seed corpus and of its
// crashes/ folder (inputs that once broke a parser and are pinned as regressions).
//
//   fuzz_<harness> DIR_OR_FILE...
//
// A missing folder counts as empty (crashes/<harness>/ exists only once a bug was fixed), but
// the run fails when no input at all was found, so a wrong corpus path cannot pass silently.
// A broken contract aborts inside the harness, which fails the test.

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size);

namespace fs = std::filesystem;

int main(int argc, char** argv) {
    std::vector<fs::path> inputs;
    for (int i = 1; i < argc; ++i) {
        const fs::path argument(argv[i]);
        std::error_code ec;
        if (fs::is_directory(argument, ec)) {
            for (const fs::directory_entry& entry : fs::recursive_directory_iterator(argument))
                if (entry.is_regular_file()) inputs.push_back(entry.path());
        } else if (fs::is_regular_file(argument, ec)) {
            inputs.push_back(argument);
        }
    }
    std::sort(inputs.begin(), inputs.end());
    if (inputs.empty()) {
        std::fprintf(stderr, "replay: no input files under the given paths\n");
        return 1;
    }
    for (const fs::path& input : inputs) {
        std::ifstream file(input, std::ios::binary);
        if (!file) {
            std::fprintf(stderr, "replay: cannot read %s\n", input.c_str());
            return 1;
        }
        const std::string bytes((std::istreambuf_iterator<char>(file)), std::istreambuf_iterator<char>());
        std::fprintf(stderr, "replay: %s (%zu bytes)\n", input.c_str(), bytes.size());
        LLVMFuzzerTestOneInput(reinterpret_cast<const std::uint8_t*>(bytes.data()), bytes.size());
    }
    std::fprintf(stderr, "replay: %zu inputs, no contract broken\n", inputs.size());
    return 0;
}
