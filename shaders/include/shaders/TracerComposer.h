#pragma once
// Composes the sphere tracer's fragment shader for one scene. Only the pieces a scene uses are
// composed: the shading mode's file, ao.glsl when ambient occlusion is on, over-relaxation when
// asked; a scene without a feature has none of its code in the source the driver sees.

#include <core/Expected.h>
#include <shaders/ShaderComposer.h>

#include <optional>
#include <string>
#include <string_view>

namespace sdfwb::shaders {

enum class ShadingMode { Normals, Gooch, Matcap, Curvature, Steps };

const char* shadingModeName(ShadingMode mode);
std::optional<ShadingMode> parseShadingMode(std::string_view name);
std::string shadingModeNames(); // "normals|gooch|matcap|curvature|steps"

struct TracerFeatures {
    ShadingMode shading = ShadingMode::Normals;
    bool ambientOcclusion = false;
    bool overRelaxation = false;
    bool stepFactor = false;  // a step factor other than 1 (sdfwb_stepFactor scales every step)
    bool statsOutput = false; // write (steps, t, |f(hit)|) instead of a colour (benchmarks, tests)
    bool cuttingPlane = false;
    bool planeClipsSurface = false; // cut the shape away on the side the plane's normal points to
    bool planeLipschitzOverlay = false;
    bool markers = false;         // ring marked points (markers.glsl)
    bool probe = false;           // record one ray's march into a storage buffer (probe.glsl, the march debugger)
    bool backgroundImage = false; // misses show an image (sdfwb_backgroundImage) instead of the colour
    // March and normal in one loop around one call of the SDF (sdfwb_traceWithNormal): a third of
    // the driver's code generation and faster frames for heavy SDFs; slower for the cheapest.
    bool fusedMarch = false;
    // The normal's taps as a loop with a constant count (unrolled by the driver: one copy of the
    // SDF per tap): faster frames for the tiniest SDFs, whose copies cost code generation little.
    bool unrolledTaps = false;
    // A cone pass per tile of pixels first finds where their marches may start (trace_core.glsl,
    // SDFWB_CONES): fewer steps per pixel for a texture fetch per pixel and a second draw. Not
    // with the march debugger or the step heat map, which show a pixel's own march.
    bool cones = false;
    // A mesh's own field drawn by one walk of its hierarchy a pixel (trace_core.glsl's
    // sdfwb_meshTrace) instead of a march; see meshRaycastApplies. Off: the sphere tracer, for
    // benchmarks (SDFWB_MESH_TRACE=march).
    bool meshRaycast = true;
    // The compute tracer: the same tracer in a compute shader over 8x8 tiles of pixels, written
    // into an image (trace_main.frag, SDFWB_COMPUTE). Only where computeTracerApplies.
    bool compute = false;
};

// Whether the compute tracer can draw a frame with these features: not the cutting plane (its
// lines are anti-aliased by screen-space derivatives, which compute shaders do not have), the
// cone pass (a second draw into the target), the march debugger or the statistics output (the
// fragment tracer's own outputs).
bool computeTracerApplies(const TracerFeatures& features);

// Whether the picture of `sdf` is drawn by the mesh walk: a mesh's own field (not a text over it),
// and not the march debugger, the step heat map or the statistics output, which show a march.
// The cone pass does not apply then.
bool meshRaycastApplies(const PreparedSdf& sdf, const TracerFeatures& features);

Expected<ComposedShader> composeTracer(const PreparedSdf& sdf, const TracerFeatures& features);

// The tracer's vertex stage (a full-screen triangle).
Expected<ComposedShader> composeTracerVertex();

} // namespace sdfwb::shaders
