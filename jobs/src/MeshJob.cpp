// mesh: the zero set by dual contouring, written through assimp and graded against the field.
#include <jobs/Jobs.h>

#include <core/Log.h>
#include <meshing/Mesh.h>
#include <sampling/FieldAudit.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <optional>

namespace sdfwb::jobs {

namespace {

std::optional<JobError> checkBoundsAndTime(const glm::vec3& low, const glm::vec3& high, float time) {
    for (int a = 0; a < 3; ++a)
        if (!std::isfinite(low[a]) || !std::isfinite(high[a]) || !(high[a] > low[a]))
            return usageError(keys({"bounds_min", "bounds_max"}) +
                              ": expected finite MINX,MINY,MINZ,MAXX,MAXY,MAXZ with each maximum above its minimum");
    if (!std::isfinite(time)) return usageError(key("time") + ": expected a finite number");
    return std::nullopt;
}

// Everything but the output file.
std::optional<JobError> validateSettings(const values::MeshRequest& request) {
    if (request.resolution < 2 || request.resolution > 2048)
        return usageError(key("resolution") + ": must be 2..2048, got " + std::to_string(request.resolution));
    if (request.refine < 0 || request.refine > 4)
        return usageError(key("refine") + ": must be 0..4 (each level four times the triangles), got " +
                          std::to_string(request.refine));
    if (auto error = checkBoundsAndTime(request.boundsMin, request.boundsMax, request.time)) return error;
    if (request.lipschitz && (!std::isfinite(*request.lipschitz) || *request.lipschitz < 0.0f))
        return usageError(key("lipschitz") + ": expected a finite number >= 0 (0 skips nothing)");
    if (request.errorSamples > 10000000) return usageError(key("error_samples") + ": at most 10000000");
    values::ParamsRequest sdfOnly{request.sdf};
    return validate(sdfOnly); // the SDF's name, entry and parameter values
}

} // namespace

std::optional<JobError> validate(const values::MeshRequest& request) {
    if (!meshing::canWriteMesh(request.output))
        return usageError(key("output") + ": '" + request.output + "': unsupported mesh type (use .ply, .obj, .stl or .glb)");
    const std::filesystem::path folder =
        std::filesystem::path(request.output).parent_path().empty() ? "." : std::filesystem::path(request.output).parent_path();
    std::error_code ec;
    if (!std::filesystem::is_directory(folder, ec))
        return usageError(key("output") + ": '" + request.output + "': folder '" + folder.string() + "' does not exist");
    return validateSettings(request);
}

JobResult<MeshedSdf> meshSdf(const values::MeshRequest& request, const ProgressSink& progress) {
    const auto start = std::chrono::steady_clock::now();
    if (auto error = validateSettings(request)) return *error;
    auto sdf = openSdf(request.sdf, "mesh");
    if (!sdf) return sdf.error;
    values::MeshReport report;
    sdf->describe(report);
    report.resolution = request.resolution;
    report.refine = request.refine;
    report.parameters = shaders::valuesOf(sdf->parameters);
    meshing::MeshOptions options;
    options.resolution = request.resolution;
    options.refine = request.refine;
    options.boundsMin = request.boundsMin;
    options.boundsMax = request.boundsMax;
    options.time = request.time;
    options.parameters = sdf->parameters;
    // The audit says whether |f| is the distance (exact) or only a bound, which the error's method
    // depends on: it runs when the error is wanted, and its Lipschitz estimate then skips the blocks.
    // Otherwise the bound is the mesher's own estimate from the block centres (--lipschitz: given).
    std::optional<values::Finding> verdict;
    if (request.errorSamples > 0) {
        sampling::AuditOptions audit;
        audit.samples = 4000;
        audit.seed = request.seed;
        audit.time = request.time;
        audit.convergence = false;
        audit.parameters = sdf->parameters;
        auto found = sampling::auditField(sdf->prepared, audit, {});
        if (!found) return workError(found.error().keyed());
        verdict = found->verdict;
        if (!request.lipschitz) {
            if (!std::isfinite(found->lipschitzMax) || found->verdict == values::Finding::Nan ||
                found->verdict == values::Finding::Discontinuous) {
                options.lipschitz = 0.0f;
                report.boundSource = std::string("none: the audit found the field ") + values::findingName(found->verdict) +
                                     ", so every block is evaluated";
            } else {
                options.lipschitz = std::max(1.0f, 1.25f * found->lipschitzMax);
                char text[160];
                std::snprintf(text, sizeof text, "audit estimate: 1.25 x largest quotient %.3g, at least 1 (%.2f s)",
                              double(found->lipschitzMax), found->seconds);
                report.boundSource = text;
            }
        }
    } else if (!request.lipschitz) {
        options.estimateLipschitz = true;
        report.boundSource = "estimated: 1.25 x the steepest |grad f| at the block centres, at least 1";
    }
    if (request.lipschitz) {
        options.lipschitz = *request.lipschitz;
        report.boundSource = *request.lipschitz > 0.0f ? "given (--lipschitz)" : "none: every block evaluated (--lipschitz 0)";
    }
    report.fieldVerdict = verdict;
    auto extracted = meshing::extractMesh(sdf->prepared, options, progress);
    if (progress.isCancelled()) return JobError{Failure::Cancelled, "mesh: cancelled; nothing written", {}, {}};
    if (!extracted) return workError(extracted.error().keyed());
    MeshedSdf result{std::move(extracted->first), {}};
    const meshing::Mesh& mesh = result.mesh;
    const meshing::MeshStats& stats = extracted->second;
    report.lipschitzBound = stats.lipschitzUsed;
    if (mesh.indices.empty()) {
        const std::string why = noSurfaceReason(sdf->prepared, sdf->parameters);
        return workError("mesh: " + sdf->label + " has no surface inside the bounds at resolution " +
                         std::to_string(request.resolution) + (why.empty() ? "" : ": " + why) + "; nothing written");
    }
    report.vertices = mesh.vertices.size();
    report.triangles = mesh.triangleCount();
    const auto topologyStart = std::chrono::steady_clock::now();
    // A refined mesh's topology came with it (the coarse mesh checked, the subdivision's counts).
    const meshing::Topology topology = stats.topology ? *stats.topology : meshing::checkTopology(mesh);
    for (const auto& [name, seconds] : stats.phaseSeconds) report.phaseSeconds.push_back({name, seconds});
    report.phaseSeconds.push_back(
        {"topology", std::chrono::duration<double>(std::chrono::steady_clock::now() - topologyStart).count()});
    report.boundaryEdges = topology.boundaryEdges;
    report.nonManifoldEdges = topology.nonManifoldEdges;
    report.degenerateTriangles = topology.degenerateTriangles;
    report.nonManifoldVertices = topology.nonManifoldVertices;
    report.misorientedEdges = topology.misorientedEdges;
    report.manifold = topology.manifold();
    report.watertight = topology.watertight();
    report.blocks = stats.blocks;
    report.blocksKept = stats.blocksKept;
    report.blocksGrown = stats.blocksGrown;
    report.pointsEvaluated = stats.pointsEvaluated;
    report.clampedVertices = stats.clampedVertices;
    report.verticesBesideTheirCell = stats.verticesBesideTheirCell;
    report.splitFaces = stats.splitFaces;
    report.boundsCutPoints = stats.boundsCutPoints;
    report.collinearFlips = stats.collinearFlips;
    report.foldedQuadsTurned = stats.foldedQuadsTurned;
    report.midpointsKept = stats.midpointsKept;
    if (request.selfIntersections) report.selfIntersections = meshing::countSelfIntersections(mesh);
    report.meshSeconds = stats.seconds;
    if (request.errorSamples > 0) {
        meshing::ErrorOptions errorOptions;
        errorOptions.meshPoints = errorOptions.surfacePoints = request.errorSamples;
        errorOptions.seed = request.seed;
        errorOptions.time = request.time;
        errorOptions.parameters = sdf->parameters;
        errorOptions.fieldIsExact = verdict == values::Finding::Exact;
        if (stats.boundsCutPoints > 0) errorOptions.cut = meshing::cutBox(options);
        auto error = meshing::measureError(sdf->prepared, mesh, errorOptions);
        if (!error) return workError(error.error().keyed());
        report.meshToSurfaceMean = error->meshToSurfaceMean;
        report.meshToSurfaceMax = error->meshToSurfaceMax;
        report.surfaceToMeshMean = error->surfaceToMeshMean;
        report.surfaceToMeshMax = error->surfaceToMeshMax;
        report.hausdorff = error->hausdorff;
        report.meshToSurfaceMethod = error->meshToSurfaceMethod;
        report.errorPoints = error->meshPoints + error->surfacePoints;
        report.errorSeconds = error->seconds;
    }
    report.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    result.report = std::move(report);
    return result;
}

JobResult<values::MeshReport> run(const values::MeshRequest& request, const ProgressSink& progress) {
    const auto start = std::chrono::steady_clock::now();
    if (auto error = validate(request)) return *error;
    auto meshed = meshSdf(request, progress);
    if (!meshed) return meshed.error;
    std::vector<std::string> comments;
    if (!meshed->report.meshSource.json.empty()) comments.push_back("sdfwb_mesh_source " + meshed->report.meshSource.json);
    const auto writeStart = std::chrono::steady_clock::now();
    if (auto written = meshing::writeMesh(request.output, meshed->mesh, comments); !written)
        return workError(written.error().keyed());
    values::MeshReport report = meshed->report;
    report.phaseSeconds.push_back(
        {"write", std::chrono::duration<double>(std::chrono::steady_clock::now() - writeStart).count()});
    report.output = request.output;
    report.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return report;
}

} // namespace sdfwb::jobs

