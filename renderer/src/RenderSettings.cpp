#include <renderer/RenderSettings.h>

namespace sdfwb::renderer {

const char* shadingModeName(ShadingMode mode) {
    switch (mode) {
    case ShadingMode::Normals: return "normals";
    }
    return "?";
}

std::optional<ShadingMode> parseShadingMode(std::string_view name) {
    for (ShadingMode mode : {ShadingMode::Normals})
        if (name == shadingModeName(mode)) return mode;
    return std::nullopt;
}

std::string shadingModeNames() {
    std::string names;
    for (ShadingMode mode : {ShadingMode::Normals}) {
        if (!names.empty()) names += "|";
        names += shadingModeName(mode);
    }
    return names;
}

} // namespace sdfwb::renderer
