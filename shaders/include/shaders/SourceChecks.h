#pragma once
// Checks on an SDF's files that catch, at the user's own line, what would otherwise surface as a
// confusing driver error in the composed shader (or not at all): bytes that are not ASCII outside
// comments, a main() of its own, and definitions of names with the reserved prefix `sdfwb_` (any
// letter case): every name the workbench adds to a composed shader carries it, so that prefix is the
// only thing a user file may not define (`map`, `hash`, `iTime`, `PI`, ... are the user's).

#include <shaders/Diagnostic.h>
#include <shaders/IncludeResolver.h>

#include <vector>

namespace sdfwb::shaders {

std::vector<Diagnostic> checkSourceFiles(const ResolvedSource& source);

} // namespace sdfwb::shaders
