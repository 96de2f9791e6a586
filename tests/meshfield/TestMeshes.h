#pragma once
// Meshes the mesh-field tests make themselves (a fresh clone has no shared data): a torus with
// outward, counter-clockwise faces, and broken variants of any mesh (holes, flipped faces, a
// duplicated shell), drawn from a fixed seed.

#include <meshfield/MeshField.h>

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <numbers>
#include <random>

namespace sdfwb::testing {

// The distance from p to the mesh by a scan of every triangle in double precision: the reference
// the hierarchy's answers are checked against.
inline double bruteDistance(const meshfield::TriangleMesh& mesh, const glm::dvec3& p) {
    double best = std::numeric_limits<double>::infinity();
    for (std::size_t t = 0; t < mesh.indices.size(); t += 3) {
        const glm::dvec3 q = meshfield::closestPointOnTriangle(p, glm::dvec3(mesh.vertices[mesh.indices[t]]),
                                                               glm::dvec3(mesh.vertices[mesh.indices[t + 1]]),
                                                               glm::dvec3(mesh.vertices[mesh.indices[t + 2]]));
        best = std::min(best, glm::length(p - q));
    }
    return best;
}

// A torus around z (major radius R, minor r), `around` x `across` quads, two triangles each.
inline meshfield::TriangleMesh torusMesh(float R, float r, int around, int across) {
    meshfield::TriangleMesh mesh;
    for (int i = 0; i < around; ++i)
        for (int j = 0; j < across; ++j) {
            const double u = 2.0 * std::numbers::pi * i / around;
            const double v = 2.0 * std::numbers::pi * j / across;
            mesh.vertices.emplace_back(float((R + r * std::cos(v)) * std::cos(u)), float((R + r * std::cos(v)) * std::sin(u)),
                                       float(r * std::sin(v)));
        }
    auto at = [&](int i, int j) { return std::uint32_t(((i + around) % around) * across + (j + across) % across); };
    for (int i = 0; i < around; ++i)
        for (int j = 0; j < across; ++j) {
            // Counter-clockwise seen from outside: (i,j) (i+1,j) (i+1,j+1) turns outward here.
            mesh.indices.insert(mesh.indices.end(), {at(i, j), at(i + 1, j), at(i + 1, j + 1)});
            mesh.indices.insert(mesh.indices.end(), {at(i, j), at(i + 1, j + 1), at(i, j + 1)});
        }
    return mesh;
}

// `mesh` as an OBJ file (v and f lines, 1-based).
inline void writeObj(const std::filesystem::path& path, const meshfield::TriangleMesh& mesh) {
    std::ofstream obj(path);
    for (const glm::vec3& v : mesh.vertices) obj << "v " << v.x << ' ' << v.y << ' ' << v.z << '\n';
    for (std::size_t t = 0; t < mesh.indices.size(); t += 3)
        obj << "f " << mesh.indices[t] + 1 << ' ' << mesh.indices[t + 1] + 1 << ' ' << mesh.indices[t + 2] + 1 << '\n';
}

// The exact torus's signed distance (for the polygon's inside: |d| well above the chord error).
inline double torusDistance(const glm::dvec3& p, double R, double r) {
    const double q = std::sqrt(p.x * p.x + p.y * p.y) - R;
    return std::sqrt(q * q + p.z * p.z) - r;
}

enum class Damage { RemoveOnePercent, RemoveFivePercent, FlipTenPercent, DuplicateShell };

inline const char* damageName(Damage damage) {
    switch (damage) {
    case Damage::RemoveOnePercent:
        return "1% of faces removed";
    case Damage::RemoveFivePercent:
        return "5% of faces removed";
    case Damage::FlipTenPercent:
        return "10% of faces flipped";
    case Damage::DuplicateShell:
        return "shell duplicated";
    }
    return "?";
}

inline meshfield::TriangleMesh damaged(const meshfield::TriangleMesh& mesh, Damage damage, unsigned seed = 7) {
    std::mt19937 random(seed);
    std::vector<std::size_t> faces(mesh.triangleCount());
    for (std::size_t f = 0; f < faces.size(); ++f) faces[f] = f;
    std::shuffle(faces.begin(), faces.end(), random);
    meshfield::TriangleMesh out;
    out.vertices = mesh.vertices;
    auto face = [&](std::size_t f, bool flip) {
        const std::uint32_t* t = mesh.indices.data() + 3 * f;
        if (flip)
            out.indices.insert(out.indices.end(), {t[0], t[2], t[1]});
        else
            out.indices.insert(out.indices.end(), {t[0], t[1], t[2]});
    };
    const double share = damage == Damage::RemoveOnePercent ? 0.01 : damage == Damage::RemoveFivePercent ? 0.05 : 0.10;
    const std::size_t chosen = std::size_t(std::lround(share * double(faces.size())));
    std::vector<char> picked(faces.size(), 0);
    for (std::size_t k = 0; k < chosen; ++k) picked[faces[k]] = 1;
    for (std::size_t f = 0; f < faces.size(); ++f) {
        if (picked[f] && (damage == Damage::RemoveOnePercent || damage == Damage::RemoveFivePercent)) continue;
        face(f, picked[f] && damage == Damage::FlipTenPercent);
    }
    if (damage == Damage::DuplicateShell) { // a second copy, its vertices apart, overlapping the first
        const auto offset = std::uint32_t(out.vertices.size());
        for (const glm::vec3& v : mesh.vertices) out.vertices.push_back(v * 1.0f);
        for (std::uint32_t i : mesh.indices) out.indices.push_back(i + offset);
    }
    return out;
}

} // namespace sdfwb::testing
