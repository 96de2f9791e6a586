// The GLSL field's sign lattice (MeshQuery::signLattice): every lattice point's winding number,
// boundary slope (open meshes) and nearest triangle, built once a level.

#include <meshfield/MeshQuery.h>

#include "FloatBits.h"
#include "QueryShared.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <mutex>
#include <numeric>
#include <thread>

namespace sdfwb::meshfield {
namespace {

using glm::dvec3;

// Runs work(begin, end) over [0, count) in blocks of 256 on `workers` threads (the caller's included).
template <class Work> void forEachBlock(std::size_t count, unsigned workers, const Work& work) {
    std::atomic<std::size_t> next{0};
    auto run = [&] {
        for (std::size_t i; (i = next.fetch_add(256)) < count;) work(i, std::min(count, i + 256));
    };
    std::vector<std::thread> pool;
    workers = std::min<unsigned>(workers, unsigned(count / 256 + 1));
    for (unsigned t = 1; t < workers; ++t) pool.emplace_back(run);
    run();
    for (std::thread& thread : pool) thread.join();
}

// Union-find over lattice points, the root of each set its member farthest from the surface.
struct FarthestSets {
    std::vector<std::uint32_t> parent;
    const std::vector<double>& distance;

    explicit FarthestSets(const std::vector<double>& d) : parent(d.size()), distance(d) {
        std::iota(parent.begin(), parent.end(), 0u);
    }
    std::uint32_t root(std::uint32_t i) {
        while (parent[i] != i) i = parent[i] = parent[parent[i]];
        return i;
    }
    void join(std::uint32_t a, std::uint32_t b) {
        a = root(a), b = root(b);
        if (a == b) return;
        if (distance[a] < distance[b] || (distance[a] == distance[b] && b < a)) std::swap(a, b);
        parent[b] = a;
    }
};

} // namespace

std::vector<float> MeshQuery::signLattice(int level, unsigned threads) const {
    level = std::clamp(level, 2, 7);
    std::lock_guard lock(m_latticeMutex); // one thread builds a level; the others wait for it
    std::vector<float>& kept = m_lattices[std::size_t(level)];
    if (kept.empty()) kept = buildSignLattice(level, threads);
    return kept;
}

// Each point's nearest triangle (its walk starts from the last point's triangle), and its winding
// number. On a closed mesh (no open boundary) the winding number is the same at both ends of any
// path that meets no triangle, and a lattice edge from a point whose nearest distance exceeds the
// step is such a path: the points joined by such edges share one value, computed once at the one
// farthest from the surface (where the hierarchy's approximation is best). On a 65^3 lattice that
// is about a thousand winding walks instead of 274,625 (spot, cow, fandisk: 676 to 1025), which
// had taken a third of the build. An open mesh's winding number (the bunny has holes) varies off
// the surface: each point gets its own walk, and its boundary slope.
std::vector<float> MeshQuery::buildSignLattice(int level, unsigned threads) const {
    const double step = m_cacheStep * double(m_cacheSide >> level);
    const int side = m_useCache ? (1 << level) + 1 : 0;
    std::vector<float> out = {float(m_cacheLo.x),
                              float(m_cacheLo.y),
                              float(m_cacheLo.z),
                              float(step),
                              float(side),
                              float(m_boundaryLength),
                              0.0f,
                              0.0f};
    if (side == 0) return out;
    // The GLSL field rounds p to the float lattice point the header gives: computed there.
    const glm::vec3 lo(out[0], out[1], out[2]);
    const float stepF = out[3];
    const std::size_t points = detail::latticePoints(level);
    const std::size_t n = std::size_t(side);
    const bool open = !m_boundary.empty();
    out[6] = open ? 1.0f : 0.0f;
    out[7] = 1.0f;
    const std::size_t seeds = 8 + (open ? 2 : 1) * points;
    out.resize(seeds + points);
    const double reach = double(stepF) * std::sqrt(3.0) * 0.5 * (1.0 + 1e-6); // the half diagonal, and float slack
    auto at = [&](std::size_t j) { return dvec3(lo + glm::vec3(float(j % n), float((j / n) % n), float(j / (n * n))) * stepF); };
    const unsigned workers = detail::threadCount(threads);
    std::vector<double> distance(points);
    forEachBlock(points, workers, [&](std::size_t begin, std::size_t end) {
        std::uint32_t slot = kNoSeed; // each walk starts from the last point's triangle
        for (std::size_t j = begin; j < end; ++j) {
            int feature = 0;
            dvec3 closest;
            const dvec3 q = at(j);
            distance[j] = std::sqrt(nearest(q, slot, feature, closest, nullptr, slot));
            out[seeds + j] = detail::asFloat(slot);
            if (open) {
                out[8 + j] = float(winding(q));
                out[8 + points + j] = detail::roundedUp(boundarySlope(q, reach));
            }
        }
    });
    if (open) return out;
    FarthestSets sets(distance);
    // The edge to each next neighbour meets no triangle when an end's nearest distance exceeds the
    // edge's length (of the float positions, exact in double), with slack for the walk's rounding.
    for (std::size_t j = 0; j < points; ++j) {
        const std::size_t x = j % n, y = (j / n) % n, z = j / (n * n);
        const std::size_t neighbours[3] = {x + 1 < n ? j + 1 : j, y + 1 < n ? j + n : j, z + 1 < n ? j + n * n : j};
        for (std::size_t k : neighbours)
            if (k != j && std::max(distance[j], distance[k]) > glm::length(at(k) - at(j)) * (1.0 + 1e-9))
                sets.join(std::uint32_t(j), std::uint32_t(k));
    }
    std::vector<std::uint32_t> roots;
    for (std::size_t j = 0; j < points; ++j)
        if (sets.root(std::uint32_t(j)) == j) roots.push_back(std::uint32_t(j));
    forEachBlock(roots.size(), workers, [&](std::size_t begin, std::size_t end) {
        for (std::size_t r = begin; r < end; ++r) out[8 + roots[r]] = float(winding(at(roots[r])));
    });
    for (std::size_t j = 0; j < points; ++j) out[8 + j] = out[8 + sets.root(std::uint32_t(j))];
    return out;
}

} // namespace sdfwb::meshfield
