// The error of a mesh against the exact field, both ways (see Mesh.h).
#include <meshing/Mesh.h>

#include "PointEvaluator.h"

#include <glm/geometric.hpp>
#include <glm/vector_relational.hpp>
#include <nanoflann.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
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

// Points spread on the mesh by area (and, first, its vertices when asked), with their face.
struct MeshSamples {
    std::vector<float> xyz;
    std::vector<std::uint32_t> face; // the triangle each point lies on
};

MeshSamples sampleOnMesh(const Mesh& mesh, std::uint64_t count, std::uint64_t seed, bool withVertices) {
    MeshSamples out;
    const std::size_t triangles = mesh.triangleCount();
    if (withVertices) {
        std::vector<std::uint32_t> faceOf(mesh.vertices.size(), 0);
        for (std::size_t t = 0; t < triangles; ++t)
            for (int k = 0; k < 3; ++k) faceOf[mesh.indices[3 * t + std::size_t(k)]] = std::uint32_t(t);
        for (std::size_t v = 0; v < mesh.vertices.size(); ++v) {
            out.xyz.insert(out.xyz.end(), {mesh.vertices[v].x, mesh.vertices[v].y, mesh.vertices[v].z});
            out.face.push_back(faceOf[v]);
        }
    }
    std::vector<double> cumulative(triangles);
    double total = 0.0;
    for (std::size_t t = 0; t < triangles; ++t) {
        const glm::vec3 &a = mesh.vertices[mesh.indices[3 * t]], &b = mesh.vertices[mesh.indices[3 * t + 1]],
                        &c = mesh.vertices[mesh.indices[3 * t + 2]];
        total += 0.5 * double(glm::length(glm::cross(b - a, c - a)));
        cumulative[t] = total;
    }
    std::mt19937_64 random(seed);
    std::uniform_real_distribution<double> uniform(0.0, 1.0);
    for (std::uint64_t s = 0; s < count && total > 0.0; ++s) {
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
        out.xyz.insert(out.xyz.end(), {p.x, p.y, p.z});
        out.face.push_back(std::uint32_t(f));
    }
    return out;
}

glm::vec3 faceNormal(const Mesh& mesh, std::size_t t) {
    const glm::vec3 &a = mesh.vertices[mesh.indices[3 * t]], &b = mesh.vertices[mesh.indices[3 * t + 1]],
                    &c = mesh.vertices[mesh.indices[3 * t + 2]];
    const glm::vec3 n = glm::cross(b - a, c - a);
    const float length = glm::length(n);
    return length > 0.0f ? n / length : glm::vec3(0.0f);
}

