#pragma once
// Runs the typed requests of Requests.h: the one implementation behind the CLI, job files, the
// workbench's child processes and Python. Each kind has a pure `validate` (no GL, no files written:
// option ranges, the output's type and folder, whether the SDF name resolves) and a `run`, which
// validates again, opens the SDF and does the work. Render, animate, sample, audit and bench need
// a current GL 4.3 context on the calling thread (renderer::HeadlessContext); merge and list none.

#include <meshing/Mesh.h>
#include <renderer/Image.h>
#include <values/JobKinds.h>
#include <values/Requests.h>

#include <core/Progress.h>
#include <shaders/Diagnostic.h>
#include <shaders/SdfSource.h>

#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace sdfwb::sampling {
struct SamplingJob;
}

namespace sdfwb::jobs {

enum class Failure {
    Usage,     // the request is malformed: the message names the request's keys ('output'; the CLI words them --output)
    Work,      // the work failed: the SDF does not compile, a file cannot be written
    NoGl,      // no usable GL context
    Cancelled, // cancelled through the progress sink; nothing was written
};

struct JobError {
    Failure failure = Failure::Work;
    std::string message;
    std::vector<shaders::Diagnostic> diagnostics; // the SDF's errors, with file and line
    std::vector<KeyMention> keys;                 // where `message` names request keys, for each front end's words
};

// A malformed request (Failure::Usage); the message knows the keys it names.
JobError usageError(const KeyedText& message);
// As `usageError`, for a failure of the work itself (a key's file cannot be written).
JobError workError(const KeyedText& message);

template <class Report> struct JobResult {
    std::optional<Report> report;
    JobError error; // when there is no report

    JobResult(Report value) : report(std::move(value)) {}
    JobResult(JobError failed) : error(std::move(failed)) {}
    explicit operator bool() const { return report.has_value(); }
    const Report& operator*() const { return *report; }
    const Report* operator->() const { return &*report; }
};

struct OpenedSdf {
    shaders::PreparedSdf prepared;
    std::string label; // the resolved path, or the name given with source text ("<source>" without one)
    std::vector<shaders::ParameterSetting> parameters; // every declared parameter, with the input's values
    std::vector<std::string> warnings;                 // values outside a declared @range

