// Dual contouring's steps 1-2 (Extraction.h): which blocks and sub-blocks of the grid may hold
// surface by the Lipschitz bound, and the field at their grid points.
#include "Extraction.h"

#include <core/Parallel.h>

#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <glm/vector_relational.hpp>

#include <algorithm>
#include <array>
#include <bit>
#include <bitset>
#include <cmath>
#include <limits>
#include <optional>
#include <utility>
#include <vector>

namespace sdfwb::meshing::detail {

// 1. Block centres: which blocks may hold surface.
Expected<void> Extraction::selectBlocks() {
    blocksPerAxis = (grid.n + kBlock - 1) / kBlock;
    std::vector<float> centres;
    centres.reserve(3 * std::size_t(blocksPerAxis) * blocksPerAxis * blocksPerAxis);
    for (int bk = 0; bk < blocksPerAxis; ++bk)
        for (int bj = 0; bj < blocksPerAxis; ++bj)
            for (int bi = 0; bi < blocksPerAxis; ++bi) {
                const glm::dvec3 lo = glm::dvec3(bi, bj, bk) * double(kBlock);
                const glm::dvec3 hi = glm::min(lo + double(kBlock), glm::dvec3(grid.n));
                const glm::dvec3 c = grid.origin + 0.5 * (lo + hi) * grid.step;
                centres.insert(centres.end(), {float(c.x), float(c.y), float(c.z)});
            }
    std::vector<float> centreValues, centreGradients;
    const float gradientStep = float(0.25 * std::min({grid.step.x, grid.step.y, grid.step.z}));
    if (auto ok = field.evaluate(centres, centreValues, options.estimateLipschitz ? &centreGradients : nullptr, gradientStep);
        !ok)
        return ok.error();
    stats.pointsEvaluated += centreValues.size() * (options.estimateLipschitz ? 7 : 1);
    stats.blocks = centreValues.size();
    const float bound = options.estimateLipschitz ? estimateBound(centreValues, centreGradients) : options.lipschitz;
    stats.lipschitzUsed = bound;
    const double halfDiagonal = 0.5 * glm::length(grid.step * double(kBlock));
    blockSlot.assign(centreValues.size(), -1);
    for (std::size_t b = 0; b < centreValues.size(); ++b)
        if (maySurface(centreValues[b], halfDiagonal)) keep(b);
    return {};
}

// The bound the blocks are skipped by when it is estimated: 1.25 x the steepest |grad f| at a block
// centre (a quarter-cell central difference) or quotient between neighbouring centres, at least 1.
float Extraction::estimateBound(const std::vector<float>& centreValues, const std::vector<float>& centreGradients) const {
    float steepest = 0.0f;
    for (std::size_t b = 0; b < centreValues.size(); ++b) {
        const glm::vec3 g(centreGradients[3 * b], centreGradients[3 * b + 1], centreGradients[3 * b + 2]);
        if (std::isfinite(centreValues[b]) && std::isfinite(glm::length(g))) steepest = std::max(steepest, glm::length(g));
    }
    const std::size_t n = std::size_t(blocksPerAxis);
    for (std::size_t b = 0; b < centreValues.size(); ++b) {
        const std::size_t at[3] = {b % n, b / n % n, b / (n * n)};
        const std::size_t stride[3] = {1, n, n * n};
        for (int a = 0; a < 3; ++a) {
            if (at[a] + 2 >= n) continue; // the last block may be short: its centre is off the spacing
            const float quotient = std::abs(centreValues[b + stride[a]] - centreValues[b]) / float(grid.step[a] * kBlock);
            if (std::isfinite(quotient)) steepest = std::max(steepest, quotient);
        }
    }
    return std::max(1.0f, 1.25f * steepest);
}

void Extraction::keep(std::size_t block) {
    blockSlot[block] = std::int32_t(kept.size());
    const std::size_t n = std::size_t(blocksPerAxis);
    kept.push_back({int(block % n), int(block / n % n), int(block / (n * n))});
    stats.blocksKept = kept.size();
}

// 2. The grid points of the kept blocks, (B+1)^3 per block in a dense array (a point on a face
// two kept blocks share is evaluated by both, at the same coordinates, so to the same value). Only
// the points of sub-blocks that may hold surface are evaluated (selectSubBlocks); the others hold
// the value at the centre of the octant or sub-block the bound skipped. A skipped block whose face
// with a kept block the surface crosses is kept and evaluated after all, until no crossed face
// leads to a skipped block: a bound that was too low loses no connected surface.
Expected<void> Extraction::evaluateBlocks() {
    detail::PointEvaluator lattice;
    if (auto ok = lattice.build(sdf, "analysis/lattice.glsl", options.time, options.parameters); !ok) return ok.error();
    lattice.setClip(clipLow, clipHigh);
    for (std::size_t from = 0; from < kept.size();) {
        const std::size_t to = kept.size();
        values.resize(to * std::size_t(kPoints));
        wantedSubs.resize(to, 0);
        evaluatedSubs.resize(to, 0);
        evaluatedPoints.resize(to);
        if (auto ok = selectSubBlocks(lattice, from, to); !ok) return ok.error();
        do {
            if (auto ok = evaluateWanted(lattice); !ok) return ok.error();
        } while (wantMoreSubBlocks());
        // Every block again: a repair in a later round can change an earlier block's face.
        for (std::size_t slot = 0; slot < to; ++slot) keepNeighboursAcrossCrossedFaces(slot);
        from = to;
        if (progress.isCancelled()) return makeError("mesh: cancelled");
    }
    stats.boundsCutPoints = lattice.clipped();
    return {};
}

bool Extraction::maySurface(float f, double halfDiagonal) const {
    const float bound = stats.lipschitzUsed;
    return bound <= 0.0f || !std::isfinite(f) || std::abs(double(f)) <= double(bound) * halfDiagonal * 1.001 + 1e-6;
}

// 2a. Which sub-blocks of blocks [from, to) may hold surface: the field at the centres of each
// block's eight octants, then at the centres of the eight sub-blocks of each octant that may (each
// by the bound and its half diagonal, as the blocks were). The centres are grid points and keep
// their values; the other points of a skipped cube take its centre's. A block cut short by the
// grid's end is evaluated whole, and so are the blocks of a round of fewer than
// kFewestBlocksForSubBlocks: there the two extra dispatches cost more than they save (a 16^3 grid
// took 0.6 ms longer with them).
Expected<void> Extraction::selectSubBlocks(detail::PointEvaluator& lattice, std::size_t from, std::size_t to) {
    struct Cube {
        std::size_t slot;
        std::array<int, 3> lo; // local corner, in cells
    };
    std::vector<float> indices, f;
    auto centres = [&](const std::vector<Cube>& cubes, int size) -> Expected<void> {
        if (cubes.empty()) return {};
        indices.clear();
        indices.reserve(3 * cubes.size());
        for (const Cube& c : cubes)
            for (int a = 0; a < 3; ++a)
                indices.push_back(float(kept[c.slot][std::size_t(a)] * kBlock + c.lo[std::size_t(a)] + size / 2));
        if (auto ok = lattice.evaluateLattice(indices, glm::vec3(grid.origin), glm::vec3(grid.step), 0, grid.n, f); !ok)
            return ok.error();
        stats.pointsEvaluated += f.size();
        for (std::size_t q = 0; q < cubes.size(); ++q) {
            const Cube& c = cubes[q];
            const int p = (c.lo[2] + size / 2) * kStride[2] + (c.lo[1] + size / 2) * kStride[1] + c.lo[0] + size / 2;
            values[c.slot * std::size_t(kPoints) + std::size_t(p)] = f[q];
            evaluatedPoints[c.slot].set(std::size_t(p));
        }
        return {};
    };
    // The points of a skipped cube not evaluated already take its centre's value.
    auto fill = [&](const Cube& c, int size, float value) {
        float* v = values.data() + c.slot * std::size_t(kPoints);
        const std::bitset<kPoints>& done = evaluatedPoints[c.slot];
        for (int k = c.lo[2]; k <= c.lo[2] + size; ++k)
            for (int j = c.lo[1]; j <= c.lo[1] + size; ++j)
                for (int i = c.lo[0]; i <= c.lo[0] + size; ++i)
                    if (const int p = (k * kSide + j) * kSide + i; !done.test(std::size_t(p))) v[p] = value;
    };
    constexpr std::size_t kFewestBlocksForSubBlocks = 64;
    std::vector<Cube> octants, subs;
    for (std::size_t slot = from; slot < to; ++slot) {
        const auto& b = kept[slot];
        if (to - from < kFewestBlocksForSubBlocks || b[0] * kBlock + kBlock > grid.n || b[1] * kBlock + kBlock > grid.n ||
            b[2] * kBlock + kBlock > grid.n) {
            wantedSubs[slot] = ~std::uint64_t(0);
            continue;
        }
        for (int o = 0; o < 8; ++o) octants.push_back({slot, {(o & 1) * kOctant, (o >> 1 & 1) * kOctant, (o >> 2) * kOctant}});
    }
    if (auto ok = centres(octants, kOctant); !ok) return ok.error();
    const double octantHalfDiagonal = 0.5 * glm::length(grid.step * double(kOctant));
    for (std::size_t q = 0; q < octants.size(); ++q) {
        const Cube& o = octants[q];
        if (!maySurface(f[q], octantHalfDiagonal)) {
            fill(o, kOctant, f[q]);
            continue;
        }
        for (int s = 0; s < 8; ++s)
            subs.push_back({o.slot, {o.lo[0] + (s & 1) * kSub, o.lo[1] + (s >> 1 & 1) * kSub, o.lo[2] + (s >> 2) * kSub}});
    }
    if (auto ok = centres(subs, kSub); !ok) return ok.error();
    const double subHalfDiagonal = 0.5 * glm::length(grid.step * double(kSub));
    for (std::size_t q = 0; q < subs.size(); ++q) {
        const Cube& s = subs[q];
        if (maySurface(f[q], subHalfDiagonal))
            wantedSubs[s.slot] |= std::uint64_t(1) << subIndex(s.lo[0] / kSub, s.lo[1] / kSub, s.lo[2] / kSub);
        else
            fill(s, kSub, f[q]);
    }
    return {};
}

// 2b. The grid points of every wanted sub-block not evaluated yet, each once per block: a lattice
// of single points, so each has the float position any block's lattice gives it. Chunks of blocks
// list their points on several threads, and write the values back the same way.
Expected<void> Extraction::evaluateWanted(detail::PointEvaluator& lattice) {
    const std::size_t count = wantedSubs.size();
    const std::size_t chunks = chunkCount(count, 256);
    std::vector<std::vector<std::uint16_t>> local(chunks); // per chunk, per block in order: its new points
    std::vector<std::vector<std::uint32_t>> perBlock(chunks);
    // Points past the grid's end (in a block it cuts short) have the index of the last point on
    // their line, so its value: they are copied from it, not evaluated again.
    std::vector<std::vector<std::size_t>> beyond(chunks);
    forEachChunk(count, chunks, [&](std::size_t chunk, std::size_t first, std::size_t end) {
        for (std::size_t slot = first; slot < end; ++slot) {
            std::uint64_t fresh = wantedSubs[slot] & ~evaluatedSubs[slot];
            evaluatedSubs[slot] |= fresh;
            std::bitset<kPoints>& done = evaluatedPoints[slot];
            const auto& b = kept[slot];
            const int last[3] = {grid.n - b[0] * kBlock, grid.n - b[1] * kBlock, grid.n - b[2] * kBlock};
            const std::size_t before = local[chunk].size();
            for (; fresh != 0; fresh &= fresh - 1) {
                const int s = std::countr_zero(fresh);
                const std::array<int, 3> lo = subCorner(s);
                for (int k = lo[2]; k <= lo[2] + kSub; ++k)
                    for (int j = lo[1]; j <= lo[1] + kSub; ++j)
                        for (int i = lo[0]; i <= lo[0] + kSub; ++i)
                            if (const int p = (k * kSide + j) * kSide + i; !done.test(std::size_t(p))) {
                                done.set(std::size_t(p));
                                if (i > last[0] || j > last[1] || k > last[2])
                                    beyond[chunk].push_back(slot * std::size_t(kPoints) + std::size_t(p));
                                else
                                    local[chunk].push_back(std::uint16_t(p));
                            }
            }
            perBlock[chunk].push_back(std::uint32_t(local[chunk].size() - before));
        }
    });
    std::vector<std::size_t> offset(chunks + 1, 0);
    for (std::size_t c = 0; c < chunks; ++c) offset[c + 1] = offset[c] + local[c].size();
    std::vector<float> indices(3 * offset[chunks]), fresh;
    auto walk = [&](std::size_t chunk, std::size_t first, std::size_t end, auto&& visit) {
        std::size_t at = offset[chunk], q = 0;
        for (std::size_t slot = first; slot < end; ++slot)
            for (std::uint32_t n = perBlock[chunk][slot - first]; n > 0; --n, ++q, ++at) visit(slot, local[chunk][q], at);
    };
    forEachChunk(count, chunks, [&](std::size_t chunk, std::size_t first, std::size_t end) {
        walk(chunk, first, end, [&](std::size_t slot, int p, std::size_t at) {
            const auto& b = kept[slot];
            indices[3 * at] = float(b[0] * kBlock + p % kSide);
            indices[3 * at + 1] = float(b[1] * kBlock + p / kSide % kSide);
            indices[3 * at + 2] = float(b[2] * kBlock + p / (kSide * kSide));
        });
    });
    if (auto ok = lattice.evaluateLattice(indices, glm::vec3(grid.origin), glm::vec3(grid.step), 0, grid.n, fresh); !ok)
        return ok.error();
    forEachChunk(count, chunks, [&](std::size_t chunk, std::size_t first, std::size_t end) {
        walk(chunk, first, end,
             [&](std::size_t slot, int p, std::size_t at) { values[slot * std::size_t(kPoints) + std::size_t(p)] = fresh[at]; });
        for (const std::size_t at : beyond[chunk]) {
            const std::size_t slot = at / std::size_t(kPoints);
            const int p = int(at % std::size_t(kPoints));
            const auto& b = kept[slot];
            const int i = std::min(p % kSide, grid.n - b[0] * kBlock), j = std::min(p / kSide % kSide, grid.n - b[1] * kBlock),
                      k = std::min(p / (kSide * kSide), grid.n - b[2] * kBlock);
            values[at] = values[slot * std::size_t(kPoints) + std::size_t((k * kSide + j) * kSide + i)];
        }
    });
    stats.pointsEvaluated += fresh.size();
    return {};
}

// The sub-blocks of a block that hold local grid point (i, j, k).
std::uint64_t subsHolding(int i, int j, int k) {
    std::uint64_t bits = 0;
    auto candidates = [](int c, int out[2]) {
        int count = 0;
        if (c / kSub < kSubsPerAxis) out[count++] = c / kSub;
        if (c % kSub == 0 && c > 0) out[count++] = c / kSub - 1;
        return count;
    };
    int x[2], y[2], z[2];
    const int nx = candidates(i, x), ny = candidates(j, y), nz = candidates(k, z);
    for (int a = 0; a < nx; ++a)
        for (int b = 0; b < ny; ++b)
            for (int c = 0; c < nz; ++c) bits |= std::uint64_t(1) << subIndex(x[a], y[b], z[c]);
    return bits;
}

// 2c. Where a bound that was too low skipped surface, more sub-blocks are wanted: a skipped one
// whose points are not all of one sign (so every cell the surface crosses has all eight corners
// evaluated), and those holding a point on a block's face that is not evaluated in this block and
// whose sign the neighbouring block's copy contradicts (so both blocks see the same crossings on
// their shared face). Returns whether any was.
bool Extraction::wantMoreSubBlocks() {
    const std::size_t count = wantedSubs.size();
    const std::size_t chunks = chunkCount(count, 64);
    std::vector<char> added(chunks, 0);
    forEachChunk(count, chunks, [&](std::size_t chunk, std::size_t first, std::size_t end) {
        for (std::size_t slot = first; slot < end; ++slot) {
            const float* v = values.data() + slot * std::size_t(kPoints);
            std::uint64_t more = 0;
            for (std::uint64_t skipped = ~wantedSubs[slot]; skipped != 0; skipped &= skipped - 1) {
                const int s = std::countr_zero(skipped);
                const std::array<int, 3> lo = subCorner(s);
                bool seenInside = false, seenOutside = false;
                for (int k = lo[2]; k <= lo[2] + kSub; ++k)
                    for (int j = lo[1]; j <= lo[1] + kSub; ++j)
                        for (int i = lo[0]; i <= lo[0] + kSub; ++i) {
                            const float f = v[(k * kSide + j) * kSide + i];
                            if (std::isfinite(f)) (inside(f) ? seenInside : seenOutside) = true;
                        }
                if (seenInside && seenOutside) more |= std::uint64_t(1) << s;
            }
            const auto& b = kept[slot];
            const std::bitset<kPoints>& done = evaluatedPoints[slot];
            for (int axis = 0; axis < 3; ++axis)
                for (int side = 0; side < 2; ++side) {
                    const std::optional<std::size_t> next = neighbourBlock(b, axis, side);
                    if (!next) continue;
                    const std::int32_t other = blockSlot[*next];
                    if (other < 0) continue;
                    const float* w = values.data() + std::size_t(other) * std::size_t(kPoints);
                    const int u = (axis + 1) % 3, t = (axis + 2) % 3;
                    for (int j = 0; j < kSide; ++j)
                        for (int i = 0; i < kSide; ++i) {
                            int local[3];
                            local[axis] = side ? kBlock : 0;
                            local[u] = i;
                            local[t] = j;
                            const int p = local[0] * kStride[0] + local[1] * kStride[1] + local[2] * kStride[2];
                            if (done.test(std::size_t(p))) continue;
                            const int q = p + (side ? -kBlock : kBlock) * kStride[axis];
                            if (crosses(v[p], w[q])) more |= subsHolding(local[0], local[1], local[2]);
                        }
                }
            if (more & ~wantedSubs[slot]) {
                wantedSubs[slot] |= more;
                added[chunk] = 1;
            }
        }
    });
    return std::find(added.begin(), added.end(), 1) != added.end();
}

void Extraction::keepNeighboursAcrossCrossedFaces(std::size_t slot) {
    const std::array<int, 3> b = kept[slot];
    const float* v = values.data() + slot * std::size_t(kPoints);
    for (int axis = 0; axis < 3; ++axis)
        for (int side = 0; side < 2; ++side) {
            const std::optional<std::size_t> next = neighbourBlock(b, axis, side);
            if (!next || blockSlot[*next] >= 0) continue;
            const std::size_t index = *next;
            const int u = (axis + 1) % 3, w = (axis + 2) % 3;
            bool seenInside = false, seenOutside = false;
            for (int j = 0; j < kSide && !(seenInside && seenOutside); ++j)
                for (int i = 0; i < kSide; ++i) {
                    const float f = v[(side ? kBlock : 0) * kStride[axis] + i * kStride[u] + j * kStride[w]];
                    if (!std::isfinite(f)) continue;
                    (inside(f) ? seenInside : seenOutside) = true;
                }
            if (seenInside && seenOutside) {
                keep(index);
                ++stats.blocksGrown;
            }
        }
}

} // namespace sdfwb::meshing::detail