// The nearest triangle to a point: the k-d tree gives the nearest centre; every triangle whose
// centre lies within that distance plus the largest centre-to-corner radius may be nearer, and
// those are measured exactly. Triangles far larger than the mesh's usual ones (over 4 times the
// 99th percentile of the radii: slivers across a thin wall, a broken mesh's spikes) would widen
// every search to most of the mesh; they stay out of the tree and are measured at every query.
class TriangleLocator {
public:
    explicit TriangleLocator(const Mesh& mesh)
        : m_mesh(mesh), m_tree(3, m_centres, nanoflann::KDTreeSingleIndexAdaptorParams(16)) {
        const std::size_t triangles = mesh.triangleCount();
        std::vector<float> radii(triangles);
        std::vector<glm::vec3> centres(triangles);
        for (std::size_t t = 0; t < triangles; ++t) {
            const glm::vec3 &a = mesh.vertices[mesh.indices[3 * t]], &b = mesh.vertices[mesh.indices[3 * t + 1]],
                            &c = mesh.vertices[mesh.indices[3 * t + 2]];
            centres[t] = (a + b + c) / 3.0f;
            radii[t] = std::max({glm::length(a - centres[t]), glm::length(b - centres[t]), glm::length(c - centres[t])});
        }
        float large = std::numeric_limits<float>::infinity();
        if (triangles > 0) {
            std::vector<float> sorted = radii;
            const auto at = sorted.begin() + std::ptrdiff_t(0.99 * double(triangles - 1));
            std::nth_element(sorted.begin(), at, sorted.end());
            large = 4.0f * *at;
        }
        for (std::size_t t = 0; t < triangles; ++t) {
            if (radii[t] > large) { // NaN radii stay in the tree, as before
                m_large.push_back(std::uint32_t(t));
                continue;
            }
            m_inTree.push_back(std::uint32_t(t));
            m_centres.xyz.insert(m_centres.xyz.end(), {centres[t].x, centres[t].y, centres[t].z});
            m_radius = std::max(m_radius, radii[t]);
        }
        m_tree.buildIndex();
    }
    // Distance and triangle; infinity for a non-finite point.
    std::pair<float, std::uint32_t> nearest(const glm::vec3& p) {
        if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z)) return {std::numeric_limits<float>::infinity(), 0};
        std::pair<float, std::uint32_t> best{std::numeric_limits<float>::infinity(), 0};
        auto measure = [&](std::uint32_t t) {
            const float d =
                pointTriangleDistance(p, m_mesh.vertices[m_mesh.indices[3 * t]], m_mesh.vertices[m_mesh.indices[3 * t + 1]],
                                      m_mesh.vertices[m_mesh.indices[3 * t + 2]]);
            if (d < best.first) best = {d, t};
        };
        if (!m_inTree.empty()) {
            const float query[3] = {p.x, p.y, p.z};
            std::uint32_t closest = 0;
            float closestSquared = 0.0f;
            m_tree.knnSearch(query, 1, &closest, &closestSquared);
            best.second = m_inTree[closest];
            const float radius = std::sqrt(closestSquared) + m_radius;
            m_found.clear();
            m_tree.radiusSearch(query, radius * radius, m_found, nanoflann::SearchParams(32, 0.0f, false));
            for (const auto& item : m_found) measure(m_inTree[item.first]);
        }
        for (std::uint32_t t : m_large) measure(t);
        return best;
    }

private:
    const Mesh& m_mesh;
    Centres m_centres;
    Tree m_tree;
    float m_radius = 0.0f;
    std::vector<std::uint32_t> m_inTree; // the tree's points' triangles
    std::vector<std::uint32_t> m_large;  // measured at every query
    std::vector<std::pair<std::uint32_t, float>> m_found;
};

// Inside/outside of a closed mesh at the points of a regular grid, by the parity of the crossings
// of a ray along +z through each column (the columns are offset by an irrational fraction of a
// cell so that no ray meets an edge or vertex exactly).
std::vector<std::uint8_t> occupancyByParity(const Mesh& mesh, int n, glm::dvec3 lo, glm::dvec3 hi) {
    const glm::dvec3 step = (hi - lo) / double(n);
    const double ox = 0.5 + 1e-4 * 0.7071067811865476, oy = 0.5 + 1e-4 * 0.5772156649015329;
    std::vector<std::vector<double>> columns(std::size_t(n) * std::size_t(n));
    for (std::size_t t = 0; t < mesh.triangleCount(); ++t) {
        const glm::dvec3 a(mesh.vertices[mesh.indices[3 * t]]), b(mesh.vertices[mesh.indices[3 * t + 1]]),
            c(mesh.vertices[mesh.indices[3 * t + 2]]);
        const double area = (b.x - a.x) * (c.y - a.y) - (c.x - a.x) * (b.y - a.y);
        if (area == 0.0) continue; // edge-on: no column crosses it
        const int i0 = std::max(0, int(std::ceil((std::min({a.x, b.x, c.x}) - lo.x) / step.x - ox)));
        const int i1 = std::min(n - 1, int(std::floor((std::max({a.x, b.x, c.x}) - lo.x) / step.x - ox)));
        const int j0 = std::max(0, int(std::ceil((std::min({a.y, b.y, c.y}) - lo.y) / step.y - oy)));
        const int j1 = std::min(n - 1, int(std::floor((std::max({a.y, b.y, c.y}) - lo.y) / step.y - oy)));
        for (int j = j0; j <= j1; ++j)
            for (int i = i0; i <= i1; ++i) {
                const double x = lo.x + (i + ox) * step.x, y = lo.y + (j + oy) * step.y;
                const double w0 = ((b.x - x) * (c.y - y) - (c.x - x) * (b.y - y)) / area;
                const double w1 = ((c.x - x) * (a.y - y) - (a.x - x) * (c.y - y)) / area;
                const double w2 = 1.0 - w0 - w1;
                if (w0 < 0.0 || w1 < 0.0 || w2 < 0.0) continue;
                columns[std::size_t(j) * std::size_t(n) + std::size_t(i)].push_back(w0 * a.z + w1 * b.z + w2 * c.z);
            }
    }
    std::vector<std::uint8_t> inside(std::size_t(n) * std::size_t(n) * std::size_t(n), 0);
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
            std::vector<double>& zs = columns[std::size_t(j) * std::size_t(n) + std::size_t(i)];
            std::sort(zs.begin(), zs.end());
            std::size_t crossed = 0;
            for (int k = 0; k < n; ++k) {
                const double z = lo.z + (k + 0.5) * step.z;
                while (crossed < zs.size() && zs[crossed] < z) ++crossed;
                inside[(std::size_t(k) * std::size_t(n) + std::size_t(j)) * std::size_t(n) + std::size_t(i)] = crossed % 2;
            }
        }
    return inside;
}

} // namespace

