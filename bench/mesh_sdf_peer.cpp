// The signed distance of a triangle mesh at many points, the way a demanding C++ user writes it
// with the libraries Debian ships: Embree 3 (closest point by rtcPointQuery, crossings counted by
// an intersection filter) or CGAL (AABB tree, Side_of_triangle_mesh), OpenMP over the points. The
// fair reference bench/bench_mesh_sdf.py measures sdfwb against; built by build_mesh_sdf_peer.sh.
//
//   mesh_sdf_peer --engine embree|cgal --sign parity|pseudonormal|none --mesh M.obj --points P.f32
//                 --out V.f32 [--gradient G.f32] [--threads T] [--repeat R]
//
// P.f32: x y z float32 per point. V.f32: the signed distance per point (negative inside; unsigned
// with --sign none). G.f32: the gradient from the closest point, (p - c) / |p - c| times the sign.
// Prints one JSON line: build and query seconds (the best of R query runs), points per second.
#include <embree3/rtcore.h>

#include <CGAL/AABB_face_graph_triangle_primitive.h>
#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Side_of_triangle_mesh.h>
#include <CGAL/Surface_mesh.h>

#include <omp.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <map>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#ifndef REF_FLAGS
#define REF_FLAGS "unknown"
#endif

namespace {

struct Vec {
    double x, y, z;
};
Vec operator-(Vec a, Vec b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
Vec operator+(Vec a, Vec b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
Vec operator*(Vec a, double s) { return {a.x * s, a.y * s, a.z * s}; }
double dot(Vec a, Vec b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
Vec cross(Vec a, Vec b) { return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x}; }
Vec normalized(Vec a) {
    const double l = std::sqrt(dot(a, a));
    return l > 0 ? a * (1.0 / l) : Vec{0, 0, 0};
}

[[noreturn]] void fail(const std::string& message) {
    std::fprintf(stderr, "mesh_sdf_peer: %s\n", message.c_str());
    std::exit(1);
}

struct Mesh {
    std::vector<Vec> vertices;
    std::vector<std::array<std::uint32_t, 3>> faces;
};

Mesh readObj(const std::string& path) {
    std::ifstream in(path);
    if (!in) fail(path + ": cannot open");
    Mesh mesh;
    std::string line;
    while (std::getline(in, line)) {
        std::istringstream row(line);
        std::string kind;
        row >> kind;
        if (kind == "v") {
            Vec v{};
            row >> v.x >> v.y >> v.z;
            mesh.vertices.push_back(v);
        } else if (kind == "f") {
            std::vector<long> index;
            std::string token;
            while (row >> token) {
                const long i = std::stol(token.substr(0, token.find('/')));
                index.push_back(i > 0 ? i - 1 : long(mesh.vertices.size()) + i);
            }
            for (std::size_t k = 1; k + 1 < index.size(); ++k)
                mesh.faces.push_back({std::uint32_t(index[0]), std::uint32_t(index[k]), std::uint32_t(index[k + 1])});
        }
    }
    if (mesh.faces.empty()) fail(path + ": no faces");
    for (const auto& f : mesh.faces)
        for (std::uint32_t i : f)
            if (i >= mesh.vertices.size()) fail(path + ": a face index past the vertices");
    return mesh;
}

// Ericson's closest point on triangle abc, and its feature: 0 face, 1..3 vertices a b c, 4..6 edges ab bc ca.
Vec closestOnTriangle(Vec p, Vec a, Vec b, Vec c, int& feature) {
    const Vec ab = b - a, ac = c - a, ap = p - a;
    const double d1 = dot(ab, ap), d2 = dot(ac, ap);
    if (d1 <= 0 && d2 <= 0) return feature = 1, a;
    const Vec bp = p - b;
    const double d3 = dot(ab, bp), d4 = dot(ac, bp);
    if (d3 >= 0 && d4 <= d3) return feature = 2, b;
    const double vc = d1 * d4 - d3 * d2;
    if (vc <= 0 && d1 >= 0 && d3 <= 0) return feature = 4, a + ab * (d1 / (d1 - d3));
    const Vec cp = p - c;
    const double d5 = dot(ab, cp), d6 = dot(ac, cp);
    if (d6 >= 0 && d5 <= d6) return feature = 3, c;
    const double vb = d5 * d2 - d1 * d6;
    if (vb <= 0 && d2 >= 0 && d6 <= 0) return feature = 6, a + ac * (d2 / (d2 - d6));
    const double va = d3 * d6 - d5 * d4;
    if (va <= 0 && d4 - d3 >= 0 && d5 - d6 >= 0) return feature = 5, b + (c - b) * ((d4 - d3) / ((d4 - d3) + (d5 - d6)));
    const double sum = va + vb + vc;
    if (!(sum > 0)) { // degenerate: its nearest corner
        const double da = dot(p - a, p - a), db = dot(p - b, p - b), dc = dot(p - c, p - c);
        if (da <= db && da <= dc) return feature = 1, a;
        return db <= dc ? (feature = 2, b) : (feature = 3, c);
    }
    feature = 0;
    return a + ab * (vb / sum) + ac * (vc / sum);
}

// Angle-weighted pseudonormals (Baerentzen and Aanaes 2005): per face, per edge (the sum of its
// faces' normals), per vertex (faces' normals weighted by their angle there).
struct Pseudonormals {
    std::vector<Vec> face, vertex;
    std::vector<std::array<Vec, 3>> edge; // per face: ab bc ca
    explicit Pseudonormals(const Mesh& mesh) {
        face.resize(mesh.faces.size());
        vertex.assign(mesh.vertices.size(), Vec{0, 0, 0});
        std::map<std::pair<std::uint32_t, std::uint32_t>, Vec> edges;
        for (std::size_t f = 0; f < mesh.faces.size(); ++f) {
            const auto& t = mesh.faces[f];
            const Vec a = mesh.vertices[t[0]], b = mesh.vertices[t[1]], c = mesh.vertices[t[2]];
            face[f] = normalized(cross(b - a, c - a));
            const Vec corner[3] = {a, b, c};
            for (int k = 0; k < 3; ++k) {
                const Vec u = normalized(corner[(k + 1) % 3] - corner[k]), v = normalized(corner[(k + 2) % 3] - corner[k]);
                const double angle = std::acos(std::clamp(dot(u, v), -1.0, 1.0));
                vertex[t[k]] = vertex[t[k]] + face[f] * angle;
                auto key = std::minmax(t[k], t[(k + 1) % 3]);
                edges[{key.first, key.second}] = edges[{key.first, key.second}] + face[f];
            }
        }
        edge.resize(mesh.faces.size());
        for (std::size_t f = 0; f < mesh.faces.size(); ++f)
            for (int k = 0; k < 3; ++k) {
                auto key = std::minmax(mesh.faces[f][k], mesh.faces[f][(k + 1) % 3]);
                edge[f][k] = edges[{key.first, key.second}];
            }
    }
    bool inside(const Mesh& mesh, std::size_t f, int feature, Vec p, Vec c) const {
        Vec n = face[f];
        if (feature >= 1 && feature <= 3) n = vertex[mesh.faces[f][feature - 1]];
        if (feature >= 4) n = edge[f][feature - 4];
        return dot(p - c, n) < 0;
    }
};

const Vec kRays[3] = {normalized({1.0, 0.3183, 0.1415}), normalized({-0.2718, 1.0, 0.5772}), normalized({0.1618, -0.4142, 1.0})};

struct Query {
    Vec p;
    const Mesh* mesh;
    double best2;
    Vec closest;
    std::size_t face;
    int feature;
};

bool embreeClosest(RTCPointQueryFunctionArguments* args) {
    Query& q = *static_cast<Query*>(args->userPtr);
    const auto& t = q.mesh->faces[args->primID];
    int feature = 0;
    const Vec c = closestOnTriangle(q.p, q.mesh->vertices[t[0]], q.mesh->vertices[t[1]], q.mesh->vertices[t[2]], feature);
    const double d2 = dot(q.p - c, q.p - c);
    if (d2 < q.best2) {
        q.best2 = d2;
        q.closest = c;
        q.face = args->primID;
        q.feature = feature;
        args->query->radius = float(std::sqrt(d2));
        return true;
    }
    return false;
}

struct CountingContext {
    RTCIntersectContext context; // first: Embree passes a pointer to it to the filter
    int crossings;
};

void countAndContinue(const RTCFilterFunctionNArguments* args) {
    // Every hit along the ray is counted and rejected, so that the traversal goes on to the next.
    auto* counting = reinterpret_cast<CountingContext*>(args->context);
    for (unsigned i = 0; i < args->N; ++i)
        if (args->valid[i] == -1) {
            ++counting->crossings;
            args->valid[i] = 0;
        }
}

double seconds(std::chrono::steady_clock::time_point since) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - since).count();
}

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using SurfaceMesh = CGAL::Surface_mesh<Kernel::Point_3>;
using Primitive = CGAL::AABB_face_graph_triangle_primitive<SurfaceMesh>;
using Tree = CGAL::AABB_tree<CGAL::AABB_traits<Kernel, Primitive>>;

} // namespace

