// Python bindings: `import sdfwb`. Headless (EGL), no Qt. Samples land directly in NumPy arrays
// allocated before the GPU readback, so there is no copy after it; the GIL is released while
// sampling and auditing.

#include <core/Paths.h>
#include <dataset/Catalogue.h>
#include <jobs/JobJson.h>
#include <jobs/Jobs.h>
#include <meshfield/MeshQuery.h>
#include <renderer/HeadlessContext.h>
#include <renderer/SampleCompute.h>
#include <sampling/FieldAudit.h>
#include <sampling/FieldEvaluator.h>
#include <sampling/SampleFile.h>
#include <sampling/Sampler.h>
#include <sampling/SamplerLibrary.h>
#include <shaders/ShaderComposer.h>

#include <pybind11/numpy.h>

#include <glm/vec3.hpp>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <memory>
#include <mutex>
#include <optional>
#include <string_view>

namespace py = pybind11;
using namespace sdfwb;
namespace fs = std::filesystem;

namespace {

// One EGL context for the module, created on first use. GL work is serialised by this mutex and
// the context is made current on whichever Python thread calls.
std::mutex g_glMutex;
std::unique_ptr<renderer::HeadlessContext> g_context;

// Each call makes the context current on its own thread and releases it at the end, so the next
// call may come from another Python thread.
void releaseContext() {
    if (g_context) g_context->doneCurrent();
}

// A forked child (a DataLoader worker) cannot use the GL its parent started: the driver's threads
// were not copied, so its first dispatch would wait forever. Such a child gets an error that says
// what to do instead; a child forked before the parent touched GL makes its own context.
bool g_forkedAfterGl = false;
void forgetContextAfterFork() {
    if (g_context) g_forkedAfterGl = true;
    (void)g_context.release(); // leaked: destroying it would wait on the same missing threads
    new (&g_glMutex) std::mutex;
}

renderer::HeadlessContext& context() {
    if (g_forkedAfterGl)
        throw std::runtime_error(
            "sdfwb: this process was forked after its parent used the GPU, whose driver threads a fork does not "
            "copy; start workers with the 'spawn' or 'forkserver' method (DataLoader(..., "
            "multiprocessing_context='spawn'), or sdfwb.torch.loader(...))");
    if (!g_context) {
        auto created = renderer::HeadlessContext::create();
        if (!created) throw std::runtime_error(created.error().message);
        g_context = std::move(*created);
    }
    if (!g_context->makeCurrent()) throw std::runtime_error("sdfwb: cannot make the EGL context current on this thread");
    return *g_context;
}

// `sdf` is a dataset name, a path, or GLSL source (anything with a brace and a parenthesis, which
// names and paths of SDF files do not have). `entry` names the SDF's function (empty: the default).
// `params`: None or a mapping of parameter values, {"radius": 0.3, "hollow": True, "offset": (1, 2, 0)}
// (a dict, or any collections.abc.Mapping, as the type stubs promise).
jobs::SdfInput sdfInput(const std::string& sdf, const std::string& entry, const py::object& params = py::none(),
                        const std::string& sign = {}, const std::string& normalize = {}) {
    jobs::SdfInput input;
    if (sdf.find('{') != std::string::npos && sdf.find('(') != std::string::npos)
        input = {"", entry, sdf, {}};
    else
        input = {sdf, entry, "", {}};
    input.sign = sign;
    input.normalize = normalize;
    if (params.is_none()) return input;
    if (!py::isinstance<py::dict>(params) && !py::isinstance(params, py::module_::import("collections.abc").attr("Mapping")))
        throw py::type_error("params: expected a dict (a mapping) of parameter values, or None");
    for (const auto& [key, item] : py::dict(params)) {
        shaders::ParameterValue value{py::str(key).cast<std::string>(), {}};
        if (py::isinstance<py::bool_>(item)) {
            value.value.push_back(item.cast<bool>() ? 1.0f : 0.0f);
        } else if (py::isinstance<py::float_>(item) || py::isinstance<py::int_>(item)) {
            value.value.push_back(item.cast<float>());
        } else if (py::isinstance<py::sequence>(item) && !py::isinstance<py::str>(item)) {
            for (const auto& x : item.cast<py::sequence>()) value.value.push_back(x.cast<float>());
        } else {
            throw py::type_error("params['" + value.name + "']: expected a number, a bool or a sequence of numbers");
        }
        input.params.push_back(std::move(value));
    }
    return input;
}

[[noreturn]] void raise(const jobs::JobError& error) {
    std::string message;
    for (const auto& d : error.diagnostics) message += shaders::formatDiagnostic(d) + "\n";
    message += error.message;
    if (error.failure == jobs::Failure::Usage || !error.diagnostics.empty()) throw py::value_error(message);
    throw std::runtime_error(message);
}

jobs::OpenedSdf prepare(const jobs::SdfInput& input) {
    auto opened = jobs::openSdf(input, "sdfwb");
    if (!opened) raise(opened.error);
    return *opened.report;
}

// Parameter values as a dict (bools as bools, scalars as floats, vectors as tuples).
py::dict parameterDict(const std::vector<shaders::ParameterSetting>& settings) {
    py::dict out;
    for (const shaders::ParameterSetting& s : settings) {
        const int n = shaders::componentCount(s.type);
        if (s.type == shaders::ParameterType::Bool)
            out[py::str(s.name)] = py::bool_(s.value[0] != 0.0f);
        else if (s.type == shaders::ParameterType::Int)
            out[py::str(s.name)] = py::int_(int(s.value[0]));
        else if (n == 1)
            out[py::str(s.name)] = s.value[0];
        else {
            py::list components;
            for (int k = 0; k < n; ++k) components.append(s.value[std::size_t(k)]);
            out[py::str(s.name)] = py::tuple(components);
        }
    }
    return out;
}

// The report's JSON (jobs/JobJson.h) as Python objects: the same keys `--json` prints.
py::object fromJson(const std::string& json) { return py::module_::import("json").attr("loads")(json); }

// A mesh file's provenance (file, triangles, sign, normalisation's transform, original bounds) as a
// dict, or None for GLSL.
py::object meshSourceOf(const jobs::OpenedSdf& opened) {
    const jobs::MeshSource source = opened.meshSource();
    return source.json.empty() ? py::object(py::none()) : fromJson(source.json);
}

py::array_t<float> floatArray(std::vector<py::ssize_t> shape) { return py::array_t<float>(shape); }

py::dict sample(const std::string& sdf, const std::string& pattern, std::uint64_t n, std::uint64_t seed, float time,
                float gradientStep, std::uint32_t chunk, float surfaceTolerance, const std::string& entry,
                const py::object& params, std::uint64_t firstIndex, const std::string& nearWidths, float nearTruncation,
                const std::string& sign, const std::string& normalize) {
    jobs::SampleRequest request;
    request.sdf = sdfInput(sdf, entry, params, sign, normalize);
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
    if (auto ok = sampling::validate(job); !ok) throw py::value_error(ok.error().message);
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
        std::lock_guard lock(g_glMutex);
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
                  std::uint32_t chunk, const std::string& sign, const std::string& normalize) {
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
    if (auto ok = sampling::validate(job); n > 0 && !ok) throw py::value_error(ok.error().message);
    const jobs::OpenedSdf opened = prepare(sdfInput(sdf, entry, params, sign, normalize));
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
        std::lock_guard lock(g_glMutex);
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

py::dict load(const std::string& path) {
    auto reader = sampling::SampleReader::open(path);
    if (!reader) throw py::value_error(reader.error().message);
    const auto rows = py::ssize_t((*reader)->rows());
    auto positions = floatArray({rows, 3});
    auto distances = floatArray({rows});
    auto gradients = floatArray({rows, 3});
    Expected<void> read = makeError("not read");
    {
        py::gil_scoped_release release;
        read =
            (*reader)->read(0, std::size_t(rows), positions.mutable_data(), distances.mutable_data(), gradients.mutable_data());
    }
    if (!read) throw py::value_error(read.error().message);
    py::dict result;
    result["position"] = positions;
    result["distance"] = distances;
    result["gradient"] = gradients;
    if (const auto& m = (*reader)->metadata()) {
        py::dict metadata;
        metadata["sdf"] = m->sdf;
        metadata["pattern"] = m->pattern;
        metadata["seed"] = m->seed;
        metadata["time"] = m->time;
        metadata["first_index"] = m->firstIndex;
        metadata["total_count"] = m->totalCount;
        metadata["version"] = m->version;
        if (!m->parameters.empty()) metadata["parameters"] = fromJson(m->parameters);
        if (!m->mesh.empty()) metadata["mesh"] = fromJson(m->mesh);
        result["metadata"] = metadata;
    }
    return result;
}

void save(const std::string& path, py::array_t<float, py::array::c_style | py::array::forcecast> position,
          py::array_t<float, py::array::c_style | py::array::forcecast> distance,
          py::array_t<float, py::array::c_style | py::array::forcecast> gradient, const std::string& format,
          const std::string& sdf, const std::string& pattern, std::uint64_t seed, float time) {
    if (position.ndim() != 2 || position.shape(1) != 3) throw py::value_error("save: position must have shape (N, 3)");
    const auto n = position.shape(0);
    if (distance.ndim() != 1 || distance.shape(0) != n)
        throw py::value_error("save: distance must have shape (N,) with N = len(position)");
    if (gradient.ndim() != 2 || gradient.shape(0) != n || gradient.shape(1) != 3)
        throw py::value_error("save: gradient must have shape (N, 3)");
    auto chosen = format.empty() ? sampling::formatFromPath(path) : sampling::parseFormat(format);
    if (!chosen) throw py::value_error("save: '" + path + "': unknown format (use .bin, .npz or .ply, or format=)");
    sampling::SampleMetadata metadata;
    metadata.sdf = sdf;
    metadata.pattern = pattern;
    metadata.seed = seed;
    metadata.time = time;
    metadata.totalCount = std::uint64_t(n);
    metadata.version = SDFWB_VERSION;
    Expected<void> written = makeError("not written");
    {
        py::gil_scoped_release release;
        auto writer = sampling::SampleWriter::create(path, *chosen, std::uint64_t(n), metadata);
        if (!writer)
            written = writer.error();
        else if (auto ok = (*writer)->append(position.data(), distance.data(), gradient.data(), std::size_t(n)); !ok)
            written = ok;
        else
            written = (*writer)->commit();
    }
    if (!written) throw std::runtime_error(written.error().message);
}

// Runs `work(request)` (a job returning a JobResult) with the GIL released and the module's GL
// context current; raises its failure as a Python exception.
template <class Request, class Work> auto runOnGl(const Request& request, Work work) {
    std::optional<decltype(work(request))> result;
    {
        py::gil_scoped_release release;
        std::lock_guard lock(g_glMutex);
        context();
        result.emplace(work(request));
        releaseContext();
    }
    if (!*result) raise(result->error);
    return std::move(*result);
}

py::object audit(const std::string& sdf, std::uint64_t samples, std::uint64_t seed, float time, const std::string& entry,
                 float truncationReach, const py::object& params, const std::string& sign, const std::string& normalize,
                 const py::object& probeDistance) {
    jobs::AuditRequest request;
    request.sdf = sdfInput(sdf, entry, params, sign, normalize);
    request.samples = samples;
    request.seed = seed;
    request.time = time;
    request.truncationReach = probeDistance.is_none() ? truncationReach : probeDistance.cast<float>(); // the old name
    if (auto error = jobs::validate(request)) raise(*error);
    auto result = runOnGl(request, [](const jobs::AuditRequest& r) { return jobs::run(r, {}); });
    return fromJson(jobs::toJson(*result));
}

// Any request, as a dict or its JSON text (what `sdfwb --batch CMD ... --print-request` prints);
// returns its report as `--json` prints it.
py::object run(const py::object& given) {
    const std::string text = py::isinstance<py::str>(given)
                                 ? given.cast<std::string>()
                                 : py::module_::import("json").attr("dumps")(given).cast<std::string>();
    auto request = jobs::requestFromJson(text);
    if (!request) throw py::value_error(request.error().message);
    std::string report;
    std::optional<jobs::JobError> failure;
    {
        py::gil_scoped_release release;
        std::unique_lock lock(g_glMutex, std::defer_lock);
        if (jobs::needsGl(*request)) {
            lock.lock();
            context();
        }
        std::visit(
            [&](const auto& r) {
                if (auto error = jobs::validate(r)) {
                    failure = *error;
                    return;
                }
                auto result = jobs::run(r, {});
                if (result)
                    report = jobs::toJson(*result);
                else
                    failure = result.error;
            },
            *request);
        if (lock.owns_lock()) releaseContext();
    }
    if (failure) raise(*failure);
    return fromJson(report);
}

py::object params(const std::string& sdf, const std::string& entry) {
    jobs::ParamsRequest request;
    request.sdf = sdfInput(sdf, entry);
    auto result = jobs::run(request, {});
    if (!result) raise(result.error);
    return fromJson(jobs::toJson(*result));
}

// The zero set as a mesh: vertices (V,3) float32 and faces (F,3) uint32, arrays over the
// extraction's own buffers (no copies), and the report `sdfwb --batch mesh --json` prints.
py::dict mesh(const std::string& sdf, int resolution, const py::object& bounds, float time, const py::object& lipschitz,
              std::uint64_t errorSamples, std::uint64_t seed, const std::string& entry, const py::object& params,
              const std::string& sign, const std::string& normalize, int refine) {
    jobs::MeshRequest request;
    request.sdf = sdfInput(sdf, entry, params, sign, normalize);
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
    auto result = runOnGl(request, [](const jobs::MeshRequest& r) { return jobs::meshSdf(r, {}); });
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
    jobs::EvalRequest request;
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
    auto result = runOnGl(request, [](const jobs::EvalRequest& r) { return jobs::run(r, {}); });
    return fromJson(jobs::toJson(*result));
}

py::list listSdfs() {
    dataset::Catalogue catalogue = dataset::Catalogue::scan(paths::datasetRoot());
    py::list out;
    for (const dataset::Entry& e : catalogue.entries()) {
        py::dict item;
        item["name"] = e.metadata.name;
        item["category"] = e.metadata.category;
        item["declared_type"] = dataset::declaredTypeName(e.metadata.type);
        item["animated"] = e.metadata.animated;
        item["path"] = e.path.string();
        item["author"] = e.metadata.author;
        item["license"] = e.metadata.license;
        out.append(item);
    }
    return out;
}

#if defined(__SANITIZE_ADDRESS__)
// scripts/sanitize plants a leak here (SDFWB_PLANT_LEAK=1, sanitizer builds only) to show that the
// LeakSanitizer suppression for the Python interpreter's own allocations hides no leak of sdfwb's.
[[gnu::noinline]] void sdfwbPlantedLeak() {
    auto* leaked = new std::uint64_t[8]{};
    asm volatile("" : : "r"(leaked) : "memory"); // made, then forgotten
}
#endif

} // namespace

// The docstrings below are what help(sdfwb.X) shows after pybind11's signature line; each says
// what every argument takes. python/sdfwb/_native.pyi types the same functions for mypy, and
// python/tests/test_package.py checks that the two name the same arguments and defaults.

PYBIND11_MODULE(_native, m) {
#if defined(__SANITIZE_ADDRESS__)
    if (const char* plant = std::getenv("SDFWB_PLANT_LEAK"); plant && std::string(plant) == "1") sdfwbPlantedLeak();
#endif
    m.doc() = "sdfwb: sample, audit and load signed distance functions written in GLSL (headless, EGL).";
    m.attr("__version__") = SDFWB_VERSION;
    // Float defaults spelled as written (pybind11 would print the float32 value, 0.0010000000474974513).
    m.def("sample", &sample, py::arg("sdf"), py::arg("pattern"), py::arg("n"), py::arg("seed") = 0, py::arg("time") = 0.0f,
          py::arg_v("gradient_step", 0.0f, "0.0"), py::arg("chunk") = 0u, py::arg_v("surface_tolerance", 1e-5f, "1e-5"),
          py::arg("entry") = "", py::arg("params") = py::none(), py::arg("first_index") = 0, py::arg("near_widths") = "",
          py::arg("near_truncate") = 0.0f, py::arg("sign") = "", py::arg("normalize") = "",
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
        Default 0: chosen per driver (262144 on llvmpipe, 16777216 on a GPU).
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
        'unit-sphere' (box centred, farthest vertex at 1). Default '': none.

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
    m.def("evaluate", &evaluate, py::arg("sdf"), py::arg("points"), py::arg("params") = py::none(), py::arg("time") = 0.0f,
          py::arg("gradient") = true, py::arg_v("gradient_step", 0.0f, "0.0"), py::arg("entry") = "", py::arg("chunk") = 0u,
          py::arg("sign") = "", py::arg("normalize") = "",
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
        driver (262144 on llvmpipe, 16777216 on a GPU).
    sign (str): for a mesh file, as for sample(). Default '': winding.
    normalize (str): for a mesh file, as for sample(). Default '': none.

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
    m.def("_forget_context_after_fork", &forgetContextAfterFork,
          "Called by os.register_at_fork in a forked child: the child makes its own EGL context, or is told to use "
          "'spawn' when its parent had used the GPU.");
    m.def("load", &load, py::arg("path"),
          R"doc(Reads a sample file (as written by save(), sdfwb --batch sample or merge) into NumPy arrays.

Args:
    path (str): a .bin, .npz or .ply file (the type from the extension, any case).

Returns:
    dict: position (R, 3), distance (R,) and gradient (R, 3) float32 arrays, and, for .npz and .ply files
    (a .bin holds none), metadata (dict: sdf, pattern, seed, time, first_index, total_count, version, and
    parameters, the values the SDF was sampled with, when it declares any).

Raises:
    ValueError: an unknown extension, a missing, unreadable or corrupt file.)doc");
    m.def("save", &save, py::arg("path"), py::arg("position"), py::arg("distance"), py::arg("gradient"), py::arg("format") = "",
          py::arg("sdf") = "", py::arg("pattern") = "", py::arg("seed") = 0, py::arg("time") = 0.0f,
          R"doc(Writes arrays to a sample file atomically (a temporary file renamed into place), with metadata that load()
reads back.

Args:
    path (str): the file to write; its folder must exist.
    position (array_like): shape (N, 3), converted to float32.
    distance (array_like): shape (N,), converted to float32.
    gradient (array_like): shape (N, 3), converted to float32.
    format (str): 'bin', 'npz' or 'ply'. Default '': from the extension of path (.bin, .npz, .ply, any case).
    sdf (str): recorded as the metadata's sdf (the name or path the rows came from). Default ''.
    pattern (str): recorded as the metadata's pattern. Default ''.
    seed (int): 0 to 2**64 - 1, recorded as the metadata's seed. Default 0.
    time (float): recorded as the metadata's time. Default 0.

Returns:
    None (.npz and .ply files hold the metadata; a .bin holds the rows alone)

Raises:
    ValueError: arrays of the wrong shapes, or an unknown format or extension.
    RuntimeError: the file cannot be written.)doc");
    m.def("audit", &audit, py::arg("sdf"), py::arg("samples") = 100000, py::arg("seed") = 0, py::arg("time") = 0.0f,
          py::arg("entry") = "", py::arg("truncation_reach") = 3.0f, py::arg("params") = py::none(), py::arg("sign") = "",
          py::arg("normalize") = "", py::arg("probe_distance") = py::none(),
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
    normalize (str): for a mesh file, as for sample(). Default '': none.
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
    m.def("run", &run, py::arg("request"),
          R"doc(Runs one request of any kind, as `sdfwb --batch` would.

Args:
    request (dict | str): a JSON object, as a dict or its JSON text, with a "kind" (render, animate, sample,
        audit, merge, list, bench, params, mesh, eval, run, probe) and the keys
        `sdfwb --batch CMD ... --print-request` prints; absent keys keep their defaults, unknown keys are errors.

Returns:
    dict: the report, with the keys `sdfwb --batch CMD ... --json` prints.

Raises:
    ValueError: invalid JSON, an unknown kind or key, an argument out of range, or GLSL errors.
    TypeError: a dict that cannot be written as JSON.
    RuntimeError: the job failed while running (GL, files, ...).

The GIL is released while it runs.)doc");
    m.def("params", &params, py::arg("sdf"), py::arg("entry") = "",
          R"doc(The parameters `sdf` declares: uniforms with a default, annotated
`// @range MIN MAX @step S @log @label "..." @color`.

Args:
    sdf (str): a dataset name, a path to a .glsl file, or GLSL source text, as for sample().
    entry (str): the SDF's function when it is not `sdf`, as for sample(). Default ''.

Returns:
    dict: what `sdfwb --batch params --json` prints: sdf (the resolved path, or <source>), parameters (a list
    of dicts: name, type (float, int, bool, vec2, vec3, vec4), default (a list of floats), minimum, maximum,
    step (None when not declared), log, color, label, line, column) and warnings (file:line:column strings).

Raises:
    ValueError: an unknown SDF, a bad entry, or declarations with errors (with file:line:column).
    RuntimeError: the file cannot be read.)doc");
    m.def("mesh", &mesh, py::arg("sdf"), py::arg("resolution") = 128, py::arg("bounds") = py::none(), py::arg("time") = 0.0f,
          py::arg("lipschitz") = py::none(), py::arg("error_samples") = 0, py::arg("seed") = 0, py::arg("entry") = "",
          py::arg("params") = py::none(), py::arg("sign") = "", py::arg("normalize") = "", py::arg("refine") = 0,
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
    m.def(
        "_job_kinds",
        [] {
            py::list rows;
            for (const jobs::JobKind& kind : jobs::kJobKinds)
                rows.append(py::make_tuple(std::string(kind.name), kind.needsGl, std::string(kind.python)));
            return rows;
        },
        "The job kinds' table (values/JobKinds.h): (kind, needs GL, Python function or '' for run only).");
    m.def("list_sdfs", &listSdfs,
          R"doc(The dataset's SDFs.

Returns:
    list[dict]: one dict per SDF: name, category, declared_type, animated (bool), path, author, license.)doc");
}