Expected<MeshError> measureError(const shaders::PreparedSdf& sdf, const Mesh& mesh, const ErrorOptions& options) {
    const auto start = std::chrono::steady_clock::now();
    if (mesh.indices.empty()) return makeError("mesh error: the mesh has no triangles");
    MeshError error;
    // Surface points first: the reference for surface -> mesh, and for mesh -> surface when the
    // field is not exact.
    std::vector<float> surface, distances, gradients;
    {
        detail::PointEvaluator field;
        if (auto ok = field.build(sdf, "surface", options.time, options.parameters); !ok) return ok.error();
        if (auto ok = field.generate(options.surfacePoints, options.seed, surface, distances, gradients); !ok) return ok.error();
    }
    // Mesh -> surface, at the vertices and at area-weighted points on the faces: |f| for an exact
    // field, else the distance to the nearest surface point.
    const MeshSamples onMesh = sampleOnMesh(mesh, options.meshPoints, options.seed, true);
    std::vector<float> meshDistances, meshGradients;
    {
        detail::PointEvaluator field;
        if (auto ok = field.build(sdf, "analysis/points.glsl", options.time, options.parameters); !ok) return ok.error();
        if (options.cut) field.setClip(glm::dvec3(options.cut->first), glm::dvec3(options.cut->second));
        if (auto ok = field.evaluate(onMesh.xyz, meshDistances, &meshGradients); !ok) return ok.error();
    }
    if (options.fieldIsExact) {
        error.meshToSurfaceMethod = "|f| (the field is exact: |f| is the distance)";
        for (float& d : meshDistances) d = std::abs(d);
    } else {
        // |f| underestimates the distance where |grad f| < 1; one Newton step along the gradient,
        // |f| / |grad f|, is the first-order distance to the zero set for any smooth field.
        error.meshToSurfaceMethod =
            "|f| / max(|grad f|, 0.25) (the field is not exact, so |f| alone underestimates the distance)";
        for (std::size_t s = 0; s < meshDistances.size(); ++s) {
            const float g = glm::length(glm::vec3(meshGradients[3 * s], meshGradients[3 * s + 1], meshGradients[3 * s + 2]));
            meshDistances[s] = std::abs(meshDistances[s]) / std::max(g, 0.25f); // at most 4 x |f| where the gradient vanishes
        }
    }
    {
        double sum = 0.0;
        std::uint64_t counted = 0;
        for (float d : meshDistances) {
            if (!std::isfinite(d)) continue;
            sum += double(d);
            error.meshToSurfaceMax = std::max(error.meshToSurfaceMax, d);
            ++counted;
        }
        error.meshPoints = counted;
        error.meshToSurfaceMean = counted ? float(sum / double(counted)) : 0.0f;
    }
    // Surface -> mesh: the surface points to the nearest triangle.
    TriangleLocator locator(mesh);
    double sum = 0.0;
    std::uint64_t counted = 0;
    for (std::size_t s = 0; s < distances.size(); ++s) {
        if (!std::isfinite(distances[s])) continue; // a ray that missed
        if (options.cut) {
            const glm::vec3 p(surface[3 * s], surface[3 * s + 1], surface[3 * s + 2]);
            if (glm::any(glm::lessThan(p, options.cut->first)) || glm::any(glm::greaterThan(p, options.cut->second)))
                continue; // cut away with the field
        }
        const float d = locator.nearest(glm::vec3(surface[3 * s], surface[3 * s + 1], surface[3 * s + 2])).first;
        if (!std::isfinite(d)) continue;
        sum += double(d);
        error.surfaceToMeshMax = std::max(error.surfaceToMeshMax, d);
        ++counted;
    }
    error.surfacePoints = counted;
    error.surfaceToMeshMean = counted ? float(sum / double(counted)) : 0.0f;
    error.hausdorff = std::max(error.meshToSurfaceMax, error.surfaceToMeshMax);
    error.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return error;
}

