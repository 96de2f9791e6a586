// Dual contouring's step 4 (Extraction.h): a vertex per patch of surface in each cell, placed by
// its QEF, the ambiguous faces kept manifold, and the vertices projected onto the surface.
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

// 4. Vertices: one per patch of surface in each cell. A cell's crossing edges are joined along
// its faces (an ambiguous face, with four crossings, is split by the sign of its bilinear
// centre, which both cells sharing it see alike), so two sheets through one cell get a vertex
// each and the mesh stays manifold. Each vertex is its patch's QEF minimiser, clamped into the cell.
void Extraction::placeVertices() {
    blockCells.assign(kept.size(), {});
    struct Placed { // one chunk's: its vertices numbered from 0, shifted when the chunks are joined
        std::vector<glm::vec3> vertices;
        std::vector<std::array<std::int32_t, 3>> vertexCell, jointCells;
        std::vector<CellRecord> records;
        std::uint64_t creasesOnFaces = 0, verticesBesideTheirCell = 0, clampedVertices = 0;
    };
    const std::size_t chunks = chunkCount(kept.size(), 32);
    std::vector<Placed> placed(chunks);
    forEachChunk(kept.size(), chunks, [&](std::size_t chunk, std::size_t first, std::size_t end) {
        Placed& out = placed[chunk];
        for (std::size_t slot = first; slot < end; ++slot) {
            const auto& b = kept[slot];
            const float* v = values.data() + slot * std::size_t(kPoints);
            const RankedBits<kEdgeSlots>& bits = blockEdges[slot];
            const std::uint64_t evaluated = evaluatedSubs[slot];
            for (int k = 0; k < kBlock && b[2] * kBlock + k < grid.n; ++k)
                for (int j = 0; j < kBlock && b[1] * kBlock + j < grid.n; ++j)
                    for (int i = 0; i < kBlock && b[0] * kBlock + i < grid.n; ++i) {
                        if (!(evaluated >> subIndex(i / kSub, j / kSub, k / kSub) & 1u)) continue; // one sign throughout
                        const int p = (k * kSide + j) * kSide + i;
                        float corner[8];
                        int signs = 0;
                        for (int c = 0; c < 8; ++c) {
                            corner[c] = v[p + (c & 1) * kStride[0] + (c >> 1 & 1) * kStride[1] + (c >> 2) * kStride[2]];
                            signs |= int(inside(corner[c])) << c;
                        }
                        if (signs == 0 || signs == 0xff) continue; // one side (NaN counts as outside, and crosses nothing)
                        int present = 0;
                        std::uint32_t global[12];
                        for (int l = 0; l < 12; ++l) {
                            if (!crosses(corner[tables.edgeCorner[l][0]], corner[tables.edgeCorner[l][1]])) continue;
                            present |= 1 << l;
                            const int* o = tables.edgeOffset[l];
                            global[l] = bits.rank(3 * (p + o[0] * kStride[0] + o[1] * kStride[1] + o[2] * kStride[2]) + l / 4);
                        }
                        if (present == 0) continue;
                        int parent[12];
                        for (int l = 0; l < 12; ++l) parent[l] = l;
                        auto find = [&](int x) {
                            while (parent[x] != x) x = parent[x] = parent[parent[x]];
                            return x;
                        };
                        auto join = [&](int a, int c) { parent[find(a)] = find(c); };
                        int ambiguous = 0, crossPaired = 0;
                        for (int face = 0; face < 6; ++face) {
                            const int* fe = tables.faceEdges[face];
                            int on[4], count = 0;
                            for (int q = 0; q < 4; ++q)
                                if (present >> fe[q] & 1) on[count++] = fe[q];
                            if (count == 4) {
                                const int* fc = tables.faceCorners[face];
                                const float c00 = corner[fc[0]];
                                const float centre = 0.25f * (c00 + corner[fc[1]] + corner[fc[2]] + corner[fc[3]]);
                                const int paired = inside(centre) == inside(c00) ? 0 : 1;
                                for (const auto& segment : kSegments[paired]) join(fe[segment[0]], fe[segment[1]]);
                                ambiguous |= 1 << face;
                                crossPaired |= paired << face;
                            } else {
                                for (int q = 1; q < count; ++q) join(on[0], on[q]);
                            }
                        }
                        const std::int32_t cell[3] = {b[0] * kBlock + i, b[1] * kBlock + j, b[2] * kBlock + k};
                        const glm::dvec3 lo = glm::dvec3(grid.point(cell[0], cell[1], cell[2]));
                        const glm::dvec3 hi = glm::dvec3(grid.point(cell[0] + 1, cell[1] + 1, cell[2] + 1));
                        CellRecord record{std::uint32_t(out.vertices.size()), 0, 0, std::uint8_t(crossPaired)};
                        for (int face = 0; face < 6; ++face)
                            if (ambiguous >> face & 1 && find(tables.faceEdges[face][0]) == find(tables.faceEdges[face][1]))
                                record.jointFaces |= std::uint8_t(1 << face);
                        if (record.jointFaces != 0) out.jointCells.push_back({cell[0], cell[1], cell[2]});
                        std::uint32_t patch = 0;
                        for (int root = 0; root < 12; ++root) {
                            if (!(present >> root & 1) || find(root) != root) continue;
                            glm::dvec3 points[13], patchNormals[13];
                            int count = 0;
                            for (int l = 0; l < 12; ++l) {
                                if (!(present >> l & 1) || find(l) != root) continue;
                                record.vertexOfEdge |= patch << (2 * l);
                                const std::size_t e = global[l];
                                const glm::dvec3 n(normals[3 * e], normals[3 * e + 1], normals[3 * e + 2]);
                                const double length = glm::length(n);
                                points[count] = glm::dvec3(crossings[3 * e], crossings[3 * e + 1], crossings[3 * e + 2]);
                                patchNormals[count++] = length > 0.0 && std::isfinite(length) ? n / length : glm::dvec3(0.0);
                            }
                            QefSolution qef = solveQef(points, patchNormals, count);
                            if (qef.freeCount > 0 && count < 13)
                                if (const auto crease = creaseOnUpperFace(points, patchNormals, count, qef, cell, hi)) {
                                    points[count] = crease->first;
                                    patchNormals[count++] = crease->second;
                                    qef = solveQef(points, patchNormals, count);
                                    ++out.creasesOnFaces;
                                }
                            const glm::dvec3 x =
                                placeVertex(qef, lo, hi, vertexMargin, out.verticesBesideTheirCell, out.clampedVertices);
                            out.vertices.push_back(glm::vec3(x));
                            out.vertexCell.push_back({cell[0], cell[1], cell[2]});
                            ++patch;
                        }
                        blockCells[slot].set((k * kBlock + j) * kBlock + i);
                        out.records.push_back(record);
                    }
        }
    });
    for (Placed& part : placed) {
        const auto base = std::uint32_t(mesh.vertices.size());
        for (CellRecord& record : part.records) record.firstVertex += base;
        mesh.vertices.insert(mesh.vertices.end(), part.vertices.begin(), part.vertices.end());
        vertexCell.insert(vertexCell.end(), part.vertexCell.begin(), part.vertexCell.end());
        jointCells.insert(jointCells.end(), part.jointCells.begin(), part.jointCells.end());
        cellRecords.insert(cellRecords.end(), part.records.begin(), part.records.end());
        stats.creasesOnFaces += part.creasesOnFaces;
        stats.verticesBesideTheirCell += part.verticesBesideTheirCell;
        stats.clampedVertices += part.clampedVertices;
    }
    std::uint32_t cellCount = 0;
    for (RankedBits<kCells>& bits : blockCells) cellCount = bits.number(cellCount);
    stats.activeCells = cellRecords.size();
}

