#pragma once
// Subdivision of a mesh whose new vertices are moved onto the exact surface. Private to meshing/.

#include <meshing/Mesh.h>

#include <cstdint>

namespace sdfwb::meshing::detail {

class PointEvaluator;

struct RefineCounts {
    std::uint64_t pointsEvaluated = 0; // field evaluations (each point with its gradient: seven)
    std::uint64_t midpointsKept = 0;   // midpoints left where they were (no usable step onto the surface)
};

// `levels` times: every triangle is cut into four at its edges' midpoints, and each midpoint takes
// one Newton step onto the zero set (f and grad f from `field`, which is the mesher's and cuts by
// its box). A step longer than a quarter of the edge is not taken (a thin wall's other sheet, a
// gradient that vanishes): the midpoint stays. Topology and orientation are kept: a watertight,
// manifold mesh stays so, with 4^levels times the triangles.
// Fails, leaving the mesh as it was, when the result would have more than `triangleLimit` triangles.
Expected<RefineCounts> refineOntoSurface(Mesh& mesh, PointEvaluator& field, int levels, float gradientStep,
                                         std::uint64_t triangleLimit);

} // namespace sdfwb::meshing::detail
