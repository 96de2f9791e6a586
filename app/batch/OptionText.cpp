// The compound options' text forms (OptionText.h).
#include "OptionText.h"

#include <core/Regex.h>

#include <cstdio>
#include <regex>

namespace sdfwb::app::detail {

std::optional<Size> parseSize(const std::string& text) {
    static const std::regex pattern(R"(^\s*(\d{1,5})\s*[xX]\s*(\d{1,5})\s*$)", kLinearRegex);
    std::smatch match;
    if (!std::regex_match(text, match, pattern)) return std::nullopt;
    Size size{std::stoi(match[1].str()), std::stoi(match[2].str())};
    if (size.width < 1 || size.height < 1 || size.width > 16384 || size.height > 16384) return std::nullopt;
    return size;
}

std::optional<glm::vec3> parseVec3(const std::string& text) {
    float x, y, z;
    char tail;
    if (std::sscanf(text.c_str(), " %f , %f , %f %c", &x, &y, &z, &tail) != 3) return std::nullopt;
    return glm::vec3(x, y, z);
}

bool parseBounds(const std::string& text, glm::vec3& low, glm::vec3& high) {
    float v[6];
    char tail;
    if (std::sscanf(text.c_str(), " %f , %f , %f , %f , %f , %f %c", &v[0], &v[1], &v[2], &v[3], &v[4], &v[5], &tail) != 6 ||
        !(v[3] > v[0] && v[4] > v[1] && v[5] > v[2]))
        return false;
    low = {v[0], v[1], v[2]};
    high = {v[3], v[4], v[5]};
    return true;
}

bool parseShard(const std::string& text, std::uint32_t& index, std::uint32_t& count) {
    static const std::regex pattern(R"(^\s*(\d{1,9})\s*/\s*(\d{1,9})\s*$)", kLinearRegex);
    std::smatch match;
    if (!std::regex_match(text, match, pattern)) return false;
    index = std::uint32_t(std::stoul(match[1].str()));
    count = std::uint32_t(std::stoul(match[2].str()));
    return count > 0 && index < count;
}

std::optional<values::PlaneSpec> parsePlane(const std::string& text) {
    values::PlaneSpec plane;
    glm::vec3& n = plane.normal;
    char tail;
    if (std::sscanf(text.c_str(), " %f , %f , %f , %f %c", &n.x, &n.y, &n.z, &plane.offset, &tail) != 4 || n == glm::vec3(0.0f))
        return std::nullopt;
    return plane;
}

} // namespace sdfwb::app::detail
