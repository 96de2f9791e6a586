#include "References.h"

#include <glm/geometric.hpp>

#include <cmath>

namespace sdfwb::bench {

double distance(const Shape& shape, const glm::dvec3& p) {
    if (shape.kind == Shape::Sphere) return glm::length(p) - shape.major;
    const double ring = std::sqrt(p.x * p.x + p.z * p.z) - shape.major;
    return std::sqrt(ring * ring + p.y * p.y) - shape.minor;
}

glm::dvec3 gradient(const Shape& shape, const glm::dvec3& p) {
    if (shape.kind == Shape::Sphere) return glm::normalize(p);
    // From the nearest point of the tube's axis circle towards p.
    const double planar = std::sqrt(p.x * p.x + p.z * p.z);
    const glm::dvec3 axisPoint =
        planar > 0.0 ? glm::dvec3(p.x, 0.0, p.z) * (shape.major / planar) : glm::dvec3(shape.major, 0.0, 0.0);
    return glm::normalize(p - axisPoint);
}

std::optional<double> intersect(const Shape& shape, const glm::dvec3& origin, const glm::dvec3& direction) {
    if (shape.kind == Shape::Sphere) {
        const double b = glm::dot(origin, direction);
        const double c = glm::dot(origin, origin) - shape.major * shape.major;
        const double discriminant = b * b - c;
        if (discriminant < 0.0) return std::nullopt;
        const double t = -b - std::sqrt(discriminant);
        return t > 0.0 ? std::optional<double>(t) : std::nullopt;
    }
    double t = 0.0;
    for (int step = 0; step < 100000; ++step) {
        const double d = distance(shape, origin + t * direction);
        if (d < 1e-12) return t;
        t += d;
        if (t > 100.0) break;
    }
    return std::nullopt;
}

} // namespace sdfwb::bench
