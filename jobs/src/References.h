#pragma once
// Reference implementations in double precision for the benchmarks: exact distances and
// gradients of a sphere and a torus, and the exact first intersection of a ray with them.

#include <glm/vec3.hpp>

#include <optional>

namespace sdfwb::bench {

struct Shape {
    enum Kind { Sphere, Torus } kind;
    double major; // sphere: radius; torus: distance from the centre to the tube's axis
    double minor; // torus: tube radius (unused for the sphere)
};

// Signed distance and its gradient (unit length wherever it is defined).
double distance(const Shape& shape, const glm::dvec3& p);
glm::dvec3 gradient(const Shape& shape, const glm::dvec3& p);

// First t > 0 with origin + t direction on the surface (direction unit), to ~1e-12: closed form
// for the sphere; for the torus, sphere tracing in double on its exact distance, which converges
// to the first root (steps never cross the surface) and stops at |f| < 1e-12.
std::optional<double> intersect(const Shape& shape, const glm::dvec3& origin, const glm::dvec3& direction);

} // namespace sdfwb::bench
