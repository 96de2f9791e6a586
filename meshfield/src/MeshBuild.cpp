// Building a MeshField from a triangle mesh: checks, normalisation, edge counts, the binary
// hierarchy (binned SAH) and its four-wide copy, the winding numbers' dipoles and moments, the
// pseudonormals; and loading meshes from files through a cache. The queries are in MeshField.cpp.

#include <meshfield/MeshField.h>

#include "FloatBits.h"

#include <glm/geometric.hpp>
#include <glm/mat3x3.hpp>
#include <glm/matrix.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <deque>
#include <limits>
#include <map>
#include <mutex>
#include <tuple>
#include <unordered_map>

namespace sdfwb::meshfield {
namespace fs = std::filesystem;
namespace {

using detail::asBits;
using detail::asFloat;
using glm::dvec3;

constexpr std::uint32_t kLeafSize = kMaxLeafTriangles;
constexpr int kBins = 16;
constexpr std::size_t kMaxDepth = 60; // shaders/mesh/mesh_field.glsl's stack holds depth + 2 entries

double seconds(std::chrono::steady_clock::time_point since) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - since).count();
}

// A float no larger (no smaller) than `value`: the GPU's boxes must hold what the double boxes hold.
float down(double value) {
    float f = float(value);
    return double(f) > value ? std::nextafter(f, -std::numeric_limits<float>::infinity()) : f;
}
float up(double value) {
    float f = float(value);
    return double(f) < value ? std::nextafter(f, std::numeric_limits<float>::infinity()) : f;
}

void grow(Box& box, const dvec3& p) {
    box.lo = glm::min(box.lo, p);
    box.hi = glm::max(box.hi, p);
}
Box emptyBox() {
    const double inf = std::numeric_limits<double>::infinity();
    return {dvec3(inf), dvec3(-inf)};
}
double halfArea(const Box& box) {
    const dvec3 e = glm::max(box.hi - box.lo, dvec3(0.0));
    return e.x * e.y + e.y * e.z + e.z * e.x;
}

// The four-wide hierarchy (kWideNodeFloats) from the binary one: each node takes its binary node's
// children, or a child's children where that child is inner, so that one step tests four boxes.
void buildWideNodes(MeshField& field) {
    field.wideNodes.clear();
    field.wideDepth = 0;
    if (field.nodes.empty()) return;
    auto binary = [&](std::uint32_t index) { return field.nodes.data() + std::size_t(index) * kNodeFloats; };
    auto isLeaf = [&](std::uint32_t index) { return asBits(binary(index)[7]) > 0; };
    // Returns the wide node's index; `level` counts inner nodes from the root.
    auto collapse = [&](auto& self, std::uint32_t index, std::size_t level) -> std::uint32_t {
        field.wideDepth = std::max(field.wideDepth, level + 1);
        std::uint32_t members[4];
        int n = 0;
        if (isLeaf(index)) { // a leaf root: one child
            members[n++] = index;
        } else {
            const std::uint32_t left = asBits(binary(index)[3]);
            for (std::uint32_t c : {left, left + 1}) {
                if (isLeaf(c)) {
                    members[n++] = c;
                } else {
                    const std::uint32_t grand = asBits(binary(c)[3]);
                    members[n++] = grand;
                    members[n++] = grand + 1;
                }
            }
        }
        const std::uint32_t at = std::uint32_t(field.wideNodes.size() / kWideNodeFloats);
        field.wideNodes.resize(field.wideNodes.size() + kWideNodeFloats);
        float node[kWideNodeFloats];
        for (int k = 0; k < 4; ++k) {
            for (int a = 0; a < 3; ++a) {
                node[4 * a + k] = std::numeric_limits<float>::infinity();
                node[12 + 4 * a + k] = -std::numeric_limits<float>::infinity();
            }
            node[24 + k] = asFloat(0u);
            node[28 + k] = asFloat(0u);
        }
        for (int k = 0; k < n; ++k) {
            const float* m = binary(members[k]);
            for (int a = 0; a < 3; ++a) {
                node[4 * a + k] = m[a];
                node[12 + 4 * a + k] = m[4 + a];
            }
            const std::uint32_t count = asBits(m[7]);
            node[28 + k] = asFloat(count);
            node[24 + k] = asFloat(count > 0 ? asBits(m[3]) : self(self, members[k], level + 1));
        }
        std::copy(node, node + kWideNodeFloats, field.wideNodes.begin() + std::ptrdiff_t(at) * kWideNodeFloats);
        return at;
    };
    collapse(collapse, 0, 0);
}

