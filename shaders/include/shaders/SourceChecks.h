#pragma once
// Checks on an SDF's files that catch, at the user's own line, what would otherwise surface as a
// confusing driver error in the composed shader (or not at all): bytes that are not ASCII outside
// comments, a main() of its own, and functions, uniforms or structs whose names the workbench's
// shaders (tracer, samplers) define as well.

#include <shaders/Diagnostic.h>
#include <shaders/IncludeResolver.h>

#include <vector>

namespace sdfwb::shaders {

std::vector<Diagnostic> checkSourceFiles(const ResolvedSource& source);

} // namespace sdfwb::shaders