// f at the eight corners of cell c (corner x + 2y + 4z); false outside the grid and in blocks
// skipped as empty.
bool Extraction::cellCorners(const std::int64_t c[3], float corner[8]) const {
    for (int a = 0; a < 3; ++a)
        if (c[a] < 0 || c[a] >= grid.n) return false;
    const std::int32_t slot = blockSlot[blockIndexOf(c)];
    if (slot < 0) return false;
    const float* v = values.data() + std::size_t(slot) * std::size_t(kPoints);
    int p = 0;
    for (int a = 0; a < 3; ++a) p += int(c[a] % kBlock) * kStride[a];
    for (int k = 0; k < 8; ++k) corner[k] = v[p + (k & 1) * kStride[0] + (k >> 1 & 1) * kStride[1] + (k >> 2) * kStride[2]];
    return true;
}

// A crease that lies exactly on a face between two cells (a hexagonal prism's corner on the plane
// x = 0) leaves each cell's crossings on one face only, and each cell's vertex on its own face, so
// the triangles between them cut the crease off (by a quarter cell). The crossings on that face's
// edges lie on the crease, their normals a mix of the two faces'; the QEF drops the direction that
// mix turns by. A patch with such a crossing on its upper face gets, through it, the plane of the
// cell above whose normal turns furthest from the face the mixed normal is nearest (further than
// the mixed one does): its vertex goes onto the crease, and the cell above keeps its flat vertex,
// whose triangles then lie in that face. Only the lower cell moves: both would put their vertices
// at one point. The crease must lie in the face, the patch's face must reach a tenth of a cell off
// it, and neither face may lie in the grid's plane (the Menger sponge's walls on grid planes are
// right as they are). Returns the crossing and the other face's normal.
std::optional<std::pair<glm::dvec3, glm::dvec3>> Extraction::creaseOnUpperFace(const glm::dvec3* points,
                                                                               const glm::dvec3* patchNormals, int count,
                                                                               const QefSolution& qef, const std::int32_t cell[3],
                                                                               const glm::dvec3& hi) const {
    constexpr double kFlat = 0.99619469809;   // cos 5 degrees: a normal this close is the same face's
    constexpr double kCrease = 0.93969262078; // cos 20 degrees: two faces turning further meet at a crease
    for (int i = 0; i < count; ++i) {
        // Only a normal the QEF dropped: it turns along a direction the solution left free (a right
        // angle's mixed normal, 45 degrees off, is kept, and the vertex is on the crease already).
        double dropped = 0.0;
        for (int k = 0; k < qef.freeCount; ++k)
            dropped = std::max(dropped, std::abs(glm::dot(patchNormals[i], qef.free[std::size_t(k)])));
        if (dropped < 0.2) continue;
        int own = -1; // the face this crossing's normal mixes with: the nearest other normal of the patch
        for (int j = 0; j < count; ++j) {
            const double turn = glm::dot(patchNormals[j], patchNormals[i]);
            if (turn <= kFlat && (own < 0 || turn > glm::dot(patchNormals[own], patchNormals[i]))) own = j;
        }
        if (own < 0) continue;
        const double mixed = glm::dot(patchNormals[i], patchNormals[own]);
        for (int a = 0; a < 3; ++a) {
            if (!(std::abs(points[i][a] - hi[a]) < 1e-4 * grid.step[a])) continue;
            std::int64_t above[3] = {cell[0], cell[1], cell[2]};
            ++above[a];
            std::optional<glm::dvec3> other;
            forEachCrossingOf(above, [&](std::uint32_t e) {
                glm::dvec3 n(normals[3 * e], normals[3 * e + 1], normals[3 * e + 2]);
                const double length = glm::length(n);
                if (!(length > 0.0) || !std::isfinite(length)) return;
                n /= length;
                const glm::dvec3 q(crossings[3 * e], crossings[3 * e + 1], crossings[3 * e + 2]);
                if (!(std::abs(glm::dot(n, points[i] - q)) < 1e-3 * grid.step[a])) return; // its plane misses the crossing
                if (!other || glm::dot(n, patchNormals[own]) < glm::dot(*other, patchNormals[own])) other = n;
            });
            if (!other) continue;
            const double turn = glm::dot(*other, patchNormals[own]);
            // The own face must reach well off the crease (a box whose edges lie on grid lines has only
            // mixed normals, each beside a crease: those cells keep their vertices).
            double reach = 0.0;
            for (int j = 0; j < count; ++j)
                if (glm::dot(patchNormals[j], patchNormals[own]) > kFlat)
                    reach = std::max(reach, std::abs(glm::dot(*other, points[j] - points[i])));
            // The crease must lie in the face (not cross it), and neither face in the grid's plane
            // itself (a face on a plane of the grid is met by crossings a 1024th of an edge off it,
            // and its cells are right as they are).
            const glm::dvec3 along = glm::cross(patchNormals[own], *other);
            const bool inTheFace = std::abs(along[a]) < 0.05 * glm::length(along);
            const bool faceInThePlane = std::abs((*other)[a]) > 0.95 || std::abs(patchNormals[own][a]) > 0.95;
            if (turn < kCrease && turn < mixed - 1e-3 && reach > 0.1 * grid.step[a] && inTheFace && !faceInThePlane)
                return std::pair{points[i], *other};
        }
    }
    return std::nullopt;
}