int main(int argc, char** argv) {
    std::string engine = "embree", sign = "parity", meshPath, pointsPath, outPath, gradientPath;
    int threads = omp_get_max_threads(), repeat = 3;
    for (int i = 1; i < argc; ++i) {
        const std::string arg = argv[i];
        auto value = [&]() -> std::string {
            if (i + 1 >= argc) fail(arg + ": expected a value");
            return argv[++i];
        };
        if (arg == "--engine")
            engine = value();
        else if (arg == "--sign")
            sign = value();
        else if (arg == "--mesh")
            meshPath = value();
        else if (arg == "--points")
            pointsPath = value();
        else if (arg == "--out")
            outPath = value();
        else if (arg == "--gradient")
            gradientPath = value();
        else if (arg == "--threads")
            threads = std::stoi(value());
        else if (arg == "--repeat")
            repeat = std::stoi(value());
        else
            fail("unknown argument '" + arg + "'");
    }
    if (engine != "embree" && engine != "cgal") fail("--engine: expected embree or cgal, got '" + engine + "'");
    if (sign != "parity" && sign != "pseudonormal" && sign != "none") fail("--sign: expected parity, pseudonormal or none");
    if (meshPath.empty() || pointsPath.empty() || outPath.empty()) fail("--mesh, --points and --out are required");
    if (threads < 1 || repeat < 1) fail("--threads and --repeat must be at least 1");
    omp_set_num_threads(threads);

    const Mesh mesh = readObj(meshPath);
    std::ifstream pointsFile(pointsPath, std::ios::binary | std::ios::ate);
    if (!pointsFile) fail(pointsPath + ": cannot open");
    const std::size_t n = std::size_t(pointsFile.tellg()) / 12;
    std::vector<float> points(3 * n);
    pointsFile.seekg(0);
    pointsFile.read(reinterpret_cast<char*>(points.data()), std::streamsize(12 * n));
    std::vector<float> values(n), gradients(gradientPath.empty() ? 0 : 3 * n);

    const auto buildStart = std::chrono::steady_clock::now();
    std::unique_ptr<Pseudonormals> pseudonormals;
    if (sign == "pseudonormal") pseudonormals = std::make_unique<Pseudonormals>(mesh);
    RTCDevice device = nullptr;
    RTCScene scene = nullptr;
    SurfaceMesh surface;
    std::unique_ptr<Tree> tree;
    std::unique_ptr<CGAL::Side_of_triangle_mesh<SurfaceMesh, Kernel>> side;
    std::vector<std::size_t> faceOfCgal; // Surface_mesh face index -> our face
    std::size_t refused = 0;
    if (engine == "embree") {
        device = rtcNewDevice(nullptr);
        scene = rtcNewScene(device);
        rtcSetSceneBuildQuality(scene, RTC_BUILD_QUALITY_HIGH);
        rtcSetSceneFlags(scene, RTC_SCENE_FLAG_ROBUST); // watertight: a ray through a shared edge counts once
        RTCGeometry geometry = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_TRIANGLE);
        auto* v = static_cast<float*>(rtcSetNewGeometryBuffer(geometry, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3,
                                                              3 * sizeof(float), mesh.vertices.size()));
        for (std::size_t i = 0; i < mesh.vertices.size(); ++i) {
            v[3 * i] = float(mesh.vertices[i].x);
            v[3 * i + 1] = float(mesh.vertices[i].y);
            v[3 * i + 2] = float(mesh.vertices[i].z);
        }
        auto* f = static_cast<std::uint32_t*>(rtcSetNewGeometryBuffer(geometry, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3,
                                                                      3 * sizeof(std::uint32_t), mesh.faces.size()));
        for (std::size_t i = 0; i < mesh.faces.size(); ++i) std::memcpy(f + 3 * i, mesh.faces[i].data(), 12);
        rtcSetGeometryIntersectFilterFunction(geometry, countAndContinue);
        rtcCommitGeometry(geometry);
        rtcAttachGeometry(scene, geometry);
        rtcReleaseGeometry(geometry);
        rtcCommitScene(scene);
    } else {
        std::vector<SurfaceMesh::Vertex_index> handles;
        for (const Vec& v : mesh.vertices) handles.push_back(surface.add_vertex(Kernel::Point_3(v.x, v.y, v.z)));
        for (std::size_t i = 0; i < mesh.faces.size(); ++i) {
            const auto& t = mesh.faces[i];
            const auto face = surface.add_face(handles[t[0]], handles[t[1]], handles[t[2]]);
            if (face == SurfaceMesh::null_face()) {
                ++refused;
                continue;
            }
            faceOfCgal.resize(std::size_t(face.idx()) + 1);
            faceOfCgal[face.idx()] = i;
        }
        tree = std::make_unique<Tree>(faces(surface).first, faces(surface).second, surface);
        tree->build();
        tree->accelerate_distance_queries();
        if (sign == "parity") side = std::make_unique<CGAL::Side_of_triangle_mesh<SurfaceMesh, Kernel>>(*tree);
    }
    const double buildSeconds = seconds(buildStart);

    auto evaluate = [&](std::size_t i) {
        Query q{{points[3 * i], points[3 * i + 1], points[3 * i + 2]}, &mesh, std::numeric_limits<double>::infinity(), {}, 0, 0};
        bool inside = false;
        if (engine == "embree") {
            RTCPointQuery query{float(q.p.x), float(q.p.y), float(q.p.z), 0.0f, std::numeric_limits<float>::infinity()};
            RTCPointQueryContext context;
            rtcInitPointQueryContext(&context);
            rtcPointQuery(scene, &query, &context, embreeClosest, &q);
            if (sign == "parity") {
                int votes = 0;
                for (const Vec& d : kRays) {
                    CountingContext counting;
                    rtcInitIntersectContext(&counting.context);
                    counting.crossings = 0;
                    RTCRayHit ray{};
                    ray.ray.org_x = float(q.p.x);
                    ray.ray.org_y = float(q.p.y);
                    ray.ray.org_z = float(q.p.z);
                    ray.ray.dir_x = float(d.x);
                    ray.ray.dir_y = float(d.y);
                    ray.ray.dir_z = float(d.z);
                    ray.ray.tnear = 0.0f;
                    ray.ray.tfar = std::numeric_limits<float>::infinity();
                    ray.ray.mask = 0xffffffffu;
                    ray.hit.geomID = RTC_INVALID_GEOMETRY_ID;
                    rtcIntersect1(scene, &counting.context, &ray);
                    votes += counting.crossings & 1;
                }
                inside = votes >= 2;
            }
        } else {
            const Kernel::Point_3 p(q.p.x, q.p.y, q.p.z);
            const auto hit = tree->closest_point_and_primitive(p);
            const std::size_t f = faceOfCgal[std::size_t(hit.second.idx())];
            const auto& t = mesh.faces[f];
            // The feature of the closest point (for pseudonormals), and the point in double.
            q.closest = closestOnTriangle(q.p, mesh.vertices[t[0]], mesh.vertices[t[1]], mesh.vertices[t[2]], q.feature);
            q.face = f;
            q.best2 = dot(q.p - q.closest, q.p - q.closest);
            if (sign == "parity") inside = (*side)(p) == CGAL::ON_BOUNDED_SIDE;
        }
        if (sign == "pseudonormal") inside = pseudonormals->inside(mesh, q.face, q.feature, q.p, q.closest);
        const double d = std::sqrt(q.best2);
        values[i] = float(inside ? -d : d);
        if (!gradients.empty()) {
            Vec g = d > 0 ? (q.p - q.closest) * ((inside ? -1.0 : 1.0) / d) : Vec{0, 0, 0};
            gradients[3 * i] = float(g.x);
            gradients[3 * i + 1] = float(g.y);
            gradients[3 * i + 2] = float(g.z);
        }
    };

    double best = std::numeric_limits<double>::infinity();
    for (int r = 0; r < repeat; ++r) {
        const auto start = std::chrono::steady_clock::now();
#pragma omp parallel for schedule(dynamic, 1024)
        for (std::size_t i = 0; i < n; ++i) evaluate(i);
        best = std::min(best, seconds(start));
    }
    std::ofstream(outPath, std::ios::binary).write(reinterpret_cast<const char*>(values.data()), std::streamsize(4 * n));
    if (!gradientPath.empty())
        std::ofstream(gradientPath, std::ios::binary)
            .write(reinterpret_cast<const char*>(gradients.data()), std::streamsize(12 * n));
    std::printf("{\"engine\": \"%s\", \"sign\": \"%s\", \"threads\": %d, \"points\": %zu, \"triangles\": %zu, "
                "\"build_seconds\": %.6f, \"query_seconds\": %.6f, \"points_per_second\": %.1f, \"compiler_flags\": \"%s\", "
                "\"notes\": \"%s\"}\n",
                engine.c_str(), sign.c_str(), threads, n, mesh.faces.size(), buildSeconds, best, double(n) / best, REF_FLAGS,
                engine == "embree" ? "closest point in double from Embree's candidates; rays: robust scene, every crossing "
                                     "counted by an intersection filter"
                                   : (refused ? "CGAL Surface_mesh refused some faces (non-manifold)"
                                              : "Epick kernel; Side_of_triangle_mesh on the distance tree"));
    if (scene) rtcReleaseScene(scene);
    if (device) rtcReleaseDevice(device);
    return 0;
}
