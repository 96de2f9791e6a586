#pragma once
// Where sdfwb finds its data (dataset, shader library, samplers) and whether a path stays
// inside a set of allowed roots.

#include <filesystem>
#include <vector>

namespace sdfwb::paths {

// The data root: $SDFWB_DATA_DIR, else <exe>/../share/sdfwb when installed, else the source tree
// this binary was built from. Holds dataset/ and shaders/.
std::filesystem::path dataRoot();

// Folder of the dataset's .glsl files (dataRoot()/dataset).
std::filesystem::path datasetRoot();

// Folder of the shared GLSL helper library that SDFs may #include (dataRoot()/shaders/lib).
std::filesystem::path shaderLibraryRoot();

// True when `path` (after resolving symlinks) lies inside one of `roots`.
bool isInsideRoots(const std::filesystem::path& path, const std::vector<std::filesystem::path>& roots);

} // namespace sdfwb::paths
