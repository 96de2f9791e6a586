#pragma once
// Builds the GLSL string handed to glslang and the driver:
//   #version 430 core, feature defines (and `uniform float sdfwb_time` when the SDF needs time),
//   the compat prelude (only the parts the SDF uses), the SDF with includes expanded and
//   #line-mapped, the entry wrapper `float sdfwb_sdf(vec3)` followed by an #undef of every macro
//   the SDF defined, then the stage pieces (tracer, sampler, ...), which call sdfwb_sdf() only.
// Every name the workbench adds carries the prefix sdfwb_ (SDFWB_ for macros): the user's names
// cannot clash with them, and the user's macros cannot reach them.
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

// Texture unit of the G3D noise texture g3d_uniformRandom (SDFWB_NOISE_TEXTURE_UNIT in GLSL); the
// matcap uses unit 0.
constexpr int kNoiseTextureUnit = 7;
// Texture unit of Shadertoy's iChannel0; iChannel1..3 follow it (SDFWB_CHANNEL0_UNIT.. in GLSL).
constexpr int kChannelTextureUnit = 8;
// Shader storage binding points of a mesh SDF's buffers (shaders/mesh/mesh_field.glsl); the
// samplers use 0..4, the probe 4.
constexpr int kMeshPseudonormalsBinding = 5;
constexpr int kMeshNodesBinding = 6;
constexpr int kMeshTrianglesBinding = 7;

// Feature switches, written as `#define NAME VALUE` in name order (so equal sets give equal text).
using FeatureDefines = std::map<std::string, std::string>;

struct ComposedShader {
    Stage stage = Stage::Fragment;
    std::string text;
    SourceMap map; // source-string number -> file, for diagnostics
};

// A piece of GLSL composed after the SDF: a helper file, a sampler, the stage's main().
struct ShaderPiece {
    std::string name; // shown in diagnostics ("sdfwb:samplers/rand.glsl", or a user's path)
    std::string text;
};

// `float sdfwb_sdf(vec3 p)` calling the SDF's entry point (with sdfwb_time when it takes time,
// .x of a vector return), then `#undef NAME` for each macro the SDF defines.
std::string entryWrapper(const PreparedSdf& sdf);

// Composes the SDF followed by `pieces` in order. Adds SDFWB_ANIMATED when the SDF takes time,
// SDFWB_USES_TIME when it needs a time value, and SDFWB_COMPAT_<SYMBOL> for each compat symbol.
ComposedShader composeSdfShader(const PreparedSdf& sdf, Stage stage, const std::vector<ShaderPiece>& pieces,
                                const FeatureDefines& features);

// Loads a built-in file as a piece named "sdfwb:<path>".
Expected<ShaderPiece> builtinPiece(const std::string& relativePath);

// The compute sampling stage's pieces around a sampler (or an analysis file), in order: the
// bindings, the geometry the tracer shares (common/geometry.glsl), the samplers' helpers, the
// Metropolis chain when the sampler calls sdfwb_metropolisChain, the sampler, the stage's main().
Expected<std::vector<ShaderPiece>> samplingStagePieces(const ShaderPiece& sampler);

// Composes the SDF with a stage file (path relative to shaders/). Adds SDFWB_ANIMATED when the SDF
// takes time and SDFWB_COMPAT_<SYMBOL> for each compat symbol it uses.
Expected<ComposedShader> composeSdfShader(const PreparedSdf& sdf, Stage stage, const std::string& stageFile,
                                          const FeatureDefines& features);

// Composes a stage file that needs no SDF (the fullscreen vertex shader).
Expected<ComposedShader> composeBuiltinShader(Stage stage, const std::string& stageFile, const FeatureDefines& features);

const char* stageName(Stage stage);

} // namespace sdfwb::shaders
