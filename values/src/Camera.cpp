#include <values/Camera.h>

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include <algorithm>
#include <cmath>

namespace sdfwb::values {

PrecisionFloor precisionFloor(const Camera& camera, float epsilonScale, int heightPixels) {
    PrecisionFloor floor;
    const float magnitude =
        std::max({std::abs(camera.position.x), std::abs(camera.position.y), std::abs(camera.position.z), 1.0f});
    floor.positionFloor = std::ldexp(magnitude, -23);
    const float pixelAngle = 2.0f * std::tan(glm::radians(camera.fovYDegrees) / 2.0f) / float(std::max(heightPixels, 1));
    floor.hitTolerance = epsilonScale * pixelAngle * glm::length(camera.target - camera.position);
    floor.exceeded = floor.positionFloor > 0.5f * floor.hitTolerance;
    return floor;
}

glm::dvec3 primaryRayDirection(const Camera& camera, int x, int row, int width, int height) {
    const CameraBasis basis = cameraBasis(camera);
    const double tanHalf = std::tan(glm::radians(double(camera.fovYDegrees)) / 2.0);
    const double u = ((x + 0.5) / width * 2.0 - 1.0) * double(width) / height * tanHalf;
    const double v = ((height - 1 - row + 0.5) / height * 2.0 - 1.0) * tanHalf; // GL rows count from the bottom
    return glm::normalize(glm::dvec3(basis.forward) + u * glm::dvec3(basis.right) + v * glm::dvec3(basis.up));
}

CameraBasis cameraBasis(const Camera& camera) {
    glm::vec3 forward = camera.target - camera.position;
    float length = glm::length(forward);
    forward = length > 0.0f ? forward / length : glm::vec3(0.0f, 0.0f, -1.0f);
    glm::vec3 right = glm::cross(forward, camera.up);
    if (glm::length(right) < 1e-6f) right = glm::cross(forward, glm::vec3(1.0f, 0.0f, 0.0f));
    right = glm::normalize(right);
    glm::vec3 up = glm::cross(right, forward);
    return {right, up, forward};
}

void orbit(Camera& camera, float yawRadians, float pitchRadians) {
    glm::vec3 offset = camera.position - camera.target;
    float radius = glm::length(offset);
    if (radius <= 0.0f) return;
    float yaw = std::atan2(offset.x, offset.z) + yawRadians;
    float pitch = std::asin(std::clamp(offset.y / radius, -1.0f, 1.0f)) + pitchRadians;
    const float limit = glm::radians(89.0f);
    pitch = std::clamp(pitch, -limit, limit);
    camera.position =
        camera.target + radius * glm::vec3(std::cos(pitch) * std::sin(yaw), std::sin(pitch), std::cos(pitch) * std::cos(yaw));
}

void dolly(Camera& camera, float factor) {
    glm::vec3 offset = camera.position - camera.target;
    float radius = std::clamp(glm::length(offset) * factor, 0.05f, 1000.0f);
    camera.position = camera.target + glm::normalize(offset) * radius;
}

void turn(Camera& camera, float yawRadians, float pitchRadians) {
    glm::vec3 offset = camera.target - camera.position;
    float distance = glm::length(offset);
    if (distance <= 0.0f) return;
    glm::vec3 direction = offset / distance;
    float yaw = std::atan2(direction.x, direction.z) + yawRadians;
    const float limit = glm::radians(89.0f);
    float pitch = std::clamp(std::asin(std::clamp(direction.y, -1.0f, 1.0f)) + pitchRadians, -limit, limit);
    direction = glm::vec3(std::cos(pitch) * std::sin(yaw), std::sin(pitch), std::cos(pitch) * std::cos(yaw));
    camera.target = camera.position + distance * direction;
}

void fly(Camera& camera, glm::vec3 rightUpForward) {
    CameraBasis basis = cameraBasis(camera);
    glm::vec3 move =
        rightUpForward.x * basis.right + rightUpForward.y * glm::vec3(0.0f, 1.0f, 0.0f) + rightUpForward.z * basis.forward;
    camera.position += move;
    camera.target += move;
}

} // namespace sdfwb::values
