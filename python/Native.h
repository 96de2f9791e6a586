#pragma once
// The native module's shared parts: its one GL context, the `sdf` argument, errors as Python
// exceptions, reports as Python objects. The functions are defined by area: python/module.cpp
// (the module, files, any job, parameters, the dataset), SamplingFunctions.cpp (sample, evaluate,
// audit) and MeshFunctions.cpp (mesh, evaluate_mesh). Private to python/.

#include <jobs/Jobs.h>
#include <renderer/HeadlessContext.h>

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <mutex>
#include <optional>
#include <string>
#include <vector>

namespace sdfwb::native {

namespace py = pybind11;

// The module's one EGL context, created on first use and made current on the calling thread
// (releaseContext() undoes that); GL work holds glMutex().
std::mutex& glMutex();
renderer::HeadlessContext& context();
void releaseContext();

// `sdf` is a dataset name, a path, or GLSL source (anything with a brace and a parenthesis, which
// names and paths of SDF files do not have). `entry` names the SDF's function (empty: the default).
// `params`: None or a mapping of parameter values, {"radius": 0.3, "hollow": True, "offset": (1, 2, 0)}
// (a dict, or any collections.abc.Mapping, as the type stubs promise).
values::SdfInput sdfInput(const std::string& sdf, const std::string& entry, const py::object& params = py::none(),
                          const std::string& sign = {}, const std::string& normalize = {}, float level = 0.0f);
// What the module's functions call the request key at `path`: their keyword argument, "n=" (with
// near_truncate for near_truncation, bounds for bounds_min and bounds_max).
std::string keywordTerm(const std::string& path);
// A job's failure as ValueError (usage, GLSL diagnostics) or RuntimeError, its keys in `terms`
// (the keyword arguments; sdfwb.run passes none: its request's own JSON keys).
[[noreturn]] void raise(const jobs::JobError& error, const KeyTerms& terms = keywordTerm);
jobs::OpenedSdf prepare(const values::SdfInput& input);
// Parameter values as a dict (bools as bools, scalars as floats, vectors as tuples).
py::dict parameterDict(const std::vector<shaders::ParameterSetting>& settings);
// The report's JSON (jobs/JobJson.h) as Python objects: the same keys `--json` prints.
py::object fromJson(const std::string& json);
// A mesh file's provenance as a dict, or None for GLSL.
py::object meshSourceOf(const jobs::OpenedSdf& opened);
py::array_t<float> floatArray(std::vector<py::ssize_t> shape);

// Runs `work(request)` (a job returning a JobResult) with the GIL released and the module's GL
// context current; raises its failure as a Python exception.
template <class Request, class Work> auto runOnGl(const Request& request, Work work) {
    std::optional<decltype(work(request))> result;
    {
        py::gil_scoped_release release;
        std::lock_guard lock(glMutex());
        context();
        result.emplace(work(request));
        releaseContext();
    }
    if (!*result) raise(result->error);
    return std::move(*result);
}

void defineSampling(py::module_& m);
void defineMeshing(py::module_& m);

} // namespace sdfwb::native