// Which of the points lie near a crease of the field: its normal at the point (the unit gradient)
// and at one of 8 points `radius` away around it, in the plane normal to it, differ by more than the
// angle whose cosine is `cosAngle`. Points without a usable gradient are not near a crease.
Expected<std::vector<std::uint8_t>> nearCreases(detail::PointEvaluator& field, const std::vector<float>& points,
                                                const std::vector<float>& gradients, float radius, float cosAngle) {
    constexpr int kTaps = 8;
    const std::size_t n = points.size() / 3;
    std::vector<glm::vec3> normals(n, glm::vec3(0.0f));
    std::vector<float> taps;
    taps.reserve(3 * kTaps * n);
    for (std::size_t s = 0; s < n; ++s) {
        const glm::vec3 p(points[3 * s], points[3 * s + 1], points[3 * s + 2]);
        const glm::vec3 g(gradients[3 * s], gradients[3 * s + 1], gradients[3 * s + 2]);
        const float length = glm::length(g);
        if (length > 0.0f && std::isfinite(length)) normals[s] = g / length;
        const glm::vec3 normal = normals[s];
        // Any unit vector across the normal, then the one across both.
        const glm::vec3 other = std::abs(normal.x) < 0.6f ? glm::vec3(1, 0, 0) : glm::vec3(0, 1, 0);
        const glm::vec3 u = glm::length(normal) > 0.0f ? glm::normalize(glm::cross(normal, other)) : glm::vec3(0.0f);
        const glm::vec3 v = glm::cross(normal, u);
        for (int k = 0; k < kTaps; ++k) {
            const float angle = 6.2831853f * float(k) / float(kTaps);
            const glm::vec3 q = p + radius * (std::cos(angle) * u + std::sin(angle) * v);
            taps.insert(taps.end(), {q.x, q.y, q.z});
        }
    }
    std::vector<float> values, tapGradients;
    if (auto ok = field.evaluate(taps, values, &tapGradients); !ok) return ok.error();
    std::vector<std::uint8_t> near(n, 0);
    for (std::size_t s = 0; s < n; ++s) {
        if (glm::length(normals[s]) == 0.0f) continue;
        for (int k = 0; k < kTaps && !near[s]; ++k) {
            const std::size_t t = kTaps * s + std::size_t(k);
            const glm::vec3 g(tapGradients[3 * t], tapGradients[3 * t + 1], tapGradients[3 * t + 2]);
            const float length = glm::length(g);
            if (length > 0.0f && std::isfinite(length)) near[s] = glm::dot(normals[s], g / length) < cosAngle;
        }
    }
    return near;
}

