// The C++ reference of bench_mesh_sdf.py: a triangle mesh's signed distance at many points, written
// the way a demanding user would with the libraries such a user reaches for, Embree 3 and CGAL 5.5,
// parallel over points with OpenMP. bench/build_mesh_sdf_reference.sh compiles it (with and
// without -ffast-math) and passes the flags in as REF_FLAGS.
//
//   mesh_sdf_reference --engine embree|cgal --sign parity|pseudonormal|none --mesh M.obj|M.ply
//                      --points P.f32 --out V.f32 [--gradient G.f32] [--threads T] [--repeat R]
//                      [--order morton|input]
//
// Choices (the faster where there was one to make, measured on fandisk and the bunny):
// - embree: one triangle geometry, RTC_BUILD_QUALITY_HIGH, no RTC_SCENE_FLAG_ROBUST (a few % faster;
//   parity's majority of three rays absorbs the rare ray that slips through an edge). Closest point
//   with rtcPointQuery and a callback computing Ericson's closest point on the triangle in double
//   (from float corners; float was ~5 % faster but lets near-ties pick the wrong triangle: 3e-5
//   off in the gradient on a unit cube), shrinking the query radius. Parity counts every crossing in one traversal
//   per ray: rtcOccluded1 with an occlusion filter that counts the hit and rejects it (as fast as
//   rtcIntersect1 with an intersection filter, faster than re-casting from past each hit); a triangle
//   seen twice (spatial splits put it in several leaves) counts once.
// - cgal: AABB_tree over a triangle soup (AABB_triangle_primitive with cached triangles) in
//   CGAL::Simple_cartesian<double> (~25 % faster than Epick here), accelerate_distance_queries(),
//   closest_point_and_primitive. Parity: Side_of_triangle_mesh on a Surface_mesh of the same
//   triangles (its own tree, built with the rest).
// - both: the points are visited in Morton order (sorted inside the timed phase) and each query starts
//   from the previous point's closest triangle: its distance is the initial search radius (Embree),
//   its closest point the hint (CGAL); about 2x on random points. Parity: a point outside the mesh's
//   bounding box is outside without a ray. --order input turns the ordering and seeding off.
// - pseudonormal: angle-weighted pseudonormals (Baerentzen & Aanaes 2005) after merging equal vertex
//   positions; the feature (face, edge or vertex) of the closest point decides.

#include <embree3/rtcore.h>

#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/AABB_triangle_primitive.h>
#include <CGAL/Polygon_mesh_processing/orient_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Side_of_triangle_mesh.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>

#include <omp.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <charconv>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <limits>
#include <map>
#include <memory>
#include <sstream>
#include <string>
#include <unordered_map>
#include <vector>

#ifndef REF_FLAGS
#define REF_FLAGS "unknown"
#endif

