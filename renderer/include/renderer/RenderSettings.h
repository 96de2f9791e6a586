#pragma once
// GL-free settings that widgets and the CLI edit and the renderer consumes.

#include <glm/vec3.hpp>

#include <optional>
#include <string>
#include <string_view>

namespace sdfwb::renderer {

enum class ShadingMode { Normals };

struct TraceSettings {
    int maxSteps = 256;          // step budget per ray; a ray that runs out counts as a miss
    float stepFactor = 1.0f;     // multiply each step; 1/L for an L-Lipschitz field
    float epsilonScale = 0.5f;   // hit when |f| < epsilonScale * (pixel footprint at the hit distance)
    float boxMargin = 0.05f;     // rays are clipped to [-1-margin, 1+margin]^3 before marching
};

struct ShadingSettings {
    ShadingMode mode = ShadingMode::Normals;
    glm::vec3 background{0.16f, 0.17f, 0.19f};  // linear RGB in [0,1]
};

const char* shadingModeName(ShadingMode mode);
std::optional<ShadingMode> parseShadingMode(std::string_view name);
// "normals" (the names accepted by parseShadingMode, '|'-separated, for help texts)
std::string shadingModeNames();

} // namespace sdfwb::renderer
