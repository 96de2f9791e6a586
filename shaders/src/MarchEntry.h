#pragma once
// How prepareSdf chooses a whole shader's field from its own march (MarchEntry.cpp). Private to
// shaders/.

#include <shaders/SdfSource.h>

#include <string>

namespace sdfwb::shaders::detail {

// The function the march steps by (or the loop's inline field where it steps by several
// together), into `prepared`'s signature, entry source and reason; an error naming the candidates
// on a tie. `stripped`: the resolved text without comments.
void chooseMarchedEntry(PreparedSdf& prepared, const std::string& stripped);
// detectSignature, among overloads only the one with (animated) or without (!animated) the float
// after the point: the march calls `getDist(p)` where `getDist(vec3 p, float radius)` is defined too.
SdfSignature detectSignatureOfForm(const std::string& stripped, const std::string& entry, const std::string& returnTypes,
                                   bool animated);
// Whether `signature` has the form ENTRY(p, time) with a float not named as the time (`float
// map(vec3 p, float s)`): in a whole shader, what its march passes, not the time.
bool floatIsNotTime(const SdfSignature& signature, const std::string& stripped);
// The name of the float after the point of an ENTRY(p, time) signature (empty for others).
std::string timeParameter(const SdfSignature& signature, const std::string& stripped);
// The first march loop that writes its field inline and whose text the wrapper can run.
void chooseInlineField(PreparedSdf& prepared, const std::string& stripped);

} // namespace sdfwb::shaders::detail
