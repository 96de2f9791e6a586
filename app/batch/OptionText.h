#pragma once
// The text forms of the command line's compound options (--size WxH, --bounds, --shard K/COUNT,
// --plane NX,NY,NZ,OFFSET): parsed here, without CLI11, so CommandLine.cpp keeps to the commands.

#include <values/Requests.h>

#include <cstdint>
#include <optional>
#include <string>

namespace sdfwb::app::detail {

struct Size {
    int width = 0, height = 0;
};

// "640x360" -> 640, 360 (1..16384 each).
std::optional<Size> parseSize(const std::string& text);
// "1.5,2,-3" -> vec3
std::optional<glm::vec3> parseVec3(const std::string& text);
// "MINX,MINY,MINZ,MAXX,MAXY,MAXZ" into two corners; false when malformed or a maximum is not above its minimum.
bool parseBounds(const std::string& text, glm::vec3& low, glm::vec3& high);
// "3/8" -> 3, 8; false unless 0 <= K < COUNT.
bool parseShard(const std::string& text, std::uint32_t& index, std::uint32_t& count);
// "NX,NY,NZ,OFFSET" (dot(N, p) = OFFSET) with a non-zero normal.
std::optional<values::PlaneSpec> parsePlane(const std::string& text);

} // namespace sdfwb::app::detail
