// Dual contouring (Ju et al. 2002) on a grid whose values come from the GPU: blocks of 8^3 cells
// that a Lipschitz bound proves empty are skipped; in the others, every cell the surface crosses
// gets one vertex, the minimiser of a QEF built from the edge crossings and the field's normals
// there (so the vertex sits on sharp edges and corners, where marching cubes cuts them); every
// grid edge with a sign change becomes a quad joining the vertices of its four cells.
#include <meshing/Mesh.h>

#include "FieldProbe.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <functional>
#include <limits>
#include <unordered_map>

namespace sdfwb::meshing {
namespace {

constexpr int kBlock = 8;

// Eigen-decomposition of a symmetric 3x3 matrix by Jacobi rotations.
void symmetricEigen(std::array<std::array<double, 3>, 3> a, std::array<double, 3>& values,
                    std::array<std::array<double, 3>, 3>& vectors) {
    vectors = {{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}};
    for (int sweep = 0; sweep < 32; ++sweep) {
        const double off = a[0][1] * a[0][1] + a[0][2] * a[0][2] + a[1][2] * a[1][2];
        if (off < 1e-22) break;
        for (int p = 0; p < 2; ++p)
            for (int q = p + 1; q < 3; ++q) {
                if (std::abs(a[p][q]) < 1e-30) continue;
                const double theta = (a[q][q] - a[p][p]) / (2.0 * a[p][q]);
                const double t = (theta >= 0 ? 1.0 : -1.0) / (std::abs(theta) + std::sqrt(theta * theta + 1.0));
                const double c = 1.0 / std::sqrt(t * t + 1.0), s = t * c;
                for (int k = 0; k < 3; ++k) { // a = J^T a J
                    const double akp = a[k][p], akq = a[k][q];
                    a[k][p] = c * akp - s * akq;
                    a[k][q] = s * akp + c * akq;
                }
                for (int k = 0; k < 3; ++k) {
                    const double apk = a[p][k], aqk = a[q][k];
                    a[p][k] = c * apk - s * aqk;
                    a[q][k] = s * apk + c * aqk;
                }
                for (int k = 0; k < 3; ++k) {
                    const double vkp = vectors[k][p], vkq = vectors[k][q];
                    vectors[k][p] = c * vkp - s * vkq;
                    vectors[k][q] = s * vkp + c * vkq;
                }
            }
    }
    for (int i = 0; i < 3; ++i) values[std::size_t(i)] = a[std::size_t(i)][std::size_t(i)];
}

// The point minimising sum (n . (x - p))^2 nearest the mass point: a pseudo-inverse that drops
// directions the normals do not constrain (a flat face constrains one, an edge two, a corner three).
glm::dvec3 solveQef(const std::vector<glm::dvec3>& points, const std::vector<glm::dvec3>& normals) {
    glm::dvec3 mass(0.0);
    for (const glm::dvec3& p : points) mass += p;
    mass /= double(points.size());
    std::array<std::array<double, 3>, 3> ata{};
    glm::dvec3 atb(0.0);
    for (std::size_t i = 0; i < points.size(); ++i) {
        const glm::dvec3& n = normals[i];
        const double d = glm::dot(n, points[i] - mass);
        for (int r = 0; r < 3; ++r) {
            for (int c = 0; c < 3; ++c) ata[std::size_t(r)][std::size_t(c)] += n[r] * n[c];
            atb[r] += n[r] * d;
        }
    }
    std::array<double, 3> values{};
    std::array<std::array<double, 3>, 3> vectors{};
    symmetricEigen(ata, values, vectors);
    const double largest = std::max({std::abs(values[0]), std::abs(values[1]), std::abs(values[2])});
    glm::dvec3 x(0.0);
    for (int k = 0; k < 3; ++k) {
        if (largest <= 0.0 || std::abs(values[std::size_t(k)]) < 0.1 * largest) continue; // unconstrained direction
        glm::dvec3 v(vectors[0][std::size_t(k)], vectors[1][std::size_t(k)], vectors[2][std::size_t(k)]);
        x += v * (glm::dot(v, atb) / values[std::size_t(k)]);
    }
    return mass + x;
}

struct Grid {
    int n; // cells per axis
    glm::dvec3 origin, step;
    glm::vec3 point(std::int64_t i, std::int64_t j, std::int64_t k) const {
        return glm::vec3(origin + glm::dvec3(double(i), double(j), double(k)) * step);
    }
    std::uint64_t pointKey(std::int64_t i, std::int64_t j, std::int64_t k) const {
        const std::uint64_t side = std::uint64_t(n) + 1;
        return (std::uint64_t(k) * side + std::uint64_t(j)) * side + std::uint64_t(i);
    }
};

} // namespace

Expected<std::pair<Mesh, MeshStats>> extractMesh(const shaders::PreparedSdf& sdf, const MeshOptions& options,
                                                 const ProgressSink& progress) {
    const auto start = std::chrono::steady_clock::now();
    if (options.resolution < 2 || options.resolution > 2048) return makeError("--resolution: must be 2..2048");
    for (int a = 0; a < 3; ++a)
        if (!(options.boundsMax[a] > options.boundsMin[a])) return makeError("--bounds: every maximum must exceed its minimum");
    Grid grid{options.resolution, glm::dvec3(options.boundsMin),
              (glm::dvec3(options.boundsMax) - glm::dvec3(options.boundsMin)) / double(options.resolution)};
    MeshStats stats;
    detail::FieldProbe probe;
    if (auto ok = probe.build(sdf, "analysis/points.glsl", options.time, options.parameters); !ok) return ok.error();

    // 1. Block centres: which blocks may hold surface.
    const int blocksPerAxis = (grid.n + kBlock - 1) / kBlock;
    std::vector<float> centres;
    for (int bk = 0; bk < blocksPerAxis; ++bk)
        for (int bj = 0; bj < blocksPerAxis; ++bj)
            for (int bi = 0; bi < blocksPerAxis; ++bi) {
                const glm::dvec3 lo = glm::dvec3(bi, bj, bk) * double(kBlock);
                const glm::dvec3 hi = glm::min(lo + double(kBlock), glm::dvec3(grid.n));
                const glm::dvec3 c = grid.origin + 0.5 * (lo + hi) * grid.step;
                centres.insert(centres.end(), {float(c.x), float(c.y), float(c.z)});
            }
    std::vector<float> centreValues;
    if (auto ok = probe.evaluate(centres, centreValues, nullptr); !ok) return ok.error();
    stats.pointsEvaluated += centreValues.size();
    stats.blocks = centreValues.size();
    const double halfDiagonal = 0.5 * glm::length(grid.step * double(kBlock));
    std::vector<std::array<int, 3>> kept;
    for (std::size_t b = 0; b < centreValues.size(); ++b) {
        const float f = centreValues[b];
        const bool maySurface = options.lipschitz <= 0.0f || !std::isfinite(f) ||
                                std::abs(double(f)) <= double(options.lipschitz) * halfDiagonal * 1.001 + 1e-6;
        if (!maySurface) continue;
        const int bi = int(b % std::size_t(blocksPerAxis)), bj = int(b / std::size_t(blocksPerAxis) % std::size_t(blocksPerAxis)),
                  bk = int(b / (std::size_t(blocksPerAxis) * std::size_t(blocksPerAxis)));
        kept.push_back({bi, bj, bk});
    }
    stats.blocksKept = kept.size();
    progress(1, 4);

    // 2. The grid points of the kept blocks, (B+1)^3 per block in a dense array (a point on a face
    // two kept blocks share is evaluated by both, at the same coordinates, so to the same value).
    constexpr int kSide = kBlock + 1;
    constexpr std::size_t kPerBlock = std::size_t(kSide) * kSide * kSide;
    std::vector<std::int32_t> blockSlot(std::size_t(blocksPerAxis) * blocksPerAxis * blocksPerAxis, -1);
    std::vector<float> points;
    points.reserve(3 * kPerBlock * kept.size());
    for (std::size_t slot = 0; slot < kept.size(); ++slot) {
        const auto& b = kept[slot];
        blockSlot[(std::size_t(b[2]) * blocksPerAxis + std::size_t(b[1])) * blocksPerAxis + std::size_t(b[0])] =
            std::int32_t(slot);
        for (int k = 0; k < kSide; ++k)
            for (int j = 0; j < kSide; ++j)
                for (int i = 0; i < kSide; ++i) {
                    // Points past the grid's far side (partial last blocks) are clamped onto it.
                    const glm::vec3 p = grid.point(std::min(b[0] * kBlock + i, grid.n), std::min(b[1] * kBlock + j, grid.n),
                                                   std::min(b[2] * kBlock + k, grid.n));
                    points.insert(points.end(), {p.x, p.y, p.z});
                }
    }
    std::vector<float> values;
    if (auto ok = probe.evaluate(points, values, nullptr); !ok) return ok.error();
    stats.pointsEvaluated += values.size();
    if (progress.isCancelled()) return makeError("mesh: cancelled");
    progress(2, 4);
    // The value at grid point (i, j, k) from a kept block that holds it; NaN when none does.
    auto value = [&](std::int64_t i, std::int64_t j, std::int64_t k) -> float {
        const std::int64_t c[3] = {i, j, k};
        std::int64_t candidates[3][2];
        int counts[3];
        for (int a = 0; a < 3; ++a) {
            counts[a] = 0;
            const std::int64_t block = std::min<std::int64_t>(c[a] / kBlock, blocksPerAxis - 1);
            candidates[a][counts[a]++] = block;
            if (c[a] % kBlock == 0 && c[a] / kBlock - 1 >= 0 && c[a] / kBlock - 1 != block)
                candidates[a][counts[a]++] = c[a] / kBlock - 1;
        }
        for (int x = 0; x < counts[0]; ++x)
            for (int y = 0; y < counts[1]; ++y)
                for (int z = 0; z < counts[2]; ++z) {
                    const std::int64_t bx = candidates[0][x], by = candidates[1][y], bz = candidates[2][z];
                    const std::int32_t slot =
                        blockSlot[(std::size_t(bz) * blocksPerAxis + std::size_t(by)) * blocksPerAxis + std::size_t(bx)];
                    if (slot < 0) continue;
                    const std::int64_t li = i - bx * kBlock, lj = j - by * kBlock, lk = k - bz * kBlock;
                    if (li < 0 || lj < 0 || lk < 0 || li > kBlock || lj > kBlock || lk > kBlock) continue;
                    return values[std::size_t(slot) * kPerBlock + std::size_t((lk * kSide + lj) * kSide + li)];
                }
        return std::numeric_limits<float>::quiet_NaN();
    };
    auto inside = [](float f) { return f < 0.0f; };

    // 3. Edges with a sign change: the crossing by linear interpolation, its normal from the GPU.
    struct Edge {
        std::int64_t i, j, k;
        int axis;
        bool startInside;
    };
    std::vector<Edge> edges;
    std::vector<float> crossings;
    const std::int64_t axisStep[3][3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    for (const auto& b : kept)
        for (int k = b[2] * kBlock; k <= std::min(grid.n, (b[2] + 1) * kBlock); ++k)
            for (int j = b[1] * kBlock; j <= std::min(grid.n, (b[1] + 1) * kBlock); ++j)
                for (int i = b[0] * kBlock; i <= std::min(grid.n, (b[0] + 1) * kBlock); ++i)
                    for (int axis = 0; axis < 3; ++axis) {
                        // Each edge once: from a point of this block along +axis, inside the block.
                        const std::int64_t e[3] = {i + axisStep[axis][0], j + axisStep[axis][1], k + axisStep[axis][2]};
                        if (e[axis] > std::min<std::int64_t>(grid.n, (b[std::size_t(axis)] + 1) * kBlock)) continue;
                        const float f0 = value(i, j, k), f1 = value(e[0], e[1], e[2]);
                        if (!std::isfinite(f0) || !std::isfinite(f1) || inside(f0) == inside(f1)) continue;
                        const double t = std::clamp(double(f0) / (double(f0) - double(f1)), 0.0, 1.0);
                        const glm::dvec3 p0 = glm::dvec3(grid.point(i, j, k)), p1 = glm::dvec3(grid.point(e[0], e[1], e[2]));
                        const glm::dvec3 p = p0 + t * (p1 - p0);
                        edges.push_back({i, j, k, axis, inside(f0)});
                        crossings.insert(crossings.end(), {float(p.x), float(p.y), float(p.z)});
                    }
    // Edges on the shared face of two kept blocks are visited from both; keep one of each.
    {
        std::unordered_map<std::uint64_t, std::size_t> seen;
        std::vector<Edge> unique;
        std::vector<float> uniqueCrossings;
        for (std::size_t e = 0; e < edges.size(); ++e) {
            const std::uint64_t key = grid.pointKey(edges[e].i, edges[e].j, edges[e].k) * 3 + std::uint64_t(edges[e].axis);
            if (!seen.try_emplace(key, e).second) continue;
            unique.push_back(edges[e]);
            uniqueCrossings.insert(uniqueCrossings.end(), crossings.begin() + std::ptrdiff_t(3 * e),
                                   crossings.begin() + std::ptrdiff_t(3 * e + 3));
        }
        edges = std::move(unique);
        crossings = std::move(uniqueCrossings);
    }
    // Linear interpolation misses the surface where the field bends along the edge (near a box's
    // edge the inside value follows another face); bisection on the field itself puts every
    // crossing on the surface to 1/1024 of a cell.
    {
        std::vector<double> low(edges.size(), 0.0), high(edges.size(), 1.0);
        std::vector<float> probes(crossings.size()), probeValues;
        // Writes the middle of edge e's bracket into `out`.
        auto middleOf = [&](std::size_t e, std::vector<float>& out) {
            const Edge& edge = edges[e];
            const glm::dvec3 p0 = glm::dvec3(grid.point(edge.i, edge.j, edge.k));
            const glm::dvec3 p1 =
                p0 + glm::dvec3(axisStep[edge.axis][0], axisStep[edge.axis][1], axisStep[edge.axis][2]) * grid.step;
            const glm::dvec3 p = p0 + 0.5 * (low[e] + high[e]) * (p1 - p0);
            out[3 * e] = float(p.x);
            out[3 * e + 1] = float(p.y);
            out[3 * e + 2] = float(p.z);
        };
        for (int iteration = 0; iteration < 10; ++iteration) {
            for (std::size_t e = 0; e < edges.size(); ++e) middleOf(e, probes);
            if (auto ok = probe.evaluate(probes, probeValues, nullptr); !ok) return ok.error();
            stats.pointsEvaluated += probeValues.size();
            for (std::size_t e = 0; e < edges.size(); ++e) {
                if (!std::isfinite(probeValues[e])) continue;
                const double middle = 0.5 * (low[e] + high[e]);
                (inside(probeValues[e]) == edges[e].startInside ? low[e] : high[e]) = middle;
            }
            if (progress.isCancelled()) return makeError("mesh: cancelled");
        }
        for (std::size_t e = 0; e < edges.size(); ++e) middleOf(e, crossings);
    }
    std::vector<float> crossingValues, normals;
    const float normalStep = float(0.05 * std::min({grid.step.x, grid.step.y, grid.step.z}));
    if (auto ok = probe.evaluate(crossings, crossingValues, &normals, normalStep); !ok) return ok.error();
    stats.pointsEvaluated += crossingValues.size();
    progress(3, 4);

    // 4. Vertices: one per patch of surface in each cell. A cell's crossing edges are joined along
    // its faces (an ambiguous face, with four crossings, is split by the sign of its bilinear
    // centre, which both cells sharing it see alike), so two sheets through one cell get a vertex
    // each and the mesh stays manifold. Each vertex is its patch's QEF minimiser, clamped into the cell.
    auto cellKey = [&](std::int64_t i, std::int64_t j, std::int64_t k) {
        return (std::uint64_t(k) * std::uint64_t(grid.n) + std::uint64_t(j)) * std::uint64_t(grid.n) + std::uint64_t(i);
    };
    auto edgeKey = [&](std::int64_t i, std::int64_t j, std::int64_t k, int axis) {
        return grid.pointKey(i, j, k) * 3 + std::uint64_t(axis);
    };
    std::unordered_map<std::uint64_t, std::uint32_t> edgeIndex;
    edgeIndex.reserve(edges.size());
    std::unordered_map<std::uint64_t, bool> activeCells;
    for (std::size_t e = 0; e < edges.size(); ++e) {
        const Edge& edge = edges[e];
        edgeIndex[edgeKey(edge.i, edge.j, edge.k, edge.axis)] = std::uint32_t(e);
        const int u = (edge.axis + 1) % 3, v = (edge.axis + 2) % 3;
        for (int du = -1; du <= 0; ++du)
            for (int dv = -1; dv <= 0; ++dv) {
                std::int64_t c[3] = {edge.i, edge.j, edge.k};
                c[u] += du;
                c[v] += dv;
                if (c[u] < 0 || c[v] < 0 || c[u] >= grid.n || c[v] >= grid.n || c[edge.axis] >= grid.n) continue;
                activeCells[cellKey(c[0], c[1], c[2])] = true;
            }
    }
    // Local edge l = axis * 4 + (offset along axis+1) + 2 * (offset along axis+2).
    auto localEdge = [](int axis, const int offset[3]) { return axis * 4 + offset[(axis + 1) % 3] + 2 * offset[(axis + 2) % 3]; };
    constexpr std::uint32_t kNone = 0xffffffffu;
    Mesh mesh;
    std::unordered_map<std::uint64_t, std::array<std::uint32_t, 12>> vertexOf; // cell -> the vertex of each local edge
    vertexOf.reserve(activeCells.size());
    std::vector<std::uint64_t> vertexCell;
    for (const auto& [key, unused] : activeCells) {
        const std::int64_t i = std::int64_t(key % std::uint64_t(grid.n)),
                           j = std::int64_t(key / std::uint64_t(grid.n) % std::uint64_t(grid.n)),
                           k = std::int64_t(key / (std::uint64_t(grid.n) * std::uint64_t(grid.n)));
        const std::int64_t origin[3] = {i, j, k};
        std::array<std::int64_t, 12> global; // index into edges, or -1
        for (int axis = 0; axis < 3; ++axis)
            for (int b = 0; b < 4; ++b) {
                std::int64_t s[3] = {i, j, k};
                s[(axis + 1) % 3] += b & 1;
                s[(axis + 2) % 3] += b >> 1;
                auto it = edgeIndex.find(edgeKey(s[0], s[1], s[2], axis));
                global[std::size_t(axis * 4 + b)] = it == edgeIndex.end() ? -1 : std::int64_t(it->second);
            }
        std::array<int, 12> parent;
        for (int l = 0; l < 12; ++l) parent[std::size_t(l)] = l;
        std::function<int(int)> find = [&](int x) {
            return parent[std::size_t(x)] == x ? x : parent[std::size_t(x)] = find(parent[std::size_t(x)]);
        };
        auto join = [&](int a, int b) { parent[std::size_t(find(a))] = find(b); };
        for (int w = 0; w < 3; ++w)
            for (int side = 0; side < 2; ++side) {
                const int up = (w + 1) % 3, vp = (w + 2) % 3;
                auto edgeAt = [&](int axis, int offU, int offV) {
                    int offset[3] = {0, 0, 0};
                    offset[w] = side;
                    offset[up] = offU;
                    offset[vp] = offV;
                    return localEdge(axis, offset);
                };
                const int eu0 = edgeAt(up, 0, 0), eu1 = edgeAt(up, 0, 1), ev0 = edgeAt(vp, 0, 0), ev1 = edgeAt(vp, 1, 0);
                std::vector<int> present;
                for (int l : {eu0, eu1, ev0, ev1})
                    if (global[std::size_t(l)] >= 0) present.push_back(l);
                if (present.size() == 4) {
                    auto corner = [&](int offU, int offV) {
                        std::int64_t c[3] = {origin[0], origin[1], origin[2]};
                        c[w] += side;
                        c[up] += offU;
                        c[vp] += offV;
                        return value(c[0], c[1], c[2]);
                    };
                    const float c00 = corner(0, 0), centre = 0.25f * (c00 + corner(1, 0) + corner(0, 1) + corner(1, 1));
                    if (inside(centre) == inside(c00)) {
                        join(eu0, ev1);
                        join(ev0, eu1);
                    } else {
                        join(eu0, ev0);
                        join(eu1, ev1);
                    }
                } else {
                    for (std::size_t q = 1; q < present.size(); ++q) join(present[0], present[q]);
                }
            }
        std::array<std::uint32_t, 12> vertexFor;
        vertexFor.fill(kNone);
        const glm::dvec3 lo = glm::dvec3(grid.point(i, j, k)), hi = glm::dvec3(grid.point(i + 1, j + 1, k + 1));
        for (int root = 0; root < 12; ++root) {
            std::vector<glm::dvec3> points, patchNormals;
            std::vector<int> members;
            for (int l = 0; l < 12; ++l) {
                if (global[std::size_t(l)] < 0 || find(l) != root) continue;
                members.push_back(l);
                const std::size_t e = std::size_t(global[std::size_t(l)]);
                glm::dvec3 n(normals[3 * e], normals[3 * e + 1], normals[3 * e + 2]);
                const double length = glm::length(n);
                points.emplace_back(crossings[3 * e], crossings[3 * e + 1], crossings[3 * e + 2]);
                patchNormals.push_back(length > 0.0 && std::isfinite(length) ? n / length : glm::dvec3(0.0));
            }
            if (members.empty()) continue;
            const glm::dvec3 x = solveQef(points, patchNormals);
            const glm::dvec3 clamped = glm::clamp(x, lo, hi);
            if (clamped != x) ++stats.clampedVertices;
            const auto id = std::uint32_t(mesh.vertices.size());
            mesh.vertices.push_back(glm::vec3(clamped));
            vertexCell.push_back(key);
            for (int l : members) vertexFor[std::size_t(l)] = id;
        }
        vertexOf[key] = vertexFor;
    }
    stats.activeCells = activeCells.size();
    // On curved surfaces the planes' minimiser lies off the surface by about h^2 times the
    // curvature: two Newton steps along the gradient put each vertex on it (a vertex already on a
    // sharp edge or corner has f = 0 and stays). Steps are kept within the vertex's cell.
    for (int iteration = 0; iteration < 2; ++iteration) {
        std::vector<float> positions, fieldValues, gradients;
        positions.reserve(3 * mesh.vertices.size());
        for (const glm::vec3& v : mesh.vertices) positions.insert(positions.end(), {v.x, v.y, v.z});
        if (auto ok = probe.evaluate(positions, fieldValues, &gradients, normalStep); !ok) return ok.error();
        stats.pointsEvaluated += fieldValues.size();
        for (std::uint32_t vertex = 0; vertex < mesh.vertices.size(); ++vertex) {
            const std::uint64_t key = vertexCell[vertex];
            const float f = fieldValues[vertex];
            const glm::vec3 g(gradients[3 * vertex], gradients[3 * vertex + 1], gradients[3 * vertex + 2]);
            const float g2 = glm::dot(g, g);
            if (!std::isfinite(f) || !(g2 > 1e-12f) || !std::isfinite(g2)) continue;
            const std::int64_t i = std::int64_t(key % std::uint64_t(grid.n)),
                               j = std::int64_t(key / std::uint64_t(grid.n) % std::uint64_t(grid.n)),
                               k = std::int64_t(key / (std::uint64_t(grid.n) * std::uint64_t(grid.n)));
            const glm::vec3 moved =
                glm::clamp(mesh.vertices[vertex] - g * (f / g2), grid.point(i, j, k), grid.point(i + 1, j + 1, k + 1));
            mesh.vertices[vertex] = moved;
        }
    }

    // 5. A quad per sign-changing edge, wound so that it faces outward (towards f > 0).
    for (const Edge& edge : edges) {
        const int u = (edge.axis + 1) % 3, v = (edge.axis + 2) % 3;
        std::uint32_t quad[4];
        bool complete = true;
        const int offsets[4][2] = {{-1, -1}, {0, -1}, {0, 0}, {-1, 0}};
        for (int q = 0; q < 4 && complete; ++q) {
            std::int64_t c[3] = {edge.i, edge.j, edge.k};
            c[u] += offsets[q][0];
            c[v] += offsets[q][1];
            if (c[u] < 0 || c[v] < 0 || c[u] >= grid.n || c[v] >= grid.n || c[edge.axis] >= grid.n) {
                complete = false;
                break;
            }
            auto it = vertexOf.find(cellKey(c[0], c[1], c[2]));
            // The edge seen from this cell: at its +u side when the cell lies at -u, and so on.
            int offset[3] = {0, 0, 0};
            offset[u] = -offsets[q][0];
            offset[v] = -offsets[q][1];
            const std::uint32_t vertex = it == vertexOf.end() ? kNone : it->second[std::size_t(localEdge(edge.axis, offset))];
            if (vertex == kNone)
                complete = false;
            else
                quad[q] = vertex;
        }
        if (!complete) continue;
        // (u, v) counter-clockwise looking down +axis; the surface faces +axis when the edge starts inside.
        if (!edge.startInside) std::swap(quad[1], quad[3]);
        // Split along the shorter diagonal.
        const float d02 = glm::length(mesh.vertices[quad[0]] - mesh.vertices[quad[2]]);
        const float d13 = glm::length(mesh.vertices[quad[1]] - mesh.vertices[quad[3]]);
        if (d02 <= d13)
            mesh.indices.insert(mesh.indices.end(), {quad[0], quad[1], quad[2], quad[0], quad[2], quad[3]});
        else
            mesh.indices.insert(mesh.indices.end(), {quad[0], quad[1], quad[3], quad[1], quad[2], quad[3]});
    }
    progress(4, 4);
    stats.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return std::pair<Mesh, MeshStats>{std::move(mesh), stats};
}

Topology checkTopology(const Mesh& mesh) {
    Topology t;
    std::unordered_map<std::uint64_t, std::uint32_t> uses;
    for (std::size_t f = 0; f + 2 < mesh.indices.size(); f += 3) {
        const std::uint32_t v[3] = {mesh.indices[f], mesh.indices[f + 1], mesh.indices[f + 2]};
        if (v[0] == v[1] || v[1] == v[2] || v[0] == v[2]) ++t.degenerateTriangles;
        for (int e = 0; e < 3; ++e) {
            const std::uint32_t a = std::min(v[e], v[(e + 1) % 3]), b = std::max(v[e], v[(e + 1) % 3]);
            ++uses[(std::uint64_t(a) << 32) | b];
        }
    }
    t.edges = uses.size();
    for (const auto& [edge, count] : uses) {
        if (count == 1) ++t.boundaryEdges;
        if (count > 2) ++t.nonManifoldEdges;
    }
    return t;
}

} // namespace sdfwb::meshing