struct Builder {
    const std::vector<dvec3>& centroid;
    const std::vector<Box>& triBox;
    std::vector<std::uint32_t>& order;
    struct Node {
        Box box;
        std::uint32_t firstOrLeft = 0;
        std::uint32_t count = 0;
    };
    std::vector<Node> nodes;
    std::size_t depth = 0;

    Box bounds(std::uint32_t first, std::uint32_t count) const {
        Box box = emptyBox();
        for (std::uint32_t i = first; i < first + count; ++i) {
            grow(box, triBox[order[i]].lo);
            grow(box, triBox[order[i]].hi);
        }
        return box;
    }

    // Splits node `index` (covering order[first, first + count)) by the binned surface area heuristic.
    void split(std::uint32_t index, std::uint32_t first, std::uint32_t count, std::size_t level) {
        depth = std::max(depth, level);
        nodes[index].box = bounds(first, count);
        nodes[index].firstOrLeft = first;
        nodes[index].count = count;
        if (count <= kLeafSize) return;
        Box cbox = emptyBox();
        for (std::uint32_t i = first; i < first + count; ++i) grow(cbox, centroid[order[i]]);
        int bestAxis = -1;
        int bestBin = 0;
        double bestCost = std::numeric_limits<double>::infinity();
        // Past kMaxDepth (a long chain of lopsided splits), halves: the depth stays bounded and no
        // leaf holds more than kLeafSize triangles.
        for (int axis = 0; axis < 3 && level < kMaxDepth; ++axis) {
            const double lo = cbox.lo[axis];
            const double extent = cbox.hi[axis] - lo;
            if (!(extent > 0.0)) continue;
            std::array<Box, kBins> binBox;
            std::array<std::uint32_t, kBins> binCount{};
            binBox.fill(emptyBox());
            for (std::uint32_t i = first; i < first + count; ++i) {
                const std::uint32_t t = order[i];
                const int b = std::min(kBins - 1, int((centroid[t][axis] - lo) / extent * kBins));
                ++binCount[std::size_t(b)];
                grow(binBox[std::size_t(b)], triBox[t].lo);
                grow(binBox[std::size_t(b)], triBox[t].hi);
            }
            std::array<double, kBins> rightCost{};
            Box right = emptyBox();
            std::uint32_t rightCount = 0;
            // An empty bin's box is inverted (lo = +inf, hi = -inf): growing by its corners would make
            // every split across a gap in the centroids cost infinity, and the tree would never cut
            // between two separate sheets (a 1.1 M-triangle bunny had 1 % of its leaves spanning
            // front and back).
            for (int b = kBins - 1; b > 0; --b) {
                if (binCount[std::size_t(b)] > 0) {
                    grow(right, binBox[std::size_t(b)].lo);
                    grow(right, binBox[std::size_t(b)].hi);
                }
                rightCount += binCount[std::size_t(b)];
                rightCost[std::size_t(b)] = rightCount ? double(rightCount) * halfArea(right) : 0.0;
            }
            Box left = emptyBox();
            std::uint32_t leftCount = 0;
            for (int b = 0; b < kBins - 1; ++b) {
                if (binCount[std::size_t(b)] > 0) {
                    grow(left, binBox[std::size_t(b)].lo);
                    grow(left, binBox[std::size_t(b)].hi);
                }
                leftCount += binCount[std::size_t(b)];
                if (leftCount == 0 || leftCount == count) continue;
                const double cost = double(leftCount) * halfArea(left) + rightCost[std::size_t(b) + 1];
                if (cost < bestCost) {
                    bestCost = cost;
                    bestAxis = axis;
                    bestBin = b;
                }
            }
        }
        std::uint32_t middle = first;
        if (bestAxis >= 0) {
            const double lo = cbox.lo[bestAxis];
            const double extent = cbox.hi[bestAxis] - lo;
            auto* begin = order.data() + first;
            auto* end = begin + count;
            auto* cut = std::partition(begin, end, [&](std::uint32_t t) {
                return std::min(kBins - 1, int((centroid[t][bestAxis] - lo) / extent * kBins)) <= bestBin;
            });
            middle = std::uint32_t(cut - order.data());
        }
        if (middle == first || middle == first + count) {
            // Every centroid in one place, or past kMaxDepth: halve the list.
            middle = first + count / 2;
        }
        const std::uint32_t left = std::uint32_t(nodes.size());
        nodes.emplace_back();
        nodes.emplace_back();
        nodes[index].firstOrLeft = left;
        nodes[index].count = 0;
        split(left, first, middle - first, level + 1);
        split(left + 1, middle, first + count - middle, level + 1);
    }
};

