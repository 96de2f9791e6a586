// The mesh's clean-up and checks (Topology.h, Mesh.h): welding vertices at one position, flipping
// zero-area triangles away, counting degenerate triangles, and the topology check.
#include "Topology.h"

#include <core/Parallel.h>

#include <glm/geometric.hpp>

#include <algorithm>
#include <array>
#include <cstdint>
#include <unordered_map>
#include <utility>
#include <vector>

namespace sdfwb::meshing {

namespace detail {

void weldCoincidentVertices(Mesh& mesh, float tolerance) {
    std::vector<std::uint32_t>& indices = mesh.indices;
    auto same = [&](std::uint32_t a, std::uint32_t b) { return glm::length(mesh.vertices[a] - mesh.vertices[b]) <= tolerance; };
    std::vector<std::pair<std::uint32_t, std::uint32_t>> pairs;
    for (std::size_t t = 0; t + 2 < indices.size(); t += 3)
        for (std::size_t e = 0; e < 3; ++e) {
            const std::uint32_t a = indices[t + e], b = indices[t + (e + 1) % 3];
            if (a != b && same(a, b)) pairs.emplace_back(std::min(a, b), std::max(a, b));
        }
    if (pairs.empty()) return;
    std::sort(pairs.begin(), pairs.end());
    pairs.erase(std::unique(pairs.begin(), pairs.end()), pairs.end());
    // The triangles around each vertex involved; a merge hands the merged vertex's to the survivor.
    std::unordered_map<std::uint32_t, std::vector<std::uint32_t>> around;
    for (const auto& [a, b] : pairs) around[a], around[b];
    for (std::size_t t = 0; t + 2 < indices.size(); t += 3)
        for (std::size_t e = 0; e < 3; ++e)
            if (const auto it = around.find(indices[t + e]); it != around.end()) it->second.push_back(std::uint32_t(t / 3));
    std::unordered_map<std::uint32_t, std::uint32_t> parent; // union-find over the vertices merged
    auto find = [&](std::uint32_t v) {
        for (auto it = parent.find(v); it != parent.end() && it->second != v; it = parent.find(v)) v = it->second;
        return v;
    };
    // The neighbours of v in the mesh as merged so far, and how many of v's triangles hold `other`.
    std::vector<std::uint32_t> ringA, ringB;
    auto ring = [&](std::uint32_t v, std::uint32_t other, std::vector<std::uint32_t>& out) {
        out.clear();
        std::size_t holding = 0;
        for (std::uint32_t t : around[v]) {
            const std::uint32_t f[3] = {find(indices[3 * t]), find(indices[3 * t + 1]), find(indices[3 * t + 2])};
            if (f[0] == f[1] || f[1] == f[2] || f[0] == f[2]) continue; // collapsed already
            holding += f[0] == other || f[1] == other || f[2] == other;
            for (std::uint32_t n : f)
                if (n != v) out.push_back(n);
        }
        std::sort(out.begin(), out.end());
        out.erase(std::unique(out.begin(), out.end()), out.end());
        return holding;
    };
    std::vector<std::uint32_t> common;
    for (const auto& [a, b] : pairs) {
        const std::uint32_t ra = find(a), rb = find(b);
        if (ra == rb) continue;
        const std::size_t shared = ring(ra, rb, ringA);
        ring(rb, ra, ringB);
        common.clear();
        std::set_intersection(ringA.begin(), ringA.end(), ringB.begin(), ringB.end(), std::back_inserter(common));
        if (common.size() == shared) {
            const std::uint32_t keep = std::min(ra, rb), gone = std::max(ra, rb);
            parent[keep] = keep;
            parent[gone] = keep;
            std::vector<std::uint32_t>& into = around[keep];
            const std::vector<std::uint32_t>& from = around[gone];
            into.insert(into.end(), from.begin(), from.end());
            continue;
        }
        for (const auto& [v, others] : {std::pair{ra, &ringA}, std::pair{rb, &ringB}}) {
            glm::vec3 middle(0.0f);
            int count = 0;
            for (std::uint32_t n : *others)
                if (n != ra && n != rb) {
                    middle += mesh.vertices[n];
                    ++count;
                }
            if (count > 0) mesh.vertices[v] += 0.01f * (middle / float(count) - mesh.vertices[v]);
        }
    }
    if (parent.empty()) return;
    std::size_t kept = 0;
    for (std::size_t t = 0; t + 2 < indices.size(); t += 3) {
        const std::uint32_t a = find(indices[t]), b = find(indices[t + 1]), c = find(indices[t + 2]);
        if (a == b || b == c || a == c) continue;
        indices[kept++] = a;
        indices[kept++] = b;
        indices[kept++] = c;
    }
    indices.resize(kept);
    std::vector<std::uint32_t> renumber(mesh.vertices.size(), 0xffffffffu);
    for (std::uint32_t v : indices) renumber[v] = 0;
    std::uint32_t next = 0;
    for (std::size_t v = 0; v < mesh.vertices.size(); ++v)
        if (renumber[v] == 0) {
            renumber[v] = next;
            mesh.vertices[next++] = mesh.vertices[v];
        }
    mesh.vertices.resize(next);
    for (std::uint32_t& v : indices) v = renumber[v];
}

} // namespace detail

std::uint64_t flipCollinearTriangles(Mesh& mesh) {
    const std::size_t vertexCount = mesh.vertices.size();
    // The corner of triangle t strictly between the other two when the three lie on one line, else -1.
    auto middleCorner = [&](std::size_t t) {
        const std::uint32_t* v = &mesh.indices[3 * t];
        if (v[0] == v[1] || v[1] == v[2] || v[0] == v[2] || std::max({v[0], v[1], v[2]}) >= vertexCount) return -1;
        const glm::dvec3 p[3] = {glm::dvec3(mesh.vertices[v[0]]), glm::dvec3(mesh.vertices[v[1]]),
                                 glm::dvec3(mesh.vertices[v[2]])};
        const glm::dvec3 n = glm::cross(p[1] - p[0], p[2] - p[0]);
        if (n.x != 0.0 || n.y != 0.0 || n.z != 0.0) return -1;
        for (int k = 0; k < 3; ++k) {
            const glm::dvec3 a = p[(k + 1) % 3], b = p[(k + 2) % 3], c = p[k];
            const double length2 = glm::dot(b - a, b - a), s = length2 > 0.0 ? glm::dot(c - a, b - a) / length2 : -1.0;
            if (s > 0.0 && s < 1.0 && c != a && c != b) return k;
        }
        return -1;
    };
    auto key = [](std::uint64_t a, std::uint64_t b) { return (a << 32) | b; };
    std::uint64_t flips = 0;
    for (int round = 0; round < 4; ++round) {
        const std::size_t triangles = mesh.triangleCount();
        const std::size_t chunks = chunkCount(triangles, 65536);
        std::vector<std::vector<std::pair<std::uint32_t, int>>> found(chunks); // (triangle, middle corner)
        forEachChunk(triangles, chunks, [&](std::size_t chunk, std::size_t first, std::size_t end) {
            for (std::size_t t = first; t < end; ++t)
                if (const int k = middleCorner(t); k >= 0) found[chunk].emplace_back(std::uint32_t(t), k);
        });
        std::vector<std::pair<std::uint32_t, int>> flat;
        for (const auto& part : found) flat.insert(flat.end(), part.begin(), part.end());
        if (flat.empty()) break;
        // One pass over the mesh: the triangle across each long edge (which runs it backwards), and
        // every neighbour of each middle vertex (a flip must not make an edge that exists).
        std::unordered_map<std::uint64_t, std::uint32_t> across;
        std::unordered_map<std::uint32_t, std::vector<std::uint32_t>> neighbours;
        for (const auto& [t, k] : flat) {
            const std::uint32_t* v = &mesh.indices[3 * std::size_t(t)];
            across.emplace(key(v[(k + 2) % 3], v[(k + 1) % 3]), std::uint32_t(-1));
            neighbours.emplace(v[k], std::vector<std::uint32_t>{});
        }
        for (std::size_t t = 0; t < triangles; ++t) {
            const std::uint32_t* v = &mesh.indices[3 * t];
            for (int e = 0; e < 3; ++e) {
                if (auto it = across.find(key(v[e], v[(e + 1) % 3])); it != across.end()) it->second = std::uint32_t(t);
                if (auto it = neighbours.find(v[e]); it != neighbours.end())
                    it->second.insert(it->second.end(), {v[(e + 1) % 3], v[(e + 2) % 3]});
            }
        }
        std::vector<bool> touched(triangles, false);
        std::uint64_t made = 0;
        for (const auto& [t, k] : flat) {
            // A triangle an earlier flip of this pass rewrote waits for the next pass.
            if (touched[t]) continue;
            std::uint32_t* v = &mesh.indices[3 * std::size_t(t)];
            const std::uint32_t a = v[(k + 1) % 3], b = v[(k + 2) % 3], c = v[k];
            const std::uint32_t other = across.at(key(b, a));
            if (other == std::uint32_t(-1) || other == t || touched[other]) continue;
            std::uint32_t* w = &mesh.indices[3 * std::size_t(other)];
            int at = 0; // w = (b, a, d) once rotated
            while (at < 3 && !(w[at] == b && w[(at + 1) % 3] == a)) ++at;
            if (at == 3) continue;
            const std::uint32_t d = w[(at + 2) % 3];
            const std::vector<std::uint32_t>& around = neighbours.at(c);                        // (c is always in the map)
            if (d == c || std::find(around.begin(), around.end(), d) != around.end()) continue; // c-d exists
            // (a, b, c) and (b, a, d) become (c, a, d) and (c, d, b): t' split at c, t gone.
            v[0] = c, v[1] = a, v[2] = d;
            w[0] = c, w[1] = d, w[2] = b;
            touched[t] = touched[other] = true;
            for (const auto& [from, to] : {std::pair{c, d}, std::pair{d, c}}) // the new edge, for later checks
                if (auto it = neighbours.find(from); it != neighbours.end()) it->second.push_back(to);
            ++made;
        }
        flips += made;
        if (made == 0) break;
    }
    return flips;
}

namespace detail {

std::uint64_t nudgeCollinearVertices(Mesh& mesh) {
    const std::size_t triangles = mesh.triangleCount(), vertexCount = mesh.vertices.size();
    auto normal = [&](std::size_t t) {
        const std::uint32_t* v = &mesh.indices[3 * t];
        const glm::dvec3 p(mesh.vertices[v[0]]), q(mesh.vertices[v[1]]), r(mesh.vertices[v[2]]);
        return glm::cross(q - p, r - p);
    };
    auto zero = [](const glm::dvec3& n) { return n.x == 0.0 && n.y == 0.0 && n.z == 0.0; };
    // The middle vertex of each collinear triangle (the one strictly between the other two).
    std::vector<std::uint32_t> middles;
    for (std::size_t t = 0; t < triangles; ++t) {
        const std::uint32_t* v = &mesh.indices[3 * t];
        if (v[0] == v[1] || v[1] == v[2] || v[0] == v[2] || std::max({v[0], v[1], v[2]}) >= vertexCount) continue;
        if (!zero(normal(t))) continue;
        for (int k = 0; k < 3; ++k) {
            const glm::dvec3 a(mesh.vertices[v[(k + 1) % 3]]), b(mesh.vertices[v[(k + 2) % 3]]), c(mesh.vertices[v[k]]);
            const double length2 = glm::dot(b - a, b - a), s = length2 > 0.0 ? glm::dot(c - a, b - a) / length2 : -1.0;
            if (s > 0.0 && s < 1.0) middles.push_back(v[k]);
        }
    }
    if (middles.empty()) return 0;
    std::sort(middles.begin(), middles.end());
    middles.erase(std::unique(middles.begin(), middles.end()), middles.end());
    std::unordered_map<std::uint32_t, std::vector<std::uint32_t>> around; // the triangles of each middle vertex
    for (std::uint32_t v : middles) around.emplace(v, std::vector<std::uint32_t>{});
    for (std::size_t t = 0; t < triangles; ++t)
        for (int k = 0; k < 3; ++k)
            if (auto it = around.find(mesh.indices[3 * t + std::size_t(k)]); it != around.end())
                it->second.push_back(std::uint32_t(t));
    std::uint64_t moved = 0;
    for (std::uint32_t v : middles) {
        const std::vector<std::uint32_t>& ring = around.at(v);
        glm::dvec3 centre(0.0);
        int count = 0;
        for (std::uint32_t t : ring)
            for (int k = 0; k < 3; ++k)
                if (const std::uint32_t w = mesh.indices[3 * std::size_t(t) + std::size_t(k)]; w != v) {
                    centre += glm::dvec3(mesh.vertices[w]);
                    ++count;
                }
        if (count == 0) continue;
        centre /= double(count);
        const glm::vec3 from = mesh.vertices[v];
        std::vector<glm::dvec3> before;
        for (std::uint32_t t : ring) before.push_back(normal(t));
        for (double step : {1e-3, 1e-2, 1e-1, 0.5}) {
            // Tried where the mesh stores it, and put back unless every triangle around keeps its side.
            mesh.vertices[v] = glm::vec3(glm::dvec3(from) + step * (centre - glm::dvec3(from)));
            bool fine = mesh.vertices[v] != from;
            for (std::size_t i = 0; fine && i < ring.size(); ++i) {
                const glm::dvec3 after = normal(ring[i]);
                fine = !zero(after) && (zero(before[i]) || glm::dot(before[i], after) > 0.0);
            }
            if (fine) {
                ++moved;
                break;
            }
            mesh.vertices[v] = from;
        }
    }
    return moved;
}

} // namespace detail

std::uint64_t countDegenerateTriangles(const Mesh& mesh) {
    const std::size_t triangles = mesh.indices.size() / 3, vertexCount = mesh.vertices.size();
    const std::size_t chunks = chunkCount(triangles, 65536);
    std::vector<std::uint64_t> degenerate(chunks, 0);
    forEachChunk(triangles, chunks, [&](std::size_t chunk, std::size_t first, std::size_t end) {
        for (std::size_t f = first; f < end; ++f) {
            const std::uint32_t v[3] = {mesh.indices[3 * f], mesh.indices[3 * f + 1], mesh.indices[3 * f + 2]};
            if (v[0] == v[1] || v[1] == v[2] || v[0] == v[2]) {
                ++degenerate[chunk];
            } else if (std::max({v[0], v[1], v[2]}) < vertexCount) {
                const glm::dvec3 p(mesh.vertices[v[0]]), q(mesh.vertices[v[1]]), r(mesh.vertices[v[2]]);
                const glm::dvec3 n = glm::cross(q - p, r - p);
                if (n.x == 0.0 && n.y == 0.0 && n.z == 0.0) ++degenerate[chunk];
            }
        }
    });
    std::uint64_t total = 0;
    for (std::uint64_t d : degenerate) total += d;
    return total;
}

Topology subdividedTopology(Topology coarse, std::uint64_t triangles, int levels) {
    for (int level = 0; level < levels; ++level) {
        coarse.edges = 2 * coarse.edges + 3 * triangles;
        triangles *= 4;
        coarse.boundaryEdges *= 2;
        coarse.nonManifoldEdges *= 2;
        coarse.misorientedEdges *= 2;
    }
    coarse.degenerateTriangles = 0;
    return coarse;
}

Topology checkTopology(const Mesh& mesh) {
    Topology t;
    const std::size_t triangles = mesh.indices.size() / 3, vertexCount = mesh.vertices.size();
    t.degenerateTriangles = countDegenerateTriangles(mesh);
    // Edges: each triangle's three, filed under their lower vertex as (higher vertex, whether the
    // triangle runs it downwards); a vertex's short list, sorted, has a run per undirected edge.
    std::uint32_t top = 0;
    for (std::uint32_t v : mesh.indices) top = std::max(top, v);
    const std::size_t lists = mesh.indices.empty() ? 0 : std::size_t(top) + 1;
    std::vector<std::uint32_t> begin(lists + 1, 0);
    auto forEachEdge = [&](auto&& visit) {
        for (std::size_t c = 0; c < 3 * triangles; ++c) {
            const std::uint32_t a = mesh.indices[c], b = mesh.indices[c - c % 3 + (c + 1) % 3];
            visit(std::min(a, b), (std::uint64_t(std::max(a, b)) << 1) | std::uint64_t(a > b));
        }
    };
    forEachEdge([&](std::uint32_t low, std::uint64_t) { ++begin[std::size_t(low) + 1]; });
    for (std::size_t v = 0; v < lists; ++v) begin[v + 1] += begin[v];
    std::vector<std::uint64_t> filed(3 * triangles);
    {
        std::vector<std::uint32_t> at(begin.begin(), begin.end() - 1);
        forEachEdge([&](std::uint32_t low, std::uint64_t key) { filed[at[low]++] = key; });
    }
    // Vertex manifoldness: the triangles around a vertex, joined where they share an edge through
    // it, form one fan. Union-find over each vertex's corners; its neighbours are few, so a short
    // list finds the corner that saw a neighbour first.
    std::vector<std::uint32_t> start(vertexCount + 1, 0);
    for (std::uint32_t v : mesh.indices)
        if (v < vertexCount) ++start[v + 1];
    for (std::size_t v = 0; v < vertexCount; ++v) start[v + 1] += start[v];
    std::vector<std::uint32_t> corners(mesh.indices.size()), fill(start.begin(), start.end() - 1);
    for (std::size_t c = 0; c < mesh.indices.size(); ++c)
        if (mesh.indices[c] < vertexCount) corners[fill[mesh.indices[c]]++] = std::uint32_t(c);

    const std::size_t chunks = chunkCount(std::max(lists, vertexCount), 16384);
    std::vector<Topology> parts(chunks);
    forEachChunk(std::max(lists, vertexCount), chunks, [&](std::size_t chunk, std::size_t first, std::size_t end) {
        Topology& part = parts[chunk];
        for (std::size_t v = first; v < std::min(end, lists); ++v) {
            const auto from = filed.begin() + begin[v], to = filed.begin() + begin[v + 1];
            std::sort(from, to);
            for (auto i = from, j = from; i != to; i = j) {
                while (j != to && *j >> 1 == *i >> 1) ++j;
                ++part.edges;
                if (j - i == 1) ++part.boundaryEdges;
                if (j - i > 2) ++part.nonManifoldEdges;
                // Orientation: an edge of two triangles is run once each way (its reverse belongs to
                // the neighbour); counted where both run it the same way.
                if (j - i == 2 && *i == *(i + 1)) ++part.misorientedEdges;
            }
        }
        std::vector<std::uint32_t> parent;
        std::vector<std::pair<std::uint32_t, std::uint32_t>> seen; // (neighbour vertex, the corner that saw it)
        for (std::size_t v = first; v < std::min(end, vertexCount); ++v) {
            const std::uint32_t n = start[v + 1] - start[v];
            if (n < 2) continue;
            parent.resize(n);
            for (std::uint32_t i = 0; i < n; ++i) parent[i] = i;
            auto find = [&](std::uint32_t x) {
                while (parent[x] != x) x = parent[x] = parent[parent[x]];
                return x;
            };
            seen.clear();
            std::uint32_t groups = n;
            for (std::uint32_t i = 0; i < n; ++i) {
                const std::size_t c = corners[start[v] + i], f = c - c % 3;
                for (int k = 1; k <= 2; ++k) {
                    const std::uint32_t other = mesh.indices[f + (c - f + std::size_t(k)) % 3];
                    const auto it = std::find_if(seen.begin(), seen.end(), [&](const auto& s) { return s.first == other; });
                    if (it == seen.end()) {
                        seen.emplace_back(other, i);
                        continue;
                    }
                    const std::uint32_t x = find(i), y = find(it->second);
                    if (x != y) {
                        parent[x] = y;
                        --groups;
                    }
                }
            }
            if (groups > 1) ++part.nonManifoldVertices;
        }
    });
    for (const Topology& part : parts) {
        t.edges += part.edges;
        t.boundaryEdges += part.boundaryEdges;
        t.nonManifoldEdges += part.nonManifoldEdges;
        t.misorientedEdges += part.misorientedEdges;
        t.nonManifoldVertices += part.nonManifoldVertices;
    }
    return t;
}

} // namespace sdfwb::meshing
