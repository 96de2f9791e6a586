// sdfwb.sample, sdfwb.evaluate and sdfwb.audit: the GIL is released while the GPU works.

#include "Native.h"

#include <jobs/JobJson.h>
#include <meshfield/MeshQuery.h>
#include <renderer/SampleCompute.h>
#include <sampling/FieldAudit.h>
#include <sampling/FieldEvaluator.h>
#include <sampling/Sampler.h>
#include <sampling/SamplerLibrary.h>
#include <shaders/ShaderComposer.h>

#include <cstdint>
#include <memory>

namespace sdfwb::native {

py::dict sample(const std::string& sdf, const std::string& pattern, std::uint64_t n, std::uint64_t seed, float time,
                float gradientStep, std::uint32_t chunk, float surfaceTolerance, const std::string& entry,
                const py::object& params, std::uint64_t firstIndex, const std::string& nearWidths, float nearTruncation,
                const std::string& sign, const std::string& normalize, float level) {
    values::SampleRequest request;
    request.sdf = sdfInput(sdf, entry, params, sign, normalize, level);
    request.pattern = pattern;
    request.count = n;
    request.seed = seed;
    request.time = time;
    request.gradientStep = gradientStep;
    request.chunkSize = chunk;
    request.surfaceTolerance = surfaceTolerance;
    request.nearWidths = nearWidths;
    request.nearTruncation = nearTruncation;
    if (auto error = jobs::validate(request)) raise(*error);
    sampling::SamplingJob job = jobs::samplingJob(request);
    job.indexOffset = firstIndex;
    if (auto ok = sampling::validate(job); !ok) raise(jobs::usageError(ok.error().keyed()));
    const jobs::OpenedSdf opened = prepare(request.sdf);
    const shaders::PreparedSdf& prepared = opened.prepared;
    job.sdfParameters = opened.parameters;
    auto sampler = sampling::findSampler(pattern, sampling::samplerFolders());
    if (!sampler) throw py::value_error("pattern: " + sampler.error().message);
    auto positions = floatArray({py::ssize_t(n), 3});
    auto distances = floatArray({py::ssize_t(n)});
    auto gradients = floatArray({py::ssize_t(n), 3});
    float* p = positions.mutable_data();
    float* d = distances.mutable_data();
    float* g = gradients.mutable_data();
    Expected<sampling::SamplingReport> report = makeError("not run");
    std::string compileErrors;
    {
        py::gil_scoped_release release;
        std::lock_guard lock(glMutex());
        context();
        renderer::SampleCompute compute;
        auto diagnostics = compute.build(prepared, *sampler);
        if (shaders::hasErrors(diagnostics)) {
            for (const auto& diagnostic : diagnostics) compileErrors += shaders::formatDiagnostic(diagnostic) + "\n";
        } else {
            report = sampling::sampleInto(compute, job, p, d, g, {});
        }
        compute.releaseGl();
        releaseContext();
    }
    if (!compileErrors.empty()) throw py::value_error(compileErrors); // the user's GLSL: a value error
    if (!report) throw std::runtime_error(report.error().message);
    py::dict result;
    result["position"] = positions;
    result["distance"] = distances;
    result["gradient"] = gradients;
    result["bad_rows"] = report->badRows;
    result["seconds"] = report->seconds;
    result["mesh_source"] = meshSourceOf(opened);
    result["parameters"] = parameterDict(opened.parameters);
    return result;
}

// The field at the caller's points through the samplers' own stage (analysis/points.glsl): the
// same compiled SDF, gradient stencil and step as `sample`, so the values are bit-equal to what a
// sampler writes at those positions. The points are read in place (float32, C order: no copy).
py::dict evaluate(const std::string& sdf, py::array_t<float, py::array::c_style | py::array::forcecast> points,
                  const py::object& params, float time, bool gradient, float gradientStep, const std::string& entry,
                  std::uint32_t chunk, const std::string& sign, const std::string& normalize, float level) {
    if (points.ndim() != 2 || points.shape(1) != 3) {
        std::string shape;
        for (py::ssize_t a = 0; a < points.ndim(); ++a) shape += (a ? ", " : "") + std::to_string(points.shape(a));
        throw py::value_error("evaluate: points must have shape (N, 3), not (" + shape + ")");
    }
    const auto n = points.shape(0);
    if (std::uint64_t(n) > 0xffffffffull) throw py::value_error("evaluate: at most 4294967295 points per call");
    sampling::SamplingJob job; // checked as the samplers check their jobs
    job.count = std::uint64_t(n);
    job.gradientStep = gradientStep == 0.0f ? 1e-3f : gradientStep; // a negative or NaN step fails validate()
    job.meshGradientTaps = gradientStep != 0.0f;
    job.chunkSize = chunk;
    if (auto ok = sampling::validate(job); n > 0 && !ok) raise(jobs::usageError(ok.error().keyed()));
    const jobs::OpenedSdf opened = prepare(sdfInput(sdf, entry, params, sign, normalize, level));
    sampling::FieldSettings settings;
    settings.time = time;
    settings.gradientStep = job.gradientStep;
    settings.meshGradientTaps = job.meshGradientTaps;
    settings.chunk = chunk;
    settings.parameters = opened.parameters;
    auto distances = floatArray({n});
    py::object gradients = py::none();
    float* g = nullptr;
    if (gradient) {
        auto array = floatArray({n, 3});
        g = array.mutable_data();
        gradients = array;
    }
    float* d = distances.mutable_data();
    Expected<sampling::SamplingReport> report = sampling::SamplingReport{};
    std::string compileErrors;
    std::optional<meshfield::QueryCounters> meshCounters;
    if (n > 0) {
        py::gil_scoped_release release;
        std::lock_guard lock(glMutex());
        context();
        sampling::FieldEvaluator field;
        auto diagnostics = field.build(opened.prepared);
        if (shaders::hasErrors(diagnostics)) {
            for (const auto& diagnostic : diagnostics) compileErrors += shaders::formatDiagnostic(diagnostic) + "\n";
        } else {
            report = field.evaluate(points.data(), std::uint64_t(n), d, g, settings);
            if (std::string_view(field.meshEngine()) == "cpu" || field.countsMeshWalks()) {
                meshCounters.emplace();
                field.addMeshCounters(*meshCounters);
            }
        }
        field.releaseGl();
        releaseContext();
    }
    if (!compileErrors.empty()) throw py::value_error(compileErrors);
    if (!report) throw std::runtime_error(report.error().message);
    py::dict result;
    result["distance"] = distances;
    result["gradient"] = gradients;
    result["bad_rows"] = report->badRows;
    result["seconds"] = report->seconds;
    result["mesh_source"] = meshSourceOf(opened);
    py::object nodes = py::none();
    if (meshCounters) {
        py::dict counts;
        counts["rows"] = std::uint64_t(n);
        counts["nearest"] = meshCounters->nearestNodes;
        counts["winding"] = meshCounters->windingNodes;
        counts["segment"] = meshCounters->segmentNodes;
        counts["cached_signs"] = meshCounters->cachedSigns;
        counts["crossed_signs"] = meshCounters->crossedSigns;
        nodes = counts;
    }
    result["mesh_nodes"] = nodes;
    return result;
}

py::object audit(const std::string& sdf, std::uint64_t samples, std::uint64_t seed, float time, const std::string& entry,
                 float truncationReach, const py::object& params, const std::string& sign, const std::string& normalize,
                 float level, const py::object& probeDistance) {
    values::AuditRequest request;
    request.sdf = sdfInput(sdf, entry, params, sign, normalize, level);
    request.samples = samples;
    request.seed = seed;
    request.time = time;
    request.truncationReach = probeDistance.is_none() ? truncationReach : probeDistance.cast<float>(); // the old name
    if (auto error = jobs::validate(request)) raise(*error);
    auto result = runOnGl(request, [](const values::AuditRequest& r) { return jobs::run(r, {}); });
    return fromJson(jobs::toJson(*result));
}

namespace {

void defineSample(py::module_& m) {
    // Float defaults spelled as written (pybind11 would print the float32 value, 0.0010000000474974513).
    m.def("sample", &sample, py::arg("sdf"), py::arg("pattern"), py::arg("n"), py::arg("seed") = 0, py::arg("time") = 0.0f,
          py::arg_v("gradient_step", 0.0f, "0.0"), py::arg("chunk") = 0u, py::arg_v("surface_tolerance", 1e-5f, "1e-5"),
          py::arg("entry") = "", py::arg("params") = py::none(), py::arg("first_index") = 0, py::arg("near_widths") = "",
          py::arg("near_truncate") = 0.0f, py::arg("sign") = "", py::arg("normalize") = "", py::arg("level") = 0.0f,
          R"doc(Samples `n` points of `sdf` with `pattern`: the same values as `sdfwb --batch sample` with the same seed.

Args:
    sdf (str): a dataset name (any case, see list_sdfs()), a path to a .glsl file or a triangle mesh (see sign),
        or GLSL source text (anything
        containing both '{' and '(') defining `float sdf(vec3 p)` or the function `entry` names.
    pattern (str): a built-in pattern (grid, image, jitter, rand, surface, near, metropolis, metropolis_curvature),
        a path to a sampler .glsl file (contains '/' or ends in .glsl) defining
        `bool samplePosition(uint index, out vec3 position)`, or the name of such a file in a folder of
        $SDFWB_SAMPLER_PATH (':'-separated) or $XDG_DATA_HOME/sdfwb/samplers (~/.local/share/sdfwb/samplers).
    n (int): the number of rows, 1 to 4294967295.
    seed (int): 0 to 2**64 - 1; a row depends on seed and its sample index alone. Default 0.
    time (float): seconds, finite: the time an animated SDF (`ENTRY(vec3 p, float time)`) is sampled at. Default 0.
    gradient_step (float): > 0, world units: the step of the central differences of `gradient`. Default 0:
        1e-3, except that a mesh's own field writes its exact gradient (from the closest point).
    chunk (int): rows per GPU dispatch (memory: 28 bytes a row), 1 to 33554432; does not change the values.
        Default 0: chosen per driver (262144 on llvmpipe, 2097152 on a GPU).
    surface_tolerance (float): > 0: |f| at which the rays of surface, near and metropolis stop (accuracy
        against time; see docs/benchmarks.md). Default 1e-5.
    entry (str): the SDF's function when it is not `sdf`, a GLSL identifier other than main, gl_* and sdfwb_*
        (e.g. 'map'; vec2/vec4 returns give the distance in .x). Default '': the file's `entry:` metadata, else
        sdf, else the first of map, scene, sceneSDF, sdScene, de, DE that it defines.
    params (Mapping[str, bool | float | Sequence[float]] | None): values for the SDF's declared parameters,
        e.g. {'radius': 0.3, 'offset': (0, 0.1, 0), 'capped': True}: 1 to 4 finite numbers each
        (sdfwb.params(sdf) lists them). Default None: the declared defaults.
    first_index (int): the first row's sample index; first_index + n <= 2**32. first_index=k*n gives the
        k-th batch of an endless stream. Default 0.
    near_widths (str): pattern 'near' only: a mixture of up to 4 Gaussian offsets 'W:P,...' (widths and weights
        positive, e.g. '0.005:0.8,0.05:0.2'). Default '': one width, 0.005.
    near_truncate (float): >= 0: with near_widths, offsets beyond this many standard deviations are redrawn
        (not clamped). Default 0: no truncation.
    sign (str): for a mesh file (.obj .ply .stl .off .glb ...): how inside is decided: 'winding' (generalized
        winding numbers; right behind holes, flipped faces and duplicated parts), 'parity' (ray crossings) or
        'pseudonormal' (exact on closed meshes). Default '': winding.
    normalize (str): for a mesh file: 'none', 'unit-cube' (bounding box centred, longest side 2) or
        'unit-sphere' (box centred, farthest vertex at 1). For a GLSL field: 'unit-cube' or 'unit-sphere' frame
        its surface the same way, its box found by the field's values (a pasted scene built around its own
        camera), and 'X0,Y0,Z0,X1,Y1,Z1' frames that box; positions and distances are then the framed
        field's (the field's point is centre + scale * position, logged). Default '': none.
    level (float): a GLSL field's surface is where it equals this: the field becomes f - level (an unsigned
        field, never negative, as many pasted shaders march, gets an inside: give its march's hit threshold,
        e.g. 0.001). Default 0.

Returns:
    dict: position (n, 3), distance (n,) and gradient (n, 3) as float32 NumPy arrays that own their memory
    (gradient raw, not normalised); bad_rows (int: rows with NaN or Inf, e.g. near rays that found no surface);
    seconds (float); parameters (dict: every declared parameter's value, bools as bool, vectors as tuples);
    mesh_source (dict for a mesh file: file, triangles, closed, sign, normalize, transform (4x4, column-major),
    bounds (the file's box); None for GLSL).

Raises:
    ValueError: an argument out of range, an unknown SDF, pattern or parameter, or GLSL errors (with
        file:line:column).
    TypeError: params is not a mapping, or a value is not a number, a bool or a sequence of numbers.
    RuntimeError: no EGL/GL, a GPU failure, or a process forked after its parent used the GPU.

The GIL is released while sampling.)doc");
}

void defineEvaluate(py::module_& m) {
    m.def("evaluate", &evaluate, py::arg("sdf"), py::arg("points"), py::arg("params") = py::none(), py::arg("time") = 0.0f,
          py::arg("gradient") = true, py::arg_v("gradient_step", 0.0f, "0.0"), py::arg("entry") = "", py::arg("chunk") = 0u,
          py::arg("sign") = "", py::arg("normalize") = "", py::arg("level") = 0.0f,
          R"doc(The field of `sdf` at the caller's points, through the samplers' own stage: bit-equal to what the samplers
write at the same positions with the same gradient_step.

Args:
    sdf (str): a dataset name, a path to a .glsl file, or GLSL source text, as for sample().
    points (array_like): shape (N, 3), N <= 4294967295 (N = 0 gives empty arrays); float32 C-order arrays are
        read in place, anything else is converted to float32 once.
    params (Mapping[str, bool | float | Sequence[float]] | None): parameter values, as for sample(). Default None.
    time (float): seconds, finite, for animated SDFs. Default 0.
    gradient (bool): also return the gradient; False evaluates the field once per point instead of seven
        times. Default True.
    gradient_step (float): > 0, world units: the step of the central differences. Default 0: 1e-3, except
        that a mesh's own field gives its exact gradient (from the closest point).
    entry (str): the SDF's function when it is not `sdf`, as for sample(). Default ''.
    chunk (int): points per GPU dispatch, 1 to 33554432; does not change the values. Default 0: chosen per
        driver (262144 on llvmpipe, 2097152 on a GPU).
    sign (str): for a mesh file, as for sample(). Default '': winding.
    normalize (str): as for sample(). Default '': none.
    level (float): as for sample(). Default 0.

Returns:
    dict: distance (N,) float32; gradient (N, 3) float32 (raw central differences), or None when
    gradient=False; bad_rows (int: rows with NaN or Inf); seconds (float); mesh_source (dict for a mesh file, as
    for sample(); None for GLSL); mesh_nodes (dict when the native CPU engine evaluated a mesh's own field, or the GLSL
    field did with SDFWB_MESH_COUNT=1 set (its counts are per field evaluation: a sign from its lattice
    is a cached_sign), else None: rows, and the hierarchy nodes its walks visited, a count that does not depend on the driver:
    nearest (the closest-point walks), winding (the winding-number walks), segment (the walks of the
    segments from a lattice point), and how many rows took their sign from the sign cache (cached_signs) or
    from a lattice point and the triangles between (crossed_signs)).

Raises:
    ValueError: points not of shape (N, 3), an argument out of range, an unknown SDF or parameter, or GLSL
        errors (with file:line:column).
    TypeError: params is not a mapping of numbers, bools or sequences of numbers.
    RuntimeError: no EGL/GL, a GPU failure, or a process forked after its parent used the GPU.

The GIL is released while the GPU works.)doc");
}

void defineAudit(py::module_& m) {
    m.def("audit", &audit, py::arg("sdf"), py::arg("samples") = 100000, py::arg("seed") = 0, py::arg("time") = 0.0f,
          py::arg("entry") = "", py::arg("truncation_reach") = 3.0f, py::arg("params") = py::none(), py::arg("sign") = "",
          py::arg("normalize") = "", py::arg("level") = 0.0f, py::arg("probe_distance") = py::none(),
          R"doc(Audits the field of `sdf`: is it an exact distance, a conservative bound, or worse?

Args:
    sdf (str): a dataset name, a path to a .glsl file, or GLSL source text, as for sample().
    samples (int): points probed, 64 to 100000000. Default 100000.
    seed (int): 0 to 2**64 - 1. Default 0.
    time (float): seconds, finite, for animated SDFs. Default 0.
    entry (str): the SDF's function when it is not `sdf`, as for sample(). Default ''.
    truncation_reach (float): 0.1 to 100, world units: how far rays from the surface outward look for a
        plateau (truncation). Default 3.
    params (Mapping[str, bool | float | Sequence[float]] | None): parameter values, as for sample(). Default None.
    sign (str): for a mesh file, as for sample(). Default '': winding.
    normalize (str): as for sample(). Default '': none.
    level (float): as for sample(). Default 0.
    probe_distance (float | None): truncation_reach's old name, still accepted. Default None.

Returns:
    dict: the report `sdfwb --batch audit --json` prints: verdict (the most severe finding: exact,
    conservative, non-conservative, truncated, discontinuous, nan), flags (every finding with its evidence and
    up to 16 example points), reason, lipschitz, safe_step_factor, truncation_distance, nan_fraction, entry,
    seconds, ...

Raises:
    ValueError: an argument out of range, an unknown SDF or parameter, or GLSL errors (with file:line:column).
    TypeError: params is not a mapping of numbers, bools or sequences of numbers.
    RuntimeError: no EGL/GL, a GPU failure, or a process forked after its parent used the GPU.

The GIL is released while auditing.)doc");
}

} // namespace

void defineSampling(py::module_& m) {
    defineSample(m);
    defineEvaluate(m);
    defineAudit(m);
}

} // namespace sdfwb::native
