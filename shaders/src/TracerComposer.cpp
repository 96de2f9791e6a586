#include <shaders/TracerComposer.h>

namespace sdfwb::shaders {

namespace {
constexpr ShadingMode kModes[] = {ShadingMode::Normals, ShadingMode::Gooch, ShadingMode::Matcap, ShadingMode::Curvature,
                                  ShadingMode::Steps};
}

const char* shadingModeName(ShadingMode mode) {
    switch (mode) {
    case ShadingMode::Normals:
        return "normals";
    case ShadingMode::Gooch:
        return "gooch";
    case ShadingMode::Matcap:
        return "matcap";
    case ShadingMode::Curvature:
        return "curvature";
    case ShadingMode::Steps:
        return "steps";
    }
    return "?";
}

std::optional<ShadingMode> parseShadingMode(std::string_view name) {
    for (ShadingMode mode : kModes)
        if (name == shadingModeName(mode)) return mode;
    return std::nullopt;
}

std::string shadingModeNames() {
    std::string names;
    for (ShadingMode mode : kModes) names += (names.empty() ? "" : "|") + std::string(shadingModeName(mode));
    return names;
}

bool meshRaycastApplies(const PreparedSdf& sdf, const TracerFeatures& features) {
    return features.meshRaycast && sdf.mesh && sdf.meshIsTheField && !features.probe && !features.statsOutput &&
           features.shading != ShadingMode::Steps;
}

bool computeTracerApplies(const TracerFeatures& features) {
    return !features.cuttingPlane && !features.cones && !features.probe && !features.statsOutput;
}

Expected<ComposedShader> composeTracer(const PreparedSdf& sdf, const TracerFeatures& features) {
    FeatureDefines defines;
    std::string mode = shadingModeName(features.shading);
    std::string upper;
    for (char c : mode) upper += char(std::toupper(static_cast<unsigned char>(c)));
    defines["SDFWB_SHADING_" + upper] = "1";
    std::vector<std::string> files = {"common/geometry.glsl", "tracer/trace_core.glsl", "tracer/shading_" + mode + ".glsl",
                                      "tracer/trace_main.frag"};
    // The heat map shows tracing cost only: no lighting terms.
    if (features.ambientOcclusion && features.shading != ShadingMode::Steps) {
        defines["SDFWB_AO"] = "1";
        files.insert(files.end() - 1, "tracer/ao.glsl");
    }
    if (features.overRelaxation) defines["SDFWB_OVERRELAX"] = "1";
    if (features.stepFactor) defines["SDFWB_STEP_FACTOR"] = "1";
    if (features.fusedMarch) defines["SDFWB_FUSED_MARCH"] = "1";
    if (features.unrolledTaps && !features.fusedMarch) defines["SDFWB_UNROLLED_TAPS"] = "1";
    const bool meshRaycast = meshRaycastApplies(sdf, features);
    if (meshRaycast) defines["SDFWB_MESH_RAYCAST"] = "1";
    if (features.cones && !meshRaycast && !features.probe && features.shading != ShadingMode::Steps) defines["SDFWB_CONES"] = "1";
    if (features.cuttingPlane) {
        defines["SDFWB_PLANE"] = "1";
        if (features.planeClipsSurface) defines["SDFWB_PLANE_CLIP"] = "1";
        // A mesh's own field is a distance by construction (its sign jumps over an open mesh's
        // holes are hatched): the plane reads it from the texture and has no slope overlay.
        if (meshRaycast)
            defines["SDFWB_PLANE_FIELD"] = "1";
        else if (features.planeLipschitzOverlay)
            defines["SDFWB_PLANE_LIPSCHITZ"] = "1";
        files.insert(files.end() - 1, "tracer/plane.glsl");
    }
    if (features.statsOutput) defines["SDFWB_OUTPUT_STATS"] = "1";
    if (features.markers && !features.statsOutput) {
        defines["SDFWB_MARKERS"] = "1";
        files.insert(files.end() - 1, "tracer/markers.glsl");
    }
    if (features.backgroundImage && !features.statsOutput && features.shading != ShadingMode::Steps)
        defines["SDFWB_BACKGROUND_IMAGE"] = "1";
    if (features.probe) {
        defines["SDFWB_PROBE"] = "1";
        files.insert(files.begin(), "tracer/probe.glsl");
    }
    const bool compute = features.compute && computeTracerApplies(features);
    if (compute) defines["SDFWB_COMPUTE"] = "1";
    std::vector<ShaderPiece> pieces;
    for (const std::string& file : files) {
        auto piece = builtinPiece(file);
        if (!piece) return piece.error();
        pieces.push_back(std::move(*piece));
    }
    return composeSdfShader(sdf, compute ? Stage::Compute : Stage::Fragment, pieces, defines);
}

Expected<ComposedShader> composeTracerVertex() { return composeBuiltinShader(Stage::Vertex, "tracer/trace.vert", {}); }

} // namespace sdfwb::shaders
