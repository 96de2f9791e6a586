#pragma once
// Where a field's surface lies, found by its values: for framing a GLSL field whose surface is not
// in [-1, 1]^3 (a pasted Shadertoy scene built around its own camera), as --normalize frames a mesh.

#include <core/Expected.h>
#include <sampling/FieldEvaluator.h>

#include <array>
#include <cstddef>
#include <optional>

namespace sdfwb::sampling {

struct SurfaceBox {
    std::array<float, 3> low{}, high{}; // the box of where the surface crosses the lattice, grown by a cell
    std::array<float, 3> centre{};      // the box's centre
    float radius = 0.0f;                // the farthest crossing from the centre, plus a cell
    float searched = 0.0f;              // the half side of the cube the points were found in
    float cell = 0.0f;                  // that cube's lattice spacing
    int points = 0;                     // the crossings (lattice edges the surface cuts)
    // A floor: where this (smallest) cube's crossings are one layer across it, perpendicular to axis
    // `floorAxis` at `floorAt` (-1: none), and a larger cube holds surface away from that layer that
    // stays off its faces (objects standing on a floor outside [-1, 1]^3, as in many tutorials' scenes):
    // that surface's box, reaching to the floor's level.
    int floorAxis = -1;
    float floorAt = 0.0f;
    bool onFloor = false;
    std::array<float, 3> onFloorLow{}, onFloorHigh{};
};

// The values the search's lattices held (finite ones): a field with no surface is told apart by
// them (never negative and near 0 somewhere: an unsigned distance; otherwise no surface at all).
struct FieldRange {
    float least = 0.0f, most = 0.0f;
    bool negative = false; // some value below 0
    std::size_t finite = 0;
    // The finest lattice's spacing: every point of its cube lies within sqrt(3)/2 of it from a
    // lattice point, so a distance that stays above that there has no zero in the cube.
    float finest = 0.0f;
};

// Cubes centred at the origin of half side 1, 2, 4, ... 64, each on a 40^3 lattice (values only),
// and in each where the surface crosses the lattice's edges: the zero between neighbours whose values
// have opposite signs (a glow's density, above 0 everywhere, has none).
// The first cube whose crossings stay off its faces gives the box (a bounded scene seen whole); where
// every cube's crossings reach its faces (a floor, an endless repetition), the smallest cube with any,
// and where that is a floor, what stands on it (SurfaceBox::onFloor).
// None (nullopt): no surface in the largest cube (a glow's density, a field never 0). `largest`
// (a power of 2) bounds the cubes: 1 asks only whether the surface crosses [-1, 1]^3. `evaluator`
// is built with the field; a current GL context is needed.
// `range`, when given, gets the values of every lattice searched.
Expected<std::optional<SurfaceBox>> findSurfaceBox(FieldEvaluator& evaluator, const FieldSettings& settings,
                                                   float largest = 64.0f, FieldRange* range = nullptr);

} // namespace sdfwb::sampling
