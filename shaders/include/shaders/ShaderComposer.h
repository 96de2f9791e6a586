#pragma once
// Builds the GLSL string handed to glslang and the driver:
//   #version 430 core, feature defines, the G3D compat prelude (only the parts the SDF uses),
//   the SDF with includes expanded and #line-mapped, then the stage file (tracer, sampler, ...).
// Features that are off are not compiled in: the stage files test the defines with #ifdef.
// Pure function: no GL, no I/O beyond reading built-in shader files.

#include <core/Expected.h>
#include <shaders/SdfSource.h>
#include <shaders/SourceMap.h>

#include <map>
#include <string>
#include <vector>

namespace sdfwb::shaders {

enum class Stage { Vertex, Fragment, Compute };

// Feature switches, written as `#define NAME VALUE` in name order (so equal sets give equal text).
using FeatureDefines = std::map<std::string, std::string>;

struct ComposedShader {
    Stage stage = Stage::Fragment;
    std::string text;
    SourceMap map;  // source-string number -> file, for diagnostics
};

// A piece of GLSL composed after the SDF: a helper file, a sampler, the stage's main().
struct ShaderPiece {
    std::string name;  // shown in diagnostics ("sdfwb:samplers/rand.glsl", or a user's path)
    std::string text;
};

// Composes the SDF followed by `pieces` in order. Adds SDFWB_ANIMATED when the SDF takes time,
// SDFWB_USES_TIME when it needs a time value, and SDFWB_COMPAT_<SYMBOL> for each compat symbol.
ComposedShader composeSdfShader(const PreparedSdf& sdf, Stage stage, const std::vector<ShaderPiece>& pieces,
                                const FeatureDefines& features);

// Loads a built-in file as a piece named "sdfwb:<path>".
Expected<ShaderPiece> builtinPiece(const std::string& relativePath);

// Composes the SDF with a stage file (path relative to shaders/). Adds SDFWB_ANIMATED when the SDF
// takes time and SDFWB_COMPAT_<SYMBOL> for each compat symbol it uses.
Expected<ComposedShader> composeSdfShader(const PreparedSdf& sdf, Stage stage, const std::string& stageFile,
                                          const FeatureDefines& features);

// Composes a stage file that needs no SDF (the fullscreen vertex shader).
Expected<ComposedShader> composeBuiltinShader(Stage stage, const std::string& stageFile, const FeatureDefines& features);

const char* stageName(Stage stage);

} // namespace sdfwb::shaders
