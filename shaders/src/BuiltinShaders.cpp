#include <shaders/BuiltinShaders.h>
#include <shaders/EmbeddedFiles.h>

#include <core/TextFile.h>

#include <cstdlib>
#include <filesystem>

namespace sdfwb::shaders {

Expected<std::string> builtinShader(std::string_view relativePath) {
    if (const char* overrideDir = std::getenv("SDFWB_SHADER_DIR"); overrideDir && *overrideDir) {
        std::filesystem::path candidate = std::filesystem::path(overrideDir) / std::string(relativePath);
        std::error_code ec;
        if (std::filesystem::is_regular_file(candidate, ec)) return readTextFile(candidate);
    }
    for (const detail::EmbeddedFile& file : detail::embeddedFiles())
        if (file.path == relativePath) return std::string(file.text);
    return makeError("shaders: no built-in shader named '" + std::string(relativePath) + "'");
}

std::vector<std::string> builtinShaderPaths() {
    std::vector<std::string> paths;
    for (const detail::EmbeddedFile& file : detail::embeddedFiles()) paths.emplace_back(file.path);
    return paths;
}

} // namespace sdfwb::shaders
