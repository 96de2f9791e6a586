#pragma once
// What the meshing tests share: the fixture (an SDF from its text, a mesh extracted from it), the
// box and sphere fields, and exact geometry to compare meshes with (boxes, rotations, icospheres,
// their distances and sags, a mesh's volume and its triangles in a canonical order).
#include <meshing/Mesh.h>
#include <sampling/FieldEvaluator.h>

#include "GlTestContext.h"
#include "common/SourceSdfs.h"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>
#include <glm/mat3x3.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <numeric>
#include <string>
#include <tuple>
#include <unistd.h>
#include <unordered_map>

namespace sdfwb::meshtest {

class MeshTest : public sdfwb::testing::GlTest {
protected:
    static shaders::PreparedSdf source(const std::string& text) {
        shaders::IncludeOptions options;
        auto sdf = shaders::prepareSdf(text, "<test>", {}, options);
        EXPECT_TRUE(sdf.ok());
        return sdf;
    }
    static meshing::Mesh extract(const shaders::PreparedSdf& sdf, int resolution, float lipschitz = 1.0f) {
        meshing::MeshOptions options;
        options.resolution = resolution;
        options.lipschitz = lipschitz;
        auto mesh = meshing::extractMesh(sdf, options, {});
        EXPECT_TRUE(mesh) << (mesh ? "" : mesh.error().message);
        return mesh ? mesh->first : meshing::Mesh{};
    }
};

inline constexpr const char* kBox =
    "float sdf(vec3 p) { vec3 q = abs(p) - vec3(0.5); return length(max(q, 0.0)) + min(max(q.x, max(q.y, q.z)), 0.0); }";
inline constexpr const char* kSphere = "float sdf(vec3 p) { return length(p) - 0.6; }";

// Distance from p to the segment ab.
inline float segmentDistance(glm::vec3 p, glm::vec3 a, glm::vec3 b) {
    const float t = std::clamp(glm::dot(p - a, b - a) / glm::dot(b - a, b - a), 0.0f, 1.0f);
    return glm::length(p - (a + t * (b - a)));
}

inline glm::dvec3 corner(const meshing::Mesh& mesh, std::size_t triangle, int k) {
    return glm::dvec3(mesh.vertices[mesh.indices[3 * triangle + std::size_t(k)]]);
}

// The signed volume the triangles enclose (positive when they face outward).
inline double signedVolume(const meshing::Mesh& mesh) {
    double volume = 0.0;
    for (std::size_t t = 0; t < mesh.triangleCount(); ++t)
        volume += glm::dot(corner(mesh, t, 0), glm::cross(corner(mesh, t, 1), corner(mesh, t, 2))) / 6.0;
    return volume;
}

// A closed, consistently oriented 2-manifold facing outward: every directed edge (a, b) is used by
// exactly one triangle and its reverse (b, a) by exactly one other, no triangle repeats a vertex
// or has zero area, and the signed volume is positive.
inline ::testing::AssertionResult closedAndOutward(const meshing::Mesh& mesh) {
    if (mesh.indices.empty() || mesh.indices.size() % 3 != 0)
        return ::testing::AssertionFailure() << mesh.indices.size() << " indices";
    std::unordered_map<std::uint64_t, std::uint32_t> directed;
    std::uint64_t repeated = 0, zeroArea = 0;
    for (std::size_t t = 0; t < mesh.triangleCount(); ++t) {
        const std::uint32_t* v = &mesh.indices[3 * t];
        if (v[0] == v[1] || v[1] == v[2] || v[0] == v[2]) ++repeated;
        if (glm::length(glm::cross(corner(mesh, t, 1) - corner(mesh, t, 0), corner(mesh, t, 2) - corner(mesh, t, 0))) == 0.0)
            ++zeroArea;
        for (int e = 0; e < 3; ++e) ++directed[(std::uint64_t(v[e]) << 32) | v[(e + 1) % 3]];
    }
    std::uint64_t reused = 0, unpaired = 0;
    for (const auto& [edge, uses] : directed) {
        if (uses != 1) ++reused;
        const auto reverse = directed.find((edge << 32) | (edge >> 32));
        if (reverse == directed.end() || reverse->second != 1) ++unpaired;
    }
    const double volume = signedVolume(mesh);
    if (repeated || zeroArea || reused || unpaired || !(volume > 0.0))
        return ::testing::AssertionFailure()
               << repeated << " triangles repeat a vertex, " << zeroArea << " have zero area, " << reused
               << " directed edges are used more than once, " << unpaired << " lack their reverse; signed volume " << volume;
    return ::testing::AssertionSuccess();
}

// The rotation by `angle` about `axis` (normalised; Rodrigues), and a GLSL box of half-sizes `half`
// under it: the field is the axis-aligned box's at R^T p.
inline glm::dmat3 rotation(glm::dvec3 axis, double angle) {
    const glm::dvec3 k = glm::normalize(axis);
    const double c = std::cos(angle), s = std::sin(angle);
    glm::dmat3 r(c); // glm: r[column][row]
    const glm::dmat3 cross(0.0, k.z, -k.y, -k.z, 0.0, k.x, k.y, -k.x, 0.0);
    for (int col = 0; col < 3; ++col)
        for (int row = 0; row < 3; ++row) r[col][row] += s * cross[col][row] + (1.0 - c) * k[row] * k[col];
    return r;
}
const glm::dmat3 kTilt = rotation({1.0, 2.0, 3.0}, 0.3);

// The arguments of a GLSL mat3(...) that is R^T: mat3 takes columns, so R's rows as its columns.
inline std::string transposedMat3(const glm::dmat3& r) {
    std::string matrix;
    char number[32];
    for (int row = 0; row < 3; ++row)
        for (int col = 0; col < 3; ++col) {
            std::snprintf(number, sizeof number, "%.9e", r[col][row]);
            matrix += (matrix.empty() ? "" : ", ") + std::string(number);
        }
    return matrix;
}

inline std::string rotatedBoxSource(const glm::dmat3& r, glm::dvec3 half) {
    const std::string matrix = transposedMat3(r);
    char text[512];
    std::snprintf(text, sizeof text,
                  "float sdf(vec3 p) { vec3 q = abs(mat3(%s) * p) - vec3(%.9e, %.9e, %.9e); "
                  "return length(max(q, 0.0)) + min(max(q.x, max(q.y, q.z)), 0.0); }",
                  matrix.c_str(), half.x, half.y, half.z);
    return text;
}

inline double boxDistance(glm::dvec3 p, glm::dvec3 half) {
    const glm::dvec3 q = glm::abs(p) - half;
    return glm::length(glm::max(q, 0.0)) + std::min(std::max(q.x, std::max(q.y, q.z)), 0.0);
}

// A box of half-sizes `half` under the rotation r: its 8 corners (corner c = x + 2y + 4z) and 12
// triangles, counter-clockwise seen from outside.
inline meshing::Mesh boxMesh(const glm::dmat3& r, glm::dvec3 half) {
    meshing::Mesh mesh;
    for (int c = 0; c < 8; ++c)
        mesh.vertices.push_back(glm::vec3(r * (half * glm::dvec3((c & 1) ? 1 : -1, (c & 2) ? 1 : -1, (c & 4) ? 1 : -1))));
    for (int axis = 0; axis < 3; ++axis)
        for (int side = 0; side < 2; ++side) {
            const int u = 1 << ((axis + 1) % 3), v = 1 << ((axis + 2) % 3), w = side << axis;
            // (u, v, axis) is right-handed: 0, u, u + v, v runs counter-clockwise seen from +axis.
            std::uint32_t quad[4] = {std::uint32_t(w), std::uint32_t(w + u), std::uint32_t(w + u + v), std::uint32_t(w + v)};
            if (side == 0) std::swap(quad[1], quad[3]);
            mesh.indices.insert(mesh.indices.end(), {quad[0], quad[1], quad[2], quad[0], quad[2], quad[3]});
        }
    return mesh;
}

// An icosahedron split `levels` times (each triangle into four), its vertices on the sphere of
// radius `radius` about the origin, counter-clockwise seen from outside.
inline meshing::Mesh icosphere(int levels, double radius) {
    const double g = (1.0 + std::sqrt(5.0)) / 2.0;
    std::vector<glm::dvec3> points = {{-1, g, 0},  {1, g, 0},  {-1, -g, 0}, {1, -g, 0}, {0, -1, g},  {0, 1, g},
                                      {0, -1, -g}, {0, 1, -g}, {g, 0, -1},  {g, 0, 1},  {-g, 0, -1}, {-g, 0, 1}};
    for (glm::dvec3& p : points) p = glm::normalize(p);
    std::vector<std::uint32_t> faces = {0, 11, 5,  0, 5,  1, 0, 1, 7, 0, 7,  10, 0, 10, 11, 1, 5, 9, 5, 11,
                                        4, 11, 10, 2, 10, 7, 6, 7, 1, 8, 3,  9,  4, 3,  4,  2, 3, 2, 6, 3,
                                        6, 8,  3,  8, 9,  4, 9, 5, 2, 4, 11, 6,  2, 10, 8,  6, 7, 9, 8, 1};
    for (int level = 0; level < levels; ++level) {
        std::map<std::pair<std::uint32_t, std::uint32_t>, std::uint32_t> middles;
        auto middle = [&](std::uint32_t a, std::uint32_t b) {
            const auto [it, added] = middles.try_emplace({std::min(a, b), std::max(a, b)}, std::uint32_t(points.size()));
            if (added) points.push_back(glm::normalize(points[a] + points[b]));
            return it->second;
        };
        std::vector<std::uint32_t> finer;
        for (std::size_t f = 0; f < faces.size(); f += 3) {
            const std::uint32_t a = faces[f], b = faces[f + 1], c = faces[f + 2];
            const std::uint32_t ab = middle(a, b), bc = middle(b, c), ca = middle(c, a);
            finer.insert(finer.end(), {a, ab, ca, b, bc, ab, c, ca, bc, ab, bc, ca});
        }
        faces = std::move(finer);
    }
    meshing::Mesh mesh;
    for (const glm::dvec3& p : points) mesh.vertices.push_back(glm::vec3(radius * p));
    mesh.indices = std::move(faces);
    return mesh;
}

// How far the flat faces of a mesh whose vertices lie on the sphere of `radius` about the origin
// dip inside it: the largest distance from that sphere to a face's plane.
inline double largestSag(const meshing::Mesh& mesh, double radius) {
    double sag = 0.0;
    for (std::size_t t = 0; t < mesh.triangleCount(); ++t) {
        const glm::dvec3 a = corner(mesh, t, 0), b = corner(mesh, t, 1), c = corner(mesh, t, 2);
        sag = std::max(sag, radius - glm::dot(glm::normalize(glm::cross(b - a, c - a)), a));
    }
    return sag;
}

// The mesh's triangles as positions, each rotated (keeping its winding) to start at its least
// vertex, sorted: equal for two meshes with the same triangles, whatever their vertex order.
inline std::vector<std::array<float, 9>> canonicalTriangles(const meshing::Mesh& mesh) {
    auto less = [](const glm::vec3& a, const glm::vec3& b) { return std::tie(a.x, a.y, a.z) < std::tie(b.x, b.y, b.z); };
    std::vector<std::array<float, 9>> out;
    for (std::size_t t = 0; t < mesh.triangleCount(); ++t) {
        glm::vec3 p[3];
        for (int k = 0; k < 3; ++k) p[k] = mesh.vertices[mesh.indices[3 * t + std::size_t(k)]];
        const int first = less(p[1], p[0]) ? (less(p[2], p[1]) ? 2 : 1) : (less(p[2], p[0]) ? 2 : 0);
        std::array<float, 9> row;
        for (int k = 0; k < 3; ++k)
            for (int a = 0; a < 3; ++a) row[std::size_t(3 * k + a)] = p[(first + k) % 3][a];
        out.push_back(row);
    }
    std::sort(out.begin(), out.end());
    return out;
}

// The largest |f| at the mesh's vertices.
inline float largestVertexDistance(const shaders::PreparedSdf& sdf, const meshing::Mesh& mesh) {
    sampling::FieldEvaluator field;
    EXPECT_FALSE(shaders::hasErrors(field.build(sdf)));
    std::vector<float> points, distances(mesh.vertices.size());
    for (const glm::vec3& v : mesh.vertices) points.insert(points.end(), {v.x, v.y, v.z});
    auto report = field.evaluate(points.data(), mesh.vertices.size(), distances.data(), nullptr, sampling::FieldSettings{});
    EXPECT_TRUE(report) << (report ? "" : report.error().message);
    float largest = 0.0f;
    for (float d : distances) largest = std::max(largest, std::abs(d));
    return largest;
}

inline void expectSameTopology(const meshing::Topology& a, const meshing::Topology& b, const std::string& what) {
    EXPECT_EQ(a.edges, b.edges) << what;
    EXPECT_EQ(a.boundaryEdges, b.boundaryEdges) << what;
    EXPECT_EQ(a.nonManifoldEdges, b.nonManifoldEdges) << what;
    EXPECT_EQ(a.degenerateTriangles, b.degenerateTriangles) << what;
    EXPECT_EQ(a.nonManifoldVertices, b.nonManifoldVertices) << what;
    EXPECT_EQ(a.misorientedEdges, b.misorientedEdges) << what;
}

} // namespace sdfwb::meshtest
