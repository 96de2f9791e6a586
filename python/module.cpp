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

#include "Native.h"

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

using namespace sdfwb;
namespace fs = std::filesystem;

namespace sdfwb::native {

// One EGL context for the module, created on first use. GL work is serialised by this mutex and
// the context is made current on whichever Python thread calls.
std::mutex g_glMutex;
std::unique_ptr<renderer::HeadlessContext> g_context;

std::mutex& glMutex() { return g_glMutex; }

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

values::SdfInput sdfInput(const std::string& sdf, const std::string& entry, const py::object& params, const std::string& sign,
                          const std::string& normalize, float level) {
    values::SdfInput input;
    if (sdf.find('{') != std::string::npos && sdf.find('(') != std::string::npos)
        input = {"", entry, sdf, {}};
    else
        input = {sdf, entry, "", {}};
    input.sign = sign;
    input.normalize = normalize;
    input.level = level;
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

std::string keywordTerm(const std::string& path) {
    std::string name(keyName(path));
    if (name == "near_truncation") name = "near_truncate";
    if (name == "bounds_min" || name == "bounds_max") name = "bounds";
    return name + "=";
}

[[noreturn]] void raise(const jobs::JobError& error, const KeyTerms& terms) {
    std::string message;
    for (const auto& d : error.diagnostics) message += shaders::formatDiagnostic(d) + "\n";
    message += terms ? worded(error.message, error.keys, terms) : error.message;
    if (error.failure == jobs::Failure::Usage || !error.diagnostics.empty()) throw py::value_error(message);
    throw std::runtime_error(message);
}

jobs::OpenedSdf prepare(const values::SdfInput& input) {
    // Opening may evaluate the field (a GLSL field's --normalize, the check of a pasted scene's box).
    auto opened = [&] {
        py::gil_scoped_release release;
        std::lock_guard lock(g_glMutex);
        context();
        return jobs::openSdf(input, "sdfwb");
    }();
    if (!opened) raise(opened.error);
    return *opened.report;
}

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

py::object fromJson(const std::string& json) { return py::module_::import("json").attr("loads")(json); }

// A mesh file's provenance (file, triangles, sign, normalisation's transform, original bounds) as a
// dict, or None for GLSL.
py::object meshSourceOf(const jobs::OpenedSdf& opened) {
    const values::MeshSource source = opened.meshSource();
    return source.json.empty() ? py::object(py::none()) : fromJson(source.json);
}

py::array_t<float> floatArray(std::vector<py::ssize_t> shape) { return py::array_t<float>(shape); }

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
        if (values::needsGl(*request)) {
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
    if (failure) raise(*failure, KeyTerms()); // a request's keys, as its JSON wrote them
    return fromJson(report);
}

py::object params(const std::string& sdf, const std::string& entry) {
    values::ParamsRequest request;
    request.sdf = sdfInput(sdf, entry);
    auto result = jobs::run(request, {});
    if (!result) raise(result.error);
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

} // namespace sdfwb::native

using namespace sdfwb::native;

// The docstrings below are what help(sdfwb.X) shows after pybind11's signature line; each says
// what every argument takes. python/sdfwb/_native.pyi types the same functions for mypy, and
// python/tests/test_package.py checks that the two name the same arguments and defaults.

PYBIND11_MODULE(_native, m) {
#if defined(__SANITIZE_ADDRESS__)
    if (const char* plant = std::getenv("SDFWB_PLANT_LEAK"); plant && std::string(plant) == "1") sdfwbPlantedLeak();
#endif
    m.doc() = "sdfwb: sample, audit and load signed distance functions written in GLSL (headless, EGL).";
    m.attr("__version__") = SDFWB_VERSION;
    defineSampling(m); // sample, evaluate, audit: SamplingFunctions.cpp
    defineMeshing(m);  // mesh, evaluate_mesh: MeshFunctions.cpp
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
    m.def(
        "_job_kinds",
        [] {
            py::list rows;
            for (const values::JobKind& kind : values::kJobKinds)
                rows.append(py::make_tuple(std::string(kind.name), kind.needsGl, std::string(kind.python)));
            return rows;
        },
        "The job kinds' table (values/JobKinds.h): (kind, needs GL, Python function or '' for run only).");
    m.def("list_sdfs", &listSdfs,
          R"doc(The dataset's SDFs.

Returns:
    list[dict]: one dict per SDF: name, category, declared_type, animated (bool), path, author, license.)doc");
}
