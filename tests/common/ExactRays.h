#pragma once
// Primary rays built by the tests themselves (double precision), so that answers computed from
// them do not inherit a mistake of the renderer's own helpers (values::primaryRayDirection).

#include <values/Camera.h>

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include <cmath>

namespace sdfwb::testing {

// The unit direction through the centre of pixel (x, row), rows from the top, of a width x height
// frame: a pinhole camera at `position` looking at `target`, vertical field of view fovY, square
// pixels, `up` made orthogonal to the view.
inline glm::dvec3 pixelRay(const values::Camera& camera, int x, int row, int width, int height) {
    const glm::dvec3 forward = glm::normalize(glm::dvec3(camera.target) - glm::dvec3(camera.position));
    const glm::dvec3 right = glm::normalize(glm::cross(forward, glm::dvec3(camera.up)));
    const glm::dvec3 up = glm::cross(right, forward);
    const double tanHalf = std::tan(double(camera.fovYDegrees) * M_PI / 360.0);
    const double u = ((x + 0.5) / width * 2.0 - 1.0) * tanHalf * width / height;
    const double v = (1.0 - (row + 0.5) / height * 2.0) * tanHalf;
    return glm::normalize(forward + u * right + v * up);
}

} // namespace sdfwb::testing