// The record of cell c; null when the cell was not meshed (outside the grid, in a skipped block,
// or with no crossing).
const CellRecord* Extraction::recordAt(const std::int64_t c[3]) const {
    for (int a = 0; a < 3; ++a)
        if (c[a] < 0 || c[a] >= grid.n) return nullptr;
    const std::int32_t slot = blockSlot[blockIndexOf(c)];
    if (slot < 0) return nullptr;
    const int local = int(((c[2] % kBlock) * kBlock + c[1] % kBlock) * kBlock + c[0] % kBlock);
    const RankedBits<kCells>& cells = blockCells[std::size_t(slot)];
    if (!cells.test(local)) return nullptr;
    return &cellRecords[cells.rank(local)];
}

// The index (into edges and crossings) of local edge l of meshed cell c.
std::uint32_t Extraction::crossingOf(const std::int64_t c[3], int l) const {
    const std::int32_t slot = blockSlot[blockIndexOf(c)];
    const int* o = tables.edgeOffset[l];
    int point = 0;
    for (int a = 0; a < 3; ++a) point += int(c[a] % kBlock + o[a]) * kStride[a];
    return blockEdges[std::size_t(slot)].rank(3 * point + l / 4);
}

// Calls visit(index) for each crossing on the twelve edges of cell c (none outside the grid or in
// a skipped block). Crossings are placed before any vertex is.
template <class Visit> void Extraction::forEachCrossingOf(const std::int64_t c[3], Visit&& visit) const {
    float corner[8];
    if (!cellCorners(c, corner)) return;
    for (int l = 0; l < 12; ++l)
        if (crosses(corner[tables.edgeCorner[l][0]], corner[tables.edgeCorner[l][1]])) visit(crossingOf(c, l));
}

