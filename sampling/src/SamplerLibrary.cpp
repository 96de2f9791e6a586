#include <sampling/SamplerLibrary.h>

#include <core/Paths.h>
#include <core/Regex.h>
#include <core/TextFile.h>
#include <shaders/BuiltinShaders.h>
#include <shaders/SdfSource.h>

#include <cstdlib>
#include <regex>
#include <sstream>

namespace sdfwb::sampling {
namespace fs = std::filesystem;

const std::vector<std::string>& builtinPatterns() {
    static const std::vector<std::string> patterns = {"grid",    "image", "jitter",     "rand",
                                                      "surface", "near",  "metropolis", "metropolis_curvature"};
    return patterns;
}

std::vector<fs::path> samplerFolders() {
    std::vector<fs::path> folders;
    if (const char* list = std::getenv("SDFWB_SAMPLER_PATH"); list && *list) {
        std::stringstream stream(list);
        std::string folder;
        while (std::getline(stream, folder, ':'))
            if (!folder.empty()) folders.emplace_back(folder);
    }
    if (const char* data = std::getenv("XDG_DATA_HOME"); data && *data)
        folders.push_back(fs::path(data) / "sdfwb" / "samplers");
    else if (const char* home = std::getenv("HOME"); home && *home)
        folders.push_back(fs::path(home) / ".local" / "share" / "sdfwb" / "samplers");
    return folders;
}

namespace {

Expected<shaders::ShaderPiece> checked(shaders::ShaderPiece piece) {
    static const std::regex definition(R"(\bbool\s+samplePosition\s*\(\s*(in\s+)?uint\s+\w+\s*,\s*out\s+vec3\s+\w+\s*\)\s*\{)",
                                       kLinearRegex);
    if (!std::regex_search(shaders::stripComments(piece.text), definition))
        return makeError(piece.name + ": not a sampler: it must define `bool samplePosition(uint index, out vec3 position)`");
    return piece;
}

} // namespace

Expected<shaders::ShaderPiece> findSampler(const std::string& pattern, const std::vector<fs::path>& folders) {
    std::error_code ec;
    if (pattern.find('/') != std::string::npos || pattern.ends_with(".glsl")) {
        if (!fs::is_regular_file(pattern, ec)) return makeError("'" + pattern + "': no such sampler file");
        auto text = readTextFile(pattern);
        if (!text) return text.error();
        return checked({pattern, std::move(*text)});
    }
    for (const std::string& name : builtinPatterns()) {
        if (name != pattern) continue;
        auto piece = shaders::builtinPiece("samplers/" + name + ".glsl");
        if (!piece) return piece.error();
        return checked(std::move(*piece));
    }
    for (const fs::path& folder : folders) {
        fs::path candidate = folder / (pattern + ".glsl");
        if (!fs::is_regular_file(candidate, ec)) continue;
        // A name looks only inside the sampler folders: a symlink out of them is refused (an
        // explicit path, above, is the user's own choice).
        if (!paths::isInsideRoots(candidate, {folder}))
            return makeError("'" + pattern + "': " + candidate.string() + " leads outside the sampler folder " + folder.string() +
                             " (a symlink?); refused");
        auto text = readTextFile(candidate);
        if (!text) return text.error();
        return checked({candidate.string(), std::move(*text)});
    }
    std::string names;
    for (const std::string& name : builtinPatterns()) names += (names.empty() ? "" : ", ") + name;
    return makeError("'" + pattern + "': unknown pattern (built-in: " + names + "; or a path to a sampler .glsl file)");
}

} // namespace sdfwb::sampling
