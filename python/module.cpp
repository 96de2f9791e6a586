// Python bindings: `import sdfwb`. Headless (EGL), no Qt. Samples land directly in NumPy arrays
// allocated before the GPU readback, so there is no copy after it; the GIL is released while
// sampling and auditing.

#include <core/Paths.h>
#include <dataset/Catalogue.h>
#include <jobs/JobJson.h>
#include <jobs/Jobs.h>
#include <renderer/HeadlessContext.h>
#include <renderer/SampleCompute.h>
#include <sampling/FieldAudit.h>
#include <sampling/SampleFile.h>
#include <sampling/Sampler.h>
#include <sampling/SamplerLibrary.h>
#include <shaders/ShaderComposer.h>

#include <pybind11/numpy.h>

#include <glm/vec3.hpp>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <filesystem>
#include <memory>
#include <mutex>

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
// `params`: None or a dict of parameter values, {"radius": 0.3, "hollow": True, "offset": (1, 2, 0)}.
jobs::SdfInput sdfInput(const std::string& sdf, const std::string& entry, const py::object& params = py::none()) {
    jobs::SdfInput input;
    if (sdf.find('{') != std::string::npos && sdf.find('(') != std::string::npos)
        input = {"", entry, sdf, {}};
    else
        input = {sdf, entry, "", {}};
    if (params.is_none()) return input;
    if (!py::isinstance<py::dict>(params)) throw py::type_error("params: expected a dict of parameter values, or None");
    for (const auto& [key, item] : params.cast<py::dict>()) {
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

py::array_t<float> floatArray(std::vector<py::ssize_t> shape) { return py::array_t<float>(shape); }

py::dict sample(const std::string& sdf, const std::string& pattern, std::uint64_t n, std::uint64_t seed, float time,
                float gradientStep, std::uint32_t chunk, float surfaceTolerance, const std::string& entry,
                const py::object& params, std::uint64_t firstIndex, const std::string& nearWidths, float nearTruncation) {
    jobs::SampleRequest request;
    request.sdf = sdfInput(sdf, entry, params);
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
    result["parameters"] = parameterDict(opened.parameters);
    return result;
}

// The field at the caller's points through the samplers' own stage (analysis/points.glsl): the
// same compiled SDF, gradient stencil and step as `sample`, so the values are bit-equal to what a
// sampler writes at those positions. The points are read in place (float32, C order: no copy).
py::dict evaluate(const std::string& sdf, py::array_t<float, py::array::c_style | py::array::forcecast> points,
                  const py::object& params, float time, bool gradient, float gradientStep, const std::string& entry,
                  std::uint32_t chunk) {
    if (points.ndim() != 2 || points.shape(1) != 3) {
        std::string shape;
        for (py::ssize_t a = 0; a < points.ndim(); ++a) shape += (a ? ", " : "") + std::to_string(points.shape(a));
        throw py::value_error("evaluate: points must have shape (N, 3), not (" + shape + ")");
    }
    const auto n = points.shape(0);
    if (std::uint64_t(n) > 0xffffffffull) throw py::value_error("evaluate: at most 4294967295 points per call");
    sampling::SamplingJob job;
    job.count = std::uint64_t(n);
    job.time = time;
    job.gradientStep = gradientStep;
    job.chunkSize = chunk;
    job.inputPoints = points.data();
    if (auto ok = sampling::validate(job); n > 0 && !ok) throw py::value_error(ok.error().message);
    const jobs::OpenedSdf opened = prepare(sdfInput(sdf, entry, params));
    job.sdfParameters = opened.parameters;
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
    if (n > 0) {
        py::gil_scoped_release release;
        std::lock_guard lock(g_glMutex);
        context();
        renderer::SampleCompute compute;
        auto stage = shaders::builtinPiece("analysis/points.glsl");
        if (!stage) {
            report = stage.error();
        } else {
            auto diagnostics = compute.build(opened.prepared, *stage);
            if (shaders::hasErrors(diagnostics)) {
                for (const auto& diagnostic : diagnostics) compileErrors += shaders::formatDiagnostic(diagnostic) + "\n";
            } else {
                report = sampling::sampleInto(compute, job, nullptr, d, g, {});
            }
        }
        compute.releaseGl();
        releaseContext();
    }
    if (!compileErrors.empty()) throw py::value_error(compileErrors);
    if (!report) throw std::runtime_error(report.error().message);
    py::dict result;
    result["distance"] = distances;
    result["gradient"] = gradients;
    result["bad_rows"] = report->badRows;
    result["seconds"] = report->seconds;
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
                 float probeDistance, const py::object& params) {
    jobs::AuditRequest request;
    request.sdf = sdfInput(sdf, entry, params);
    request.samples = samples;
    request.seed = seed;
    request.time = time;
    request.probeDistance = probeDistance;
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
              std::uint64_t errorSamples, std::uint64_t seed, const std::string& entry, const py::object& params) {
    jobs::MeshRequest request;
    request.sdf = sdfInput(sdf, entry, params);
    request.resolution = resolution;
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

// Grades any mesh file against the exact field: the report `sdfwb --batch eval --json` prints.
py::object evaluateMesh(const std::string& mesh, const std::string& sdf, float tau, std::uint64_t points, int occupancyResolution,
                        std::uint64_t seed, float time, const std::string& entry, const py::object& params) {
    jobs::EvalRequest request;
    request.sdf = sdfInput(sdf, entry, params);
    request.mesh = mesh;
    request.tau = tau;
    request.points = points;
    request.occupancyResolution = occupancyResolution;
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

} // namespace

PYBIND11_MODULE(_native, m) {
    m.doc() = "sdfwb: sample, audit and load signed distance functions written in GLSL (headless, EGL).";
    m.attr("__version__") = SDFWB_VERSION;
    m.def("sample", &sample, py::arg("sdf"), py::arg("pattern"), py::arg("n"), py::arg("seed") = 0, py::arg("time") = 0.0f,
          py::arg("gradient_step") = 1e-3f, py::arg("chunk") = 1u << 18, py::arg("surface_tolerance") = 1e-5f,
          py::arg("entry") = "", py::arg("params") = py::none(), py::arg("first_index") = 0, py::arg("near_widths") = "",
          py::arg("near_truncate") = 0.0f,
          "Samples `n` points of `sdf` (dataset name, path or GLSL source) with `pattern`. Returns a dict of float32 arrays\n"
          "position (n,3), distance (n,), gradient (n,3) (raw, not normalised) plus bad_rows and seconds. Same seed, same\n"
          "values as `sdfwb --batch sample`. surface_tolerance: |f| at which the rays of surface/near/metropolis stop\n"
          "(accuracy against time; see docs/benchmarks.md). entry: the SDF's function when it is not sdf (e.g. 'map';\n"
          "vec2/vec4 returns give the distance in .x). params: values for the SDF's declared parameters, e.g.\n"
          "{'radius': 0.3, 'offset': (0, 0.1, 0)} (sdfwb.params(sdf) lists them); the result's `parameters` holds every\n"
          "parameter's value. first_index: the first row's sample index (rows depend on seed and index alone, so\n"
          "first_index=k*n gives the k-th batch of an endless stream). near_widths: near's mixture of Gaussian offsets\n"
          "'W:P,...' (e.g. '0.005:0.8,0.05:0.2'), truncated at near_truncate deviations when > 0. The GIL is released while "
          "sampling.");
    m.def("evaluate", &evaluate, py::arg("sdf"), py::arg("points"), py::arg("params") = py::none(), py::arg("time") = 0.0f,
          py::arg("gradient") = true, py::arg("gradient_step") = 1e-3f, py::arg("entry") = "", py::arg("chunk") = 1u << 18,
          "The field of `sdf` at the caller's points ((N,3) float32, read in place): a dict with distance (N,) and\n"
          "gradient (N,3) (raw central differences with gradient_step; None when gradient=False, which evaluates the\n"
          "field once per point instead of seven times), bad_rows and seconds. Bit-equal to what the samplers write\n"
          "at the same positions with the same gradient_step. The GIL is released while the GPU works.");
    m.def("_forget_context_after_fork", &forgetContextAfterFork, "Called by os.register_at_fork in a forked child.");
    m.def("load", &load, py::arg("path"), "Reads a .bin, .npz or .ply sample file into a dict of arrays (and its metadata).");
    m.def("save", &save, py::arg("path"), py::arg("position"), py::arg("distance"), py::arg("gradient"), py::arg("format") = "",
          py::arg("sdf") = "", py::arg("pattern") = "", py::arg("seed") = 0, py::arg("time") = 0.0f,
          "Writes arrays to a .bin, .npz or .ply sample file (atomically).");
    m.def("audit", &audit, py::arg("sdf"), py::arg("samples") = 100000, py::arg("seed") = 0, py::arg("time") = 0.0f,
          py::arg("entry") = "", py::arg("probe_distance") = 3.0f, py::arg("params") = py::none(),
          "Field audit: verdict (the most severe finding: exact, conservative, non-conservative, truncated, discontinuous,\n"
          "nan), flags (every finding with its evidence and up to 16 example points) and figures.");
    m.def("run", &run, py::arg("request"),
          "Runs one request (a dict, or its JSON text) of any kind: render, animate, sample, audit, merge, list, bench.\n"
          "The keys are those `sdfwb --batch CMD ... --print-request` prints; absent keys keep their defaults, unknown keys\n"
          "are errors. Returns the report as a dict, with the keys `--json` prints. The GIL is released while it runs.");
    m.def("params", &params, py::arg("sdf"), py::arg("entry") = "",
          "The parameters `sdf` declares (uniforms with a default, annotated // @range MIN MAX @step S @log @label \"...\"\n"
          "@color): a dict with `parameters` (name, type, default, minimum, maximum, step, log, color, label, line, column)\n"
          "and `warnings`, as `sdfwb --batch params --json` prints it. Errors raise ValueError with file:line:column.");
    m.def("mesh", &mesh, py::arg("sdf"), py::arg("resolution") = 128, py::arg("bounds") = py::none(), py::arg("time") = 0.0f,
          py::arg("lipschitz") = py::none(), py::arg("error_samples") = 0, py::arg("seed") = 0, py::arg("entry") = "",
          py::arg("params") = py::none(),
          "The zero set of `sdf` as a mesh (dual contouring, sharp edges kept): a dict with `vertices` (V,3) float32 and\n"
          "`faces` (F,3) uint32, arrays over the extraction's own memory (no copies), and `report` (what\n"
          "`sdfwb --batch mesh --json` prints: topology, the Lipschitz bound used, timings; the error against the field when\n"
          "error_samples > 0). bounds: (minx, miny, minz, maxx, maxy, maxz), default the [-1,1]^3 box.");
    m.def("evaluate_mesh", &evaluateMesh, py::arg("mesh"), py::arg("sdf"), py::arg("tau") = 0.01f, py::arg("points") = 100000,
          py::arg("occupancy_resolution") = 128, py::arg("seed") = 0, py::arg("time") = 0.0f, py::arg("entry") = "",
          py::arg("params") = py::none(),
          "Grades the mesh file `mesh` (any format assimp reads) against the exact field of `sdf`: chamfer_l1 (mean of the\n"
          "two mean unsquared distances), chamfer_l2 (the same, squared), fscore at tau (with precision and recall),\n"
          "normal_consistency, hausdorff, iou (grid of occupancy_resolution^3), and the point counts; the same dict\n"
          "`sdfwb --batch eval --json` prints, `conventions` included.");
    m.def("list_sdfs", &listSdfs,
          "The dataset: one dict per SDF (name, category, declared_type, animated, path, author, license).");
}
