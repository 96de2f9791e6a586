// Fuzzes the dataset's `/* sdfwb ... */` metadata parser (dataset/src/Metadata.cpp), which reads
// the head of every .glsl file in the dataset folder and of any file the user opens. Errors must
// name the file and a line inside the text; accepted blocks must have a name.

#include <dataset/Metadata.h>

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>

namespace {

void require(bool condition, const char* what) {
    if (!condition) {
        std::fprintf(stderr, "fuzz_metadata: contract broken: %s\n", what);
        std::abort();
    }
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string text(reinterpret_cast<const char*>(data), size);
    const std::string fileName = "fuzz.glsl";
    auto metadata = sdfwb::dataset::parseMetadata(text, fileName);
    if (!metadata) {
        const std::string& message = metadata.error().message;
        require(message.rfind(fileName + ":", 0) == 0, "the error does not start with the file name");
        // "fuzz.glsl:LINE: ..." with 1 <= LINE <= the text's line count.
        const std::size_t colon = message.find(':', fileName.size() + 1);
        require(colon != std::string::npos, "the error has no line number");
        const long line = std::strtol(message.c_str() + fileName.size() + 1, nullptr, 10);
        const long lines = 1 + long(std::count(text.begin(), text.end(), '\n'));
        require(line >= 1 && line <= lines, "the error's line number is outside the text");
        return 0;
    }
    require(!metadata->name.empty(), "accepted metadata without a name");
    require(sdfwb::dataset::declaredTypeName(metadata->type)[0] != '?', "accepted an unknown type");
    return 0;
}