// The edge measures over the points near creases: `accuracy` and `completeness` hold each point's
// distance (infinite where it has none).
std::optional<EdgeEvaluation> edgeMeasures(const std::vector<float>& accuracy, const std::vector<std::uint8_t>& meshNear,
                                           const std::vector<float>& completeness, const std::vector<std::uint8_t>& surfaceNear,
                                           float tau) {
    // One pass over one set: the mean, the share within tau and the largest distance of its points
    // near a crease.
    struct Tally {
        double sum = 0.0;
        std::uint64_t within = 0, count = 0;
        float largest = 0.0f;
    };
    auto tally = [tau](const std::vector<float>& distances, const std::vector<std::uint8_t>& near) {
        Tally t;
        for (std::size_t s = 0; s < distances.size(); ++s) {
            if (!near[s] || !std::isfinite(distances[s])) continue;
            t.sum += double(distances[s]);
            t.within += distances[s] < tau;
            t.largest = std::max(t.largest, distances[s]);
            ++t.count;
        }
        return t;
    };
    const Tally mesh = tally(accuracy, meshNear), surface = tally(completeness, surfaceNear);
    if (surface.count == 0) return std::nullopt; // no crease on the exact surface
    EdgeEvaluation e;
    e.meshPoints = mesh.count;
    e.surfacePoints = surface.count;
    e.hausdorff = std::max(mesh.largest, surface.largest);
    e.accuracyMean = mesh.count ? float(mesh.sum / double(mesh.count)) : 0.0f;
    e.completenessMean = float(surface.sum / double(surface.count));
    e.chamferL1 = 0.5f * (e.accuracyMean + e.completenessMean);
    e.precision = mesh.count ? float(double(mesh.within) / double(mesh.count)) : 0.0f;
    e.recall = float(double(surface.within) / double(surface.count));
    e.fscore = e.precision + e.recall > 0.0f ? 2.0f * e.precision * e.recall / (e.precision + e.recall) : 0.0f;
    return e;
}

