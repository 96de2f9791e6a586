#pragma once
// The GLSL files that ship inside sdfwb (stage files, preludes). They are embedded at build
// time; when $SDFWB_SHADER_DIR names a folder (a development checkout's shaders/), files found
// there win, so shader edits need no rebuild.

#include <core/Expected.h>

#include <string>
#include <string_view>
#include <vector>

namespace sdfwb::shaders {

// Text of a built-in file by its path relative to shaders/ ("tracer/trace.frag").
Expected<std::string> builtinShader(std::string_view relativePath);

// Every embedded path, for tests that check each one compiles.
std::vector<std::string> builtinShaderPaths();

} // namespace sdfwb::shaders
