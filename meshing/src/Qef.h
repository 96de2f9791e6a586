#pragma once
// The QEF of dual contouring: where a cell's vertex goes from its crossings and their normals
// (DualContouring.cpp).

#include <glm/vec3.hpp>

#include <array>
#include <cstdint>

namespace sdfwb::meshing::detail {

// The point minimising sum (n . (x - p))^2 nearest the mass point: a pseudo-inverse that drops
// directions the normals do not constrain (a flat face constrains one, an edge two, a corner three).
// `free` holds the dropped directions: every point + span(free) minimises the sum as well.
struct QefSolution {
    glm::dvec3 point{0.0};
    glm::dvec3 mass{0.0}; // the crossings' mean
    std::array<glm::dvec3, 3> free{};
    int freeCount = 0;
};

QefSolution solveQef(const glm::dvec3* points, const glm::dvec3* normals, int count);

// The part [t0, t1] of the line p + t d inside the box [lo, hi]; false when it misses the box.
bool clipLine(const glm::dvec3& p, const glm::dvec3& d, const glm::dvec3& lo, const glm::dvec3& hi, double& t0, double& t1);

// Where a cell's vertex goes. The QEF's minimiser when it lies in the cell. A sharp edge (one free
// direction) is a line of minimisers: the point of that line nearest the minimiser inside the cell,
// else inside the cell grown by `margin` on every side (an edge that passes just beside the cell,
// whose two faces the cell's crossings see: clamping would pull the vertex off the edge by up to
// the margin). A corner (no free direction) within the margin goes there too, also when the cell it
// lies in has a vertex of its own: that cell may see only two of the corner's faces and put its
// vertex on their edge, and clamping this one left the corner cut off (a rotated box at 32^3: a
// Hausdorff distance of 0.1 cell; placed, 40x less). Anything else is clamped into the cell. `left` counts vertices placed
// outside their cell, `clamped` those moved off their QEF's minimisers.
glm::dvec3 placeVertex(const QefSolution& qef, const glm::dvec3& lo, const glm::dvec3& hi, double margin, std::uint64_t& left,
                       std::uint64_t& clamped);

} // namespace sdfwb::meshing::detail