Expected<MeshEvaluation> evaluateMesh(const shaders::PreparedSdf& sdf, const Mesh& mesh, const EvalOptions& options) {
    const auto start = std::chrono::steady_clock::now();
    if (mesh.indices.empty()) return makeError("eval: the mesh has no triangles");
    if (!(options.tau > 0.0f)) return makeError("eval: --tau must be positive");
    if (!(options.edgeRadius >= 0.0f) || !(options.edgeAngleDegrees > 0.0f && options.edgeAngleDegrees < 180.0f))
        return makeError("eval: the edge radius must be 0 or more and the edge angle between 0 and 180 degrees");
    MeshEvaluation e;
    e.tau = options.tau;
    // Accuracy: points on the mesh to the surface, |f| (the distance for an exact field).
    const MeshSamples onMesh = sampleOnMesh(mesh, options.points, options.seed, false);
    detail::PointEvaluator field;
    if (auto ok = field.build(sdf, "analysis/points.glsl", options.time, options.parameters); !ok) return ok.error();
    std::vector<float> values, gradients;
    if (auto ok = field.evaluate(onMesh.xyz, values, &gradients); !ok) return ok.error();
    double sum1 = 0.0, sum2 = 0.0, normalSum = 0.0;
    std::uint64_t within = 0, counted = 0, normals = 0;
    std::vector<float> accuracy(values.size(), std::numeric_limits<float>::infinity());
    for (std::size_t s = 0; s < values.size(); ++s) {
        if (!std::isfinite(values[s])) continue;
        const double d = std::abs(double(values[s]));
        accuracy[s] = float(d);
        sum1 += d;
        sum2 += d * d;
        e.accuracyMax = std::max(e.accuracyMax, float(d));
        within += d < options.tau;
        ++counted;
        const glm::vec3 g(gradients[3 * s], gradients[3 * s + 1], gradients[3 * s + 2]);
        if (glm::length(g) > 0.0f && std::isfinite(glm::length(g))) {
            normalSum += std::abs(double(glm::dot(glm::normalize(g), faceNormal(mesh, onMesh.face[s]))));
            ++normals;
        }
    }
    e.meshPoints = counted;
    e.accuracyMean = counted ? float(sum1 / double(counted)) : 0.0f;
    const double accuracySquared = counted ? sum2 / double(counted) : 0.0;
    e.precision = counted ? float(double(within) / double(counted)) : 0.0f;
    // Completeness: points on the exact surface to the nearest triangle.
    std::vector<float> surface, distances, surfaceGradients;
    {
        detail::PointEvaluator sampler;
        if (auto ok = sampler.build(sdf, "surface", options.time, options.parameters); !ok) return ok.error();
        if (auto ok = sampler.generate(options.points, options.seed + 1, surface, distances, surfaceGradients); !ok)
            return ok.error();
    }
    TriangleLocator locator(mesh);
    double sum1b = 0.0, sum2b = 0.0, normalSumB = 0.0;
    std::uint64_t withinB = 0, countedB = 0, normalsB = 0;
    std::vector<float> completeness(distances.size(), std::numeric_limits<float>::infinity());
    for (std::size_t s = 0; s < distances.size(); ++s) {
        if (!std::isfinite(distances[s])) continue;
        const auto [d, face] = locator.nearest(glm::vec3(surface[3 * s], surface[3 * s + 1], surface[3 * s + 2]));
        if (!std::isfinite(d)) continue;
        completeness[s] = d;
        sum1b += double(d);
        sum2b += double(d) * double(d);
        e.completenessMax = std::max(e.completenessMax, d);
        withinB += d < options.tau;
        ++countedB;
        const glm::vec3 g(surfaceGradients[3 * s], surfaceGradients[3 * s + 1], surfaceGradients[3 * s + 2]);
        if (glm::length(g) > 0.0f && std::isfinite(glm::length(g))) {
            normalSumB += std::abs(double(glm::dot(glm::normalize(g), faceNormal(mesh, face))));
            ++normalsB;
        }
    }
    e.surfacePoints = countedB;
    e.completenessMean = countedB ? float(sum1b / double(countedB)) : 0.0f;
    e.recall = countedB ? float(double(withinB) / double(countedB)) : 0.0f;
    e.chamferL1 = 0.5f * (e.accuracyMean + e.completenessMean);
    e.chamferL2 = float(0.5 * (accuracySquared + (countedB ? sum2b / double(countedB) : 0.0)));
    e.normalConsistency =
        float(0.5 * ((normals ? normalSum / double(normals) : 0.0) + (normalsB ? normalSumB / double(normalsB) : 0.0)));
    e.fscore = e.precision + e.recall > 0.0f ? 2.0f * e.precision * e.recall / (e.precision + e.recall) : 0.0f;
    e.hausdorff = std::max(e.accuracyMax, e.completenessMax);
    if (options.edgeRadius > 0.0f) {
        const float cosAngle = std::cos(options.edgeAngleDegrees * 3.14159265f / 180.0f);
        auto meshNear = nearCreases(field, onMesh.xyz, gradients, options.edgeRadius, cosAngle);
        if (!meshNear) return meshNear.error();
        auto surfaceNear = nearCreases(field, surface, surfaceGradients, options.edgeRadius, cosAngle);
        if (!surfaceNear) return surfaceNear.error();
        e.edges = edgeMeasures(accuracy, *meshNear, completeness, *surfaceNear, options.tau);
    }
    // Volume IoU: occupancy of the field (f < 0) against the mesh's (ray parity) on a grid.
    const Topology topology = checkTopology(mesh);
    e.closed = topology.boundaryEdges == 0;
    if (options.occupancyResolution > 0) {
        const int n = options.occupancyResolution;
        const glm::dvec3 lo(options.boundsMin), hi(options.boundsMax), step = (hi - lo) / double(n);
        std::vector<float> grid;
        grid.reserve(3 * std::size_t(n) * std::size_t(n) * std::size_t(n));
        for (int k = 0; k < n; ++k)
            for (int j = 0; j < n; ++j)
                for (int i = 0; i < n; ++i) {
                    const glm::dvec3 p = lo + (glm::dvec3(i, j, k) + 0.5) * step;
                    grid.insert(grid.end(), {float(p.x), float(p.y), float(p.z)});
                }
        std::vector<float> occupancy;
        if (auto ok = field.evaluate(grid, occupancy, nullptr); !ok) return ok.error();
        const std::vector<std::uint8_t> meshInside = occupancyByParity(mesh, n, lo, hi);
        std::uint64_t both = 0, either = 0;
        for (std::size_t q = 0; q < occupancy.size(); ++q) {
            const bool a = occupancy[q] < 0.0f, b = meshInside[q] != 0;
            both += a && b;
            either += a || b;
        }
        e.iou = either ? float(double(both) / double(either)) : 1.0f;
        e.occupancyPoints = occupancy.size();
    }
    e.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return e;
}

} // namespace sdfwb::meshing
