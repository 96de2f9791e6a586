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
// need one) are parameters, and uniforms with Fragmentarium's annotations (slider[MIN,DEFAULT,MAX],
// checkbox[BOOL], color[R,G,B]; its `#preset Default` block sets defaults too), and an ISF
// shader's JSON INPUTS (float, long, bool, event, color, point2D). One parser, pure
// (no GL, no I/O); problems are diagnostics with the file, line and column.

#include <core/Expected.h>
#include <shaders/Diagnostic.h>

#include <array>
#include <cstdint>
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
    std::size_t initializerOffset = 0; // the initializer's text in the file (for rewriting defaults)
    std::size_t initializerLength = 0;
    // How the default is written there: a GLSL initializer, or Fragmentarium's annotation after
    // the declaration (`uniform float Scale; slider[-3,3,5]`: the middle value, vectors as
    // `(x,y,z)`) or a line of its `#preset Default` block (`Scale = 2.5`, vectors as `x,y,z`),
    // which overrides the slider), or an ISF header's INPUTS entry (its DEFAULT, JSON: `0.5`,
    // `[0.5, 0.5]`, `true`; none: the initializer's length is 0 and saving leaves it out).
    enum class Syntax : std::uint8_t { Glsl, FragmentariumSlider, FragmentariumPreset, Isf };
    Syntax syntax = Syntax::Glsl;
};

struct ParameterScan {
    std::vector<Parameter> parameters; // in declaration order
    std::vector<Diagnostic> diagnostics;
};

// Reads the parameters declared in `text` (one file's text; `file` labels the diagnostics).
ParameterScan parseParameters(const std::string& text, const std::string& file);

// A value given for a parameter: `--param NAME=VALUE` (vectors as x,y,z; bools true/false), a
// request's "params" object, Python's params= dict. One number fills every component.
struct ParameterValue {
    std::string name;
    std::vector<float> value;
    bool operator==(const ParameterValue&) const = default;
};

// Reads "NAME=VALUE[,VALUE...]" (VALUE: a finite number, true or false); errors quote the text.
Expected<ParameterValue> parseParameterValue(const std::string& text);
// "NAME=V" or "NAME=X,Y,Z" (shortest decimals), the form parseParameterValue reads.
std::string formatParameterValue(const ParameterValue& value);

// One declared parameter's value as the GPU gets it.
struct ParameterSetting {
    std::string name;
    ParameterType type = ParameterType::Float;
    std::array<float, 4> value{};
    bool operator==(const ParameterSetting&) const = default;
};

struct ResolvedParameters {
    std::vector<ParameterSetting> settings; // every declared parameter, in declaration order
    std::vector<std::string> warnings;      // values outside a @range
};

// Every declared parameter with its given value or its default. Errors name the parameter: an
// unknown name (listing the declared ones), a wrong number of components, an int that is not
// whole, a bool other than 0 or 1. A value outside the @range is a warning, not an error.
Expected<ResolvedParameters> resolveParameters(const std::vector<Parameter>& declared, const std::vector<ParameterValue>& given);

// The settings as values, every component of each (for reports, requests and metadata).
std::vector<ParameterValue> valuesOf(const std::vector<ParameterSetting>& settings);

// The values as a JSON object, {"radius":0.3,"count":4,"hollow":false,"tint":[1,0.5,0]}, for
// sample files' metadata; "" when there are none.
std::string parametersJson(const std::vector<ParameterSetting>& settings);

// The GLSL literal of a value: "0.3", "4", "true", "vec3(1, 0.5, 0)".
std::string glslLiteral(ParameterType type, const std::array<float, 4>& value);

// `text` with the initializers of the given parameters replaced by their values ("Save values as
// defaults"); `declared` must come from parseParameters(text, ...).
std::string withDefaults(const std::string& text, const std::vector<Parameter>& declared,
                         const std::vector<ParameterSetting>& values);

// ---- families ----

// `--sweep NAME=FROM:TO:COUNT`: COUNT evenly spaced values from FROM to TO (both included; vectors
// as x,y,z at both ends).
struct ParameterSweep {
    std::string name;
    std::vector<float> from, to;
    int count = 0;
    bool operator==(const ParameterSweep&) const = default;
};
Expected<ParameterSweep> parseParameterSweep(const std::string& text);
std::string formatParameterSweep(const ParameterSweep& sweep);

// The instances of a family: the grid of every sweep (the first varies slowest), or, with
// randomize > 0, that many draws uniform within each ranged parameter's @range (log-uniform for
// @log; bools fair coins; ints whole), deterministic in `seed`. `base` values hold throughout
// (unless swept or drawn). Each instance lists every parameter it sets. Errors name the sweep or
// parameter (unknown name, no @range to draw from, more than 100000 instances).
Expected<std::vector<std::vector<ParameterValue>>> familyInstances(const std::vector<Parameter>& declared,
                                                                   const std::vector<ParameterValue>& base,
                                                                   const std::vector<ParameterSweep>& sweeps,
                                                                   std::uint32_t randomize, std::uint64_t seed);

} // namespace sdfwb::shaders
