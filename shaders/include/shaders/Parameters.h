#pragma once
// Parameters: annotated uniforms that become live controls and shape families. Declared in plain
// GLSL that compiles anywhere, the initializer being the default and a trailing comment giving
// the range and presentation:
//     uniform float radius = 0.5;            // @range 0.1 1.0 @step 0.01 @label "Radius"
//     uniform int   count  = 4;              // @range 1 12
//     uniform bool  hollow = false;
//     uniform vec3  tint   = vec3(1, 0.5, 0); // @color
//     uniform vec2  offset = vec2(0.0);       // @range -1 1
//     uniform float scale  = 1.0;            // @range 0.01 100 @log
// Only file-scope `uniform` declarations with an initializer (or with annotations, which then
// need one) are parameters. One parser, pure (no GL, no I/O); problems are diagnostics with the
// file, line and column.

#include <shaders/Diagnostic.h>

#include <array>
#include <optional>
#include <string>
#include <vector>

namespace sdfwb::shaders {

enum class ParameterType { Float, Int, Bool, Vec2, Vec3, Vec4 };

// "float", "int", "bool", "vec2", "vec3", "vec4"
const char* parameterTypeName(ParameterType type);
// 1 for scalars, 2-4 for vectors.
int componentCount(ParameterType type);

struct Parameter {
    std::string name;
    ParameterType type = ParameterType::Float;
    std::array<float, 4> defaultValue{}; // the initializer, per component (bool: 0 or 1)
    std::optional<float> minimum;        // @range, applied to every component
    std::optional<float> maximum;
    std::optional<float> step; // @step
    bool logarithmic = false;  // @log: sliders move in log space (needs minimum > 0)
    bool color = false;        // @color: a vec3/vec4 edited as a colour
    std::string label;         // @label "..."; empty: the name
    int line = 0;              // of the declaration, 1-based
    int column = 0;
};

struct ParameterScan {
    std::vector<Parameter> parameters; // in declaration order
    std::vector<Diagnostic> diagnostics;
};

// Reads the parameters declared in `text` (one file's text; `file` labels the diagnostics).
ParameterScan parseParameters(const std::string& text, const std::string& file);

} // namespace sdfwb::shaders