// 4b. Manifold across ambiguous faces. When the patches on both sides of an ambiguous face each
// join the face's two segments (a tunnel thinner than a cell), the edge between their two vertices
// would be shared by the four quads of the face's four crossing edges. Each segment gets a vertex
// of its own on the face instead (the middle of its two crossings, projected onto the surface with
// the others), which connectQuads puts between the two cells' vertices: every edge then has two
// triangles and every vertex one fan.
void Extraction::splitJoinedFaces() {
    cellVertexCount = mesh.vertices.size();
    for (const auto& cell : jointCells) {
        const std::int64_t lower[3] = {cell[0], cell[1], cell[2]};
        const CellRecord* near = recordAt(lower);
        for (int w = 0; w < 3; ++w) {
            const int face = 2 * w + 1;
            if (!(near->jointFaces >> face & 1)) continue;
            std::int64_t upper[3] = {lower[0], lower[1], lower[2]};
            ++upper[w];
            const CellRecord* far = recordAt(upper);
            if (far == nullptr || !(far->jointFaces >> (2 * w) & 1)) continue;
            const int paired = near->crossPaired >> face & 1;
            for (int segment = 0; segment < 2; ++segment) {
                glm::vec3 middle(0.0f);
                for (int end = 0; end < 2; ++end) {
                    const std::uint32_t e = crossingOf(lower, tables.faceEdges[face][kSegments[paired][segment][end]]);
                    middle += 0.5f * glm::vec3(crossings[3 * e], crossings[3 * e + 1], crossings[3 * e + 2]);
                }
                faceVertices.emplace(faceKey(lower, w, segment), std::uint32_t(mesh.vertices.size()));
                mesh.vertices.push_back(middle);
                vertexCell.push_back(cell);
            }
            ++stats.splitFaces;
        }
    }
}

