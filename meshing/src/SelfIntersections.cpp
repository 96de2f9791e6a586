// Pairs of triangles that cross each other without sharing a vertex, found through a uniform grid
// of the triangles' bounding boxes (see Mesh.h).
#include <meshing/Mesh.h>

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <unordered_map>
#include <vector>

namespace sdfwb::meshing {
namespace {

using Triangle = std::array<glm::dvec3, 3>;

// Whether the segment a-b meets the triangle's interior or boundary (Moller-Trumbore with the
// segment's parameter in [0, 1]); a segment in the triangle's plane does not count here: two
// coplanar triangles that overlap are caught by their other edges only when they also cross.
bool segmentMeetsTriangle(const glm::dvec3& a, const glm::dvec3& b, const Triangle& t) {
    const glm::dvec3 direction = b - a, e1 = t[1] - t[0], e2 = t[2] - t[0];
    const glm::dvec3 p = glm::cross(direction, e2);
    const double determinant = glm::dot(e1, p);
    const double scale = glm::length(direction) * glm::length(e1) * glm::length(e2);
    if (!(std::abs(determinant) > 1e-12 * scale)) return false;
    const double inverse = 1.0 / determinant;
    const glm::dvec3 s = a - t[0];
    const double u = glm::dot(s, p) * inverse;
    if (u < 0.0 || u > 1.0) return false;
    const glm::dvec3 q = glm::cross(s, e1);
    const double v = glm::dot(direction, q) * inverse;
    if (v < 0.0 || u + v > 1.0) return false;
    const double along = glm::dot(e2, q) * inverse;
    return along >= 0.0 && along <= 1.0;
}

bool trianglesCross(const Triangle& x, const Triangle& y) {
    for (int e = 0; e < 3; ++e) {
        if (segmentMeetsTriangle(x[std::size_t(e)], x[std::size_t((e + 1) % 3)], y)) return true;
        if (segmentMeetsTriangle(y[std::size_t(e)], y[std::size_t((e + 1) % 3)], x)) return true;
    }
    return false;
}

} // namespace

std::uint64_t countSelfIntersections(const Mesh& mesh) {
    const std::size_t count = mesh.indices.size() / 3;
    if (count < 2) return 0;
    std::vector<Triangle> triangles(count);
    std::vector<glm::dvec3> low(count), high(count);
    glm::dvec3 all0(std::numeric_limits<double>::max()), all1(-std::numeric_limits<double>::max());
    double edgeSum = 0.0;
    for (std::size_t t = 0; t < count; ++t) {
        for (int c = 0; c < 3; ++c)
            triangles[t][std::size_t(c)] = glm::dvec3(mesh.vertices[mesh.indices[3 * t + std::size_t(c)]]);
        low[t] = glm::min(triangles[t][0], glm::min(triangles[t][1], triangles[t][2]));
        high[t] = glm::max(triangles[t][0], glm::max(triangles[t][1], triangles[t][2]));
        all0 = glm::min(all0, low[t]);
        all1 = glm::max(all1, high[t]);
        edgeSum += glm::length(triangles[t][1] - triangles[t][0]);
    }
    // Cells about two mean edges wide: a triangle's box covers a few of them.
    const double cell = std::max(2.0 * edgeSum / double(count), 1e-9);
    auto cellOf = [&](const glm::dvec3& p) { return glm::ivec3(glm::floor((p - all0) / cell)); };
    auto key = [](const glm::ivec3& c) {
        return (std::uint64_t(std::uint32_t(c.x)) << 42) ^ (std::uint64_t(std::uint32_t(c.y)) << 21) ^
               std::uint64_t(std::uint32_t(c.z));
    };
    std::unordered_map<std::uint64_t, std::vector<std::uint32_t>> cells;
    cells.reserve(count * 2);
    for (std::size_t t = 0; t < count; ++t) {
        const glm::ivec3 c0 = cellOf(low[t]), c1 = cellOf(high[t]);
        for (int z = c0.z; z <= c1.z; ++z)
            for (int y = c0.y; y <= c1.y; ++y)
                for (int x = c0.x; x <= c1.x; ++x) cells[key({x, y, z})].push_back(std::uint32_t(t));
    }
    std::uint64_t crossings = 0;
    for (const auto& [cellKey, members] : cells)
        for (std::size_t i = 0; i < members.size(); ++i)
            for (std::size_t j = i + 1; j < members.size(); ++j) {
                const std::uint32_t a = members[i], b = members[j];
                // Boxes apart, or a pair seen in another cell: each pair is tested in the cell
                // that holds the low corner of the two boxes' overlap, once.
                const glm::dvec3 overlapLow = glm::max(low[a], low[b]), overlapHigh = glm::min(high[a], high[b]);
                if (glm::any(glm::greaterThan(overlapLow, overlapHigh))) continue;
                if (key(cellOf(overlapLow)) != cellKey) continue;
                bool shared = false;
                for (int p = 0; p < 3 && !shared; ++p)
                    for (int q = 0; q < 3 && !shared; ++q)
                        shared = mesh.indices[3 * a + std::size_t(p)] == mesh.indices[3 * b + std::size_t(q)];
                if (shared) continue; // neighbours meet at their shared vertex or edge
                crossings += trianglesCross(triangles[a], triangles[b]);
            }
    return crossings;
}

} // namespace sdfwb::meshing
