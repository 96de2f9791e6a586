#include <sampling/SurfaceBox.h>

#include <algorithm>
#include <cmath>
#include <vector>

namespace sdfwb::sampling {

namespace {

constexpr int kSide = 40;

// Where the surface crosses the lattice's edges: between neighbours along an axis whose values
// have opposite signs, the zero of the line through them, in lattice units (x = i + t). A value
// near 0 alone is not enough: a glow's density keeps above 0 and dips near it. `values` holds the
// kSide^3 values, x fastest.
std::vector<std::array<float, 3>> surfaceCrossings(const std::vector<float>& values) {
    auto at = [&](int i, int j, int k) { return values[(std::size_t(k) * kSide + j) * kSide + i]; };
    std::vector<std::array<float, 3>> crossings;
    for (int k = 0; k < kSide; ++k)
        for (int j = 0; j < kSide; ++j)
            for (int i = 0; i < kSide; ++i) {
                const float f = at(i, j, k);
                if (!std::isfinite(f)) continue;
                for (int axis = 0; axis < 3; ++axis) {
                    int n[3] = {i, j, k};
                    if (++n[axis] >= kSide) continue;
                    const float g = at(n[0], n[1], n[2]);
                    if (!std::isfinite(g) || (f < 0.0f) == (g < 0.0f)) continue;
                    std::array<float, 3> zero = {float(i), float(j), float(k)};
                    zero[std::size_t(axis)] += f / (f - g);
                    crossings.push_back(zero);
                }
            }
    return crossings;
}

// The axis across which the crossings form one layer (at most two cells thick) while they reach
// the cube's faces along the other two, or -1.
int floorAxis(const std::array<float, 3>& low, const std::array<float, 3>& high) {
    for (int a = 0; a < 3; ++a) {
        bool across = high[std::size_t(a)] - low[std::size_t(a)] <= 2.0f;
        for (int b = 0; b < 3; ++b)
            if (b != a) across = across && low[std::size_t(b)] < 1.0f && high[std::size_t(b)] > float(kSide - 2);
        if (across) return a;
    }
    return -1;
}

// Whether this larger cube's crossings off `box`'s floor layer (further than two of its cells from
// it) stay off its faces: then they are what stands on the floor, and `box` gets their box.
bool standsOnFloor(SurfaceBox& box, const std::vector<std::array<float, 3>>& surface, float half, float cell) {
    const std::size_t axis = std::size_t(box.floorAxis);
    std::array<float, 3> low{}, high{};
    bool any = false;
    for (const auto& p : surface) {
        std::array<float, 3> world;
        for (std::size_t a = 0; a < 3; ++a) world[a] = -half + cell * p[a];
        if (std::abs(world[axis] - box.floorAt) <= 2.0f * cell) continue;
        // Within two cells of this cube's faces: an endless scene (its surface may skip a coarse
        // lattice's outer layer), or one a larger cube may hold.
        if (p[0] < 2.0f || p[1] < 2.0f || p[2] < 2.0f || p[0] > float(kSide - 3) || p[1] > float(kSide - 3) ||
            p[2] > float(kSide - 3))
            return false;
        for (std::size_t a = 0; a < 3; ++a)
            low[a] = any ? std::min(low[a], world[a]) : world[a], high[a] = any ? std::max(high[a], world[a]) : world[a];
        any = true;
    }
    if (!any) return false;
    for (std::size_t a = 0; a < 3; ++a) low[a] -= cell, high[a] += cell; // as the box, grown by a cell
    low[axis] = std::min(low[axis], box.floorAt), high[axis] = std::max(high[axis], box.floorAt);
    box.onFloor = true, box.onFloorLow = low, box.onFloorHigh = high;
    return true;
}

} // namespace

Expected<std::optional<SurfaceBox>> findSurfaceBox(FieldEvaluator& evaluator, const FieldSettings& settings, float largest,
                                                   FieldRange* range) {
    const std::size_t count = std::size_t(kSide) * kSide * kSide;
    std::vector<float> points(3 * count), values(count);
    std::optional<SurfaceBox> first; // the smallest cube's box, where every cube's touches its faces
    for (float half = 1.0f; half <= largest; half *= 2.0f) {
        const float cell = 2.0f * half / float(kSide - 1);
        for (int k = 0; k < kSide; ++k)
            for (int j = 0; j < kSide; ++j)
                for (int i = 0; i < kSide; ++i) {
                    float* p = &points[3 * ((std::size_t(k) * kSide + j) * kSide + i)];
                    p[0] = -half + cell * float(i), p[1] = -half + cell * float(j), p[2] = -half + cell * float(k);
                }
        auto evaluated = evaluator.evaluate(points.data(), count, values.data(), nullptr, settings);
        if (!evaluated) return evaluated.error();
        if (range && (range->finest == 0.0f || cell < range->finest)) range->finest = cell;
        if (range)
            for (const float f : values) {
                if (!std::isfinite(f)) continue;
                range->least = range->finite ? std::min(range->least, f) : f;
                range->most = range->finite ? std::max(range->most, f) : f;
                range->negative = range->negative || f < 0.0f;
                ++range->finite;
            }
        const std::vector<std::array<float, 3>> surface = surfaceCrossings(values);
        if (surface.empty()) continue;
        SurfaceBox box;
        std::array<float, 3> low = surface.front(), high = surface.front();
        for (const auto& p : surface)
            for (std::size_t a = 0; a < 3; ++a) low[a] = std::min(low[a], p[a]), high[a] = std::max(high[a], p[a]);
        bool touches = false; // the surface may go on beyond this cube
        for (std::size_t a = 0; a < 3; ++a) {
            touches = touches || low[a] < 1.0f || high[a] > float(kSide - 2);
            // Grown by a cell: between the lattice's edges the surface may reach a little further.
            box.low[a] = -half + cell * (low[a] - 1.0f), box.high[a] = -half + cell * (high[a] + 1.0f);
            box.centre[a] = 0.5f * (box.low[a] + box.high[a]);
        }
        for (const auto& p : surface)
            box.radius = std::max(box.radius, std::hypot(-half + cell * p[0] - box.centre[0], -half + cell * p[1] - box.centre[1],
                                                         -half + cell * p[2] - box.centre[2]));
        box.radius += cell;
        box.searched = half;
        box.cell = cell;
        box.points = int(surface.size());
        if (!touches) return std::optional<SurfaceBox>(box);
        if (!first) {
            first = box;
            first->floorAxis = floorAxis(low, high);
            if (first->floorAxis >= 0) first->floorAt = -half + cell * 0.5f * (low[first->floorAxis] + high[first->floorAxis]);
        } else if (first->floorAxis >= 0 && standsOnFloor(*first, surface, half, cell)) {
            return first;
        }
    }
    return first;
}

} // namespace sdfwb::sampling
