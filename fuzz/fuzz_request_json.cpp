// Fuzzes the JSON form of requests (jobs/src/JobJson.cpp: requestFromJson), which reads what
// `sdfwb --batch request`, job-file lines, the workbench's children and Python's sdfwb.run are
// given. Contract: no crash, and every request it accepts survives a round trip unchanged
// (toJson, then requestFromJson again, gives an equal request and the same text).

#include <jobs/JobJson.h>

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>

namespace {

void require(bool condition, const char* what) {
    if (!condition) {
        std::fprintf(stderr, "fuzz_request_json: contract broken: %s\n", what);
        std::abort();
    }
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string text(reinterpret_cast<const char*>(data), size);
    auto request = sdfwb::jobs::requestFromJson(text);
    if (!request) {
        require(!request.error().message.empty(), "a refusal without a message");
        return 0;
    }
    const std::string json = sdfwb::jobs::toJson(*request);
    auto again = sdfwb::jobs::requestFromJson(json);
    require(bool(again), "toJson wrote a request requestFromJson refuses");
    require(*again == *request, "a request changed in a round trip");
    require(sdfwb::jobs::toJson(*again) == json, "the JSON text changed in a round trip");
    return 0;
}
