#pragma once
// The JSON header of an ISF shader (the Interactive Shader Format of VDMX, Resolume, Millumin and
// editor.isf.video): the first comment of the file, `/*{ "ISFVSN": "2", "INPUTS": [...] }*/`, whose
// INPUTS the host declares as uniforms. Read leniently (a comma too many, comments before it) with
// each value's place in the text, for Parameters.cpp (inputs as parameters) and ForeignHosts.cpp
// (their declarations). Its own reader rather than nlohmann-json: saving a parameter's default
// rewrites DEFAULT in place, which needs each value's offset, and ISF headers in the wild carry
// trailing commas Debian's nlohmann-json (3.11) refuses. Private to shaders/.

#include <cstddef>
#include <string>
#include <vector>

namespace sdfwb::shaders::detail {

struct IsfInput {
    std::string name, type, label; // TYPE: float, long, bool, event, color, point2D, image, audio, audioFFT
    std::vector<double> value;     // DEFAULT: a number (true/false as 1/0) or an array's numbers
    std::vector<double> low, high; // MIN and MAX, likewise (a long's VALUES give both)
    std::size_t nameOffset = 0;    // of NAME's string in the text
    std::size_t valueOffset = 0;   // of DEFAULT's value in the text, and its length (0: none)
    std::size_t valueLength = 0;
};

struct IsfHeader {
    bool found = false;  // the first comment is a JSON object with INPUTS or ISFVSN
    std::size_t end = 0; // the offset just after the comment's `*/`
    std::vector<IsfInput> inputs;
};

IsfHeader readIsfHeader(const std::string& text);

// A Synesthesia scene's scene.json (beside its main.glsl): its CONTROLS, read as ISF's INPUTS are
// (TYPE "slider", "knob smooth", "xy", "color", ...); none where the text is no JSON object.
std::vector<IsfInput> readSceneControls(const std::string& json);

} // namespace sdfwb::shaders::detail