namespace sdfwb::jobs {

std::optional<JobError> validate(const values::EvalRequest& request) {
    if (request.mesh.empty()) return usageError(key("mesh") + ": no mesh file given");
    std::error_code ec;
    if (!std::filesystem::is_regular_file(request.mesh, ec))
        return usageError(key("mesh") + ": '" + request.mesh + "': no such file");
    if (request.points < 100 || request.points > 10000000) return usageError(key("points") + ": must be 100..10000000");
    if (!(request.tau > 0.0f) || !std::isfinite(request.tau)) return usageError(key("tau") + ": must be a positive number");
    if (request.occupancyResolution < 0 || request.occupancyResolution > 512)
        return usageError(key("occupancy_resolution") + ": must be 0..512 (0: no IoU)");
    if (!(request.edgeRadius >= 0.0f) || !std::isfinite(request.edgeRadius))
        return usageError(key("edge_radius") + ": must be 0 (no edge measures) or a positive number");
    if (!(request.edgeAngle > 0.0f && request.edgeAngle < 180.0f))
        return usageError(key("edge_angle") + ": must be between 0 and 180 degrees");
    if (auto error = checkBoundsAndTime(request.boundsMin, request.boundsMax, request.time)) return error;
    values::ParamsRequest sdfOnly{request.sdf};
    return validate(sdfOnly);
}

JobResult<values::EvalReport> run(const values::EvalRequest& request, const ProgressSink&) {
    const auto start = std::chrono::steady_clock::now();
    if (auto error = validate(request)) return *error;
    auto mesh = meshing::readMesh(request.mesh);
    if (!mesh) return workError("grade: " + mesh.error().message);
    auto sdf = openSdf(request.sdf, "grade");
    if (!sdf) return sdf.error;
    meshing::EvalOptions options;
    options.points = request.points;
    options.tau = request.tau;
    options.occupancyResolution = request.occupancyResolution;
    options.edgeRadius = request.edgeRadius;
    options.edgeAngleDegrees = request.edgeAngle;
    options.boundsMin = request.boundsMin;
    options.boundsMax = request.boundsMax;
    options.seed = request.seed;
    options.time = request.time;
    options.parameters = sdf->parameters;
    auto e = meshing::evaluateMesh(sdf->prepared, *mesh, options);
    if (!e) return workError(e.error().keyed());
    values::EvalReport report;
    sdf->describe(report);
    report.mesh = request.mesh;
    report.vertices = mesh->vertices.size();
    report.triangles = mesh->triangleCount();
    report.closed = e->closed;
    report.meshPoints = e->meshPoints;
    report.surfacePoints = e->surfacePoints;
    report.occupancyPoints = e->occupancyPoints;
    report.accuracyMean = e->accuracyMean;
    report.accuracyMax = e->accuracyMax;
    report.completenessMean = e->completenessMean;
    report.completenessMax = e->completenessMax;
    report.chamferL1 = e->chamferL1;
    report.chamferL2 = e->chamferL2;
    report.normalConsistency = e->normalConsistency;
    report.tau = e->tau;
    report.precision = e->precision;
    report.recall = e->recall;
    report.fscore = e->fscore;
    report.hausdorff = e->hausdorff;
    report.iou = e->iou;
    report.edgeRadius = request.edgeRadius;
    report.edgeAngle = request.edgeAngle;
    if (e->edges) {
        const meshing::EdgeEvaluation& edges = *e->edges;
        report.edges =
            values::EvalEdges{edges.chamferL1,    edges.fscore,           edges.precision,  edges.recall,       edges.hausdorff,
                              edges.accuracyMean, edges.completenessMean, edges.meshPoints, edges.surfacePoints};
    }
    report.conventions =
        "accuracy: mesh points (by area) -> |f|, the exact distance for an exact field; completeness: exact-surface points -> "
        "nearest triangle; chamfer_l1 = (mean accuracy + mean completeness) / 2, not squared; chamfer_l2 = the same of squared "
        "distances; F-score at tau from both shares within tau; normal consistency = mean |cos| of face normal and field "
        "gradient over both point sets; IoU on the centres of an n^3 grid, mesh inside by ray parity; no normalisation (the "
        "SDF's units); edges: the same over the points of either set near a crease of the exact field (its normal turns by "
        "more than edge_angle degrees within edge_radius in the tangent plane), null when the exact surface has none";
    report.parameters = shaders::valuesOf(sdf->parameters);
    if (!e->closed && e->iou)
        report.warnings.push_back("the mesh has boundary edges: its inside (and the IoU) is not well defined");
    report.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return report;
}

} // namespace sdfwb::jobs
