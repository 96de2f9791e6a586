// sdfwb.mesh and sdfwb.evaluate_mesh: the zero set as a mesh, and any mesh graded against the field.

#include "Native.h"

#include <jobs/JobJson.h>

#include <glm/vec3.hpp>
#include <pybind11/stl.h>

#include <cstdint>
#include <vector>

namespace sdfwb::native {

// The zero set as a mesh: vertices (V,3) float32 and faces (F,3) uint32, arrays over the
// extraction's own buffers (no copies), and the report `sdfwb --batch mesh --json` prints.
py::dict mesh(const std::string& sdf, int resolution, const py::object& bounds, float time, const py::object& lipschitz,
              std::uint64_t errorSamples, std::uint64_t seed, const std::string& entry, const py::object& params,
              const std::string& sign, const std::string& normalize, float level, int refine) {
    values::MeshRequest request;
    request.sdf = sdfInput(sdf, entry, params, sign, normalize, level);
    request.resolution = resolution;
    request.refine = refine;
    request.time = time;
    request.errorSamples = errorSamples;
    request.seed = seed;
    if (!bounds.is_none()) {
        auto values = bounds.cast<std::vector<float>>();
        if (values.size() != 6) throw py::value_error("bounds: expected (minx, miny, minz, maxx, maxy, maxz)");
        request.boundsMin = {values[0], values[1], values[2]};
        request.boundsMax = {values[3], values[4], values[5]};
    }
    if (!lipschitz.is_none()) request.lipschitz = lipschitz.cast<float>();
    auto result = runOnGl(request, [](const values::MeshRequest& r) { return jobs::meshSdf(r, {}); });
    jobs::MeshedSdf& meshed = *result.report;
    auto* vertices = new std::vector<glm::vec3>(std::move(meshed.mesh.vertices));
    auto* indices = new std::vector<std::uint32_t>(std::move(meshed.mesh.indices));
    py::capsule ownsVertices(vertices, [](void* p) { delete static_cast<std::vector<glm::vec3>*>(p); });
    py::capsule ownsIndices(indices, [](void* p) { delete static_cast<std::vector<std::uint32_t>*>(p); });
    static_assert(sizeof(glm::vec3) == 3 * sizeof(float), "vertices are three packed floats");
    py::dict out;
    out["vertices"] = py::array_t<float>({py::ssize_t(vertices->size()), py::ssize_t(3)},
                                         reinterpret_cast<float*>(vertices->data()), ownsVertices);
    out["faces"] = py::array_t<std::uint32_t>({py::ssize_t(indices->size() / 3), py::ssize_t(3)}, indices->data(), ownsIndices);
    out["report"] = fromJson(jobs::toJson(meshed.report));
    return out;
}

// Grades any mesh file against the exact field: the report `sdfwb --batch grade --json` prints.
py::object evaluateMesh(const std::string& mesh, const std::string& sdf, float tau, std::uint64_t points, int occupancyResolution,
                        float edgeRadius, float edgeAngle, std::uint64_t seed, float time, const std::string& entry,
                        const py::object& params) {
    values::EvalRequest request;
    request.sdf = sdfInput(sdf, entry, params);
    request.mesh = mesh;
    request.tau = tau;
    request.points = points;
    request.occupancyResolution = occupancyResolution;
    request.edgeRadius = edgeRadius;
    request.edgeAngle = edgeAngle;
    request.seed = seed;
    request.time = time;
    if (auto error = jobs::validate(request)) raise(*error);
    auto result = runOnGl(request, [](const values::EvalRequest& r) { return jobs::run(r, {}); });
    return fromJson(jobs::toJson(*result));
}

void defineMeshing(py::module_& m) {
    m.def("mesh", &mesh, py::arg("sdf"), py::arg("resolution") = 128, py::arg("bounds") = py::none(), py::arg("time") = 0.0f,
          py::arg("lipschitz") = py::none(), py::arg("error_samples") = 0, py::arg("seed") = 0, py::arg("entry") = "",
          py::arg("params") = py::none(), py::arg("sign") = "", py::arg("normalize") = "", py::arg("level") = 0.0f,
          py::arg("refine") = 0,
          R"doc(The zero set of `sdf` as a triangle mesh, by dual contouring (sharp edges and corners kept).

Args:
    sdf (str): a dataset name, a path to a .glsl file, or GLSL source text, as for sample().
    resolution (int): grid cells per axis, 2 to 2048. Default 128.
    bounds (Sequence[float] | None): (minx, miny, minz, maxx, maxy, maxz), finite, each maximum above its
        minimum. Default None: the box [-1, 1]^3.
    time (float): seconds, finite, for animated SDFs. Default 0.
    lipschitz (float | None): the bound on |grad f| that lets empty blocks be skipped, finite, >= 0 (0: skip
        nothing). Default None: 1.25 x the steepest |grad f| at the block centres, at least 1 (the audit's
        estimate when error_samples is given).
    error_samples (int): points each way for the error against the field, 0 to 10000000 (0: not measured).
        Default 0.
    seed (int): 0 to 2**64 - 1, for the error's points. Default 0.
    entry (str): the SDF's function when it is not `sdf`, as for sample(). Default ''.
    params (Mapping[str, bool | float | Sequence[float]] | None): parameter values, as for sample(). Default None.
    sign (str): for a mesh file, as for sample() (meshing a broken mesh's winding-number inside gives a
        watertight mesh). Default '': winding.
    normalize (str): for a mesh file, as for sample(). Default '': none.
    level (float): as for sample(): the surface extracted is f = level. Default 0.
    refine (int): 0 to 4: times every triangle is cut into four after extraction, each new vertex stepped onto
        the exact surface. On smooth surfaces each level quarters the error (as doubling the resolution does) at
        far less cost; creases stay where the grid put them. Default 0.

Returns:
    dict: vertices (V, 3) float32 and faces (F, 3) uint32, arrays over the extraction's own memory (no
    copies), and report (what `sdfwb --batch mesh --json` prints: topology, the Lipschitz bound used, timings;
    the error against the field when error_samples > 0).

Raises:
    ValueError: an argument out of range, an unknown SDF or parameter, or GLSL errors (with file:line:column).
    TypeError: params is not a mapping of numbers, bools or sequences of numbers.
    RuntimeError: bounds or lipschitz holding something other than numbers (pybind11's cast error), no EGL/GL,
        a GPU failure, or a process forked after its parent used the GPU.)doc");
    m.def("evaluate_mesh", &evaluateMesh, py::arg("mesh"), py::arg("sdf"), py::arg_v("tau", 0.01f, "0.01"),
          py::arg("points") = 100000, py::arg("occupancy_resolution") = 128, py::arg_v("edge_radius", 0.02f, "0.02"),
          py::arg_v("edge_angle", 30.0f, "30.0"), py::arg("seed") = 0, py::arg("time") = 0.0f, py::arg("entry") = "",
          py::arg("params") = py::none(),
          R"doc(Grades a mesh file against the exact field of `sdf`.

Args:
    mesh (str): a mesh file in any format assimp reads (.ply, .obj, .stl, .glb, .off, ...).
    sdf (str): a dataset name, a path to a .glsl file, or GLSL source text, as for sample().
    tau (float): > 0, world units: the distance threshold of the F-score. Default 0.01.
    points (int): points each way (mesh to surface, surface to mesh), 100 to 10000000. Default 100000.
    occupancy_resolution (int): the IoU grid's side, 0 to 512 (0: no IoU). Default 128.
    edge_radius (float): >= 0, world units: points this near a crease of the exact field count for the edge
        measures (0: none). Default 0.02.
    edge_angle (float): degrees, between 0 and 180: how far the field's normal turns across a crease. Default 30.
    seed (int): 0 to 2**64 - 1. Default 0.
    time (float): seconds, finite, for animated SDFs. Default 0.
    entry (str): the SDF's function when it is not `sdf`, as for sample(). Default ''.
    params (Mapping[str, bool | float | Sequence[float]] | None): parameter values, as for sample(). Default None.

Returns:
    dict: what `sdfwb --batch grade --json` prints: chamfer_l1 (mean of the two mean unsquared distances),
    chamfer_l2 (the same, squared), fscore at tau (with precision and recall), normal_consistency, hausdorff,
    iou (None without an IoU grid), edges (the same measures over the points near creases: chamfer_l1, fscore,
    precision, recall, hausdorff and their point counts; None when the exact surface has no crease), the point
    counts and conventions.

Raises:
    ValueError: a missing mesh file, an argument out of range, an unknown SDF or parameter, or GLSL errors.
    TypeError: params is not a mapping of parameter values.
    RuntimeError: an unreadable mesh, no EGL/GL, or a GPU failure.)doc");
}

} // namespace sdfwb::native