using EdgeUses = std::unordered_map<std::uint64_t, std::uint32_t>;

Expected<void> checkMesh(const TriangleMesh& mesh, const std::string& name, const MeshFieldOptions& options) {
    if (mesh.indices.empty()) return Error{name + ": the mesh holds no triangles"};
    for (std::uint32_t i : mesh.indices)
        if (i >= mesh.vertices.size())
            return Error{name + ": a triangle names vertex " + std::to_string(i) + " of " + std::to_string(mesh.vertices.size())};
    for (const glm::vec3& v : mesh.vertices)
        if (!std::isfinite(v.x) || !std::isfinite(v.y) || !std::isfinite(v.z))
            return Error{name + ": a vertex is not a finite number"};
    if (!(options.beta >= 1.0)) return Error{name + ": beta must be at least 1"};
    // The GPU's nearest walk keeps a leaf's first triangle in 28 bits (mesh_field.glsl).
    if (mesh.triangleCount() >= (std::size_t(1) << 28))
        return Error{name + ": " + std::to_string(mesh.triangleCount()) + " triangles; sdfwb holds at most 268,435,455"};
    return {};
}

void normalise(TriangleMesh& mesh, MeshField& field, const MeshFieldOptions& options) {
    // Normalisation (mesh_to_sdf's conventions): unit-cube puts the bounding box's centre at the
    // origin and its longest side at 2 ([-1, 1]); unit-sphere puts the box's centre at the origin
    // and the farthest vertex at distance 1.
    Box box = emptyBox();
    for (const glm::vec3& v : mesh.vertices) grow(box, dvec3(v));
    field.originalBounds = box;
    const dvec3 centre = (box.lo + box.hi) * 0.5;
    double scale = 1.0;
    dvec3 shift(0.0);
    if (options.normalize == Normalization::UnitCube) {
        const dvec3 e = box.hi - box.lo;
        const double longest = std::max({e.x, e.y, e.z});
        scale = longest > 0.0 ? 2.0 / longest : 1.0;
        shift = -centre;
    } else if (options.normalize == Normalization::UnitSphere) {
        double radius = 0.0;
        for (const glm::vec3& v : mesh.vertices) radius = std::max(radius, glm::length(dvec3(v) - centre));
        scale = radius > 0.0 ? 1.0 / radius : 1.0;
        shift = -centre;
    }
    field.transform = {scale, 0, 0, 0, 0, scale, 0, 0, 0, 0, scale, 0, shift.x * scale, shift.y * scale, shift.z * scale, 1};
    if (options.normalize != Normalization::None)
        for (glm::vec3& v : mesh.vertices) v = glm::vec3((dvec3(v) + shift) * scale);
    Box fieldBox = emptyBox();
    for (const glm::vec3& v : mesh.vertices) grow(fieldBox, dvec3(v));
    field.bounds = fieldBox;
}

