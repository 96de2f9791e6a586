// Fuzzes the job-file reader (app/batch/CommandLine.cpp: splitWords, the line checks and every
// step's option parsing) through checkJobFile, which stops where the work would start: no GL,
// no dataset scan, nothing written. The input is the job file's text.

#include <batch/CommandLine.h>

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>

namespace {

void require(bool condition, const char* what) {
    if (!condition) {
        std::fprintf(stderr, "fuzz_job_file: contract broken: %s\n", what);
        std::abort();
    }
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string text(reinterpret_cast<const char*>(data), size);
    const int exitCode = sdfwb::app::checkJobFile(text, "fuzz.job");
    require(exitCode == 0 || exitCode == 2, "an exit code other than 0 or 2 from parsing alone");
    return 0;
}
