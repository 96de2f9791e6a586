#pragma once
// Loops a driver would cut short. Mesa's llvmpipe (the CPU renderer used when there is no GPU)
// ends every loop after 65535 iterations and says nothing: a field that sums 200000 terms is
// silently wrong. What can be seen in the code is found here: a `for` loop whose counter starts,
// stops and steps by constants (glslang's syntax tree of the composed shader), run more times
// than the driver allows. Loops with a `break` may end earlier; the warning says "up to".

#include <shaders/Diagnostic.h>
#include <shaders/SdfSource.h>
#include <shaders/ShaderComposer.h>

#include <cstdint>
#include <string_view>
#include <vector>

namespace sdfwb::shaders {

constexpr std::uint64_t kLlvmpipeLoopLimit = 65535;

// Warnings at the user's file and line for each constant-count loop of `shader` (composed from
// `sdf`) that runs more than `limit` times (nothing when the shader does not parse: its errors are
// reported elsewhere). Only SDFs with a number of 32768 or more in their own files are parsed: no
// constant loop of theirs can run longer otherwise, and most SDFs pay nothing.
std::vector<Diagnostic> findLongLoops(const PreparedSdf& sdf, const ComposedShader& shader, std::uint64_t limit,
                                      std::string_view driver);

// The loop limit of the GL renderer named `rendererString` (GL_RENDERER), 0 when none is known.
std::uint64_t loopLimitOf(std::string_view rendererString);

// Whether any file of the SDF holds a number of at least 32768 (an integer of 5 digits or more, or
// an exponent of 5 or more; signs and the digits of a fraction do not count): findLongLoops parses
// the shader only then, since a loop cannot reach the limit without such a number.
bool hasLargeNumber(const PreparedSdf& sdf);

// The limit of the renderer this process draws with: set by the renderer module when it meets
// its GL context, read by the editor's checks (0 until then, or when the driver has none).
void setDriverLoopLimit(std::uint64_t limit);
std::uint64_t driverLoopLimit();

} // namespace sdfwb::shaders