namespace {

// ---------------------------------------------------------------------------------------------
// Small vectors

template <class T> struct V3 { T x, y, z; };
template <class T> inline V3<T> operator+(V3<T> a, V3<T> b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
template <class T> inline V3<T> operator-(V3<T> a, V3<T> b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
template <class T> inline V3<T> operator*(V3<T> a, T s) { return {a.x * s, a.y * s, a.z * s}; }
template <class T> inline T dot(V3<T> a, V3<T> b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
template <class T> inline V3<T> cross(V3<T> a, V3<T> b) {
    return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
using Vec3f = V3<float>;
using Vec3d = V3<double>;

[[noreturn]] void fail(const std::string& message) {
    std::fprintf(stderr, "mesh_sdf_reference: %s\n", message.c_str());
    std::exit(1);
}

// ---------------------------------------------------------------------------------------------
// Input and output

struct Mesh {
    std::vector<float> positions;       // 3 per vertex
    std::vector<std::uint32_t> corners; // 3 per triangle
    std::size_t triangles() const { return corners.size() / 3; }
    Vec3f vertex(std::uint32_t v) const { return {positions[3 * v], positions[3 * v + 1], positions[3 * v + 2]}; }
};

std::string readFile(const std::string& path, const char* what) {
    std::ifstream in(path, std::ios::binary);
    if (!in) fail("cannot open " + std::string(what) + " '" + path + "'");
    std::ostringstream buffer;
    buffer << in.rdbuf();
    if (in.bad()) fail("cannot read " + std::string(what) + " '" + path + "'");
    return buffer.str();
}

// OBJ: "v x y z" and "f a b c ..." (1-based or negative indices, "a/b/c" forms, polygons as fans);
// every other line is ignored.
Mesh readObj(const std::string& path) {
    const std::string text = readFile(path, "mesh");
    Mesh mesh;
    std::vector<std::int64_t> polygon;
    const char* s = text.data();
    const char* end = s + text.size();
    std::size_t lineNumber = 0;
    auto bad = [&](const char* why) { fail("mesh '" + path + "', line " + std::to_string(lineNumber) + ": " + why); };
    while (s < end) {
        const char* eol = static_cast<const char*>(std::memchr(s, '\n', std::size_t(end - s)));
        if (!eol) eol = end;
        ++lineNumber;
        auto skipSpace = [&](const char* q) {
            while (q < eol && (*q == ' ' || *q == '\t' || *q == '\r')) ++q;
            return q;
        };
        const char* q = skipSpace(s);
        if (q + 1 < eol && q[0] == 'v' && (q[1] == ' ' || q[1] == '\t')) {
            q += 2;
            for (int k = 0; k < 3; ++k) {
                q = skipSpace(q);
                if (q < eol && *q == '+') ++q;
                float value = 0.0f;
                auto [next, error] = std::from_chars(q, eol, value);
                if (error == std::errc::result_out_of_range)
                    value = std::strtof(std::string(q, next).c_str(), nullptr);
                else if (error != std::errc())
                    bad("expected three coordinates after 'v'");
                mesh.positions.push_back(value);
                q = next;
            }
        } else if (q + 1 < eol && q[0] == 'f' && (q[1] == ' ' || q[1] == '\t')) {
            q += 2;
            polygon.clear();
            while (true) {
                q = skipSpace(q);
                if (q >= eol) break;
                std::int64_t index = 0;
                const auto [next, error] = std::from_chars(q, eol, index);
                if (error != std::errc()) bad("expected a vertex index after 'f'");
                const std::int64_t count = std::int64_t(mesh.positions.size() / 3);
                if (index < 0) index += count + 1; // relative
                if (index < 1 || index > count) bad("vertex index out of range");
                polygon.push_back(index - 1);
                q = next;
                while (q < eol && *q != ' ' && *q != '\t' && *q != '\r') ++q; // "/vt/vn"
            }
            if (polygon.size() < 3) bad("a face needs at least three vertices");
            for (std::size_t k = 1; k + 1 < polygon.size(); ++k) {
                mesh.corners.push_back(std::uint32_t(polygon[0]));
                mesh.corners.push_back(std::uint32_t(polygon[k]));
                mesh.corners.push_back(std::uint32_t(polygon[k + 1]));
            }
        }
        s = eol + 1;
    }
    if (mesh.corners.empty()) fail("mesh '" + path + "' has no faces");
    return mesh;
}

// PLY (bench_mesh_sdf.py hands its big mesh over as one): ascii or binary_little_endian, the vertex
// element's x, y, z and the face element's vertex_indices (or vertex_index) list, polygons as fans.
Mesh readPly(const std::string& path) {
    const std::string text = readFile(path, "mesh");
    auto bad = [&](const std::string& why) -> void { fail("mesh '" + path + "' (PLY): " + why); };
    struct Property {
        std::string name;
        std::string type, countType; // countType: non-empty for a list
    };
    struct Element {
        std::string name;
        std::size_t count;
        std::vector<Property> properties;
    };
    std::vector<Element> elements;
    std::string format;
    std::size_t at = 0;
    while (true) {
        const std::size_t eol = text.find('\n', at);
        if (eol == std::string::npos) bad("no end_header");
        std::istringstream line(text.substr(at, eol - at));
        at = eol + 1;
        std::string word;
        line >> word;
        if (word == "end_header") break;
        if (word == "format")
            line >> format;
        else if (word == "element") {
            Element e{};
            line >> e.name >> e.count;
            elements.push_back(e);
        } else if (word == "property") {
            if (elements.empty()) bad("a property before any element");
            Property property;
            line >> property.type;
            if (property.type == "list") line >> property.countType >> property.type;
            line >> property.name;
            elements.back().properties.push_back(property);
        }
    }
    const bool binary = format == "binary_little_endian";
    if (!binary && format != "ascii") bad("format '" + format + "' is not supported (ascii or binary_little_endian)");
    auto size = [&](const std::string& type) -> std::size_t {
        if (type == "char" || type == "uchar" || type == "int8" || type == "uint8") return 1;
        if (type == "short" || type == "ushort" || type == "int16" || type == "uint16") return 2;
        if (type == "int" || type == "uint" || type == "int32" || type == "uint32" || type == "float" || type == "float32")
            return 4;
        if (type == "double" || type == "float64") return 8;
        bad("unknown property type '" + type + "'");
        return 0;
    };
    const char* q = text.data() + at;
    const char* end = text.data() + text.size();
    auto next = [&](const std::string& type) -> double { // the next value, as a double
        if (!binary) {
            while (q < end && std::isspace(static_cast<unsigned char>(*q))) ++q;
            char* stop = nullptr;
            const double value = std::strtod(q, &stop);
            if (stop == q) bad("expected a number");
            q = stop;
            return value;
        }
        const std::size_t n = size(type);
        if (std::size_t(end - q) < n) bad("file ends early");
        unsigned char b[8];
        std::memcpy(b, q, n);
        q += n;
        if (type == "char" || type == "int8") return double(std::int8_t(b[0]));
        if (type == "uchar" || type == "uint8") return double(b[0]);
        if (type == "short" || type == "int16") return double(std::int16_t(b[0] | b[1] << 8));
        if (type == "ushort" || type == "uint16") return double(std::uint16_t(b[0] | b[1] << 8));
        std::uint32_t u32;
        std::memcpy(&u32, b, 4);
        if (type == "int" || type == "int32") return double(std::int32_t(u32));
        if (type == "uint" || type == "uint32") return double(u32);
        if (n == 4) {
            float f;
            std::memcpy(&f, b, 4);
            return double(f);
        }
        double d;
        std::memcpy(&d, b, 8);
        return d;
    };
    Mesh mesh;
    std::vector<std::int64_t> polygon;
    for (const Element& element : elements) {
        for (std::size_t i = 0; i < element.count; ++i) {
            double xyz[3] = {0.0, 0.0, 0.0};
            for (const Property& property : element.properties) {
                if (property.countType.empty()) {
                    const double value = next(property.type);
                    if (element.name == "vertex" && property.name.size() == 1 && property.name[0] >= 'x' &&
                        property.name[0] <= 'z')
                        xyz[property.name[0] - 'x'] = value;
                    continue;
                }
                const std::size_t count = std::size_t(next(property.countType));
                const bool indices =
                    element.name == "face" && (property.name == "vertex_indices" || property.name == "vertex_index");
                polygon.clear();
                for (std::size_t k = 0; k < count; ++k) polygon.push_back(std::int64_t(next(property.type)));
                if (!indices) continue;
                if (count < 3) bad("a face needs at least three vertices");
                for (std::int64_t v : polygon)
                    if (v < 0 || v >= std::int64_t(mesh.positions.size() / 3)) bad("vertex index out of range");
                for (std::size_t k = 1; k + 1 < count; ++k) {
                    mesh.corners.push_back(std::uint32_t(polygon[0]));
                    mesh.corners.push_back(std::uint32_t(polygon[k]));
                    mesh.corners.push_back(std::uint32_t(polygon[k + 1]));
                }
            }
            if (element.name == "vertex")
                for (double c : xyz) mesh.positions.push_back(float(c));
        }
    }
    if (mesh.corners.empty()) fail("mesh '" + path + "' has no faces");
    return mesh;
}

Mesh readMesh(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    char magic[4] = {};
    in.read(magic, 4);
    return std::string(magic, 4) == "ply\n" || std::string(magic, 4) == "ply\r" ? readPly(path) : readObj(path);
}

std::vector<float> readPoints(const std::string& path) {
    const std::string bytes = readFile(path, "points file");
    if (bytes.size() % 12 != 0) fail("points file '" + path + "': size is not a multiple of 12 bytes (3 float32 per point)");
    if (bytes.empty()) fail("points file '" + path + "' is empty");
    std::vector<float> points(bytes.size() / 4);
    std::memcpy(points.data(), bytes.data(), bytes.size());
    return points;
}

void writeFloats(const std::string& path, const std::vector<float>& values, const char* what) {
    std::FILE* file = std::fopen(path.c_str(), "wb");
    if (!file) fail("cannot write " + std::string(what) + " '" + path + "'");
    const bool ok = std::fwrite(values.data(), sizeof(float), values.size(), file) == values.size();
    if (std::fclose(file) != 0 || !ok) fail("cannot write " + std::string(what) + " '" + path + "'");
}

// ---------------------------------------------------------------------------------------------
// The closest point on a triangle (Ericson, Real-Time Collision Detection, 5.1.5: Voronoi regions
// of the vertices, then the edges, then the face) and which feature it lies on.

enum Feature : int { kFace = 0, kVertexA, kVertexB, kVertexC, kEdgeAB, kEdgeBC, kEdgeCA };

template <class T> V3<T> onSegment(V3<T> p, V3<T> a, V3<T> b, int edge, int& feature) {
    const V3<T> ab = b - a;
    const T length2 = dot(ab, ab);
    const T t = length2 > T(0) ? std::clamp(dot(p - a, ab) / length2, T(0), T(1)) : T(0);
    feature = t <= T(0) ? kVertexA + edge : t >= T(1) ? kVertexA + (edge + 1) % 3 : kEdgeAB + edge;
    return a + ab * t;
}

// With ab = b - a, ac = c - a and their products precomputed: of the six dot products the regions
// need only dot(ab, p - a) and dot(ac, p - a) remain, the rest follow from them.
template <class T> V3<T> closestOnTriangle(V3<T> p, V3<T> a, V3<T> ab, V3<T> ac, T abab, T abac, T acac, int& feature) {
    const V3<T> ap = p - a;
    const T d1 = dot(ab, ap), d2 = dot(ac, ap);
    if (d1 <= T(0) && d2 <= T(0)) {
        feature = kVertexA;
        return a;
    }
    const T d3 = d1 - abab, d4 = d2 - abac; // dot(ab, p - b), dot(ac, p - b)
    if (d3 >= T(0) && d4 <= d3) {
        feature = kVertexB;
        return a + ab;
    }
    const T vc = d1 * d4 - d3 * d2;
    if (vc <= T(0) && d1 >= T(0) && d3 <= T(0)) {
        feature = kEdgeAB;
        return a + ab * (d1 / (d1 - d3));
    }
    const T d5 = d1 - abac, d6 = d2 - acac; // dot(ab, p - c), dot(ac, p - c)
    if (d6 >= T(0) && d5 <= d6) {
        feature = kVertexC;
        return a + ac;
    }
    const T vb = d5 * d2 - d1 * d6;
    if (vb <= T(0) && d2 >= T(0) && d6 <= T(0)) {
        feature = kEdgeCA;
        return a + ac * (d2 / (d2 - d6));
    }
    const T va = d3 * d6 - d5 * d4;
    if (va <= T(0) && d4 - d3 >= T(0) && d5 - d6 >= T(0)) {
        feature = kEdgeBC;
        return a + ab + (ac - ab) * ((d4 - d3) / ((d4 - d3) + (d5 - d6)));
    }
    const T sum = va + vb + vc;
    if (!(sum > T(0))) { // degenerate (zero-area) triangle: the nearest of its three edges
        const V3<T> b = a + ab, c = a + ac;
        int f0, f1, f2;
        const V3<T> q0 = onSegment(p, a, b, 0, f0), q1 = onSegment(p, b, c, 1, f1), q2 = onSegment(p, c, a, 2, f2);
        const T e0 = dot(p - q0, p - q0), e1 = dot(p - q1, p - q1), e2 = dot(p - q2, p - q2);
        if (e0 <= e1 && e0 <= e2) return feature = f0, q0;
        if (e1 <= e2) return feature = f1, q1;
        return feature = f2, q2;
    }
    feature = kFace;
    const T inverse = T(1) / sum;
    return a + ab * (vb * inverse) + ac * (vc * inverse);
}

template <class T> V3<T> closestOnTriangle(V3<T> p, V3<T> a, V3<T> b, V3<T> c, int& feature) {
    const V3<T> ab = b - a, ac = c - a;
    return closestOnTriangle(p, a, ab, ac, dot(ab, ab), dot(ab, ac), dot(ac, ac), feature);
}

// ---------------------------------------------------------------------------------------------
// Angle-weighted pseudonormals: per triangle 7 unit normals in Feature order (face, vertex A, B, C,
// edge AB, BC, CA), vertices merged by equal position first.

std::vector<float> buildPseudonormals(const Mesh& mesh) {
    const std::size_t triangleCount = mesh.triangles();
    // Merge equal positions.
    std::vector<std::uint32_t> merged(mesh.positions.size() / 3);
    {
        struct Key {
            std::uint32_t x, y, z;
            bool operator==(const Key&) const = default;
        };
        struct Hash {
            std::size_t operator()(const Key& k) const {
                std::uint64_t h = k.x * 0x9e3779b97f4a7c15ull;
                h = (h ^ (h >> 29) ^ k.y) * 0xbf58476d1ce4e5b9ull;
                h = (h ^ (h >> 31) ^ k.z) * 0x94d049bb133111ebull;
                return std::size_t(h ^ (h >> 32));
            }
        };
        std::unordered_map<Key, std::uint32_t, Hash> ids;
        ids.reserve(merged.size());
        for (std::size_t v = 0; v < merged.size(); ++v) {
            std::uint32_t bits[3];
            std::memcpy(bits, &mesh.positions[3 * v], sizeof bits);
            for (std::uint32_t& b : bits)
                if ((b & 0x7fffffffu) == 0) b = 0; // -0 is 0
            const Key key{bits[0], bits[1], bits[2]};
            merged[v] = ids.emplace(key, std::uint32_t(ids.size())).first->second;
        }
    }
    auto normalized = [](Vec3d v) {
        const double length = std::sqrt(dot(v, v));
        return length > 0.0 ? v * (1.0 / length) : Vec3d{0.0, 0.0, 0.0};
    };
    auto vertex = [&](std::uint32_t v) {
        const Vec3f p = mesh.vertex(v);
        return Vec3d{p.x, p.y, p.z};
    };
    std::vector<Vec3d> faceNormals(triangleCount);
    std::vector<Vec3d> vertexSums(merged.size(), Vec3d{0.0, 0.0, 0.0});
    std::unordered_map<std::uint64_t, Vec3d> edgeSums;
    edgeSums.reserve(triangleCount * 2);
    auto edgeKey = [&](std::uint32_t u, std::uint32_t v) {
        u = merged[u], v = merged[v];
        return u < v ? (std::uint64_t(u) << 32 | v) : (std::uint64_t(v) << 32 | u);
    };
    for (std::size_t t = 0; t < triangleCount; ++t) {
        const std::uint32_t* c = &mesh.corners[3 * t];
        const Vec3d p[3] = {vertex(c[0]), vertex(c[1]), vertex(c[2])};
        const Vec3d n = normalized(cross(p[1] - p[0], p[2] - p[0]));
        faceNormals[t] = n;
        for (int k = 0; k < 3; ++k) {
            const Vec3d e1 = normalized(p[(k + 1) % 3] - p[k]), e2 = normalized(p[(k + 2) % 3] - p[k]);
            const double angle = std::acos(std::clamp(dot(e1, e2), -1.0, 1.0));
            Vec3d& sum = vertexSums[merged[c[k]]];
            sum = sum + n * angle;
            Vec3d& edge = edgeSums.try_emplace(edgeKey(c[k], c[(k + 1) % 3]), Vec3d{0.0, 0.0, 0.0}).first->second;
            edge = edge + n;
        }
    }
    std::vector<float> normals(triangleCount * 21);
    for (std::size_t t = 0; t < triangleCount; ++t) {
        const std::uint32_t* c = &mesh.corners[3 * t];
        const Vec3d n[7] = {faceNormals[t],
                            normalized(vertexSums[merged[c[0]]]),
                            normalized(vertexSums[merged[c[1]]]),
                            normalized(vertexSums[merged[c[2]]]),
                            normalized(edgeSums[edgeKey(c[0], c[1])]),
                            normalized(edgeSums[edgeKey(c[1], c[2])]),
                            normalized(edgeSums[edgeKey(c[2], c[0])])};
        for (int k = 0; k < 7; ++k) {
            normals[21 * t + 3 * k] = float(n[k].x);
            normals[21 * t + 3 * k + 1] = float(n[k].y);
            normals[21 * t + 3 * k + 2] = float(n[k].z);
        }
    }
    return normals;
}

// ---------------------------------------------------------------------------------------------
// Query order: Morton order of the points inside their bounding box (30-bit codes, LSD radix sort
// of code and index), so that consecutive queries are near each other.

std::uint32_t spreadBits(std::uint32_t v) { // 10 bits to every third of 30
    v = (v | (v << 16)) & 0x030000FFu;
    v = (v | (v << 8)) & 0x0300F00Fu;
    v = (v | (v << 4)) & 0x030C30C3u;
    v = (v | (v << 2)) & 0x09249249u;
    return v;
}

void mortonOrder(const std::vector<float>& points, std::vector<std::uint32_t>& order, std::vector<std::uint64_t>& keys,
                 std::vector<std::uint64_t>& scratch) {
    const std::int64_t n = std::int64_t(points.size() / 3);
    float lo[3] = {points[0], points[1], points[2]}, hi[3] = {points[0], points[1], points[2]};
#pragma omp parallel for reduction(min : lo[:3]) reduction(max : hi[:3]) schedule(static)
    for (std::int64_t i = 0; i < n; ++i)
        for (int k = 0; k < 3; ++k) lo[k] = std::min(lo[k], points[3 * i + k]), hi[k] = std::max(hi[k], points[3 * i + k]);
    float scale[3];
    for (int k = 0; k < 3; ++k) scale[k] = hi[k] > lo[k] ? 1023.0f / (hi[k] - lo[k]) : 0.0f;
    keys.resize(std::size_t(n));
    scratch.resize(std::size_t(n));
#pragma omp parallel for schedule(static)
    for (std::int64_t i = 0; i < n; ++i) {
        std::uint32_t cell[3];
        for (int k = 0; k < 3; ++k) cell[k] = std::uint32_t(std::clamp((points[3 * i + k] - lo[k]) * scale[k], 0.0f, 1023.0f));
        const std::uint32_t code = spreadBits(cell[0]) | spreadBits(cell[1]) << 1 | spreadBits(cell[2]) << 2;
        keys[std::size_t(i)] = std::uint64_t(code) << 32 | std::uint64_t(i);
    }
    for (int shift = 32; shift < 62; shift += 10) { // 3 passes of 10 bits over the code
        std::size_t count[1025] = {};
        for (std::uint64_t key : keys) ++count[((key >> shift) & 1023u) + 1];
        for (int b = 0; b < 1024; ++b) count[b + 1] += count[b];
        for (std::uint64_t key : keys) scratch[count[(key >> shift) & 1023u]++] = key;
        keys.swap(scratch);
    }
    order.resize(std::size_t(n));
    for (std::int64_t i = 0; i < n; ++i) order[std::size_t(i)] = std::uint32_t(keys[std::size_t(i)]);
}

// ---------------------------------------------------------------------------------------------
// Shared setup and output

enum class Sign { Parity, Pseudonormal, None };

struct Options {
    std::string engine, sign, mesh, points, out, gradient, order = "morton";
    int threads = 0, repeat = 3;
};

struct Box {
    float lo[3], hi[3];
    bool contains(Vec3f p) const {
        return p.x >= lo[0] && p.x <= hi[0] && p.y >= lo[1] && p.y <= hi[1] && p.z >= lo[2] && p.z <= hi[2];
    }
};

Box boundsOf(const Mesh& mesh) {
    Box box;
    for (int k = 0; k < 3; ++k) box.lo[k] = std::numeric_limits<float>::max(), box.hi[k] = -box.lo[k];
    for (std::uint32_t v : mesh.corners)
        for (int k = 0; k < 3; ++k)
            box.lo[k] = std::min(box.lo[k], mesh.positions[3 * v + k]),
            box.hi[k] = std::max(box.hi[k], mesh.positions[3 * v + k]);
    return box;
}

// Writes point i's value and gradient from its closest point c (on triangle t), the unsigned distance
// and the sign (+1 outside, -1 inside): gradient (p - c) / |p - c| times the sign, the face normal
// where p == c.
template <class T>
inline void store(float* values, float* gradients, std::size_t i, V3<T> p, V3<T> c, T distance, T sign, const float* faceNormal) {
    values[i] = float(distance * sign);
    if (!gradients) return;
    float* g = gradients + 3 * i;
    if (distance > T(0)) {
        const V3<T> d = (p - c) * (sign / distance);
        g[0] = float(d.x), g[1] = float(d.y), g[2] = float(d.z);
    } else {
        g[0] = faceNormal[0], g[1] = faceNormal[1], g[2] = faceNormal[2];
    }
}

// ---------------------------------------------------------------------------------------------
// Embree

// The parity rays' directions (sdfwb's: meshfield/src/MeshField.cpp parityDirections()).
Vec3f parityDirection(int k) {
    static const double d[3][3] = {{1.0, 0.3183, 0.1415}, {-0.2718, 1.0, 0.5772}, {0.1618, -0.4142, 1.0}};
    const double length = std::sqrt(d[k][0] * d[k][0] + d[k][1] * d[k][1] + d[k][2] * d[k][2]);
    return {float(d[k][0] / length), float(d[k][1] / length), float(d[k][2] / length)};
}

// What the point query callback reads of a triangle, one cache line: its corners and the products of
// its edge vectors (in double, as the callback computes).
struct alignas(64) TriangleRecord {
    float corner[3][3];
    double abab, abac, acac;
    Vec3d vertex(int k) const { return {corner[k][0], corner[k][1], corner[k][2]}; }
    Vec3d closest(Vec3d p, int& feature) const {
        const Vec3d a = vertex(0), ab = vertex(1) - a, ac = vertex(2) - a; // differences of floats: exact
        return closestOnTriangle(p, a, ab, ac, abab, abac, acac, feature);
    }
};

TriangleRecord makeRecord(Vec3f a, Vec3f b, Vec3f c) {
    TriangleRecord r{};
    const Vec3f corners[3] = {a, b, c};
    for (int k = 0; k < 3; ++k) r.corner[k][0] = corners[k].x, r.corner[k][1] = corners[k].y, r.corner[k][2] = corners[k].z;
    const Vec3d ab = r.vertex(1) - r.vertex(0), ac = r.vertex(2) - r.vertex(0);
    r.abab = dot(ab, ab), r.abac = dot(ab, ac), r.acac = dot(ac, ac);
    return r;
}

// The search radius a little above the distance found: rounding to float must not cut off a triangle
// that is closer by less than float's resolution.
constexpr float kRadiusMargin = 1.0f + 1e-6f;

struct EmbreeClosest {
    Vec3d p;
    const TriangleRecord* triangles;
    double distance2;
    std::uint32_t triangle;
    int feature;
    Vec3d closest;
};

// Embree calls this for every triangle of each leaf it reaches. In double: in float, two triangles
// whose distances differ by less than float's resolution of the squared distance tie, and the wrong
// one's closest point shows in the gradient (~1e-5 at d ~ 1).
bool embreeClosestCallback(RTCPointQueryFunctionArguments* args) {
    EmbreeClosest& q = *static_cast<EmbreeClosest*>(args->userPtr);
    const TriangleRecord& t = q.triangles[args->primID];
    int feature;
    const Vec3d c = t.closest(q.p, feature);
    const Vec3d d = q.p - c;
    const double distance2 = dot(d, d);
    if (!(distance2 < q.distance2)) return false;
    q.distance2 = distance2;
    q.triangle = args->primID;
    q.feature = feature;
    q.closest = c;
    args->query->radius = float(std::sqrt(distance2)) * kRadiusMargin;
    return true;
}

// Counts the crossings of one ray: the filter sees every hit, counts it unless that triangle was
// already counted (RTC_BUILD_QUALITY_HIGH's spatial splits report a triangle once per leaf it is in)
// and rejects it, so that traversal goes on to the ray's end.
struct CrossingContext {
    RTCIntersectContext context; // first: Embree hands this pointer back to the filter
    unsigned count;
    unsigned seen[64];
};

void countCrossing(const RTCFilterFunctionNArguments* args) {
    args->valid[0] = 0;
    CrossingContext& c = *reinterpret_cast<CrossingContext*>(const_cast<RTCIntersectContext*>(args->context));
    const unsigned triangle = RTCHitN_primID(args->hit, args->N, 0);
    const unsigned stored = std::min(c.count, 64u);
    for (unsigned k = 0; k < stored; ++k)
        if (c.seen[k] == triangle) return;
    if (c.count < 64) c.seen[c.count] = triangle;
    ++c.count;
}

struct EmbreeEngine {
    RTCDevice device = nullptr;
    RTCScene scene = nullptr;
    std::vector<TriangleRecord> triangles;

    void build(const Mesh& mesh, int threads) {
        const std::string config = "threads=" + std::to_string(threads);
        device = rtcNewDevice(config.c_str());
        if (!device) fail("rtcNewDevice failed (error " + std::to_string(int(rtcGetDeviceError(nullptr))) + ")");
        scene = rtcNewScene(device);
        rtcSetSceneBuildQuality(scene, RTC_BUILD_QUALITY_HIGH);
        RTCGeometry geometry = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_TRIANGLE);
        rtcSetGeometryBuildQuality(geometry, RTC_BUILD_QUALITY_HIGH);
        const std::size_t vertexCount = mesh.positions.size() / 3, triangleCount = mesh.triangles();
        float* vertices = static_cast<float*>(
            rtcSetNewGeometryBuffer(geometry, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, 3 * sizeof(float), vertexCount));
        std::uint32_t* indices = static_cast<std::uint32_t*>(rtcSetNewGeometryBuffer(
            geometry, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, 3 * sizeof(std::uint32_t), triangleCount));
        if (!vertices || !indices) fail("Embree could not allocate the mesh's buffers");
        std::memcpy(vertices, mesh.positions.data(), mesh.positions.size() * sizeof(float));
        std::memcpy(indices, mesh.corners.data(), mesh.corners.size() * sizeof(std::uint32_t));
        rtcSetGeometryOccludedFilterFunction(geometry, countCrossing);
        rtcCommitGeometry(geometry);
        rtcAttachGeometry(scene, geometry);
        rtcReleaseGeometry(geometry);
        rtcCommitScene(scene);
        if (rtcGetDeviceError(device) != RTC_ERROR_NONE) fail("Embree failed to build the scene");
        triangles.resize(triangleCount);
        for (std::size_t t = 0; t < triangleCount; ++t)
            triangles[t] = makeRecord(mesh.vertex(mesh.corners[3 * t]), mesh.vertex(mesh.corners[3 * t + 1]),
                                      mesh.vertex(mesh.corners[3 * t + 2]));
    }
    ~EmbreeEngine() {
        if (scene) rtcReleaseScene(scene);
        if (device) rtcReleaseDevice(device);
    }

    bool odd(Vec3f p, Vec3f direction) const {
        CrossingContext c;
        rtcInitIntersectContext(&c.context);
        c.count = 0;
        RTCRay ray;
        ray.org_x = p.x, ray.org_y = p.y, ray.org_z = p.z, ray.tnear = 0.0f;
        ray.dir_x = direction.x, ray.dir_y = direction.y, ray.dir_z = direction.z, ray.time = 0.0f;
        ray.tfar = std::numeric_limits<float>::infinity();
        ray.mask = 0xFFFFFFFFu, ray.id = 0, ray.flags = 0;
        rtcOccluded1(scene, &c.context, &ray);
        return c.count & 1u;
    }

    // Closest point of p; `seed` (a triangle index or ~0u) gives the initial search radius.
    EmbreeClosest closest(Vec3f p, std::uint32_t seed) const {
        EmbreeClosest q{Vec3d{p.x, p.y, p.z}, triangles.data(), std::numeric_limits<double>::max(), 0, kFace,
                        Vec3d{p.x, p.y, p.z}};
        RTCPointQuery query;
        query.x = p.x, query.y = p.y, query.z = p.z, query.time = 0.0f;
        query.radius = std::numeric_limits<float>::max(); // (finite: -ffast-math)
        if (seed != ~0u) {
            const TriangleRecord& t = triangles[seed];
            q.closest = t.closest(q.p, q.feature);
            q.distance2 = dot(q.p - q.closest, q.p - q.closest);
            q.triangle = seed;
            query.radius = float(std::sqrt(q.distance2)) * kRadiusMargin;
        }
        RTCPointQueryContext context;
        rtcInitPointQueryContext(&context);
        rtcPointQuery(scene, &query, &context, embreeClosestCallback, &q);
        return q;
    }
};

// ---------------------------------------------------------------------------------------------
// CGAL

using Kernel = CGAL::Simple_cartesian<double>;
using CgalPoint = Kernel::Point_3;
using CgalTriangle = Kernel::Triangle_3;
using CgalPrimitive = CGAL::AABB_triangle_primitive<Kernel, std::vector<CgalTriangle>::const_iterator, CGAL::Tag_true>;
using CgalTree = CGAL::AABB_tree<CGAL::AABB_traits<Kernel, CgalPrimitive>>;
using CgalMesh = CGAL::Surface_mesh<CgalPoint>;
using CgalSide = CGAL::Side_of_triangle_mesh<CgalMesh, Kernel>;

struct CgalEngine {
    std::vector<CgalTriangle> soup;
    std::unique_ptr<CgalTree> tree;
    CgalMesh surface;
    std::unique_ptr<CgalSide> side;
    bool repaired = false;

    void build(const Mesh& mesh, bool parity) {
        soup.reserve(mesh.triangles());
        auto point = [&](std::uint32_t v) {
            const Vec3f p = mesh.vertex(v);
            return CgalPoint(p.x, p.y, p.z);
        };
        for (std::size_t t = 0; t < mesh.triangles(); ++t)
            soup.emplace_back(point(mesh.corners[3 * t]), point(mesh.corners[3 * t + 1]), point(mesh.corners[3 * t + 2]));
        tree = std::make_unique<CgalTree>(soup.cbegin(), soup.cend());
        tree->build();
        tree->accelerate_distance_queries();
        if (!parity) return;
        // Side_of_triangle_mesh needs a Surface_mesh: equal positions merged, degenerate faces dropped;
        // a soup that is not a manifold polygon mesh is made one by orient_polygon_soup (which
        // duplicates what it must; crossings are counted whatever the faces' orientation).
        std::vector<CgalPoint> vertices;
        std::vector<std::array<std::size_t, 3>> faces;
        {
            std::map<std::array<float, 3>, std::size_t> ids;
            std::vector<std::size_t> merged(mesh.positions.size() / 3);
            for (std::size_t v = 0; v < merged.size(); ++v) {
                const auto [it, added] = ids.try_emplace( // (-0 == 0 for std::less)
                    {mesh.positions[3 * v], mesh.positions[3 * v + 1], mesh.positions[3 * v + 2]}, vertices.size());
                if (added) vertices.push_back(point(std::uint32_t(v)));
                merged[v] = it->second;
            }
            for (std::size_t t = 0; t < mesh.triangles(); ++t) {
                const std::array<std::size_t, 3> f = {merged[mesh.corners[3 * t]], merged[mesh.corners[3 * t + 1]],
                                                      merged[mesh.corners[3 * t + 2]]};
                if (f[0] != f[1] && f[1] != f[2] && f[2] != f[0]) faces.push_back(f);
            }
        }
        namespace PMP = CGAL::Polygon_mesh_processing;
        if (!PMP::is_polygon_soup_a_polygon_mesh(faces)) {
            PMP::orient_polygon_soup(vertices, faces);
            repaired = true;
        }
        PMP::polygon_soup_to_polygon_mesh(vertices, faces, surface);
        side = std::make_unique<CgalSide>(surface);
        const CGAL::Bbox_3 box = tree->bbox();
        (*side)(CgalPoint((box.xmin() + box.xmax()) / 2, (box.ymin() + box.ymax()) / 2,
                          (box.zmin() + box.zmax()) / 2)); // builds its tree
    }
};

// ---------------------------------------------------------------------------------------------

double secondsSince(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

std::string jsonEscape(const std::string& s) {
    std::string out;
    for (char c : s) {
        if (c == '"' || c == '\\') out += '\\';
        if (c == '\n') {
            out += "\\n";
            continue;
        }
        out += c;
    }
    return out;
}

const char* kUsage = "usage: mesh_sdf_reference --engine embree|cgal --sign parity|pseudonormal|none --mesh M.obj "
                     "--points P.f32 --out V.f32 [--gradient G.f32] [--threads T] [--repeat R] [--order morton|input]";

Options parseArguments(int argc, char** argv) {
    Options o;
    auto integer = [](const std::string& name, const std::string& text) {
        int value = 0;
        const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
        if (error != std::errc() || end != text.data() + text.size() || value < 1)
            fail("argument " + name + ": expected a positive integer, got '" + text + "'");
        return value;
    };
    for (int i = 1; i < argc; ++i) {
        const std::string name = argv[i];
        if (name == "--help" || name == "-h") {
            std::puts(kUsage);
            std::exit(0);
        }
        if (i + 1 >= argc) fail("argument " + name + " needs a value\n" + kUsage);
        const std::string value = argv[++i];
        if (name == "--engine")
            o.engine = value;
        else if (name == "--sign")
            o.sign = value;
        else if (name == "--mesh")
            o.mesh = value;
        else if (name == "--points")
            o.points = value;
        else if (name == "--out")
            o.out = value;
        else if (name == "--gradient")
            o.gradient = value;
        else if (name == "--threads")
            o.threads = integer(name, value);
        else if (name == "--repeat")
            o.repeat = integer(name, value);
        else if (name == "--order")
            o.order = value;
        else
            fail("unknown argument '" + name + "'\n" + kUsage);
    }
    if (o.engine != "embree" && o.engine != "cgal") fail("argument --engine: expected embree or cgal, got '" + o.engine + "'");
    if (o.sign != "parity" && o.sign != "pseudonormal" && o.sign != "none")
        fail("argument --sign: expected parity, pseudonormal or none, got '" + o.sign + "'");
    if (o.order != "morton" && o.order != "input") fail("argument --order: expected morton or input, got '" + o.order + "'");
    if (o.mesh.empty()) fail("argument --mesh is required");
    if (o.points.empty()) fail("argument --points is required");
    if (o.out.empty()) fail("argument --out is required");
    return o;
}

} // namespace

int main(int argc, char** argv) {
    const Options options = parseArguments(argc, argv);
    const Sign sign = options.sign == "parity" ? Sign::Parity : options.sign == "pseudonormal" ? Sign::Pseudonormal : Sign::None;
    const int threads = options.threads > 0 ? options.threads : omp_get_max_threads();
    omp_set_num_threads(threads);
    omp_set_dynamic(0);

    const Mesh mesh = readMesh(options.mesh);
    const std::vector<float> points = readPoints(options.points);
    const std::size_t n = points.size() / 3;
    const bool morton = options.order == "morton";
    const bool wantGradient = !options.gradient.empty();

    // Build: the acceleration structure and the pseudonormals.
    const auto buildStart = std::chrono::steady_clock::now();
    EmbreeEngine embree;
    CgalEngine cgal;
    if (options.engine == "embree")
        embree.build(mesh, threads);
    else
        cgal.build(mesh, sign == Sign::Parity);
    std::vector<float> normals;
    if (sign == Sign::Pseudonormal)
        normals = buildPseudonormals(mesh);
    else { // face normals only, for the gradient where p is on the surface
        normals.assign(mesh.triangles() * 21, 0.0f);
        for (std::size_t t = 0; t < mesh.triangles(); ++t) {
            const Vec3f a = mesh.vertex(mesh.corners[3 * t]), b = mesh.vertex(mesh.corners[3 * t + 1]),
                        c = mesh.vertex(mesh.corners[3 * t + 2]);
            const Vec3f n = cross(b - a, c - a);
            const float length = std::sqrt(dot(n, n));
            if (length > 0.0f)
                normals[21 * t] = n.x / length, normals[21 * t + 1] = n.y / length, normals[21 * t + 2] = n.z / length;
        }
    }
    const Box box = boundsOf(mesh);
    const double buildSeconds = secondsSince(buildStart);

    std::vector<float> values(n), gradients(wantGradient ? 3 * n : 0);
    float* const valuesOut = values.data();
    float* const gradientsOut = wantGradient ? gradients.data() : nullptr;
    const float* const normalsIn = normals.data();
    std::vector<std::uint32_t> order;
    std::vector<std::uint64_t> keys, scratch;
    const Vec3f directions[3] = {parityDirection(0), parityDirection(1), parityDirection(2)};
    const std::int64_t count = std::int64_t(n);
    constexpr std::int64_t kChunk = 256;

    // Points visited in Morton order are scattered in memory: the point a few ahead, and where its
    // values go, are fetched while this one is queried (as sdfwb's engine does).
    auto prefetchAhead = [&](std::int64_t j) {
        constexpr std::int64_t kAhead = 4;
        if (j + kAhead >= count) return;
        const std::size_t ahead = order[std::size_t(j + kAhead)];
        __builtin_prefetch(points.data() + 3 * ahead);
        __builtin_prefetch(valuesOut + ahead, 1);
        if (gradientsOut) __builtin_prefetch(gradientsOut + 3 * ahead, 1);
    };
    auto queryEmbree = [&] {
#pragma omp parallel
        {
            std::uint32_t seed = ~0u;
#pragma omp for schedule(dynamic, kChunk)
            for (std::int64_t j = 0; j < count; ++j) {
                if (morton) prefetchAhead(j);
                const std::size_t i = morton ? order[std::size_t(j)] : std::size_t(j);
                const Vec3f p{points[3 * i], points[3 * i + 1], points[3 * i + 2]};
                const EmbreeClosest q = embree.closest(p, seed);
                if (morton) seed = q.triangle;
                double s = 1.0;
                if (sign == Sign::Parity) {
                    if (box.contains(p)) {
                        const bool a = embree.odd(p, directions[0]), b = embree.odd(p, directions[1]);
                        const bool inside = a == b ? a : embree.odd(p, directions[2]);
                        s = inside ? -1.0 : 1.0;
                    }
                } else if (sign == Sign::Pseudonormal) {
                    const float* nrm = normalsIn + 21 * std::size_t(q.triangle) + 3 * q.feature;
                    s = dot(q.p - q.closest, Vec3d{nrm[0], nrm[1], nrm[2]}) < 0.0 ? -1.0 : 1.0;
                }
                store(valuesOut, gradientsOut, i, q.p, q.closest, std::sqrt(q.distance2), s,
                      normalsIn + 21 * std::size_t(q.triangle));
            }
        }
    };

    auto queryCgal = [&] {
        const CgalTree& tree = *cgal.tree;
        const CgalTriangle* soup = cgal.soup.data();
#pragma omp parallel
        {
            bool seeded = false;
            CgalTree::Point_and_primitive_id hint;
#pragma omp for schedule(dynamic, kChunk)
            for (std::int64_t j = 0; j < count; ++j) {
                if (morton) prefetchAhead(j);
                const std::size_t i = morton ? order[std::size_t(j)] : std::size_t(j);
                const CgalPoint p(points[3 * i], points[3 * i + 1], points[3 * i + 2]);
                const CgalTree::Point_and_primitive_id hit =
                    seeded ? tree.closest_point_and_primitive(p, hint) : tree.closest_point_and_primitive(p);
                if (morton) hint = hit, seeded = true;
                const std::size_t t = std::size_t(hit.second - cgal.soup.cbegin());
                const Vec3d pd{p.x(), p.y(), p.z()}, cd{hit.first.x(), hit.first.y(), hit.first.z()};
                double s = 1.0;
                if (sign == Sign::Parity) {
                    s = (*cgal.side)(p) == CGAL::ON_BOUNDED_SIDE ? -1.0 : 1.0;
                } else if (sign == Sign::Pseudonormal) {
                    const CgalTriangle& tri = soup[t];
                    auto corner = [&](int k) { return Vec3d{tri[k].x(), tri[k].y(), tri[k].z()}; };
                    int feature;
                    closestOnTriangle(pd, corner(0), corner(1), corner(2), feature);
                    const float* nrm = normalsIn + 21 * t + 3 * feature;
                    s = dot(pd - cd, Vec3d{nrm[0], nrm[1], nrm[2]}) < 0.0 ? -1.0 : 1.0;
                }
                const Vec3d d = pd - cd;
                store(valuesOut, gradientsOut, i, pd, cd, std::sqrt(dot(d, d)), s, normalsIn + 21 * t);
            }
        }
    };

    double best = std::numeric_limits<double>::max();
    for (int r = 0; r < options.repeat; ++r) {
        const auto start = std::chrono::steady_clock::now();
        if (morton) mortonOrder(points, order, keys, scratch);
        if (options.engine == "embree")
            queryEmbree();
        else
            queryCgal();
        best = std::min(best, secondsSince(start));
    }

    writeFloats(options.out, values, "values file (--out)");
    if (wantGradient) writeFloats(options.gradient, gradients, "gradient file (--gradient)");

    std::string notes;
    if (options.engine == "embree") {
        notes = "Embree " + std::to_string(RTC_VERSION_MAJOR) + "." + std::to_string(RTC_VERSION_MINOR) + "." +
                std::to_string(RTC_VERSION_PATCH) +
                ": one triangle geometry, RTC_BUILD_QUALITY_HIGH, no RTC_SCENE_FLAG_ROBUST; closest point by rtcPointQuery "
                "with a callback that computes Ericson's closest point on the triangle in double and shrinks the radius";
        if (sign == Sign::Parity)
            notes += "; parity: majority of 3 rays (the third only when the first two disagree), every crossing counted in "
                     "one rtcOccluded1 per ray by an occlusion filter that counts and rejects each hit (duplicate triangles "
                     "from spatial splits ignored)";
    } else {
        notes = "CGAL " CGAL_VERSION_STR ": AABB_tree of a triangle soup (AABB_triangle_primitive, cached triangles) in "
                "Simple_cartesian<double>, accelerate_distance_queries(), closest_point_and_primitive";
        if (sign == Sign::Parity)
            notes += std::string("; parity: Side_of_triangle_mesh on a Surface_mesh of the same triangles") +
                     (cgal.repaired ? " (not a manifold soup: made one by orient_polygon_soup)" : "") +
                     " (meaningful on closed meshes only)";
    }
    if (sign == Sign::Parity) notes += "; a point outside the mesh's bounding box is outside without a ray";
    if (sign == Sign::Pseudonormal)
        notes += "; pseudonormal: angle-weighted vertex, edge (sum of adjacent faces) and face normals after merging equal "
                 "positions, the closest point's feature decides";
    if (morton)
        notes += "; points visited in Morton order (sort timed) with each query seeded by the previous point's closest "
                 "triangle (Embree: initial radius; CGAL: hint), the point 4 ahead and its outputs prefetched";
    notes += "; build_seconds: acceleration structure(s)" + std::string(sign == Sign::Pseudonormal ? " and pseudonormals" : "") +
             "; query_seconds: best of " + std::to_string(options.repeat) + ", value + " +
             (wantGradient ? "gradient" : "no gradient");

    const double rate = double(n) / best;
    std::printf("{\"engine\":\"%s\",\"sign\":\"%s\",\"threads\":%d,\"points\":%zu,\"triangles\":%zu,\"build_seconds\":%.6f,"
                "\"query_seconds\":%.6f,\"points_per_second\":%.1f,\"compiler_flags\":\"%s\",\"notes\":\"%s\"}\n",
                options.engine.c_str(), options.sign.c_str(), threads, n, mesh.triangles(), buildSeconds, best, rate,
                jsonEscape(REF_FLAGS).c_str(), jsonEscape(notes).c_str());
    return 0;
}
