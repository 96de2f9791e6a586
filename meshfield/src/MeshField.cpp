// A MeshField's names and options, the exact geometry (closest point on a triangle, solid angle),
// and its double-precision queries: distance, winding number, inside. Building it: MeshBuild.cpp.

#include <meshfield/MeshField.h>

#include "FloatBits.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <numbers>

namespace sdfwb::meshfield {
namespace fs = std::filesystem;
namespace {

using detail::asBits;
using glm::dvec3;

double boxDistance2(const dvec3& p, const Box& box) {
    const dvec3 d = glm::max(glm::max(box.lo - p, p - box.hi), dvec3(0.0));
    return glm::dot(d, d);
}

// Ray-triangle crossing (Moller-Trumbore): the ray's parameter, or a negative value for none.
double crossing(const dvec3& origin, const dvec3& direction, const dvec3& a, const dvec3& b, const dvec3& c) {
    const dvec3 e1 = b - a;
    const dvec3 e2 = c - a;
    const dvec3 h = glm::cross(direction, e2);
    const double det = glm::dot(e1, h);
    if (std::abs(det) < 1e-300) return -1.0;
    const double inv = 1.0 / det;
    const dvec3 s = origin - a;
    const double u = glm::dot(s, h) * inv;
    if (u < 0.0 || u > 1.0) return -1.0;
    const dvec3 q = glm::cross(s, e1);
    const double v = glm::dot(direction, q) * inv;
    if (v < 0.0 || u + v > 1.0) return -1.0;
    return glm::dot(e2, q) * inv;
}

bool rayHitsBox(const dvec3& origin, const dvec3& inverse, const Box& box) {
    double t0 = 0.0;
    double t1 = std::numeric_limits<double>::infinity();
    for (int k = 0; k < 3; ++k) {
        double a = (box.lo[k] - origin[k]) * inverse[k];
        double b = (box.hi[k] - origin[k]) * inverse[k];
        if (a > b) std::swap(a, b);
        t0 = std::max(t0, a);
        t1 = std::min(t1, b);
    }
    return t0 <= t1;
}

} // namespace

// The three directions parity counts crossings along (also in shaders/mesh/mesh_field.glsl):
// skewed, so that axis-aligned meshes' edges and vertices are rarely hit exactly.
const std::array<glm::dvec3, 3>& parityDirections() {
    static const std::array<glm::dvec3, 3> directions = {glm::normalize(dvec3(1.0, 0.3183, 0.1415)),
                                                         glm::normalize(dvec3(-0.2718, 1.0, 0.5772)),
                                                         glm::normalize(dvec3(0.1618, -0.4142, 1.0))};
    return directions;
}

const char* signName(SignMethod method) {
    switch (method) {
    case SignMethod::Winding:
        return "winding";
    case SignMethod::Parity:
        return "parity";
    case SignMethod::Pseudonormal:
        return "pseudonormal";
    }
    return "?";
}

const char* normalizationName(Normalization method) {
    switch (method) {
    case Normalization::None:
        return "none";
    case Normalization::UnitCube:
        return "unit-cube";
    case Normalization::UnitSphere:
        return "unit-sphere";
    }
    return "?";
}

Expected<SignMethod> parseSign(const std::string& text) {
    for (SignMethod method : {SignMethod::Winding, SignMethod::Parity, SignMethod::Pseudonormal})
        if (text == signName(method)) return method;
    return Error{"expected winding, parity or pseudonormal, got '" + text + "'"};
}

Expected<Normalization> parseNormalization(const std::string& text) {
    for (Normalization method : {Normalization::None, Normalization::UnitCube, Normalization::UnitSphere})
        if (text == normalizationName(method)) return method;
    return Error{"expected none, unit-cube or unit-sphere, got '" + text + "'"};
}

Expected<MeshFieldOptions> parseMeshFieldOptions(const std::string& sign, const std::string& normalize) {
    MeshFieldOptions options;
    if (!sign.empty()) {
        auto method = parseSign(sign);
        if (!method) return Error{"sign: " + method.error().message};
        options.sign = *method;
    }
    if (!normalize.empty()) {
        auto normalization = parseNormalization(normalize);
        if (!normalization) return Error{"normalize: " + normalization.error().message};
        options.normalize = *normalization;
    }
    return options;
}

bool isMeshPath(const fs::path& path) {
    std::string extension = path.extension().string();
    std::transform(extension.begin(), extension.end(), extension.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    for (const char* known : {".obj", ".ply", ".stl", ".off", ".glb", ".gltf", ".fbx", ".dae", ".3ds"})
        if (extension == known) return true;
    return false;
}

glm::dvec3 closestPointOnTriangle(const dvec3& p, const dvec3& a, const dvec3& b, const dvec3& c, int* feature) {
    int region = 0;
    auto result = [&](int r, const dvec3& q) {
        region = r;
        if (feature) *feature = region;
        return q;
    };
    const dvec3 ab = b - a;
    const dvec3 ac = c - a;
    const dvec3 ap = p - a;
    const double d1 = glm::dot(ab, ap);
    const double d2 = glm::dot(ac, ap);
    if (d1 <= 0.0 && d2 <= 0.0) return result(1, a);
    const dvec3 bp = p - b;
    const double d3 = glm::dot(ab, bp);
    const double d4 = glm::dot(ac, bp);
    if (d3 >= 0.0 && d4 <= d3) return result(2, b);
    const double vc = d1 * d4 - d3 * d2;
    if (vc <= 0.0 && d1 >= 0.0 && d3 <= 0.0) return result(4, a + ab * (d1 / (d1 - d3)));
    const dvec3 cp = p - c;
    const double d5 = glm::dot(ab, cp);
    const double d6 = glm::dot(ac, cp);
    if (d6 >= 0.0 && d5 <= d6) return result(3, c);
    const double vb = d5 * d2 - d1 * d6;
    if (vb <= 0.0 && d2 >= 0.0 && d6 <= 0.0) return result(6, a + ac * (d2 / (d2 - d6)));
    const double va = d3 * d6 - d5 * d4;
    if (va <= 0.0 && d4 - d3 >= 0.0 && d5 - d6 >= 0.0) return result(5, b + (c - b) * ((d4 - d3) / ((d4 - d3) + (d5 - d6))));
    const double sum = va + vb + vc;
    if (!(sum > 0.0)) { // a degenerate triangle: the nearest of its edges
        int best = 4;
        dvec3 q = a;
        double bestD = std::numeric_limits<double>::infinity();
        const dvec3 ends[3][2] = {{a, b}, {b, c}, {c, a}};
        for (int e = 0; e < 3; ++e) {
            const dvec3 d = ends[e][1] - ends[e][0];
            const double len2 = glm::dot(d, d);
            const double t = len2 > 0.0 ? std::clamp(glm::dot(p - ends[e][0], d) / len2, 0.0, 1.0) : 0.0;
            const dvec3 r = ends[e][0] + d * t;
            if (glm::dot(p - r, p - r) < bestD) {
                bestD = glm::dot(p - r, p - r);
                q = r;
                best = 4 + e;
            }
        }
        return result(best, q);
    }
    return result(0, a + ab * (vb / sum) + ac * (vc / sum));
}

double solidAngle(const dvec3& p, const dvec3& a, const dvec3& b, const dvec3& c) {
    const dvec3 A = a - p;
    const dvec3 B = b - p;
    const dvec3 C = c - p;
    const double la = glm::length(A);
    const double lb = glm::length(B);
    const double lc = glm::length(C);
    const double det = glm::dot(A, glm::cross(B, C));
    const double den = la * lb * lc + glm::dot(A, B) * lc + glm::dot(B, C) * la + glm::dot(C, A) * lb;
    return 2.0 * std::atan2(det, den);
}

namespace {

dvec3 corner(const MeshField& field, std::uint32_t slot, int k) {
    const float* t = field.triangles.data() + std::size_t(slot) * kTriangleFloats + std::size_t(k) * 4;
    return dvec3(t[0], t[1], t[2]);
}

struct NodeView {
    Box box;
    std::uint32_t firstOrLeft;
    std::uint32_t count;
};
NodeView nodeAt(const MeshField& field, std::uint32_t index) {
    const float* n = field.nodes.data() + std::size_t(index) * kNodeFloats;
    return {{dvec3(n[0], n[1], n[2]), dvec3(n[4], n[5], n[6])}, asBits(n[3]), asBits(n[7])};
}

// The nearest triangle slot (leaf order), its feature, and the squared distance.
double nearest(const MeshField& field, const dvec3& p, std::uint32_t* slot, int* feature, dvec3* point) {
    double best = std::numeric_limits<double>::infinity();
    std::vector<std::uint32_t> stack{0};
    stack.reserve(field.depth + 2);
    while (!stack.empty()) {
        const std::uint32_t index = stack.back();
        stack.pop_back();
        const NodeView node = nodeAt(field, index);
        if (boxDistance2(p, node.box) >= best) continue;
        if (node.count > 0) {
            for (std::uint32_t s = node.firstOrLeft; s < node.firstOrLeft + node.count; ++s) {
                int f = 0;
                const dvec3 q = closestPointOnTriangle(p, corner(field, s, 0), corner(field, s, 1), corner(field, s, 2), &f);
                const double d2 = glm::dot(p - q, p - q);
                if (d2 < best) {
                    best = d2;
                    if (slot) *slot = s;
                    if (feature) *feature = f;
                    if (point) *point = q;
                }
            }
            continue;
        }
        const double dl = boxDistance2(p, nodeAt(field, node.firstOrLeft).box);
        const double dr = boxDistance2(p, nodeAt(field, node.firstOrLeft + 1).box);
        if (dl < dr) {
            stack.push_back(node.firstOrLeft + 1);
            stack.push_back(node.firstOrLeft);
        } else {
            stack.push_back(node.firstOrLeft);
            stack.push_back(node.firstOrLeft + 1);
        }
    }
    return best;
}

} // namespace

double MeshField::distance(const dvec3& p) const { return std::sqrt(nearest(*this, p, nullptr, nullptr, nullptr)); }

double MeshField::windingExact(const dvec3& p) const {
    double sum = 0.0;
    const std::size_t count = triangles.size() / kTriangleFloats;
    for (std::uint32_t s = 0; s < count; ++s) sum += solidAngle(p, corner(*this, s, 0), corner(*this, s, 1), corner(*this, s, 2));
    return sum / (4.0 * std::numbers::pi);
}

// A far cluster's share of 4 pi times the winding number at p, d = c - p (kNodeFloats): the
// solid angle a t n . (x - p) / |x - p|^3 of each triangle, expanded about c to first order in
// x - c. The first term is the dipole's; the second is sum_ij J_ij M_ij with the Jacobian
// J = I / |d|^3 - 3 d d^T / |d|^5 of (x - p) / |x - p|^3.
double farCluster(const float* n, const dvec3& d, double dist2) {
    const double inverse3 = 1.0 / (dist2 * std::sqrt(dist2));
    double dMd = 0.0;
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) dMd += d[i] * double(n[16 + 4 * i + j]) * d[j];
    const double trace = double(n[16]) + double(n[21]) + double(n[26]);
    return glm::dot(dvec3(n[12], n[13], n[14]), d) * inverse3 + trace * inverse3 - 3.0 * dMd * inverse3 / dist2;
}

double MeshField::winding(const dvec3& p) const {
    double sum = 0.0;
    std::vector<std::uint32_t> stack{0};
    while (!stack.empty()) {
        const std::uint32_t index = stack.back();
        stack.pop_back();
        const float* n = nodes.data() + std::size_t(index) * kNodeFloats;
        const dvec3 d = dvec3(n[8], n[9], n[10]) - p;
        const double dist2 = glm::dot(d, d);
        const double reach = options.beta * double(n[11]);
        if (dist2 > reach * reach) { // far: the cluster as a dipole and its second moment
            sum += farCluster(n, d, dist2);
            continue;
        }
        const NodeView node = nodeAt(*this, index);
        if (node.count > 0) {
            for (std::uint32_t s = node.firstOrLeft; s < node.firstOrLeft + node.count; ++s)
                sum += solidAngle(p, corner(*this, s, 0), corner(*this, s, 1), corner(*this, s, 2));
        } else {
            stack.push_back(node.firstOrLeft);
            stack.push_back(node.firstOrLeft + 1);
        }
    }
    return sum / (4.0 * std::numbers::pi);
}

bool MeshField::inside(const dvec3& p) const {
    switch (options.sign) {
    case SignMethod::Winding:
        return winding(p) > 0.5;
    case SignMethod::Parity: {
        int votes = 0;
        for (const dvec3& direction : parityDirections()) {
            const dvec3 inverse = 1.0 / direction;
            int crossings = 0;
            std::vector<std::uint32_t> stack{0};
            while (!stack.empty()) {
                const NodeView node = nodeAt(*this, stack.back());
                stack.pop_back();
                if (!rayHitsBox(p, inverse, node.box)) continue;
                if (node.count > 0) {
                    for (std::uint32_t s = node.firstOrLeft; s < node.firstOrLeft + node.count; ++s)
                        if (crossing(p, direction, corner(*this, s, 0), corner(*this, s, 1), corner(*this, s, 2)) > 0.0)
                            ++crossings;
                } else {
                    stack.push_back(node.firstOrLeft);
                    stack.push_back(node.firstOrLeft + 1);
                }
            }
            votes += crossings % 2;
        }
        return votes >= 2;
    }
    case SignMethod::Pseudonormal: {
        std::uint32_t slot = 0;
        int feature = 0;
        dvec3 q(0.0);
        nearest(*this, p, &slot, &feature, &q);
        static constexpr int kSlotOfFeature[7] = {0, 4, 5, 6, 1, 2, 3};
        const float* normal =
            pseudonormals.data() + std::size_t(slot) * kPseudonormalFloats + std::size_t(kSlotOfFeature[feature]) * 4;
        return glm::dot(p - q, dvec3(normal[0], normal[1], normal[2])) < 0.0;
    }
    }
    return false;
}

std::string MeshField::glslSource() const {
    std::string label = name; // inside a comment: no "*/" may end it early
    for (std::size_t at = label.find("*/"); at != std::string::npos; at = label.find("*/")) label.replace(at, 2, "* /");
    char line[512];
    std::snprintf(line, sizeof line,
                  "/* sdfwb\n"
                  "   mesh: %s, %zu triangles, %s\n"
                  "   sign: %s; normalize: %s\n"
                  "*/\n"
                  "// The mesh's signed distance: shaders/mesh/mesh_field.glsl traverses its hierarchy on the GPU.\n"
                  "float sdf(vec3 p) { return sdfwb_meshSdf(p); }\n",
                  label.c_str(), mesh.triangleCount(), closed() ? "closed" : "open or non-manifold", signName(options.sign),
                  normalizationName(options.normalize));
    return line;
}

std::string MeshField::provenanceJson() const {
    std::string file;
    for (char c : name) {
        if (c == '"' || c == '\\') file += '\\';
        if (static_cast<unsigned char>(c) >= 0x20) file += c;
    }
    auto number = [](double value) {
        char text[32];
        std::snprintf(text, sizeof text, "%.17g", value);
        return std::string(text);
    };
    std::string json = "{\"file\": \"" + file + "\", \"triangles\": " + std::to_string(mesh.triangleCount()) +
                       ", \"closed\": " + (closed() ? "true" : "false") + ", \"sign\": \"" + signName(options.sign) +
                       "\", \"normalize\": \"" + normalizationName(options.normalize) + "\", \"transform\": [";
    for (std::size_t k = 0; k < transform.size(); ++k) json += (k ? ", " : "") + number(transform[k]);
    json += "], \"bounds\": [" + number(originalBounds.lo.x) + ", " + number(originalBounds.lo.y) + ", " +
            number(originalBounds.lo.z) + ", " + number(originalBounds.hi.x) + ", " + number(originalBounds.hi.y) + ", " +
            number(originalBounds.hi.z) + "]}";
    return json;
}

std::string MeshField::summary() const {
    char line[512];
    std::snprintf(line, sizeof line,
                  "%s: %zu triangles, %zu boundary and %zu non-manifold edges; bounds [%.4g %.4g %.4g]..[%.4g %.4g %.4g] "
                  "(file: [%.4g %.4g %.4g]..[%.4g %.4g %.4g]); sign %s, normalize %s; hierarchy of %zu nodes, depth %zu, "
                  "built in %.3f s, %.1f MB on the GPU",
                  name.c_str(), mesh.triangleCount(), boundaryEdges, nonManifoldEdges, bounds.lo.x, bounds.lo.y, bounds.lo.z,
                  bounds.hi.x, bounds.hi.y, bounds.hi.z, originalBounds.lo.x, originalBounds.lo.y, originalBounds.lo.z,
                  originalBounds.hi.x, originalBounds.hi.y, originalBounds.hi.z, signName(options.sign),
                  normalizationName(options.normalize), nodes.size() / kNodeFloats, depth, buildSeconds,
                  double(gpuBytes()) / 1e6);
    return line;
}

} // namespace sdfwb::meshfield