// Boundary and non-manifold edges; every edge's uses (vertex pairs, the lower index first).
EdgeUses countEdges(const TriangleMesh& mesh, MeshField& field) {
    EdgeUses edgeUses;
    edgeUses.reserve(mesh.indices.size());
    for (std::size_t t = 0; t < mesh.indices.size(); t += 3)
        for (int k = 0; k < 3; ++k) {
            std::uint32_t a = mesh.indices[t + std::size_t(k)];
            std::uint32_t b = mesh.indices[t + std::size_t((k + 1) % 3)];
            if (a > b) std::swap(a, b);
            ++edgeUses[(std::uint64_t(a) << 32) | b];
        }
    for (const auto& [edge, uses] : edgeUses) {
        if (uses == 1) ++field.boundaryEdges;
        if (uses > 2) ++field.nonManifoldEdges;
    }
    return edgeUses;
}

// The binary hierarchy over the triangles, their floats in leaf order with the area shares;
// `order` maps a leaf slot to the mesh's triangle.
Builder buildHierarchy(const TriangleMesh& mesh, MeshField& field, std::vector<dvec3>& centroid, std::vector<Box>& triBox,
                       std::vector<std::uint32_t>& order) {
    const std::size_t count = mesh.triangleCount();
    centroid.resize(count);
    triBox.resize(count);
    order.resize(count);
    for (std::size_t t = 0; t < count; ++t) {
        const dvec3 a(mesh.vertices[mesh.indices[3 * t]]);
        const dvec3 b(mesh.vertices[mesh.indices[3 * t + 1]]);
        const dvec3 c(mesh.vertices[mesh.indices[3 * t + 2]]);
        centroid[t] = (a + b + c) / 3.0;
        triBox[t] = {glm::min(glm::min(a, b), c), glm::max(glm::max(a, b), c)};
        order[t] = std::uint32_t(t);
    }
    Builder builder{centroid, triBox, order, {}, 0};
    builder.nodes.reserve(2 * count / kLeafSize + 2);
    builder.nodes.emplace_back();
    builder.split(0, 0, std::uint32_t(count), 0);
    field.depth = builder.depth;

    field.triangles.resize(count * kTriangleFloats);
    for (std::size_t s = 0; s < count; ++s)
        for (int k = 0; k < 3; ++k) {
            const glm::vec3& v = mesh.vertices[mesh.indices[3 * std::size_t(order[s]) + std::size_t(k)]];
            float* out = field.triangles.data() + s * kTriangleFloats + std::size_t(k) * 4;
            out[0] = v.x;
            out[1] = v.y;
            out[2] = v.z;
            out[3] = 0.0f;
        }
    // The first corner's w: the share of the mesh's area in this triangle and those before it (leaf
    // order; 1 for the last), what sdfwb_meshSurfacePoint draws triangles by.
    {
        std::vector<double> cumulative(count);
        double total = 0.0;
        for (std::size_t s = 0; s < count; ++s) {
            const float* t = field.triangles.data() + s * kTriangleFloats;
            const dvec3 a(t[0], t[1], t[2]), b(t[4], t[5], t[6]), c(t[8], t[9], t[10]);
            total += 0.5 * glm::length(glm::cross(b - a, c - a));
            cumulative[s] = total;
        }
        for (std::size_t s = 0; s < count; ++s)
            field.triangles[s * kTriangleFloats + 3] =
                s + 1 == count ? 1.0f : float(total > 0.0 ? cumulative[s] / total : double(s + 1) / double(count));
    }
    return builder;
}

