#pragma once
// --normalize for a GLSL field (jobs::openSdf): the frame (shaders::PreparedSdf::frame) a box
// gives, or the box of the field's surface found by its values (sampling/SurfaceBox.h).

#include <jobs/Jobs.h>

#include <optional>
#include <string>
#include <vector>

namespace sdfwb::jobs {

// Whether `normalize` is a box X0,Y0,Z0,X1,Y1,Z1 rather than a word (none, unit-cube, unit-sphere).
bool isFrameBox(const std::string& normalize);

// What is wrong with a box `normalize` (six finite numbers, each low below its high), for the key
// 'normalize'; nullopt when it is a good box.
std::optional<std::string> frameBoxProblem(const std::string& normalize);

// frameField (jobs/Jobs.h) frames the GLSL field as `normalize` asks: nothing for "none"; a box:
// its longest side onto [-1, 1], centred; unit-cube or unit-sphere: the surface's box (its longest
// side onto [-1, 1]) or the sphere round its centre that holds it (onto the unit sphere), found at
// time 0 with the parameters.

} // namespace sdfwb::jobs
