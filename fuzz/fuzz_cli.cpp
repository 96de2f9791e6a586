// Fuzzes sdfwb's command line (app/batch/CommandLine.cpp) through checkCommandLine, which
// parses and validates exactly as the real run does (CLI11 options of every batch command, the
// --sample form, sizes, vectors, planes, shards) and stops where the work would start: no GL,
// no dataset scan, nothing written. The input holds one argument per line (argv[1..]).

#include <batch/CommandLine.h>

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

namespace {

void require(bool condition, const char* what) {
    if (!condition) {
        std::fprintf(stderr, "fuzz_cli: contract broken: %s\n", what);
        std::abort();
    }
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string input(reinterpret_cast<const char*>(data), size);
    std::vector<std::string> arguments;
    for (std::size_t start = 0; start < input.size();) {
        std::size_t end = input.find('\n', start);
        if (end == std::string::npos) end = input.size();
        arguments.push_back(input.substr(start, end - start));
        start = end + 1;
    }
    const std::optional<int> exitCode = sdfwb::app::checkCommandLine(arguments);
    // 0 (would run, or help), 2 (bad arguments); nullopt only for the workbench's [FILE] form.
    if (exitCode)
        require(*exitCode == 0 || *exitCode == 2, "an exit code other than 0 or 2 from parsing alone");
    else
        require(arguments.size() <= 1, "the workbench was chosen for more than one argument");
    return 0;
}