// Each node's winding-number expansion (dipole, centre, radius, moment), bottom up (children come
// after their parent), and the node floats the GPU and the CPU walks read.
void writeNodes(const TriangleMesh& mesh, const Builder& builder, const std::vector<dvec3>& centroid,
                const std::vector<std::uint32_t>& order, MeshField& field) {
    const std::size_t nodeCount = builder.nodes.size();
    std::vector<dvec3> dipole(nodeCount, dvec3(0.0));
    std::vector<dvec3> weighted(nodeCount, dvec3(0.0)); // sum of area times centroid
    std::vector<double> area(nodeCount, 0.0);
    std::vector<double> radius(nodeCount, 0.0);
    std::vector<dvec3> centre2(nodeCount, dvec3(0.0));
    std::vector<glm::dmat3> moment(nodeCount, glm::dmat3(0.0)); // moment[i][j][k]: column j, row k = M_kj
    for (std::size_t i = nodeCount; i-- > 0;) {
        const Builder::Node& node = builder.nodes[i];
        if (node.count > 0) {
            for (std::uint32_t s = node.firstOrLeft; s < node.firstOrLeft + node.count; ++s) {
                const std::size_t t = order[s];
                const dvec3 a(mesh.vertices[mesh.indices[3 * t]]);
                const dvec3 b(mesh.vertices[mesh.indices[3 * t + 1]]);
                const dvec3 c(mesh.vertices[mesh.indices[3 * t + 2]]);
                const dvec3 n = 0.5 * glm::cross(b - a, c - a);
                const double at = glm::length(n);
                dipole[i] += n;
                area[i] += at;
                weighted[i] += at * centroid[t];
            }
            centre2[i] = area[i] > 0.0 ? weighted[i] / area[i] : (node.box.lo + node.box.hi) * 0.5;
            for (std::uint32_t s = node.firstOrLeft; s < node.firstOrLeft + node.count; ++s) {
                const std::size_t t = order[s];
                const dvec3 a(mesh.vertices[mesh.indices[3 * t]]);
                const dvec3 b(mesh.vertices[mesh.indices[3 * t + 1]]);
                const dvec3 c(mesh.vertices[mesh.indices[3 * t + 2]]);
                moment[i] += glm::outerProduct(0.5 * glm::cross(b - a, c - a), centroid[t] - centre2[i]);
                for (int k = 0; k < 3; ++k)
                    radius[i] =
                        std::max(radius[i], glm::length(dvec3(mesh.vertices[mesh.indices[3 * t + std::size_t(k)]]) - centre2[i]));
            }
        } else {
            const std::size_t l = node.firstOrLeft;
            const std::size_t r = l + 1;
            dipole[i] = dipole[l] + dipole[r];
            area[i] = area[l] + area[r];
            weighted[i] = weighted[l] + weighted[r];
            centre2[i] = area[i] > 0.0 ? weighted[i] / area[i] : (node.box.lo + node.box.hi) * 0.5;
            // Two bounds on the distance from the centre to the cluster's farthest vertex: the
            // children's spheres, and the node's box (every vertex lies in it). The first alone
            // grows with every level (a 1.1 M-triangle bunny's root sphere had radius 3.8 around a
            // shape of half-diagonal 1.6), and a winding walk then opens nearly every node.
            const double children =
                std::max(glm::length(centre2[l] - centre2[i]) + radius[l], glm::length(centre2[r] - centre2[i]) + radius[r]);
            const dvec3 far = glm::max(glm::abs(node.box.lo - centre2[i]), glm::abs(node.box.hi - centre2[i]));
            radius[i] = std::min(children, glm::length(far));
            // Moved from each child's centre to this one: M + dipole (c_child - c)^T.
            moment[i] = moment[l] + glm::outerProduct(dipole[l], centre2[l] - centre2[i]) + moment[r] +
                        glm::outerProduct(dipole[r], centre2[r] - centre2[i]);
        }
    }
    field.nodes.resize(nodeCount * kNodeFloats);
    for (std::size_t i = 0; i < nodeCount; ++i) {
        const Builder::Node& node = builder.nodes[i];
        float* n = field.nodes.data() + i * kNodeFloats;
        n[0] = down(node.box.lo.x);
        n[1] = down(node.box.lo.y);
        n[2] = down(node.box.lo.z);
        n[3] = asFloat(node.firstOrLeft);
        n[4] = up(node.box.hi.x);
        n[5] = up(node.box.hi.y);
        n[6] = up(node.box.hi.z);
        n[7] = asFloat(node.count);
        n[8] = float(centre2[i].x);
        n[9] = float(centre2[i].y);
        n[10] = float(centre2[i].z);
        n[11] = up(radius[i] * (1.0 + 1e-6));
        n[12] = float(dipole[i].x);
        n[13] = float(dipole[i].y);
        n[14] = float(dipole[i].z);
        n[15] = 0.0f;
        for (int row = 0; row < 3; ++row) {
            for (int column = 0; column < 3; ++column) n[16 + 4 * row + column] = float(moment[i][column][row]);
            n[19 + 4 * row] = 0.0f;
        }
    }
}

