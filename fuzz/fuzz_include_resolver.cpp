// Fuzzes the include resolver and the SDF analysis after it (shaders/src/IncludeResolver.cpp,
// shaders/src/SdfSource.cpp): #include lines, #pragma once, comments, odd bytes, and the
// detection of the sdf() signature, the G3D compat symbols and the function signatures. The root
// text is also read as a user sampler file (sampling/src/SamplerLibrary.cpp: samplePosition()).
//
// The input is up to five files separated by lines holding only `%%`: the root text (passed
// as unsaved editor text whose path is root/main.glsl), then lib/f1.glsl .. lib/f4.glsl, which
// are written to a private temporary folder before each run so the fuzzer can build include
// graphs. Fixed files sit beside them: root/shape.glsl (#pragma once), root/sub/up.glsl
// (includes ../shape.glsl), lib/chain1.glsl .. chain5.glsl (a chain deeper than the maxDepth
// of 4 used here) and outside.glsl, which lies outside the allowed roots.

#include <sampling/SamplerLibrary.h>
#include <shaders/SdfSource.h>

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <string_view>
#include <vector>

#include <unistd.h>

namespace fs = std::filesystem;
using namespace sdfwb::shaders;

namespace {

void require(bool condition, const char* what) {
    if (!condition) {
        std::fprintf(stderr, "fuzz_include_resolver: contract broken: %s\n", what);
        std::abort();
    }
}

void writeFile(const fs::path& path, std::string_view text) {
    std::ofstream(path, std::ios::binary | std::ios::trunc).write(text.data(), std::streamsize(text.size()));
}

struct Workspace {
    fs::path folder;

    Workspace() {
        std::string pattern = (fs::temp_directory_path() / "sdfwb-fuzz-include-XXXXXX").string();
        require(::mkdtemp(pattern.data()) != nullptr, "cannot create the temporary folder");
        folder = pattern;
        fs::create_directories(folder / "root" / "sub");
        fs::create_directories(folder / "lib");
        writeFile(folder / "root" / "shape.glsl", "#pragma once\nfloat shape(vec3 p) { return length(p) - 0.5; }\n");
        writeFile(folder / "root" / "sub" / "up.glsl",
                  "#include \"../shape.glsl\"\nfloat up(vec3 p) { return shape(p - vec3(0, 1, 0)); }\n");
        for (int i = 1; i <= 5; ++i)
            writeFile(folder / "lib" / ("chain" + std::to_string(i) + ".glsl"),
                      i < 5 ? "#include \"chain" + std::to_string(i + 1) + ".glsl\"\n" : std::string("float chainEnd;\n"));
        writeFile(folder / "outside.glsl", "float secret;\n");
    }
    ~Workspace() {
        std::error_code ec;
        fs::remove_all(folder, ec);
    }
};

Workspace& workspace() {
    static Workspace instance;
    return instance;
}

// Splits at lines that hold only "%%".
std::vector<std::string> splitFiles(const std::string& input) {
    std::vector<std::string> files(1);
    std::size_t start = 0;
    while (start <= input.size()) {
        std::size_t end = input.find('\n', start);
        std::string_view line = std::string_view(input).substr(start, end == std::string::npos ? std::string::npos : end - start);
        if (line == "%%" && files.size() < 5)
            files.emplace_back();
        else {
            files.back() += line;
            if (end != std::string::npos) files.back() += '\n';
        }
        if (end == std::string::npos) break;
        start = end + 1;
    }
    return files;
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const Workspace& space = workspace();
    const std::vector<std::string> files = splitFiles(std::string(reinterpret_cast<const char*>(data), size));
    for (int i = 1; i <= 4; ++i) {
        const fs::path path = space.folder / "lib" / ("f" + std::to_string(i) + ".glsl");
        if (std::size_t(i) < files.size())
            writeFile(path, files[std::size_t(i)]);
        else {
            std::error_code ec;
            fs::remove(path, ec);
        }
    }

    IncludeOptions options;
    options.libraryRoots = {space.folder / "lib"};
    options.maxDepth = 4;
    const std::string& root = files[0];
    PreparedSdf prepared = prepareSdf(root, "<fuzz>", space.folder / "root" / "main.glsl", options);

    const ResolvedSource& source = prepared.source;
    require(source.text.rfind("#line 1 0\n", 0) == 0, "the expanded text does not start with #line 1 0");
    // Another host's shader is read in sdfwb's terms (shaders/src/ForeignHosts.h), line for line.
    auto lineCount = [](const std::string& text) { return std::count(text.begin(), text.end(), '\n'); };
    require(!source.map.files.empty() && (prepared.host.empty() ? source.map.files[0].text == root
                                                                : lineCount(source.map.files[0].text) == lineCount(root)),
            "files[0] is not the root text (or, read as another host's, has other lines)");
    for (const Diagnostic& diagnostic : prepared.diagnostics) {
        require(!diagnostic.message.empty(), "a diagnostic without a message");
        if (diagnostic.line < 1) std::fprintf(stderr, "%s\n", formatDiagnostic(diagnostic).c_str());
        require(diagnostic.line >= 1, "a diagnostic before line 1");
        (void)source.map.lineText(0, diagnostic.line);
        (void)formatDiagnostic(diagnostic);
    }
    for (int index = -1; index <= int(source.map.files.size()); ++index) (void)source.map.fileName(index);
    require(prepared.ok() == !hasErrors(prepared.diagnostics), "ok() disagrees with the diagnostics");

    (void)functionSignatures(root);
    require(stripComments(root).size() == root.size(), "stripComments changed the text's length");

    const fs::path samplerPath = space.folder / "root" / "sampler.glsl";
    writeFile(samplerPath, root);
    auto sampler = sdfwb::sampling::findSampler(samplerPath.string(), {});
    if (!sampler)
        require(sampler.error().message.rfind(samplerPath.string() + ":", 0) == 0, "a sampler error does not name the file");
    return 0;
}
