// The error of a mesh against the exact field, both ways (see Mesh.h).
#include <meshing/Mesh.h>

#include "FieldProbe.h"

#include <glm/geometric.hpp>
#include <nanoflann.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <random>

namespace sdfwb::meshing {
namespace {

// Distance from p to the triangle abc (Ericson, Real-Time Collision Detection, 5.1.5).
float pointTriangleDistance(const glm::vec3& p, const glm::vec3& a, const glm::vec3& b, const glm::vec3& c) {
    const glm::vec3 ab = b - a, ac = c - a, ap = p - a;
    const float d1 = glm::dot(ab, ap), d2 = glm::dot(ac, ap);
    if (d1 <= 0.0f && d2 <= 0.0f) return glm::length(p - a);
    const glm::vec3 bp = p - b;
    const float d3 = glm::dot(ab, bp), d4 = glm::dot(ac, bp);
    if (d3 >= 0.0f && d4 <= d3) return glm::length(p - b);
    const float vc = d1 * d4 - d3 * d2;
    if (vc <= 0.0f && d1 >= 0.0f && d3 <= 0.0f) return glm::length(p - (a + ab * (d1 / (d1 - d3))));
    const glm::vec3 cp = p - c;
    const float d5 = glm::dot(ab, cp), d6 = glm::dot(ac, cp);
    if (d6 >= 0.0f && d5 <= d6) return glm::length(p - c);
    const float vb = d5 * d2 - d1 * d6;
    if (vb <= 0.0f && d2 >= 0.0f && d6 <= 0.0f) return glm::length(p - (a + ac * (d2 / (d2 - d6))));
    const float va = d3 * d6 - d5 * d4;
    if (va <= 0.0f && (d4 - d3) >= 0.0f && (d5 - d6) >= 0.0f)
        return glm::length(p - (b + (c - b) * ((d4 - d3) / ((d4 - d3) + (d5 - d6)))));
    const float denominator = 1.0f / (va + vb + vc);
    return glm::length(p - (a + ab * (vb * denominator) + ac * (vc * denominator)));
}

struct Centres {
    std::vector<float> xyz;
    std::size_t kdtree_get_point_count() const { return xyz.size() / 3; }
    float kdtree_get_pt(std::size_t i, std::size_t d) const { return xyz[3 * i + d]; }
    template <class Box> bool kdtree_get_bbox(Box&) const { return false; }
};
using Tree = nanoflann::KDTreeSingleIndexAdaptor<nanoflann::L2_Simple_Adaptor<float, Centres>, Centres, 3, std::uint32_t>;

} // namespace

Expected<MeshError> measureError(const shaders::PreparedSdf& sdf, const Mesh& mesh, const ErrorOptions& options) {
    const auto start = std::chrono::steady_clock::now();
    if (mesh.indices.empty()) return makeError("mesh error: the mesh has no triangles");
    MeshError error;
    // Mesh -> surface: |f| at the vertices and at area-weighted points on the faces.
    std::vector<float> points;
    for (const glm::vec3& v : mesh.vertices) points.insert(points.end(), {v.x, v.y, v.z});
    const std::size_t triangles = mesh.triangleCount();
    std::vector<double> cumulative(triangles);
    double total = 0.0;
    for (std::size_t t = 0; t < triangles; ++t) {
        const glm::vec3 &a = mesh.vertices[mesh.indices[3 * t]], &b = mesh.vertices[mesh.indices[3 * t + 1]],
                        &c = mesh.vertices[mesh.indices[3 * t + 2]];
        total += 0.5 * double(glm::length(glm::cross(b - a, c - a)));
        cumulative[t] = total;
    }
    std::mt19937_64 random(options.seed);
    std::uniform_real_distribution<double> uniform(0.0, 1.0);
    for (std::uint64_t s = 0; s < options.meshPoints && total > 0.0; ++s) {
        const std::size_t t =
            std::size_t(std::lower_bound(cumulative.begin(), cumulative.end(), uniform(random) * total) - cumulative.begin());
        const std::size_t f = std::min(t, triangles - 1);
        double r1 = uniform(random), r2 = uniform(random);
        if (r1 + r2 > 1.0) {
            r1 = 1.0 - r1;
            r2 = 1.0 - r2;
        }
        const glm::vec3 &a = mesh.vertices[mesh.indices[3 * f]], &b = mesh.vertices[mesh.indices[3 * f + 1]],
                        &c = mesh.vertices[mesh.indices[3 * f + 2]];
        const glm::vec3 p = a + float(r1) * (b - a) + float(r2) * (c - a);
        points.insert(points.end(), {p.x, p.y, p.z});
    }
    {
        detail::FieldProbe probe;
        if (auto ok = probe.build(sdf, "analysis/points.glsl", options.time, options.parameters); !ok) return ok.error();
        std::vector<float> values;
        if (auto ok = probe.evaluate(points, values, nullptr); !ok) return ok.error();
        double sum = 0.0;
        std::uint64_t counted = 0;
        for (float f : values) {
            if (!std::isfinite(f)) continue;
            sum += std::abs(double(f));
            error.meshToSurfaceMax = std::max(error.meshToSurfaceMax, std::abs(f));
            ++counted;
        }
        error.meshPoints = counted;
        error.meshToSurfaceMean = counted ? float(sum / double(counted)) : 0.0f;
    }
    // Surface -> mesh: points on the zero set to the nearest triangle.
    std::vector<float> surface, distances;
    {
        detail::FieldProbe probe;
        if (auto ok = probe.build(sdf, "surface", options.time, options.parameters); !ok) return ok.error();
        if (auto ok = probe.generate(options.surfacePoints, options.seed, surface, distances); !ok) return ok.error();
    }
    Centres centres;
    float largestRadius = 0.0f;
    for (std::size_t t = 0; t < triangles; ++t) {
        const glm::vec3 &a = mesh.vertices[mesh.indices[3 * t]], &b = mesh.vertices[mesh.indices[3 * t + 1]],
                        &c = mesh.vertices[mesh.indices[3 * t + 2]];
        const glm::vec3 m = (a + b + c) / 3.0f;
        centres.xyz.insert(centres.xyz.end(), {m.x, m.y, m.z});
        largestRadius = std::max({largestRadius, glm::length(a - m), glm::length(b - m), glm::length(c - m)});
    }
    Tree tree(3, centres, nanoflann::KDTreeSingleIndexAdaptorParams(16));
    tree.buildIndex();
    double sum = 0.0;
    std::uint64_t counted = 0;
    std::vector<std::pair<std::uint32_t, float>> found;
    for (std::size_t s = 0; s < distances.size(); ++s) {
        if (!std::isfinite(distances[s]) || !std::isfinite(surface[3 * s])) continue; // a ray that missed
        const float query[3] = {surface[3 * s], surface[3 * s + 1], surface[3 * s + 2]};
        std::uint32_t nearest = 0;
        float nearestSquared = 0.0f;
        tree.knnSearch(query, 1, &nearest, &nearestSquared);
        // Every triangle within (nearest centre distance + largest radius) of the point may be nearer.
        const float radius = std::sqrt(nearestSquared) + largestRadius;
        found.clear();
        tree.radiusSearch(query, radius * radius, found, nanoflann::SearchParams(32, 0.0f, false));
        const glm::vec3 p(query[0], query[1], query[2]);
        float best = std::numeric_limits<float>::infinity();
        for (const auto& item : found) {
            const std::size_t t = item.first;
            best = std::min(best,
                            pointTriangleDistance(p, mesh.vertices[mesh.indices[3 * t]], mesh.vertices[mesh.indices[3 * t + 1]],
                                                  mesh.vertices[mesh.indices[3 * t + 2]]));
        }
        if (!std::isfinite(best)) continue;
        sum += double(best);
        error.surfaceToMeshMax = std::max(error.surfaceToMeshMax, best);
        ++counted;
    }
    error.surfacePoints = counted;
    error.surfaceToMeshMean = counted ? float(sum / double(counted)) : 0.0f;
    error.hausdorff = std::max(error.meshToSurfaceMax, error.surfaceToMeshMax);
    error.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return error;
}

} // namespace sdfwb::meshing
