// The QEF of dual contouring (Qef.h).
#include "Qef.h"

#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <glm/vector_relational.hpp>

#include <algorithm>
#include <cmath>
#include <utility>

namespace sdfwb::meshing::detail {
namespace {

// Eigen-decomposition of a symmetric 3x3 matrix by Jacobi rotations.
void symmetricEigen(std::array<std::array<double, 3>, 3> a, std::array<double, 3>& values,
                    std::array<std::array<double, 3>, 3>& vectors) {
    vectors = {{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}};
    for (int sweep = 0; sweep < 32; ++sweep) {
        const double off = a[0][1] * a[0][1] + a[0][2] * a[0][2] + a[1][2] * a[1][2];
        if (off < 1e-22) break;
        for (int p = 0; p < 2; ++p)
            for (int q = p + 1; q < 3; ++q) {
                if (std::abs(a[p][q]) < 1e-30) continue;
                const double theta = (a[q][q] - a[p][p]) / (2.0 * a[p][q]);
                const double t = (theta >= 0 ? 1.0 : -1.0) / (std::abs(theta) + std::sqrt(theta * theta + 1.0));
                const double c = 1.0 / std::sqrt(t * t + 1.0), s = t * c;
                for (int k = 0; k < 3; ++k) { // a = J^T a J
                    const double akp = a[k][p], akq = a[k][q];
                    a[k][p] = c * akp - s * akq;
                    a[k][q] = s * akp + c * akq;
                }
                for (int k = 0; k < 3; ++k) {
                    const double apk = a[p][k], aqk = a[q][k];
                    a[p][k] = c * apk - s * aqk;
                    a[q][k] = s * apk + c * aqk;
                }
                for (int k = 0; k < 3; ++k) {
                    const double vkp = vectors[k][p], vkq = vectors[k][q];
                    vectors[k][p] = c * vkp - s * vkq;
                    vectors[k][q] = s * vkp + c * vkq;
                }
            }
    }
    for (int i = 0; i < 3; ++i) values[std::size_t(i)] = a[std::size_t(i)][std::size_t(i)];
}

} // namespace

QefSolution solveQef(const glm::dvec3* points, const glm::dvec3* normals, int count) {
    glm::dvec3 mass(0.0);
    for (int i = 0; i < count; ++i) mass += points[i];
    mass /= double(count);
    std::array<std::array<double, 3>, 3> ata{};
    glm::dvec3 atb(0.0);
    for (int i = 0; i < count; ++i) {
        const glm::dvec3& n = normals[i];
        const double d = glm::dot(n, points[i] - mass);
        for (int r = 0; r < 3; ++r) {
            for (int c = 0; c < 3; ++c) ata[std::size_t(r)][std::size_t(c)] += n[r] * n[c];
            atb[r] += n[r] * d;
        }
    }
    std::array<double, 3> values{};
    std::array<std::array<double, 3>, 3> vectors{};
    symmetricEigen(ata, values, vectors);
    const double largest = std::max({std::abs(values[0]), std::abs(values[1]), std::abs(values[2])});
    QefSolution out;
    glm::dvec3 x(0.0);
    for (int k = 0; k < 3; ++k) {
        const glm::dvec3 v(vectors[0][std::size_t(k)], vectors[1][std::size_t(k)], vectors[2][std::size_t(k)]);
        if (largest <= 0.0 || std::abs(values[std::size_t(k)]) < 0.1 * largest) { // unconstrained direction
            out.free[std::size_t(out.freeCount++)] = v;
            continue;
        }
        x += v * (glm::dot(v, atb) / values[std::size_t(k)]);
    }
    out.point = mass + x;
    out.mass = mass;
    return out;
}

bool clipLine(const glm::dvec3& p, const glm::dvec3& d, const glm::dvec3& lo, const glm::dvec3& hi, double& t0, double& t1) {
    t0 = -std::numeric_limits<double>::infinity();
    t1 = std::numeric_limits<double>::infinity();
    for (int a = 0; a < 3; ++a) {
        if (std::abs(d[a]) < 1e-12) {
            if (p[a] < lo[a] || p[a] > hi[a]) return false;
            continue;
        }
        double enter = (lo[a] - p[a]) / d[a], leave = (hi[a] - p[a]) / d[a];
        if (enter > leave) std::swap(enter, leave);
        t0 = std::max(t0, enter);
        t1 = std::min(t1, leave);
    }
    return t0 <= t1;
}

glm::dvec3 placeVertex(const QefSolution& qef, const glm::dvec3& lo, const glm::dvec3& hi, double margin, std::uint64_t& left,
                       std::uint64_t& clamped) {
    const glm::dvec3& x = qef.point;
    if (glm::all(glm::greaterThanEqual(x, lo)) && glm::all(glm::lessThanEqual(x, hi))) return x;
    if (qef.freeCount == 0 && glm::all(glm::greaterThanEqual(x, lo - margin)) && glm::all(glm::lessThanEqual(x, hi + margin))) {
        ++left; // a corner whose tip pokes into the next cell
        return x;
    }
    if (qef.freeCount == 1) {
        double t0 = 0.0, t1 = 0.0;
        const glm::dvec3& d = qef.free[0];
        if (clipLine(x, d, lo, hi, t0, t1)) return x + d * std::clamp(0.0, t0, t1);
        if (clipLine(x, d, lo - margin, hi + margin, t0, t1)) {
            ++left;
            return x + d * std::clamp(0.0, t0, t1);
        }
    }
    // From the crossings' mean (inside the cell) towards the minimiser, as far as the cell allows:
    // clamping coordinate by coordinate put vertices of neighbouring cells on one grid point or one
    // grid line, and triangles between them had zero area.
    ++clamped;
    double t0 = 0.0, t1 = 0.0;
    if (clipLine(qef.mass, x - qef.mass, lo, hi, t0, t1)) return qef.mass + (x - qef.mass) * std::clamp(1.0, t0, t1);
    return glm::clamp(x, lo, hi);
}

} // namespace sdfwb::meshing::detail
