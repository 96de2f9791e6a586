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

namespace sdfwb::shaders {

enum class Stage { Vertex, Fragment, Compute };

// Feature switches, written as `#define NAME VALUE` in name order (so equal sets give equal text).
using FeatureDefines = std::map<std::string, std::string>;

struct ComposedShader {
    Stage stage = Stage::Fragment;
    std::string text;
    SourceMap map;  // source-string number -> file, for diagnostics
};

// Composes the SDF with a stage file (path relative to shaders/). Adds SDFWB_ANIMATED when the SDF
// takes time and SDFWB_COMPAT_<SYMBOL> for each compat symbol it uses.
Expected<ComposedShader> composeSdfShader(const PreparedSdf& sdf, Stage stage, const std::string& stageFile,
                                          const FeatureDefines& features);

// Composes a stage file that needs no SDF (the fullscreen vertex shader).
Expected<ComposedShader> composeBuiltinShader(Stage stage, const std::string& stageFile, const FeatureDefines& features);

const char* stageName(Stage stage);

} // namespace sdfwb::shaders