// Angle-weighted vertex normals, edge normals as the sum of the faces' normals (Baerentzen and
// Aanaes), seven a triangle in leaf order.
void writePseudonormals(const TriangleMesh& mesh, const std::vector<std::uint32_t>& order, std::size_t edges, MeshField& field) {
    const std::size_t count = mesh.triangleCount();
    std::vector<dvec3> vertexNormal(mesh.vertices.size(), dvec3(0.0));
    std::unordered_map<std::uint64_t, dvec3> edgeNormal;
    edgeNormal.reserve(edges);
    std::vector<dvec3> faceNormal(count);
    for (std::size_t t = 0; t < count; ++t) {
        const std::uint32_t* idx = mesh.indices.data() + 3 * t;
        const dvec3 v[3] = {dvec3(mesh.vertices[idx[0]]), dvec3(mesh.vertices[idx[1]]), dvec3(mesh.vertices[idx[2]])};
        const dvec3 n = glm::cross(v[1] - v[0], v[2] - v[0]);
        const double len = glm::length(n);
        faceNormal[t] = len > 0.0 ? n / len : dvec3(0.0);
        for (int k = 0; k < 3; ++k) {
            const dvec3 e1 = v[(k + 1) % 3] - v[k];
            const dvec3 e2 = v[(k + 2) % 3] - v[k];
            const double l1 = glm::length(e1);
            const double l2 = glm::length(e2);
            if (l1 > 0.0 && l2 > 0.0)
                vertexNormal[idx[k]] += std::acos(std::clamp(glm::dot(e1, e2) / (l1 * l2), -1.0, 1.0)) * faceNormal[t];
            std::uint32_t a = idx[k];
            std::uint32_t b = idx[(k + 1) % 3];
            if (a > b) std::swap(a, b);
            edgeNormal[(std::uint64_t(a) << 32) | b] += faceNormal[t];
        }
    }
    field.pseudonormals.resize(count * kPseudonormalFloats);
    for (std::size_t s = 0; s < count; ++s) {
        const std::size_t t = order[s];
        const std::uint32_t* idx = mesh.indices.data() + 3 * t;
        dvec3 normals[7];
        normals[0] = faceNormal[t];
        for (int k = 0; k < 3; ++k) {
            std::uint32_t a = idx[k];
            std::uint32_t b = idx[(k + 1) % 3];
            if (a > b) std::swap(a, b);
            normals[1 + k] = edgeNormal[(std::uint64_t(a) << 32) | b];
            normals[4 + k] = vertexNormal[idx[k]];
        }
        for (int k = 0; k < 7; ++k) {
            const double len = glm::length(normals[k]);
            const dvec3 n = len > 0.0 ? normals[k] / len : dvec3(0.0);
            float* out = field.pseudonormals.data() + s * kPseudonormalFloats + std::size_t(k) * 4;
            out[0] = float(n.x);
            out[1] = float(n.y);
            out[2] = float(n.z);
            out[3] = 0.0f;
        }
    }
}