    values::MeshSource meshSource() const; // a mesh file's provenance for the report (empty for GLSL)
    // What a report of a job on this SDF says about it first: the label, the function that runs,
    // the mesh's provenance and the warnings.
    void describe(values::SdfHeader& report) const;
    // What image and video files carry beside their pixels: a mesh's provenance as
    // "sdfwb_mesh_source" (nothing for GLSL).
    renderer::FileMetadata fileMetadata() const;
};

// The shared "open the SDF" step: resolves a dataset name or a path (Usage when neither exists),
// takes `source` or reads the file, and prepares it with the entry point (Work, with diagnostics,
// when it has errors), then resolves the input's parameter values against the declarations
// (Usage naming the parameter). `what` starts the failure message ("render", "audit", ...).
JobResult<OpenedSdf> openSdf(const values::SdfInput& input, const std::string& what);

// What the workbench and the commands make of a pasted whole shader whose scene [-1, 1]^3 does not
// hold whole, from one search over [-64, 64]^3 (sampling/SurfaceBox.h). Needs a current GL context;
// all empty when the unit box holds the surface whole (or cuts a floor every larger box cuts too),
// for a mesh, or when the search fails.
//   box        X0,Y0,Z0,X1,Y1,Z1 (as --normalize takes it): the surface's box, centred on it with its
//              longest side, where a larger cube holds it whole
//   cut        that box overlaps [-1, 1]^3: the unit box cuts the scene (else nothing is in it)
//   floor      where [-1, 1]^3 holds only a plane across it ("y = 0") and the box is what stands on it
//   noSurface  why it has none anywhere (noSurfaceReason's text)
//   level      an unsigned field's surface (never negative, its own march stopping at a constant:
//              PreparedSdf::marchThreshold): that constant, which the workbench takes as --level
struct PastedView {
    std::string box, noSurface;
    float level = 0.0f;
    bool cut = false;
    std::string floor;
};
PastedView decidePastedView(const shaders::PreparedSdf& sdf, const std::vector<shaders::ParameterSetting>& parameters);

// Why a GLSL field has no surface within [-64, 64]^3, for messages: never negative but near 0 (an
// unsigned distance: --level gives it a surface), or no change of sign at all, with its values;
// empty when it has one, for a mesh, or when the search cannot run (no current GL context).
std::string noSurfaceReason(const shaders::PreparedSdf& sdf, const std::vector<shaders::ParameterSetting>& parameters);

// Frames `sdf` as --normalize `normalize` asks for a GLSL field (shaders::PreparedSdf::frame): a
// box needs no GL; unit-cube and unit-sphere search (a current GL context). Logs under `what`.
std::optional<JobError> frameField(shaders::PreparedSdf& sdf, const std::string& normalize,
                                   const std::vector<shaders::ParameterSetting>& parameters, const std::string& label,
                                   const std::string& what);

std::optional<JobError> validate(const values::RenderRequest& request);
std::optional<JobError> validate(const values::AnimateRequest& request);
std::optional<JobError> validate(const values::SampleRequest& request);
std::optional<JobError> validate(const values::AuditRequest& request);
std::optional<JobError> validate(const values::MergeRequest& request);
std::optional<JobError> validate(const values::BenchRequest& request);
inline std::optional<JobError> validate(const values::ListRequest&) { return std::nullopt; }
std::optional<JobError> validate(const values::ParamsRequest& request);
std::optional<JobError> validate(const values::MeshRequest& request);
std::optional<JobError> validate(const values::EvalRequest& request);
// Also reads the manifest: a malformed line is a usage error naming it.
std::optional<JobError> validate(const values::RunRequest& request);
std::optional<JobError> validate(const values::ProbeRequest& request);

JobResult<values::RenderReport> run(const values::RenderRequest& request, const ProgressSink& progress);
// Replays one pixel's march through the program that draws the frame (the march debugger).
JobResult<values::ProbeReport> run(const values::ProbeRequest& request, const ProgressSink& progress);
JobResult<values::AnimateReport> run(const values::AnimateRequest& request, const ProgressSink& progress);
JobResult<values::SampleReport> run(const values::SampleRequest& request, const ProgressSink& progress);
JobResult<values::AuditJobReport> run(const values::AuditRequest& request, const ProgressSink& progress);
JobResult<values::MergeReport> run(const values::MergeRequest& request, const ProgressSink& progress);
JobResult<values::ListReport> run(const values::ListRequest& request, const ProgressSink& progress);
JobResult<values::ParamsReport> run(const values::ParamsRequest& request, const ProgressSink& progress);
JobResult<values::MeshReport> run(const values::MeshRequest& request, const ProgressSink& progress);
// The mesh of a request and its report, without writing a file (Python's sdfwb.mesh); the
// request's output is not used.
struct MeshedSdf {
    meshing::Mesh mesh;
    values::MeshReport report;
};
JobResult<MeshedSdf> meshSdf(const values::MeshRequest& request, const ProgressSink& progress);
JobResult<values::EvalReport> run(const values::EvalRequest& request, const ProgressSink& progress);
// Every selected manifest item in a child process (RunRequest); `onItem` sees each outcome as it
// is recorded. Needs no GL context. An item that fails is recorded and the run goes on; the
// result is an error only for a bad request, an unwritable status file, or a cancel (the running
// item is killed and recorded as cancelled).
JobResult<values::RunReport> run(const values::RunRequest& request, const ProgressSink& progress,
                                 const std::function<void(const values::RunItemReport&)>& onItem = {});
// Writes the report's tables; the plots are drawn by the caller (bench/plot_benchmarks.py).
JobResult<values::BenchReport> run(const values::BenchRequest& request, const ProgressSink& progress);

// The sampling job a request describes (count, seed, time, shard, chunk, steps, tolerance).
sampling::SamplingJob samplingJob(const values::SampleRequest& request);
// "W:P,W:P,..." (near's mixture of Gaussian widths): the (width, weight) pairs, or what is wrong.
Expected<std::vector<std::pair<float, float>>> nearMixture(const std::string& text);

} // namespace sdfwb::jobs