// The point of the box nearest to p on the plane f + g.(x - p) = 0 (the field's linear
// approximation at p): the Newton step, and where it leaves the box, the nearest point of the plane
// on the faces it crossed, found by holding those coordinates at the face and stepping along the
// rest of the gradient. A plain clamp would leave a vertex whose surface point lies just outside its
// cell (the top of a dome that barely enters it) at the face, off the surface by up to the dome's
// height; this puts it where the surface crosses that face (alongFace: it did). Falls back to the
// clamp where the step leaves by two or more faces at once, where the point on the face would
// leave the cell by another one, or where the rest of the gradient vanishes (the plane parallel to
// the face).
glm::vec3 stepOntoPlaneInBox(const glm::vec3& p, float f, const glm::vec3& g, const glm::vec3& lo, const glm::vec3& hi,
                             bool& alongFace) {
    alongFace = false;
    const float g2 = glm::dot(g, g);
    const glm::vec3 newton = p - g * (f / g2);
    const glm::bvec3 held = glm::lessThan(newton, lo) || glm::greaterThan(newton, hi);
    const int heldCount = int(held.x) + int(held.y) + int(held.z);
    if (heldCount == 0) return newton;
    // Held axes sit on the face they crossed; the free ones take the least step that makes the
    // linear field zero.
    glm::vec3 d(0.0f), free(0.0f);
    float rest = -f;
    for (int a = 0; a < 3; ++a) {
        if (held[a]) {
            d[a] = std::clamp(newton[a], lo[a], hi[a]) - p[a];
            rest -= g[a] * d[a];
        } else {
            free[a] = g[a];
        }
    }
    const float free2 = glm::dot(free, free);
    if (heldCount == 1 && free2 > 1e-6f * g2) {
        const glm::vec3 onFace = p + d + free * (rest / free2);
        bool inside = true;
        for (int a = 0; a < 3; ++a) inside = inside && (held[a] || (onFace[a] > lo[a] && onFace[a] < hi[a]));
        alongFace = inside;
        if (inside) return onFace;
    }
    return glm::clamp(newton, lo, hi);
}

// On curved surfaces the planes' minimiser lies off the surface by about h^2 times the
// curvature: two Newton steps along the gradient put each vertex on it (a vertex already on a
// sharp edge or corner has f = 0 and stays). Steps are kept within the vertex's cell (or, for a vertex
// placed beside its cell on a sharp edge, within the same margin).
Expected<void> Extraction::projectVertices() {
    // Every vertex takes two steps; the few whose second step ran into a face of their cell (the
    // surface point lies just beyond it) take two more along that face, evaluated alone.
    std::vector<std::uint32_t> moving(mesh.vertices.size());
    for (std::size_t vertex = 0; vertex < moving.size(); ++vertex) moving[vertex] = std::uint32_t(vertex);
    std::vector<float> positions, fieldValues, gradients;
    std::vector<std::uint8_t> onFace(mesh.vertices.size(), 0);
    for (int iteration = 0; iteration < 4 && !moving.empty(); ++iteration) {
        positions.resize(3 * moving.size());
        for (std::size_t i = 0; i < moving.size(); ++i)
            for (int a = 0; a < 3; ++a) positions[3 * i + std::size_t(a)] = mesh.vertices[moving[i]][a];
        if (auto ok = field.evaluate(positions, fieldValues, &gradients, normalStep); !ok) return ok.error();
        stats.pointsEvaluated += fieldValues.size();
        forEachChunk(moving.size(), chunkCount(moving.size(), 8192), [&](std::size_t, std::size_t first, std::size_t end) {
            for (std::size_t i = first; i < end; ++i) {
                const std::uint32_t vertex = moving[i];
                const float f = fieldValues[i];
                const glm::vec3 g(gradients[3 * i], gradients[3 * i + 1], gradients[3 * i + 2]);
                const float g2 = glm::dot(g, g);
                if (!std::isfinite(f) || !(g2 > 1e-12f) || !std::isfinite(g2)) continue;
                const auto& c = vertexCell[vertex];
                const glm::vec3 cellLo = grid.point(c[0], c[1], c[2]), cellHi = grid.point(c[0] + 1, c[1] + 1, c[2] + 1);
                // A vertex placed beside its cell (on a sharp edge) keeps the margin it was given.
                const bool beside = glm::any(glm::lessThan(mesh.vertices[vertex], cellLo)) ||
                                    glm::any(glm::greaterThan(mesh.vertices[vertex], cellHi));
                const glm::vec3 margin{beside ? float(vertexMargin) : 0.0f};
                // The first step is clamped plainly: stepping along a face at once would draw the cells'
                // vertices around a needle thinner than a cell onto one point of its axis.
                bool alongFace = false;
                mesh.vertices[vertex] =
                    iteration == 0 ? glm::clamp(mesh.vertices[vertex] - g * (f / g2), cellLo - margin, cellHi + margin)
                                   : stepOntoPlaneInBox(mesh.vertices[vertex], f, g, cellLo - margin, cellHi + margin, alongFace);
                onFace[vertex] = alongFace ? 1 : 0;
            }
        });
        if (iteration == 0) continue;
        std::erase_if(moving, [&](std::uint32_t vertex) { return onFace[vertex] == 0; });
    }
    return {};
}

} // namespace sdfwb::meshing::detail
