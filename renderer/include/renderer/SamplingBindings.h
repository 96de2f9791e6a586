#pragma once
// Shader storage binding points of the sampling compute stage, mirroring
// shaders/sampling/bindings.glsl (a unit test compares the two).

namespace sdfwb::renderer {

inline constexpr int kBindingPositions = 0;
inline constexpr int kBindingDistances = 1;
inline constexpr int kBindingGradients = 2;
inline constexpr int kBindingInputs = 3;
inline constexpr int kBindingBadRows = 4;
inline constexpr int kBindingSort = 8;  // after the mesh's 5..7 (shaders::kMesh*Binding)
inline constexpr int kBindingChain = 9; // the Metropolis chains' states between passes

} // namespace sdfwb::renderer