Expected<std::shared_ptr<MeshField>> buildField(TriangleMesh mesh, const std::string& name, const MeshFieldOptions& options) {
    const auto start = std::chrono::steady_clock::now();
    if (auto ok = checkMesh(mesh, name, options); !ok) return ok.error();
    auto field = std::make_shared<MeshField>();
    field->name = name;
    field->options = options;
    normalise(mesh, *field, options);
    const EdgeUses edgeUses = countEdges(mesh, *field);
    std::vector<dvec3> centroid;
    std::vector<Box> triBox;
    std::vector<std::uint32_t> order;
    const Builder builder = buildHierarchy(mesh, *field, centroid, triBox, order);
    writeNodes(mesh, builder, centroid, order, *field);
    buildWideNodes(*field);
    if (options.sign == SignMethod::Pseudonormal) writePseudonormals(mesh, order, edgeUses.size(), *field);
    // The CPU queries read the GPU's corners: both sides answer for the same float triangles.
    field->mesh = std::move(mesh);
    field->buildSeconds = seconds(start);
    return field;
}

} // namespace

Expected<std::shared_ptr<const MeshField>> makeMeshField(TriangleMesh mesh, const std::string& name,
                                                         const MeshFieldOptions& options) {
    auto field = buildField(std::move(mesh), name, options);
    if (!field) return field.error();
    return std::shared_ptr<const MeshField>(std::move(*field));
}

Expected<std::shared_ptr<const MeshField>> loadMeshField(const fs::path& path, const MeshFieldOptions& options) {
    std::error_code ec;
    const auto size = fs::file_size(path, ec);
    if (ec) return Error{path.string() + ": cannot read the mesh: " + ec.message()};
    const auto time = fs::last_write_time(path, ec).time_since_epoch().count();
    using Key = std::tuple<std::string, std::uintmax_t, long long, int, int, double>;
    const Key key{fs::absolute(path).lexically_normal().string(),
                  size,
                  (long long)time,
                  int(options.sign),
                  int(options.normalize),
                  options.beta};
    static std::mutex mutex;
    static std::map<Key, std::weak_ptr<const MeshField>> cache;
    // The fields used last stay alive (at most 4, and 1 GB of buffers beyond the newest), so a loop
    // of calls on one mesh (evaluate() in a training loop) reads and builds it once, not every call:
    // a 1.1 M-triangle mesh takes seconds.
    static std::deque<std::shared_ptr<const MeshField>> recent;
    auto keep = [&](const std::shared_ptr<const MeshField>& field) {
        std::erase(recent, field);
        recent.push_front(field);
        std::size_t bytes = 0, kept = 0;
        for (const auto& f : recent) {
            bytes += f->gpuBytes();
            if (kept > 0 && (kept >= 4 || bytes > (std::size_t(1) << 30))) break;
            ++kept;
        }
        recent.resize(kept);
    };
    {
        std::lock_guard lock(mutex);
        if (auto it = cache.find(key); it != cache.end())
            if (auto field = it->second.lock()) {
                keep(field);
                return field;
            }
    }
    const auto start = std::chrono::steady_clock::now();
    auto mesh = readTriangleMesh(path);
    if (!mesh) return mesh.error();
    const double readSeconds = seconds(start);
    auto built = buildField(std::move(*mesh), path.filename().string(), options);
    if (!built) return built.error();
    (*built)->readSeconds = readSeconds;
    std::shared_ptr<const MeshField> field = std::move(*built);
    std::lock_guard lock(mutex);
    cache[key] = field;
    keep(field);
    return field;
}

} // namespace sdfwb::meshfield
