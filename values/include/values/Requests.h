#pragma once
// The job model's values: one typed request and one typed report per job kind. The CLI parser
// fills requests from options, job files and `sdfwb --batch request` read them as JSON
// (jobs/JobJson.h), the workbench writes them as JSON for its child processes and its panels show
// the reports as they come (widgets include this module, not jobs/), and Python builds them from
// keyword arguments or dicts; all of them run through jobs/Jobs.h. Plain values: no GL, no Qt, no
// JSON here.

#include <core/NameTable.h>
#include <shaders/Parameters.h>
#include <values/Audit.h>
#include <values/FrameSettings.h>

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <variant>
#include <vector>

namespace sdfwb::values {

// Which SDF a job runs on. `source`, when set, is compiled instead of the file's content (the
// workbench's unsaved text; Python's GLSL strings); `sdf` then still names it for includes and
// messages and may be empty.
struct SdfInput {
    std::string sdf;    // dataset name or path
    std::string entry;  // the SDF's function; empty: metadata `entry:`, sdf, or a conventional name
    std::string source; // GLSL text to use instead of reading `sdf`
    // Values for the SDF's declared parameters (--param NAME=VALUE); the others keep their defaults.
    std::vector<shaders::ParameterValue> params;
    // Images for a Shadertoy's iChannel0..3 (--channel N=FILE): entry N, "" or missing for the
    // noise texture.
    std::vector<std::string> channels;
    // A mesh file (.obj .ply .stl .off .glb ...) as the SDF: how inside is decided (--sign winding |
    // parity | pseudonormal; empty: winding) and how it is scaled (--normalize none | unit-cube |
    // unit-sphere; empty: none). See meshfield/MeshField.h.
    std::string sign;
    std::string normalize;
    // A GLSL field's surface is where it equals `level` (--level): the field becomes f - level. An
    // unsigned field (never negative: a pasted shader's distance to thin lines, floored at 0.0004)
    // has no inside; its own march stops where f drops below a small hit threshold (0.001), and
    // that level set is the surface its pictures show.
    float level = 0.0f;
    bool operator==(const SdfInput&) const = default;
};

// A shape family: the instances of `--sweep NAME=FROM:TO:COUNT` (a grid when repeated) or of
// `--randomize COUNT` (uniform within the declared ranges, drawn from the request's seed).
struct FamilySpec {
    std::vector<shaders::ParameterSweep> sweeps;
    std::uint32_t randomize = 0;
    bool empty() const { return sweeps.empty() && randomize == 0; }
    bool operator==(const FamilySpec&) const = default;
};

// Everything one picture depends on: the viewport's frame settings (shading, trace, camera,
// overlay; the base) and the document's SDF, time and plane, at a size.
struct FrameRequest : FrameSettings {
    SdfInput sdf;
    int width = 1280;
    int height = 720;
    float time = 0.0f; // seconds; the start time for animations
    values::CuttingPlane plane;
    bool operator==(const FrameRequest&) const = default;
};

struct RenderRequest {
    FrameRequest frame;
    std::string output; // .png, .jpg or .exr
    // The file's own Shadertoy picture (its mainImage at the frame's size and time, the mouse
    // never pressed) instead of sdfwb's tracer; the camera, shading and trace settings are unused.
    bool shadertoyPicture = false;
    bool operator==(const RenderRequest&) const = default;
};

struct AnimateRequest {
    FrameRequest frame;
    std::string output; // .mp4
    float seconds = 4.0f;
    int framesPerSecond = 30;
    bool turntable = false; // orbit the camera once around the Y axis over the clip
    // Parameter keyframes: the clip moves linearly from the frame's values (frame.sdf.params and
    // the defaults) at its first frame to these at its last (ints round, bools switch halfway).
    std::vector<shaders::ParameterValue> paramsEnd;
    bool operator==(const AnimateRequest&) const = default;
};

struct SampleRequest {
    SdfInput sdf;
    std::string pattern; // built-in name or sampler path
    std::uint64_t count = 0;
    std::string output;
    std::string format; // empty: from the output's extension
    std::uint64_t seed = 0;
    float time = 0.0f;
    std::uint32_t shardIndex = 0;
    std::uint32_t shardCount = 1;
    std::uint32_t chunkSize = 0; // rows per dispatch; 0: chosen per driver (2^18 on llvmpipe, 2^21 on a GPU)
    // Central-difference step of the written gradient. 0 (the default): 1e-3, except that a mesh's
    // own field writes its exact gradient (from the closest point); a step given asks for taps.
    float gradientStep = 0.0f;
    float surfaceTolerance = 1e-5f; // |f| at which surface/near/metropolis rays stop
    // near only: a mixture of Gaussian offsets "W:P,W:P" (standard deviation W with weight P, up to 4;
    // weights are normalised), truncated at nearTruncation deviations (0: not truncated). Empty:
    // the pattern's own single width 0.005.
    std::string nearWidths;
    float nearTruncation = 0.0f;
    // One output per instance (OUTPUT's stem + _00000, _00001, ...) and an index STEM_index.json;
    // every instance uses `seed`, so instance k equals a plain run with its --param values.
    FamilySpec family;
    bool operator==(const SampleRequest&) const = default;
};

// The plane dot(normal, p) = offset.
struct PlaneSpec {
    glm::vec3 normal{0.0f, 0.0f, 1.0f};
    float offset = 0.0f;
    bool operator==(const PlaneSpec&) const = default;
};

struct AuditRequest {
    SdfInput sdf;
    std::uint64_t samples = 100000;
    std::uint64_t seed = 0;
    float time = 0.0f;
    float truncationReach = 3.0f;   // truncation: probe outward from the surface this far
    std::optional<PlaneSpec> plane; // set: plane readouts instead of the volume audit
    int resolution = 256;           // grid side on the plane
    FamilySpec family;              // set: the volume audit of every instance (no plane)
    bool operator==(const AuditRequest&) const = default;
};

struct MergeRequest {
    std::string output;
    std::string format; // empty: from the output's extension
    std::vector<std::string> parts;
    bool operator==(const MergeRequest&) const = default;
};

struct ListRequest {
    // A dataset report (scripts/dataset_report.py's JSON) for each SDF's measured type and render
    // time; empty: report.json in the dataset's folder, when there is one.
    std::string report;
    bool operator==(const ListRequest&) const = default;
};

struct BenchRequest {
    std::string outputDirectory = "docs/benchmarks"; // benchmarks.md, CSV tables, images/
    int repeats = 5;
    bool quick = false;
    bool noPlots = false;
    bool operator==(const BenchRequest&) const = default;
};

// The parameters an SDF declares (annotated uniforms, shaders/Parameters.h).
struct ParamsRequest {
    SdfInput sdf;
    bool operator==(const ParamsRequest&) const = default;
};

// The zero set as a mesh (dual contouring), graded against the exact field.
struct MeshRequest {
    SdfInput sdf;
    std::string output; // .ply, .obj, .stl or .glb
    int resolution = 128;
    // Times every triangle is cut into four, the new vertices stepped onto the surface
    // (meshing::MeshOptions::refine), 0..4.
    int refine = 0;
    glm::vec3 boundsMin{-1.0f};
    glm::vec3 boundsMax{1.0f};
    float time = 0.0f;
    // The bound on |grad f| that lets empty blocks be skipped; absent: estimated by a quick audit
    // (x1.25, at least 1); 0: skip nothing.
    std::optional<float> lipschitz;
    std::uint64_t errorSamples = 100000; // points each way for the error; 0: no error measured
    std::uint64_t seed = 0;
    bool selfIntersections = false; // count the pairs of triangles that cross (meshing::countSelfIntersections)
    bool operator==(const MeshRequest&) const = default;
};

// Any mesh graded against the exact field (meshing::evaluateMesh states the conventions).
struct EvalRequest {
    SdfInput sdf;
    std::string mesh; // any format assimp reads (.ply, .obj, .stl, .glb, .off, ...)
    std::uint64_t points = 100000;
    float tau = 0.01f;
    int occupancyResolution = 128; // 0: no IoU
    float edgeRadius = 0.02f;      // points this near a crease count for the edge measures (0: none)
    float edgeAngle = 30.0f;       // degrees the field's normal turns across a crease, at least
    glm::vec3 boundsMin{-1.0f};
    glm::vec3 boundsMax{1.0f};
    float time = 0.0f;
    std::uint64_t seed = 0;
    bool operator==(const EvalRequest&) const = default;
};

// The march debugger: one pixel's ray, every step of the march that draws it.
struct ProbeRequest {
    FrameRequest frame;
    int x = 0, y = 0; // the pixel, top row 0
    bool operator==(const ProbeRequest&) const = default;
};

// Many shapes in one run: every item of a manifest (CSV or JSON lines; jobs/Manifest.h), each in a
// child process of its own, so a broken shader or a hang fails that item alone. A status file
// (JSON lines, appended as items end) records each item's outcome; a second run skips the items
// it records as done with the same content and an intact output, so a killed run resumes.
struct RunRequest {
    std::string manifest;
    std::string status;       // empty: MANIFEST.status.jsonl, or MANIFEST.status-K-of-W.jsonl with --world-size
    double itemTimeout = 0.0; // seconds an item may take before it is killed and marked failed; 0: no limit
    std::uint32_t rank = 0;   // this process takes the items whose 0-based index % worldSize == rank
    std::uint32_t worldSize = 1;
    std::vector<std::uint64_t> items; // only these items (0-based indices in the manifest); empty: all of the rank's
    bool list = false;                // report the items and their recorded state; run nothing
    std::string executable;           // the sdfwb binary that runs sample items; empty: this process's own
    std::string python;               // the interpreter that runs recipe items; empty: $SDFWB_PYTHON, else the build's
    bool operator==(const RunRequest&) const = default;
};

using Request = std::variant<RenderRequest, AnimateRequest, SampleRequest, AuditRequest, MergeRequest, ListRequest, BenchRequest,
                             ParamsRequest, MeshRequest, EvalRequest, RunRequest, ProbeRequest>;
// Each kind's name and what it needs: values/JobKinds.h, the one table of them.

// ---- reports ----

// Where a mesh SDF came from (meshfield::MeshField::provenanceJson: the file, its triangle count,
// the sign method, the normalisation's 4x4 transform and the file's bounding box), as JSON text;
// empty when the SDF is GLSL. Every report of a job on a mesh carries it, as "mesh_source".
struct MeshSource {
    std::string json;
    bool operator==(const MeshSource&) const = default;
};

// What every report of a job run on one SDF says about it: the SDF (its resolved path, or the name
// given with source text; a sample report keeps the name as given), the function that ran, a mesh
// file's provenance, and the warnings (values outside a declared @range, view settings adjusted).
// jobs::OpenedSdf::describe fills it; each report's JSON shows these four as "sdf", "entry",
// "mesh_source" and "warnings".
struct SdfHeader {
    std::string sdf;
    std::string entry;
    MeshSource meshSource;
    std::vector<std::string> warnings;
    bool operator==(const SdfHeader&) const = default;
};

struct RenderReport : SdfHeader {
    std::string output;
    int width = 0, height = 0;
    std::string shading;
    double frameMilliseconds = 0.0;
    double seconds = 0.0;
    std::string glRenderer;
    bool operator==(const RenderReport&) const = default;
};

struct AnimateReport : SdfHeader {
    std::string output;
    int frames = 0;
    int framesPerSecond = 0;
    int width = 0, height = 0; // as encoded (even)
    double renderSeconds = 0.0;
    double seconds = 0.0;
    bool operator==(const AnimateReport&) const = default;
};

// One instance of a sampled family.
struct SampleInstance {
    std::string output;
    std::vector<shaders::ParameterValue> parameters; // every declared parameter's value
    std::uint64_t rows = 0;
    std::uint64_t badRows = 0;
    double seconds = 0.0;
    bool operator==(const SampleInstance&) const = default;
};

struct SampleReport : SdfHeader {
    std::string output;
    std::string format;
    std::string pattern;
    std::uint64_t count = 0; // N of the whole run
    std::uint64_t rows = 0;  // written by this run (its shard)
    std::uint64_t firstIndex = 0;
    std::uint64_t seed = 0;
    float time = 0.0f;
    std::uint64_t badRows = 0;
    double seconds = 0.0;      // sampling and writing (every instance's)
    double setupSeconds = 0.0; // before that: the request checked, the SDF opened, its sampler compiled
    double samplesPerSecond = 0.0;
    double kernelSeconds = -1.0; // the GPU time of the dispatches (timer queries); -1: not timed (llvmpipe)
    std::string glRenderer;
    std::vector<shaders::ParameterValue> parameters; // every declared parameter's value (a single run)
    std::vector<SampleInstance> instances;           // a family: one per output
    std::string index;                               // a family: the index file (this report as JSON)
    bool operator==(const SampleReport&) const = default;
};

struct MergeReport {
    std::string output;
    std::uint64_t rows = 0;
    std::uint64_t parts = 0;
    double seconds = 0.0;
    bool operator==(const MergeReport&) const = default;
};

// One instance of an audited family: what the volume audit found at these values.
struct AuditInstance {
    std::vector<shaders::ParameterValue> parameters; // every declared parameter's value
    values::Finding verdict = values::Finding::Conservative;
    std::string reason;
    std::vector<values::Finding> flags; // most severe first
    float lipschitz = 0.0f;
    float lipschitzMax = 0.0f;
    float exactnessP99 = 0.0f;
    double seconds = 0.0;
    bool operator==(const AuditInstance&) const = default;
};

// The volume audit, the plane readouts when the request named a plane, or one line per instance
// of a family.
struct AuditJobReport : SdfHeader {
    float truncationReach = 0.0f;
    std::vector<shaders::ParameterValue> parameters; // every declared parameter's value (not a family)
    std::optional<values::AuditReport> volume;
    std::optional<PlaneSpec> plane;
    std::optional<values::PlaneReadout> readout;
    std::vector<AuditInstance> family;
};

struct ListItem {
    std::string name, category, declaredType, path, author, license, notes;
    bool animated = false;
    // From the dataset report, when it has the SDF: the audit's verdict and a 1280x720 Gooch frame's time.
    std::string measuredType;
    std::optional<double> renderMilliseconds;
    bool operator==(const ListItem&) const = default;
};

struct ListReport {
    std::vector<ListItem> items;
    std::vector<std::string> problems; // files the catalogue could not read
    std::string root;
    // The dataset report read for the measured values: its path, and the machine and date it names
    // (all empty when there was none; problems says why a report given could not be read).
    std::string report, measuredOn, measuredDate;
    bool operator==(const ListReport&) const = default;
};

struct ParamItem {
    std::string name;
    std::string type;         // float, int, bool, vec2, vec3, vec4
    std::vector<float> value; // the default, one number per component
    std::optional<float> minimum, maximum, step;
    bool logarithmic = false;
    bool color = false;
    std::string label;
    int line = 0, column = 0;
    bool operator==(const ParamItem&) const = default;
};

struct ParamsReport {
    std::string sdf;
    std::vector<ParamItem> parameters;
    std::vector<std::string> warnings; // "file:line:column: warning: ..."
    bool operator==(const ParamsReport&) const = default;
};

struct PhaseTime { // one step of a job and its wall time
    std::string name;
    double seconds = 0.0;
};

struct MeshReport : SdfHeader {
    std::string output;
    int resolution = 0;
    int refine = 0;
    std::uint64_t vertices = 0, triangles = 0;
    std::uint64_t boundaryEdges = 0, nonManifoldEdges = 0, degenerateTriangles = 0;
    std::uint64_t nonManifoldVertices = 0, misorientedEdges = 0;
    bool manifold = false; // watertight, every vertex one fan, every edge run once each way
    bool watertight = false;
    float lipschitzBound = 0.0f;
    std::string boundSource;             // where the bound came from
    std::optional<Finding> fieldVerdict; // the quick audit's verdict, run when the error is measured (else null)
    std::uint64_t blocksGrown = 0;       // kept blocks the bound skipped but the surface crosses into from a kept one
    std::uint64_t blocks = 0, blocksKept = 0, pointsEvaluated = 0, clampedVertices = 0, verticesBesideTheirCell = 0,
                  splitFaces = 0;
    std::uint64_t boundsCutPoints = 0;              // grid points inside the shape beyond the bounds: closed by caps there
    std::uint64_t collinearFlips = 0;               // zero-area triangles (vertices in a row) flipped away
    std::uint64_t foldedQuadsTurned = 0;            // quads across a crease given the diagonal along it
    std::uint64_t midpointsKept = 0;                // refinement midpoints that took no step onto the surface
    std::optional<std::uint64_t> selfIntersections; // crossing triangle pairs, when asked for
    double meshSeconds = 0.0;
    // Where the time went: the mesher's steps in order, then "topology" (the checks above) and, in
    // the file's report, "write".
    std::vector<PhaseTime> phaseSeconds;
    // The error against the exact field (absent with error_samples 0).
    std::optional<float> meshToSurfaceMean, meshToSurfaceMax, surfaceToMeshMean, surfaceToMeshMax, hausdorff;
    std::string meshToSurfaceMethod; // |f| for an exact field, else the nearest surface point
    std::uint64_t errorPoints = 0;
    double errorSeconds = 0.0;
    std::vector<shaders::ParameterValue> parameters;
    double seconds = 0.0;
    bool operator==(const MeshReport&) const = default;
};

// The eval measures over the points near creases of the exact field (meshing::EdgeEvaluation).
struct EvalEdges {
    float chamferL1 = 0.0f, fscore = 0.0f, precision = 0.0f, recall = 0.0f, hausdorff = 0.0f;
    float accuracyMean = 0.0f, completenessMean = 0.0f;
    std::uint64_t meshPoints = 0, surfacePoints = 0;
    bool operator==(const EvalEdges&) const = default;
};

struct EvalReport : SdfHeader {
    std::string mesh;
    std::uint64_t vertices = 0, triangles = 0;
    bool closed = false;
    std::uint64_t meshPoints = 0, surfacePoints = 0, occupancyPoints = 0;
    float accuracyMean = 0.0f, accuracyMax = 0.0f, completenessMean = 0.0f, completenessMax = 0.0f;
    float chamferL1 = 0.0f, chamferL2 = 0.0f, normalConsistency = 0.0f;
    float tau = 0.0f, precision = 0.0f, recall = 0.0f, fscore = 0.0f, hausdorff = 0.0f;
    std::optional<float> iou;
    float edgeRadius = 0.0f, edgeAngle = 0.0f;
    std::optional<EvalEdges> edges; // none when no point of the exact surface lies near a crease
    std::string conventions;        // what each figure means (squared or not, counts, normalisation)
    std::vector<shaders::ParameterValue> parameters;
    double seconds = 0.0;
    bool operator==(const EvalReport&) const = default;
};

// What a probed ray's march did at one event; the last ones are also how a march ends
// (ProbeReport::outcome). Its names (the JSON's and every front end's words) are in
// kMarchEventNames, once.
enum class MarchEvent { Step, RelaxedStep, Fallback, Hit, Refine, RefineUndone, LeftBox, NotFinite, OutOfSteps, MissedBox };
inline constexpr std::pair<MarchEvent, const char*> kMarchEventNames[] = {
    {MarchEvent::Step, "step"},
    {MarchEvent::RelaxedStep, "relaxed step"},
    {MarchEvent::Fallback, "fallback"},
    {MarchEvent::Hit, "hit"},
    {MarchEvent::Refine, "refine"},
    {MarchEvent::RefineUndone, "refine undone"},
    {MarchEvent::LeftBox, "left the box"},
    {MarchEvent::NotFinite, "not finite"},
    {MarchEvent::OutOfSteps, "out of steps"},
    {MarchEvent::MissedBox, "missed the box"},
};
inline const char* marchEventName(MarchEvent event) { return nameOf(kMarchEventNames, event); }
inline std::optional<MarchEvent> parseMarchEvent(std::string_view name) { return valueNamed(kMarchEventNames, name); }
// Whether the field was evaluated at this event (its f and |grad f| mean something).
inline bool evaluatesField(MarchEvent event) {
    return event == MarchEvent::Step || event == MarchEvent::RelaxedStep || event == MarchEvent::Fallback ||
           event == MarchEvent::Hit || event == MarchEvent::Refine || event == MarchEvent::RefineUndone;
}

// One event of a probed ray's march (renderer::OffscreenRenderer::ProbeEvent, with what follows
// from it).
struct ProbeStep {
    MarchEvent event = MarchEvent::Step;
    float t = 0.0f; // distance along the ray
    glm::vec3 position{0.0f};
    float f = 0.0f;              // the field there (of the traced scene: clipped by the plane when it cuts)
    float step = 0.0f;           // how far the march moved from here (negative: a fallback's way back)
    float gradientLength = 0.0f; // |grad f| estimate
    // The step passed the surface: f changes sign before the next evaluation, so it was longer than
    // the true distance (an over-relaxed step, or a field steeper than the step factor assumes).
    bool overstep = false;
    bool operator==(const ProbeStep&) const = default;
};

struct ProbeReport : SdfHeader {
    int width = 0, height = 0, x = 0, y = 0;
    glm::vec3 origin{0.0f}, direction{0.0f};
    MarchEvent outcome = MarchEvent::MissedBox; // hit, left the box, out of steps, not finite or missed the box
    std::string reason;                         // the outcome in a sentence
    int steps = 0;                              // the tracer's step count for the pixel (what the steps shading shows)
    std::optional<float> hitT;
    std::optional<float> hitResidual; // |f| at the hit, after refining
    float footprint = 0.0f;           // the hit tolerance at the hit distance (or at the last step)
    std::uint64_t oversteps = 0, fallbacks = 0;
    int maxSteps = 0;
    float stepFactor = 1.0f, overRelaxation = 1.0f;
    std::vector<ProbeStep> events;
    std::uint64_t dropped = 0; // events past the recorder's capacity
    std::vector<shaders::ParameterValue> parameters;
    double seconds = 0.0;
    bool operator==(const ProbeReport&) const = default;
};

// Where a manifest item stands. Skipped: done before (its output is there and its key unchanged);
// pending: a --list of an item not run yet. The names are the status file's and the reports'.
enum class ItemStatus { Pending, Done, Skipped, Failed, Timeout, Cancelled };
inline constexpr std::pair<ItemStatus, const char*> kItemStatusNames[] = {
    {ItemStatus::Pending, "pending"}, {ItemStatus::Done, "done"},       {ItemStatus::Skipped, "skipped"},
    {ItemStatus::Failed, "failed"},   {ItemStatus::Timeout, "timeout"}, {ItemStatus::Cancelled, "cancelled"},
};
inline const char* itemStatusName(ItemStatus status) { return nameOf(kItemStatusNames, status); }

// One manifest item's outcome, as the status file records it and the run reports it.
struct RunItemReport {
    std::uint64_t index = 0; // 0-based position among the manifest's items
    int line = 0;            // its line in the manifest
    std::string task;        // "sample" or the recipe's name
    std::string sdf;
    std::string output;
    std::string key;                         // fingerprint of the item's content: a changed line is run again
    ItemStatus status = ItemStatus::Pending; // with list: pending or the recorded one
    double seconds = 0.0;
    std::uint64_t bytes = 0; // the output's size
    std::uint64_t rows = 0, badRows = 0;
    int exitCode = 0;
    std::string error;    // the child's last message when it failed
    std::string finished; // UTC time the item ended (ISO 8601)
    bool operator==(const RunItemReport&) const = default;
};

struct RunReport {
    std::string manifest;
    std::string status; // the status file
    std::uint32_t rank = 0, worldSize = 1;
    std::uint64_t items = 0; // in the manifest
    std::uint64_t selected = 0, done = 0, skipped = 0, failed = 0;
    double seconds = 0.0;
    double shapesPerHour = 0.0; // items done by this run per hour of its wall time
    std::uint64_t bytesWritten = 0;
    std::vector<RunItemReport> results;
    bool operator==(const RunReport&) const = default;
};

struct BenchReport {
    std::string markdown, csvDirectory, imageDirectory;
    bool plotted = false;
    bool operator==(const BenchReport&) const = default;
};

} // namespace sdfwb::values
