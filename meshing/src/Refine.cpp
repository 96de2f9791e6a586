// Refinement onto the surface: on a smooth surface a mesh's error is the sag of its triangles
// between vertices that lie on the surface, about (edge length)^2 x curvature / 8. Halving every
// edge and putting the new vertex on the surface quarters it, for the cost of one field evaluation
// per edge, where a grid of twice the resolution costs eight times the cells.
#include "Refine.h"

#include "PointEvaluator.h"

#include <core/Parallel.h>

#include <glm/geometric.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

namespace sdfwb::meshing::detail {
namespace {

// Each triangle's three edges (edge k joins its vertices k and k+1) as indices into `ends`.
struct Edges {
    std::vector<std::array<std::uint32_t, 2>> ends;
    std::vector<std::array<std::uint32_t, 3>> ofTriangle;
};

// The edges of a mesh by sorting the triangles' sides: an edge shared by triangles gets one index.
Edges findEdges(const Mesh& mesh) {
    const std::size_t triangles = mesh.triangleCount();
    std::vector<std::uint64_t> sides(3 * triangles); // (low vertex, high vertex)
    std::vector<std::uint32_t> order(3 * triangles);
    for (std::size_t t = 0; t < triangles; ++t)
        for (std::size_t k = 0; k < 3; ++k) {
            const std::uint32_t a = mesh.indices[3 * t + k], b = mesh.indices[3 * t + (k + 1) % 3];
            sides[3 * t + k] = (std::uint64_t(std::min(a, b)) << 32) | std::max(a, b);
            order[3 * t + k] = std::uint32_t(3 * t + k);
        }
    std::sort(order.begin(), order.end(), [&](std::uint32_t x, std::uint32_t y) { return sides[x] < sides[y]; });
    Edges edges;
    edges.ofTriangle.resize(triangles);
    for (std::size_t i = 0; i < order.size(); ++i) {
        const std::uint64_t side = sides[order[i]];
        if (i == 0 || side != sides[order[i - 1]])
            edges.ends.push_back({std::uint32_t(side >> 32), std::uint32_t(side & 0xffffffffu)});
        edges.ofTriangle[order[i] / 3][order[i] % 3] = std::uint32_t(edges.ends.size() - 1);
    }
    return edges;
}

// One level: vertex V + e is the midpoint of edge e; edge e's halves become edges 2e (from its
// first end) and 2e + 1, and each triangle t adds the three edges between its midpoints,
// 2E + 3t + k. No search: every index follows from the coarse one. The last level needs no edges.
void split(Mesh& mesh, Edges& edges, bool last) {
    const std::size_t triangles = mesh.triangleCount(), edgeCount = edges.ends.size();
    const auto firstMidpoint = std::uint32_t(mesh.vertices.size());
    mesh.vertices.resize(mesh.vertices.size() + edgeCount);
    Edges fine;
    if (!last) {
        fine.ends.resize(2 * edgeCount + 3 * triangles);
        fine.ofTriangle.resize(4 * triangles);
    }
    std::vector<std::uint32_t> indices(12 * triangles);
    forEachChunk(edgeCount, chunkCount(edgeCount, 16384), [&](std::size_t, std::size_t first, std::size_t end) {
        for (std::size_t e = first; e < end; ++e) {
            const auto [a, b] = edges.ends[e];
            const auto m = std::uint32_t(firstMidpoint + e);
            mesh.vertices[m] = 0.5f * (mesh.vertices[a] + mesh.vertices[b]);
            if (last) continue;
            fine.ends[2 * e] = {a, m};
            fine.ends[2 * e + 1] = {m, b};
        }
    });
    forEachChunk(triangles, chunkCount(triangles, 16384), [&](std::size_t, std::size_t first, std::size_t end) {
        for (std::size_t t = first; t < end; ++t) {
            const std::uint32_t* v = &mesh.indices[3 * t];
            const auto& e = edges.ofTriangle[t];
            const std::uint32_t m[3] = {firstMidpoint + e[0], firstMidpoint + e[1], firstMidpoint + e[2]};
            const std::array<std::uint32_t, 12> children = {v[0], m[0], m[2], v[1], m[1], m[0],
                                                            v[2], m[2], m[1], m[0], m[1], m[2]};
            std::copy(children.begin(), children.end(), indices.begin() + std::ptrdiff_t(12 * t));
            if (last) continue;
            // The half of edge k that touches vertex `corner`.
            auto half = [&](int k, std::uint32_t corner) {
                return std::uint32_t(2 * e[std::size_t(k)] + (edges.ends[e[std::size_t(k)]][0] == corner ? 0 : 1));
            };
            const auto inner = std::uint32_t(2 * edgeCount + 3 * t);
            fine.ends[inner] = {m[0], m[1]};
            fine.ends[inner + 1] = {m[1], m[2]};
            fine.ends[inner + 2] = {m[2], m[0]};
            fine.ofTriangle[4 * t] = {half(0, v[0]), inner + 2, half(2, v[0])};
            fine.ofTriangle[4 * t + 1] = {half(1, v[1]), inner, half(0, v[1])};
            fine.ofTriangle[4 * t + 2] = {half(2, v[2]), inner + 1, half(1, v[2])};
            fine.ofTriangle[4 * t + 3] = {inner, inner + 1, inner + 2};
        }
    });
    mesh.indices = std::move(indices);
    edges = std::move(fine);
}

} // namespace

Expected<RefineCounts> refineOntoSurface(Mesh& mesh, PointEvaluator& field, int levels, float gradientStep,
                                         std::uint64_t triangleLimit) {
    RefineCounts counts;
    if (levels <= 0 || mesh.indices.empty()) return counts;
    const std::uint64_t coarse = mesh.triangleCount();
    const std::uint64_t fine = levels >= 12 ? std::numeric_limits<std::uint64_t>::max() : coarse << (2 * levels);
    if (fine > triangleLimit)
        return makeError("mesh: refine " + std::to_string(levels) + " would cut the " + std::to_string(coarse) +
                         " triangles into " + std::to_string(fine) + ", more than the " + std::to_string(triangleLimit) +
                         " allowed; lower the refine levels or the resolution");
    Edges edges = findEdges(mesh);
    // The gradient at every vertex: evaluated (with f) at the coarse mesh's, then each midpoint's is
    // its edge's mean. The step f / |grad f|^2 along that mean is off the true one by the angle the
    // normal turns over half an edge, a second-order change of a length that is itself second
    // order (the sag): one evaluation per midpoint, not the seven of central differences.
    std::vector<float> points(3 * mesh.vertices.size()), values, evaluated;
    for (std::size_t v = 0; v < mesh.vertices.size(); ++v)
        for (int a = 0; a < 3; ++a) points[3 * v + std::size_t(a)] = mesh.vertices[v][a];
    if (auto ok = field.evaluate(points, values, &evaluated, gradientStep); !ok) return ok.error();
    counts.pointsEvaluated += 7 * mesh.vertices.size();
    std::vector<glm::vec3> gradients(mesh.vertices.size());
    for (std::size_t v = 0; v < gradients.size(); ++v)
        gradients[v] = {evaluated[3 * v], evaluated[3 * v + 1], evaluated[3 * v + 2]};
    // Room for every level's midpoints at once: level k + 1 has 2E + 3T edges.
    std::size_t total = mesh.vertices.size();
    for (std::size_t level = 0, e = edges.ends.size(), t = mesh.triangleCount(); level < std::size_t(levels); ++level) {
        total += e;
        e = 2 * e + 3 * t;
        t *= 4;
    }
    mesh.vertices.reserve(total);
    gradients.reserve(total);
    for (int level = 0; level < levels; ++level) {
        const std::size_t firstMidpoint = mesh.vertices.size(), count = edges.ends.size();
        // Per edge: its length, and 1 - cos of the angle its ends' normals make (about half the angle
        // squared), which bounds how far the mean direction can be from the midpoint's normal.
        std::vector<float> lengths(count), bends(count);
        gradients.resize(firstMidpoint + count);
        for (std::size_t e = 0; e < count; ++e) {
            const auto [a, b] = edges.ends[e];
            lengths[e] = glm::distance(mesh.vertices[a], mesh.vertices[b]);
            // The mean direction with the mean length: two unit normals a turn apart average to a
            // shorter vector, which would stretch the step.
            const float la = glm::length(gradients[a]), lb = glm::length(gradients[b]);
            const glm::vec3 sum = gradients[a] + gradients[b];
            const float ls = glm::length(sum);
            gradients[firstMidpoint + e] = ls > 0.0f ? sum * (0.5f * (la + lb) / ls) : glm::vec3(0.0f);
            bends[e] = la > 0.0f && lb > 0.0f ? 1.0f - glm::dot(gradients[a], gradients[b]) / (la * lb) : 2.0f;
        }
        split(mesh, edges, level + 1 == levels);
        // A step along the edge's mean gradient from f at the midpoint. For a distance field the step
        // along the true normal lands on the surface; along a direction d off it, f where it lands is
        // about step x d^2 / 2. Where that may exceed 1e-5 of the edge (a long step over a tight
        // bend), a second step from f where the first landed. A midpoint whose step would be longer
        // than a quarter of its edge stays.
        std::vector<std::uint32_t> moving(count);
        for (std::size_t e = 0; e < count; ++e) moving[e] = std::uint32_t(e);
        std::uint64_t kept = 0;
        for (int step = 0; step < 2 && !moving.empty(); ++step) {
            points.resize(3 * moving.size());
            for (std::size_t i = 0; i < moving.size(); ++i)
                for (int a = 0; a < 3; ++a) points[3 * i + std::size_t(a)] = mesh.vertices[firstMidpoint + moving[i]][a];
            if (auto ok = field.evaluate(points, values, nullptr); !ok) return ok.error();
            counts.pointsEvaluated += moving.size();
            std::size_t next = 0;
            for (std::size_t i = 0; i < moving.size(); ++i) {
                const std::uint32_t e = moving[i];
                const glm::vec3 g = gradients[firstMidpoint + e];
                const float f = values[i], g2 = glm::dot(g, g);
                const glm::vec3 stepOnto = g * (-f / g2);
                const float length = glm::length(stepOnto);
                if (!std::isfinite(f) || !(g2 > 1e-12f) || !std::isfinite(g2) || !(length <= 0.25f * lengths[e])) {
                    kept += step == 0 ? 1 : 0;
                    continue;
                }
                mesh.vertices[firstMidpoint + e] += stepOnto;
                if (length * bends[e] > 1e-5f * lengths[e]) moving[next++] = e;
            }
            moving.resize(next);
        }
        counts.midpointsKept += kept;
    }
    return counts;
}

} // namespace sdfwb::meshing::detail
