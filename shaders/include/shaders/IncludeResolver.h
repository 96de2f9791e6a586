#pragma once
// Expands `#include "file"` in GLSL text, since GL drivers do not. Quoted paths are looked up
// relative to the including file's folder, then in each library root. Resolved files must lie
// inside the allowed roots (symlinks resolved); missing files, cycles, escapes and too-deep
// chains are diagnostics at the #include line. `#version` lines are blanked (the composer
// writes its own), `#extension` lines are blanked and kept for the composer to place after its
// `#version` (GLSL ES ones, GL_OES_* and GL_EXT_*, are dropped: core GLSL 4.30 has what they add)
// and `#pragma once` is honoured. Line numbers stay mapped with `#line L F`.

#include <shaders/Diagnostic.h>
#include <shaders/SourceMap.h>

#include <filesystem>
#include <string>
#include <vector>

namespace sdfwb::shaders {

struct IncludeOptions {
    // Folders includes may be read from. The root file's own folder is added automatically.
    std::vector<std::filesystem::path> libraryRoots;
    int maxDepth = 32; // longest include chain accepted
};

struct ResolvedSource {
    std::string text;                    // expanded text; starts with `#line 1 0`
    SourceMap map;                       // files[0] is the root text
    std::vector<Diagnostic> diagnostics; // resolver errors (missing, cycle, escape, depth)
    std::vector<std::string> extensions; // `#extension NAME : BEHAVIOR` lines to write after #version
};

// `name` is shown in diagnostics for the root text; `path` (may be empty for unsaved text) gives
// the folder that relative includes start from.
ResolvedSource resolveIncludes(const std::string& text, const std::string& name, const std::filesystem::path& path,
                               const IncludeOptions& options);

} // namespace sdfwb::shaders
