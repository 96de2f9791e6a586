#pragma once
// Sampling patterns are GLSL files that define `bool samplePosition(uint index, out vec3 position)`.
// The 8 built-in ones are embedded from shaders/samplers/; users add their own by dropping a
// .glsl file into a samplers folder or by passing its path.

#include <core/Expected.h>
#include <shaders/ShaderComposer.h>

#include <filesystem>
#include <string>
#include <vector>

namespace sdfwb::sampling {

// grid, image, jitter, rand, surface, near, metropolis, metropolis_curvature
const std::vector<std::string>& builtinPatterns();

// Folders searched for user patterns: each entry of $SDFWB_SAMPLER_PATH (':'-separated), then
// $XDG_DATA_HOME/sdfwb/samplers (default ~/.local/share/sdfwb/samplers).
std::vector<std::filesystem::path> samplerFolders();

// <Pattern>: a path to a .glsl file, a built-in name, or the name of a file in a samplers folder.
// Fails when nothing matches or the file defines no samplePosition().
Expected<shaders::ShaderPiece> findSampler(const std::string& pattern, const std::vector<std::filesystem::path>& folders);

} // namespace sdfwb::sampling
