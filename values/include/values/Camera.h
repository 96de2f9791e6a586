#pragma once
// A look-at perspective camera. GL-free: widgets edit it, the renderer consumes it.

#include <glm/vec3.hpp>

namespace sdfwb::values {

struct Camera {
    glm::vec3 position{2.6f, 1.5f, 1.9f}; // front (+X) three-quarter view from above
    glm::vec3 target{0.0f, 0.0f, 0.0f};
    glm::vec3 up{0.0f, 1.0f, 0.0f}; // world up; the basis is re-orthogonalised
    float fovYDegrees = 40.0f;      // vertical field of view
    float nearPlane = 0.01f;        // rays start no closer than this
    float farPlane = 100.0f;        // and end no farther
    bool operator==(const Camera&) const = default;
};

struct CameraBasis {
    glm::vec3 right, up, forward; // orthonormal, right-handed (forward = -Z in view space)
};

// What float32 can resolve in a view. The tracer computes points as (box entry) + s * direction,
// and the entry is rounded at the camera's distance from the origin: positions are known to about
// positionFloor. Hits count within hitTolerance (epsilonScale x a pixel's footprint at the target).
// When the floor reaches half the tolerance the surface shows rounding noise, not geometry.
struct PrecisionFloor {
    float positionFloor = 0.0f; // float32 spacing at max(|camera|, 1): 2^-23 of it
    float hitTolerance = 0.0f;  // at the target distance, for a viewport `heightPixels` tall
    bool exceeded = false;      // positionFloor > hitTolerance / 2
};
PrecisionFloor precisionFloor(const Camera& camera, float epsilonScale, int heightPixels);

// Fails only when position == target or forward is parallel to up; then a fixed basis is used.
CameraBasis cameraBasis(const Camera& camera);

// The unit direction of the primary ray through the centre of pixel (x, row) of a width x height
// frame, rows counted from the top, in double precision: what the tracer's primaryRay() computes
// (for reference intersections in tests and benchmarks).
glm::dvec3 primaryRayDirection(const Camera& camera, int x, int row, int width, int height);

// Orbits `camera` about its target by yaw (around world up) and pitch (clamped short of the poles).
void orbit(Camera& camera, float yawRadians, float pitchRadians);

// Moves the camera towards (factor < 1) or away from (factor > 1) its target.
void dolly(Camera& camera, float factor);

// First-person look: turns the view direction by yaw (around world up) and pitch, keeping the
// position; the target moves, at the same distance.
void turn(Camera& camera, float yawRadians, float pitchRadians);

// First-person move: by (right, up, forward) amounts in the camera's own frame; position and
// target move together.
void fly(Camera& camera, glm::vec3 rightUpForward);

} // namespace sdfwb::values
