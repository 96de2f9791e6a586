// Shader storage binding points of the sampling compute stage. Mirrored in C++ by
// renderer/include/renderer/SamplingBindings.h; a unit test checks that the two agree.
#define SDFWB_BINDING_POSITIONS 0
#define SDFWB_BINDING_DISTANCES 1
#define SDFWB_BINDING_GRADIENTS 2
#define SDFWB_BINDING_INPUTS 3
#define SDFWB_BINDING_BAD_ROWS 4
#define SDFWB_BINDING_SORT 8 // after the mesh's 5..7 (shaders::kMesh*Binding)
#define SDFWB_BINDING_CHAIN 9 // the Metropolis chains' states between passes (metropolis_chain.glsl)
