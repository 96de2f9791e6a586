#pragma once
// An SDF as the rest of the program sees it: its text with includes expanded, which signature
// it defines, which parts of the G3D compat prelude it needs, and the problems found so far.

#include <shaders/Diagnostic.h>
#include <shaders/IncludeResolver.h>

#include <filesystem>
#include <string>
#include <vector>

namespace sdfwb::shaders {

struct SdfSignature {
    bool found = false;     // a definition of sdf(vec3) or sdf(vec3, float) exists
    bool animated = false;  // sdf(vec3 p, float time)
};

// Symbols of the original sdf-explorer's G3D dialect that the text uses without declaring them.
// Each becomes a `#define SDFWB_COMPAT_<NAME>` that selects a section of prelude/g3d_compat.glsl.
struct CompatNeeds {
    std::vector<std::string> symbols;  // e.g. "pi", "saturate", "float3", "g3d_SceneTime"
    bool any() const { return !symbols.empty(); }
    bool usesSceneTime() const;
};

struct PreparedSdf {
    ResolvedSource source;
    SdfSignature signature;
    CompatNeeds compat;
    std::vector<Diagnostic> diagnostics;  // resolver errors + a missing/ill-typed sdf()

    bool ok() const { return !hasErrors(diagnostics); }
    // Needs a time value each frame: sdf(vec3, float) or the G3D scene time uniform.
    bool usesTime() const { return signature.animated || compat.usesSceneTime(); }
};

// Returns `text` with comments replaced by spaces (newlines kept, so line numbers still match).
std::string stripComments(const std::string& text);

SdfSignature detectSignature(const std::string& strippedText);

// "name(type a, type b)" for every function defined in `text` (for autocompletion and call tips).
std::vector<std::string> functionSignatures(const std::string& text);
CompatNeeds detectCompatNeeds(const std::string& strippedText);

// Resolves includes and analyses the text. `name` labels diagnostics for the root text; `path`
// may be empty for unsaved text.
PreparedSdf prepareSdf(const std::string& text, const std::string& name, const std::filesystem::path& path,
                       const IncludeOptions& options);

// Reads `path` and prepares it; an unreadable file gives a diagnostic naming it.
PreparedSdf prepareSdfFile(const std::filesystem::path& path, const IncludeOptions& options);

} // namespace sdfwb::shaders
