// Dual contouring (Ju et al. 2002) on a grid whose values come from the GPU: blocks of 8^3 cells
// that a Lipschitz bound proves empty are skipped; in the others, every patch of surface in a cell
// (its crossings joined along the cell's faces) gets one vertex, the minimiser of a QEF built from
// the patch's edge crossings and the field's normals there (so the vertex sits on sharp edges and
// corners, where marching cubes cuts them); every grid edge with a sign change becomes a polygon
// joining the vertices of its four cells, with a vertex on a face between two cells whose patches
// both join that face's two segments (a tunnel thinner than a cell), so the mesh stays manifold.
#include <meshing/Mesh.h>

#include "Extraction.h"
#include "PointEvaluator.h"
#include "Qef.h"
#include "Refine.h"
#include "Topology.h"

#include <core/Parallel.h>

#include <glm/geometric.hpp>

#include <algorithm>
#include <array>
#include <bit>
#include <bitset>
#include <chrono>
#include <cmath>
#include <iterator>
#include <limits>
#include <optional>
#include <unordered_map>
#include <utility>
#include <vector>

namespace sdfwb::meshing {

std::pair<glm::vec3, glm::vec3> cutBox(const MeshOptions& options) {
    const glm::dvec3 step = (glm::dvec3(options.boundsMax) - glm::dvec3(options.boundsMin)) / double(options.resolution);
    return {glm::vec3(glm::dvec3(options.boundsMin) - 0.5 * step), glm::vec3(glm::dvec3(options.boundsMax) + 0.5 * step)};
}

namespace detail {

Expected<std::pair<Mesh, MeshStats>> Extraction::run() {
    const auto start = std::chrono::steady_clock::now();
    // One cell of padding on every side, and the field cut by a box half a cell beyond the bounds:
    // a shape that leaves the bounds is closed there (flat caps, sharp rims), so every mesh is
    // closed. A shape inside the bounds is meshed as before: the cut changes no sign there.
    const glm::dvec3 step = (glm::dvec3(options.boundsMax) - glm::dvec3(options.boundsMin)) / double(options.resolution);
    grid = Grid{options.resolution + 2, glm::dvec3(options.boundsMin) - step, step};
    const auto [cutLow, cutHigh] = cutBox(options);
    clipLow = glm::dvec3(cutLow);
    clipHigh = glm::dvec3(cutHigh);
    if (auto ok = field.build(sdf, "analysis/points.glsl", options.time, options.parameters); !ok) return ok.error();
    field.setClip(clipLow, clipHigh);

    // A hundredth of a cell: with a twentieth, a crossing that near a crease got a normal mixed from
    // both faces, whose plane put a rotated box's corner 2.3e-3 off at 128 cells.
    normalStep = float(0.01 * std::min({grid.step.x, grid.step.y, grid.step.z}));
    vertexMargin = 0.5 * std::min({grid.step.x, grid.step.y, grid.step.z});
    auto phaseStart = start;
    auto phase = [&](const char* name) {
        const auto now = std::chrono::steady_clock::now();
        stats.phaseSeconds.emplace_back(name, std::chrono::duration<double>(now - phaseStart).count());
        phaseStart = now;
    };
    phase("compile");
    if (auto ok = selectBlocks(); !ok) return ok.error();
    phase("select blocks");
    progress(1, 4);
    if (auto ok = evaluateBlocks(); !ok) return ok.error();
    phase("evaluate blocks");
    if (progress.isCancelled()) return makeError("mesh: cancelled");
    progress(2, 4);
    findEdges();
    phase("find edges");
    if (auto ok = placeCrossings(); !ok) return ok.error();
    phase("place crossings");
    progress(3, 4);
    placeVertices();
    splitJoinedFaces();
    phase("place vertices");
    if (auto ok = projectVertices(); !ok) return ok.error();
    phase("project vertices");
    if (auto ok = connectQuads(); !ok) return ok.error();
    const auto weldTolerance = float(1e-6 * std::min({grid.step.x, grid.step.y, grid.step.z}));
    detail::weldCoincidentVertices(mesh, weldTolerance);
    stats.collinearFlips = flipCollinearTriangles(mesh);
    detail::nudgeCollinearVertices(mesh);
    phase("connect");
    if (options.refine > 0) {
        const Topology coarse = checkTopology(mesh);
        const std::uint64_t coarseTriangles = mesh.triangleCount();
        auto refined = detail::refineOntoSurface(mesh, field, options.refine, normalStep, options.refineTriangleLimit);
        if (!refined) return refined.error();
        stats.pointsEvaluated += refined->pointsEvaluated;
        stats.midpointsKept = refined->midpointsKept;
        stats.topology = subdividedTopology(coarse, coarseTriangles, options.refine);
        // Two vertices at one position that the weld had to keep apart (a pinch in a fractal's
        // tunnels) give their edges' midpoints one position too, and the triangles between those
        // zero area: welded and flipped as the coarse mesh was, and then checked afresh.
        if (countDegenerateTriangles(mesh) > 0) {
            detail::weldCoincidentVertices(mesh, weldTolerance);
            stats.collinearFlips += flipCollinearTriangles(mesh);
            detail::nudgeCollinearVertices(mesh);
            stats.topology = checkTopology(mesh);
        }
        phase("refine");
    }
    progress(4, 4);
    stats.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return std::pair<Mesh, MeshStats>{std::move(mesh), stats};
}

// 3. Edges with a sign change, block by block in slot order (so that a block's bits number them);
// chunks of blocks on several threads, joined in slot order.
void Extraction::findEdges() {
    blockEdges.assign(kept.size(), {});
    struct Found {
        std::vector<Edge> edges;
        std::vector<float> values;
    };
    const std::size_t chunks = chunkCount(kept.size(), 64);
    std::vector<Found> found(chunks);
    forEachChunk(kept.size(), chunks, [&](std::size_t chunk, std::size_t first, std::size_t end) {
        Found& out = found[chunk];
        for (std::size_t slot = first; slot < end; ++slot) {
            const auto& b = kept[slot];
            const float* v = values.data() + slot * std::size_t(kPoints);
            const bool last[3] = {b[0] == blocksPerAxis - 1, b[1] == blocksPerAxis - 1, b[2] == blocksPerAxis - 1};
            RankedBits<kEdgeSlots>& bits = blockEdges[slot];
            const std::bitset<kPoints>& evaluated = evaluatedPoints[slot];
            for (int k = 0; k < kSide; ++k)
                for (int j = 0; j < kSide; ++j)
                    for (int i = 0; i < kSide; ++i) {
                        const int p = (k * kSide + j) * kSide + i;
                        // A point no evaluated sub-block holds lies in skipped ones only, whose points
                        // have one sign (wantMoreSubBlocks): none of its edges crosses.
                        if (!evaluated.test(std::size_t(p))) continue;
                        const int local[3] = {i, j, k};
                        for (int axis = 0; axis < 3; ++axis) {
                            if (local[axis] == kBlock) continue;
                            const float f0 = v[p], f1 = v[p + kStride[axis]];
                            if (!crosses(f0, f1)) continue;
                            bits.set(3 * p + axis);
                            const bool owned = (i < kBlock || last[0]) && (j < kBlock || last[1]) && (k < kBlock || last[2]);
                            out.edges.push_back(
                                {b[0] * kBlock + i, b[1] * kBlock + j, b[2] * kBlock + k, std::int8_t(axis), inside(f0), owned});
                            out.values.insert(out.values.end(), {f0, f1});
                        }
                    }
        }
    });
    for (Found& part : found) {
        edges.insert(edges.end(), part.edges.begin(), part.edges.end());
        edgeValues.insert(edgeValues.end(), part.values.begin(), part.values.end());
    }
    std::uint32_t edgeCount = 0;
    for (RankedBits<kEdgeSlots>& bits : blockEdges) edgeCount = bits.number(edgeCount);
}

Expected<void> Extraction::placeCrossings() {
    auto edgeStart = [&](const Edge& e) { return glm::dvec3(grid.point(e.i, e.j, e.k)); };
    auto edgeVector = [&](const Edge& e) {
        glm::dvec3 d(0.0);
        d[e.axis] = grid.step[e.axis];
        return d;
    };
    // The crossing on each edge by false position with the Illinois rule (the field, not a linear
    // fit of its ends: near a box's edge the inside value follows another face): superlinear on
    // smooth and kinked fields alike; an edge stops when its crossing is known to 1e-4 of its length.
    crossings.assign(3 * edges.size(), 0.0f);
    {
        struct Bracket {
            double a = 0.0, b = 1.0, fa, fb, t;
            int side = 0;
        };
        std::vector<Bracket> brackets(edges.size());
        std::vector<std::uint32_t> active(edges.size());
        for (std::size_t e = 0; e < edges.size(); ++e) {
            brackets[e].fa = edgeValues[2 * e];
            brackets[e].fb = edgeValues[2 * e + 1];
            active[e] = std::uint32_t(e);
        }
        std::vector<float> guesses, guessValues;
        for (int iteration = 0; iteration < 8 && !active.empty(); ++iteration) {
            guesses.resize(3 * active.size());
            const std::size_t chunks = chunkCount(active.size(), 8192);
            forEachChunk(active.size(), chunks, [&](std::size_t, std::size_t first, std::size_t end) {
                for (std::size_t q = first; q < end; ++q) {
                    Bracket& r = brackets[active[q]];
                    r.t = (r.a * r.fb - r.b * r.fa) / (r.fb - r.fa);
                    if (!(r.t > r.a && r.t < r.b)) r.t = 0.5 * (r.a + r.b);
                    const glm::dvec3 p = edgeStart(edges[active[q]]) + r.t * edgeVector(edges[active[q]]);
                    guesses[3 * q] = float(p.x);
                    guesses[3 * q + 1] = float(p.y);
                    guesses[3 * q + 2] = float(p.z);
                }
            });
            if (auto ok = field.evaluate(guesses, guessValues, nullptr); !ok) return ok.error();
            stats.pointsEvaluated += guessValues.size();
            // Each chunk keeps its edges still open at its own start (in order), then the lists close up.
            std::vector<std::size_t> stillOpen(chunks);
            forEachChunk(active.size(), chunks, [&](std::size_t chunk, std::size_t first, std::size_t end) {
                std::size_t still = first;
                for (std::size_t q = first; q < end; ++q) {
                    Bracket& r = brackets[active[q]];
                    const double f = guessValues[q];
                    if (!std::isfinite(f)) continue;
                    if (inside(float(f)) == inside(float(r.fa))) {
                        r.a = r.t;
                        r.fa = f;
                        if (r.side == -1) r.fb *= 0.5;
                        r.side = -1;
                    } else {
                        r.b = r.t;
                        r.fb = f;
                        if (r.side == 1) r.fa *= 0.5;
                        r.side = 1;
                    }
                    // Done when t is known to 1e-4 of the edge: the bracket is that small, or |f| over the
                    // field's slope along the edge is (a small |f| alone misleads on an edge that grazes
                    // the surface, where the slope is small too).
                    const double slope = std::abs(r.fb - r.fa) / (r.b - r.a);
                    if (r.b - r.a > 1e-4 && std::abs(f) > 1e-4 * slope) active[still++] = active[q];
                }
                stillOpen[chunk] = still - first;
            });
            std::size_t still = 0;
            for (std::size_t chunk = 0; chunk < chunks; ++chunk) {
                const std::size_t first = active.size() * chunk / chunks;
                std::copy_n(active.begin() + std::ptrdiff_t(first), stillOpen[chunk], active.begin() + std::ptrdiff_t(still));
                still += stillOpen[chunk];
            }
            active.resize(still);
            if (progress.isCancelled()) return makeError("mesh: cancelled");
        }
        for (std::size_t e = 0; e < edges.size(); ++e) {
            const Bracket& r = brackets[e];
            // Never on a grid point itself: where the surface touches the grid at a point (f = 0
            // there, a torus's pole on a grid plane), the four cells around would otherwise put their
            // vertices within float rounding of each other and fold the mesh there.
            const double t = std::clamp(r.t, 1.0 / 1024.0, 1.0 - 1.0 / 1024.0);
            const glm::dvec3 p = edgeStart(edges[e]) + t * edgeVector(edges[e]);
            crossings[3 * e] = float(p.x);
            crossings[3 * e + 1] = float(p.y);
            crossings[3 * e + 2] = float(p.z);
        }
    }
    if (auto ok = field.evaluate(crossings, crossingValues, &normals, normalStep); !ok) return ok.error();
    stats.pointsEvaluated += crossingValues.size();
    return {};
}

namespace {

// Twice the area of the smallest triangle of the fan from polygon[apex] over the polygon.
double smallestFanTriangle(const std::vector<glm::vec3>& vertices, const std::uint32_t* polygon, int size, int apex) {
    double least = std::numeric_limits<double>::infinity();
    for (int k = 1; k + 1 < size; ++k) {
        const glm::dvec3 a(vertices[polygon[apex]]), b(vertices[polygon[(apex + k) % size]]),
            c(vertices[polygon[(apex + k + 1) % size]]);
        least = std::min(least, glm::length(glm::cross(b - a, c - a)));
    }
    return least;
}

// A fan from polygon[apex] never takes the diagonal between the two neighbours of a face vertex
// (indices from firstFaceVertex on): that edge would gain a third triangle.
bool fanAllowed(const std::uint32_t* polygon, int size, int apex, std::uint32_t firstFaceVertex) {
    for (int k = 2; k + 1 < size; ++k) { // the diagonals (apex, apex + k)
        const int other = (apex + k) % size;
        for (int between = 0; between < size; ++between) {
            const int before = (between + size - 1) % size, after = (between + 1) % size;
            if (polygon[between] >= firstFaceVertex && ((apex == before && other == after) || (other == before && apex == after)))
                return false;
        }
    }
    return true;
}

// Among the fans allowed, the one whose smallest triangle is largest (none of zero area first).
int bestFanApex(const std::vector<glm::vec3>& vertices, const std::uint32_t* polygon, int size, std::uint32_t firstFaceVertex) {
    int apex = 0;
    double best = -1.0;
    for (int k = 0; k < size; ++k)
        if (fanAllowed(polygon, size, k, firstFaceVertex))
            if (const double least = smallestFanTriangle(vertices, polygon, size, k); least > best) {
                best = least;
                apex = k;
            }
    return apex;
}

// A quad whose two diagonals lie further apart than `fold` along its normal (across a crease),
// with no triangle of zero area either way it is cut.
bool foldedQuad(const std::vector<glm::vec3>& vertices, const std::uint32_t* quad, double fold) {
    const glm::dvec3 p0(vertices[quad[0]]), p1(vertices[quad[1]]), p2(vertices[quad[2]]), p3(vertices[quad[3]]);
    const glm::dvec3 normal = glm::cross(p2 - p0, p3 - p1);
    const double length = glm::length(normal);
    return length > 0.0 && std::abs(glm::dot(0.5 * (p0 + p2 - p1 - p3), normal)) > fold * length &&
           smallestFanTriangle(vertices, quad, 4, 0) > 0.0 && smallestFanTriangle(vertices, quad, 4, 1) > 0.0;
}

} // namespace

// 5. A quad per sign-changing edge (from the block that owns it), wound so that it faces
// outward (towards f > 0).
Expected<void> Extraction::connectQuads() {
    const std::uint32_t firstFaceVertexIndex = std::uint32_t(cellVertexCount);
    const int offsets[4][2] = {{-1, -1}, {0, -1}, {0, 0}, {-1, 0}}; // the cells around an edge, in (u, v)
    const std::size_t chunks = chunkCount(edges.size(), 4096);
    std::vector<std::vector<std::uint32_t>> triangles(chunks); // each chunk's, joined in edge order
    struct Folded {
        std::size_t at; // its first triangle's first index in its chunk's triangles
        std::array<std::uint32_t, 4> quad;
        int apex; // the diagonal (apex, apex + 2) the shorter-diagonal rule chose
    };
    std::vector<std::vector<Folded>> folded(chunks);
    constexpr double kFold = 0.01;
    const double cellSize = std::min({grid.step.x, grid.step.y, grid.step.z});
    forEachChunk(edges.size(), chunks, [&](std::size_t chunk, std::size_t first, std::size_t end) {
        std::vector<std::uint32_t>& out = triangles[chunk];
        out.reserve(6 * (end - first));
        for (std::size_t index = first; index < end; ++index) {
            const Edge& edge = edges[index];
            if (!edge.owned) continue;
            const int u = (edge.axis + 1) % 3, v = (edge.axis + 2) % 3;
            std::int64_t cells[4][3];
            const CellRecord* records[4];
            int locals[4];
            std::uint32_t quad[4];
            bool complete = true;
            for (int q = 0; q < 4 && complete; ++q) {
                std::int64_t* c = cells[q];
                c[0] = edge.i;
                c[1] = edge.j;
                c[2] = edge.k;
                c[u] += offsets[q][0];
                c[v] += offsets[q][1];
                // The edge seen from this cell: at its +u side when the cell lies at -u, and so on.
                locals[q] = edge.axis * 4 + (-offsets[q][0]) + 2 * (-offsets[q][1]);
                records[q] = recordAt(c);
                complete = records[q] != nullptr;
                if (complete) quad[q] = records[q]->firstVertex + (records[q]->vertexOfEdge >> (2 * locals[q]) & 3u);
            }
            if (!complete) continue;
            // The polygon: the four cells' vertices, with a face vertex between two cells whose patches
            // both join an ambiguous face's segments (splitJoinedFaces).
            std::uint32_t polygon[8];
            int size = 0;
            for (int q = 0; q < 4; ++q) {
                polygon[size++] = quad[q];
                const int r = (q + 1) % 4;
                const int w = offsets[q][0] != offsets[r][0] ? u : v;
                const int lower = offsets[q][0] + offsets[q][1] < offsets[r][0] + offsets[r][1] ? q : r;
                const int upper = lower == q ? r : q;
                if (!(records[lower]->jointFaces >> (2 * w + 1) & 1) || !(records[upper]->jointFaces >> (2 * w) & 1)) continue;
                const int face = 2 * w + 1, paired = records[lower]->crossPaired >> face & 1;
                int segment = 1;
                for (int end = 0; end < 2; ++end)
                    if (tables.faceEdges[face][kSegments[paired][0][end]] == locals[lower]) segment = 0;
                const auto found = faceVertices.find(faceKey(cells[lower], w, segment));
                if (found == faceVertices.end()) continue;
                polygon[size++] = found->second;
            }
            // (u, v) counter-clockwise looking down +axis; the surface faces +axis when the edge starts inside.
            if (!edge.startInside) std::reverse(polygon, polygon + size);
            // A fan from one of the polygon's vertices. Without face vertices: the quad's shorter
            // diagonal. With them: never the diagonal between the two neighbours of a face vertex (the
            // edge that would gain a third triangle); every other diagonal is this polygon's alone.
            // Among the fans allowed, one with no triangle of zero area (vertices on one crease line),
            // then the one whose smallest triangle is largest.
            const std::vector<glm::vec3>& vertices = mesh.vertices;
            int apex = 0;
            if (size == 4) {
                const float d02 = glm::length(vertices[polygon[0]] - vertices[polygon[2]]);
                const float d13 = glm::length(vertices[polygon[1]] - vertices[polygon[3]]);
                apex = d02 <= d13 ? 0 : 1;
                if (!(smallestFanTriangle(vertices, polygon, 4, apex) > 0.0) &&
                    smallestFanTriangle(vertices, polygon, 4, 1 - apex) > 0.0)
                    apex = 1 - apex;
                // A quad folded by more than kFold of a cell (across a crease) is decided by the field
                // at its diagonals' middles, after this pass.
                if (foldedQuad(vertices, polygon, kFold * cellSize))
                    folded[chunk].push_back({out.size(), {polygon[0], polygon[1], polygon[2], polygon[3]}, apex});
            } else {
                apex = bestFanApex(vertices, polygon, size, firstFaceVertexIndex);
            }
            for (int k = 1; k + 1 < size; ++k)
                out.insert(out.end(), {polygon[apex], polygon[(apex + k) % size], polygon[(apex + k + 1) % size]});
        }
    });
    // Each folded quad takes the diagonal whose middle lies nearer the surface (|f| smaller by a
    // tenth at least): the one along a crease rather than the one across it, which cuts the crease
    // off (or fills a groove) by up to the fold.
    std::vector<float> middles, f;
    for (const auto& part : folded)
        for (const Folded& q : part)
            for (int d = 0; d < 2; ++d) {
                const glm::vec3 m = 0.5f * (mesh.vertices[q.quad[std::size_t(d)]] + mesh.vertices[q.quad[std::size_t(d + 2)]]);
                middles.insert(middles.end(), {m.x, m.y, m.z});
            }
    if (auto ok = field.evaluate(middles, f, nullptr); !ok) return ok.error();
    stats.pointsEvaluated += f.size();
    std::size_t at = 0;
    for (std::size_t chunk = 0; chunk < chunks; ++chunk)
        for (const Folded& q : folded[chunk]) {
            const float along02 = std::abs(f[at]), along13 = std::abs(f[at + 1]);
            at += 2;
            if (!std::isfinite(along02) || !std::isfinite(along13)) continue;
            const int apex = along02 <= along13 ? 0 : 1;
            if (apex == q.apex || (apex == 0 ? along02 : along13) > 0.9f * (apex == 0 ? along13 : along02)) continue;
            std::uint32_t* t = triangles[chunk].data() + q.at;
            const std::uint32_t a = q.quad[std::size_t(apex)], b = q.quad[std::size_t(apex + 1)],
                                c = q.quad[std::size_t(apex + 2)], d = q.quad[std::size_t((apex + 3) % 4)];
            t[0] = a, t[1] = b, t[2] = c, t[3] = a, t[4] = c, t[5] = d;
            ++stats.foldedQuadsTurned;
        }
    std::size_t total = mesh.indices.size();
    for (const auto& part : triangles) total += part.size();
    mesh.indices.reserve(total);
    for (const auto& part : triangles) mesh.indices.insert(mesh.indices.end(), part.begin(), part.end());
    return {};
}

} // namespace detail

Expected<std::pair<Mesh, MeshStats>> extractMesh(const shaders::PreparedSdf& sdf, const MeshOptions& options,
                                                 const ProgressSink& progress) {
    if (options.resolution < 2 || options.resolution > 2048) return makeError("--resolution: must be 2..2048");
    for (int a = 0; a < 3; ++a)
        if (!(options.boundsMax[a] > options.boundsMin[a])) return makeError("--bounds: every maximum must exceed its minimum");
    return detail::Extraction(sdf, options, progress).run();
}

} // namespace sdfwb::meshing
