#pragma once
// Every request and report field's name, once: `fields(v, s)` hands each member of `s` to `v`
// under its JSON key, in the order the JSON shows them. JobJson.cpp's writer and reader are the
// visitors (the JSON form, and its errors' key paths). Included by JobJson.cpp only.

#include <jobs/JobJson.h>
#include <jobs/Protocol.h>

namespace sdfwb::jobs::detail {

template <class V> void fields(V& v, values::SdfInput& s) {
    v("sdf", s.sdf);
    v("entry", s.entry);
    v("source", s.source);
    v("params", s.params);
    v("channels", s.channels);
    v("sign", s.sign);
    v("normalize", s.normalize);
    v("level", s.level);
}

template <class V> void fields(V& v, values::ShadingSettings& s) {
    v("mode", s.mode);
    v("ambient_occlusion", s.ambientOcclusion);
    v("background", s.background);
    v("light_direction", s.lightDirection);
    v("curvature_scale", s.curvatureScale);
    v("matcap", s.matcap);
    v("background_image", s.backgroundImage);
    v("markers", s.markers);
}

template <class V> void fields(V& v, values::TraceSettings& t) {
    v("max_steps", t.maxSteps);
    v("step_factor", t.stepFactor);
    v("epsilon_scale", t.epsilonScale);
    v("box_margin", t.boxMargin);
    v("over_relaxation", t.overRelaxation);
    v("cones", t.cones);
    v("cone_tile", t.coneTile);
    v("tracer", t.tracer);
}

template <class V> void fields(V& v, values::Camera& c) {
    v("position", c.position);
    v("target", c.target);
    v("up", c.up);
    v("fov", c.fovYDegrees);
    v("near", c.nearPlane);
    v("far", c.farPlane);
}

template <class V> void fields(V& v, values::CuttingPlane& p) {
    v("enabled", p.enabled);
    v("normal", p.normal);
    v("offset", p.offset);
    v("contour_spacing", p.contourSpacing);
    v("ramp_distance", p.rampDistance);
    v("clip_surface", p.clipSurface);
    v("lipschitz_overlay", p.lipschitzOverlay);
}

template <class V> void fields(V& v, values::FrameRequest& f) {
    fields(v, f.sdf);
    v("width", f.width);
    v("height", f.height);
    v("time", f.time);
    v("shading", f.shading);
    v("trace", f.trace);
    v("camera", f.camera);
    v("plane", f.plane);
    v("overlay", f.overlay);
}

template <class V> void fields(V& v, values::RenderRequest& r) {
    fields(v, r.frame);
    v("output", r.output);
    v("shadertoy_picture", r.shadertoyPicture);
}

template <class V> void fields(V& v, values::AnimateRequest& r) {
    fields(v, r.frame);
    v("output", r.output);
    v("seconds", r.seconds);
    v("fps", r.framesPerSecond);
    v("turntable", r.turntable);
    v("params_end", r.paramsEnd);
}

template <class V> void fields(V& v, values::SampleRequest& r) {
    fields(v, r.sdf);
    v("pattern", r.pattern);
    v("n", r.count);
    v("output", r.output);
    v("format", r.format);
    v("seed", r.seed);
    v("time", r.time);
    v("shard_index", r.shardIndex);
    v("shard_count", r.shardCount);
    v("chunk", r.chunkSize);
    v("gradient_step", r.gradientStep);
    v("surface_tolerance", r.surfaceTolerance);
    v("near_widths", r.nearWidths);
    v("near_truncation", r.nearTruncation);
    v("sweep", r.family.sweeps);
    v("randomize", r.family.randomize);
}

// A key that was renamed: written under its new name, read under either (the new one wins).
template <class V, class T> void renamed(V& v, const char* key, const char* oldKey, T& value) {
    if constexpr (requires { v.in.contains(key); })
        if (v.in.is_object() && !v.in.contains(key) && v.in.contains(oldKey)) return v(oldKey, value);
    v(key, value);
}

template <class V> void fields(V& v, values::AuditRequest& r) {
    fields(v, r.sdf);
    v("samples", r.samples);
    v("seed", r.seed);
    v("time", r.time);
    renamed(v, "truncation_reach", "probe_distance", r.truncationReach); // "probe_distance": the old name
    v("plane", r.plane);
    v("resolution", r.resolution);
    v("sweep", r.family.sweeps);
    v("randomize", r.family.randomize);
}

template <class V> void fields(V& v, values::MergeRequest& r) {
    v("output", r.output);
    v("format", r.format);
    v("parts", r.parts);
}

template <class V> void fields(V& v, values::ListRequest& r) { v("report", r.report); }

template <class V> void fields(V& v, values::ParamsRequest& r) { fields(v, r.sdf); }

template <class V> void fields(V& v, values::MeshRequest& r) {
    fields(v, r.sdf);
    v("output", r.output);
    v("resolution", r.resolution);
    v("refine", r.refine);
    v("bounds_min", r.boundsMin);
    v("bounds_max", r.boundsMax);
    v("time", r.time);
    v("lipschitz", r.lipschitz);
    v("error_samples", r.errorSamples);
    v("seed", r.seed);
    v("self_intersections", r.selfIntersections);
}

template <class V> void fields(V& v, values::EvalRequest& r) {
    fields(v, r.sdf);
    v("mesh", r.mesh);
    v("points", r.points);
    v("tau", r.tau);
    v("occupancy_resolution", r.occupancyResolution);
    v("edge_radius", r.edgeRadius);
    v("edge_angle", r.edgeAngle);
    v("bounds_min", r.boundsMin);
    v("bounds_max", r.boundsMax);
    v("time", r.time);
    v("seed", r.seed);
}

template <class V> void fields(V& v, values::RunRequest& r) {
    v("manifest", r.manifest);
    v("status", r.status);
    v("item_timeout", r.itemTimeout);
    v("rank", r.rank);
    v("world_size", r.worldSize);
    v("items", r.items);
    v("list", r.list);
    v("executable", r.executable);
    v("python", r.python);
}

template <class V> void fields(V& v, values::ProbeRequest& r) {
    fields(v, r.frame);
    v("x", r.x);
    v("y", r.y);
}

template <class V> void fields(V& v, values::ProbeStep& s) {
    v("event", s.event);
    v("t", s.t);
    v("position", s.position);
    v("f", s.f);
    v("step", s.step);
    v("gradient_length", s.gradientLength);
    v("overstep", s.overstep);
}

template <class V> void fields(V& v, values::ProbeReport& r) {
    v("sdf", r.sdf);
    v("entry", r.entry);
    v("width", r.width);
    v("height", r.height);
    v("x", r.x);
    v("y", r.y);
    v("origin", r.origin);
    v("direction", r.direction);
    v("outcome", r.outcome);
    v("reason", r.reason);
    v("steps", r.steps);
    v("hit_t", r.hitT);
    v("hit_residual", r.hitResidual);
    v("footprint", r.footprint);
    v("oversteps", r.oversteps);
    v("fallbacks", r.fallbacks);
    v("max_steps", r.maxSteps);
    v("step_factor", r.stepFactor);
    v("over_relaxation", r.overRelaxation);
    v("events", r.events);
    v("dropped", r.dropped);
    v("parameters", r.parameters);
    v("seconds", r.seconds);
    v("mesh_source", r.meshSource);
    v("warnings", r.warnings);
}

template <class V> void fields(V& v, values::RunItemReport& r) {
    v("index", r.index);
    v("line", r.line);
    v("task", r.task);
    v("sdf", r.sdf);
    v("output", r.output);
    v("key", r.key);
    v("status", r.status);
    v("seconds", r.seconds);
    v("bytes", r.bytes);
    v("rows", r.rows);
    v("bad_rows", r.badRows);
    v("exit_code", r.exitCode);
    v("error", r.error);
    v("finished", r.finished);
}

template <class V> void fields(V& v, values::RunReport& r) {
    v("manifest", r.manifest);
    v("status", r.status);
    v("rank", r.rank);
    v("world_size", r.worldSize);
    v("items", r.items);
    v("selected", r.selected);
    v("done", r.done);
    v("skipped", r.skipped);
    v("failed", r.failed);
    v("seconds", r.seconds);
    v("shapes_per_hour", r.shapesPerHour);
    v("bytes_written", r.bytesWritten);
    v("results", r.results);
}

template <class V> void fields(V& v, values::EvalEdges& e) {
    v("chamfer_l1", e.chamferL1);
    v("fscore", e.fscore);
    v("precision", e.precision);
    v("recall", e.recall);
    v("hausdorff", e.hausdorff);
    v("accuracy_mean", e.accuracyMean);
    v("completeness_mean", e.completenessMean);
    v("mesh_points", e.meshPoints);
    v("surface_points", e.surfacePoints);
}

template <class V> void fields(V& v, values::EvalReport& r) {
    v("mesh", r.mesh);
    v("sdf", r.sdf);
    v("entry", r.entry);
    v("vertices", r.vertices);
    v("triangles", r.triangles);
    v("closed", r.closed);
    v("chamfer_l1", r.chamferL1);
    v("chamfer_l2", r.chamferL2);
    v("normal_consistency", r.normalConsistency);
    v("tau", r.tau);
    v("precision", r.precision);
    v("recall", r.recall);
    v("fscore", r.fscore);
    v("hausdorff", r.hausdorff);
    v("iou", r.iou);
    v("edge_radius", r.edgeRadius);
    v("edge_angle", r.edgeAngle);
    v("edges", r.edges);
    v("accuracy_mean", r.accuracyMean);
    v("accuracy_max", r.accuracyMax);
    v("completeness_mean", r.completenessMean);
    v("completeness_max", r.completenessMax);
    v("mesh_points", r.meshPoints);
    v("surface_points", r.surfacePoints);
    v("occupancy_points", r.occupancyPoints);
    v("conventions", r.conventions);
    v("parameters", r.parameters);
    v("mesh_source", r.meshSource);
    v("warnings", r.warnings);
    v("seconds", r.seconds);
}

template <class V> void fields(V& v, values::MeshReport& r) {
    v("output", r.output);
    v("sdf", r.sdf);
    v("entry", r.entry);
    v("resolution", r.resolution);
    v("refine", r.refine);
    v("vertices", r.vertices);
    v("triangles", r.triangles);
    v("boundary_edges", r.boundaryEdges);
    v("non_manifold_edges", r.nonManifoldEdges);
    v("degenerate_triangles", r.degenerateTriangles);
    v("non_manifold_vertices", r.nonManifoldVertices);
    v("misoriented_edges", r.misorientedEdges);
    v("manifold", r.manifold);
    v("watertight", r.watertight);
    v("lipschitz_bound", r.lipschitzBound);
    v("bound_source", r.boundSource);
    v("field_verdict", r.fieldVerdict);
    v("blocks", r.blocks);
    v("blocks_kept", r.blocksKept);
    v("blocks_grown", r.blocksGrown);
    v("points_evaluated", r.pointsEvaluated);
    v("clamped_vertices", r.clampedVertices);
    v("vertices_beside_their_cell", r.verticesBesideTheirCell);
    v("split_faces", r.splitFaces);
    v("bounds_cut_points", r.boundsCutPoints);
    v("collinear_flips", r.collinearFlips);
    v("folded_quads_turned", r.foldedQuadsTurned);
    v("midpoints_kept", r.midpointsKept);
    v("self_intersections", r.selfIntersections);
    v("mesh_seconds", r.meshSeconds);
    v("phase_seconds", r.phaseSeconds);
    v("mesh_to_surface_mean", r.meshToSurfaceMean);
    v("mesh_to_surface_max", r.meshToSurfaceMax);
    v("surface_to_mesh_mean", r.surfaceToMeshMean);
    v("surface_to_mesh_max", r.surfaceToMeshMax);
    v("hausdorff", r.hausdorff);
    v("mesh_to_surface_method", r.meshToSurfaceMethod);
    v("error_points", r.errorPoints);
    v("error_seconds", r.errorSeconds);
    v("parameters", r.parameters);
    v("mesh_source", r.meshSource);
    v("warnings", r.warnings);
    v("seconds", r.seconds);
}

template <class V> void fields(V& v, values::PhaseTime& p) {
    v("name", p.name);
    v("seconds", p.seconds);
}

template <class V> void fields(V& v, values::ParamItem& p) {
    v("name", p.name);
    v("type", p.type);
    v("default", p.value);
    v("minimum", p.minimum);
    v("maximum", p.maximum);
    v("step", p.step);
    v("log", p.logarithmic);
    v("color", p.color);
    v("label", p.label);
    v("line", p.line);
    v("column", p.column);
}

template <class V> void fields(V& v, values::ParamsReport& r) {
    v("sdf", r.sdf);
    v("parameters", r.parameters);
    v("warnings", r.warnings);
}

template <class V> void fields(V& v, values::BenchRequest& r) {
    v("output", r.outputDirectory);
    v("repeats", r.repeats);
    v("quick", r.quick);
    v("no_plots", r.noPlots);
}

template <class V> void fields(V& v, values::RenderReport& r) {
    v("output", r.output);
    v("sdf", r.sdf);
    v("entry", r.entry);
    v("width", r.width);
    v("height", r.height);
    v("shading", r.shading);
    v("frame_ms", r.frameMilliseconds);
    v("seconds", r.seconds);
    v("gl_renderer", r.glRenderer);
    v("mesh_source", r.meshSource);
    v("warnings", r.warnings);
}

template <class V> void fields(V& v, values::AnimateReport& r) {
    v("output", r.output);
    v("sdf", r.sdf);
    v("entry", r.entry);
    v("frames", r.frames);
    v("fps", r.framesPerSecond);
    v("width", r.width);
    v("height", r.height);
    v("render_seconds", r.renderSeconds);
    v("seconds", r.seconds);
    v("mesh_source", r.meshSource);
    v("warnings", r.warnings);
}

template <class V> void fields(V& v, values::SampleReport& r) {
    v("output", r.output);
    v("format", r.format);
    v("sdf", r.sdf);
    v("entry", r.entry);
    v("pattern", r.pattern);
    v("n", r.count);
    v("rows", r.rows);
    v("first_index", r.firstIndex);
    v("seed", r.seed);
    v("time", r.time);
    v("bad_rows", r.badRows);
    v("seconds", r.seconds);
    v("setup_seconds", r.setupSeconds);
    v("samples_per_second", r.samplesPerSecond);
    v("kernel_seconds", r.kernelSeconds);
    v("gl_renderer", r.glRenderer);
    v("parameters", r.parameters);
    v("instances", r.instances);
    v("index", r.index);
    v("mesh_source", r.meshSource);
    v("warnings", r.warnings);
}

template <class V> void fields(V& v, values::SampleInstance& i) {
    v("output", i.output);
    v("parameters", i.parameters);
    v("rows", i.rows);
    v("bad_rows", i.badRows);
    v("seconds", i.seconds);
}

template <class V> void fields(V& v, values::AuditInstance& i) {
    v("parameters", i.parameters);
    v("verdict", i.verdict);
    v("reason", i.reason);
    v("flags", i.flags);
    v("lipschitz", i.lipschitz);
    v("lipschitz_max", i.lipschitzMax);
    v("exactness_error_p99", i.exactnessP99);
    v("seconds", i.seconds);
}

template <class V> void fields(V& v, values::MergeReport& r) {
    v("output", r.output);
    v("rows", r.rows);
    v("parts", r.parts);
    v("seconds", r.seconds);
}

template <class V> void fields(V& v, values::AuditFlag& f) {
    v("flag", f.finding);
    v("evidence", f.evidence);
    v("value", f.value);
    v("maximum", f.maximum);
    v("start", f.start);
    v("share", f.share);
    v("count", f.count);
    v("examples", f.examples);
}

template <class V> void fields(V& v, values::QuotientScale& q) {
    v("scale", q.step);
    v("p50", q.p50);
    v("p99", q.p99);
    v("p999", q.p999);
    v("max", q.max);
}

template <class V> void fields(V& v, values::ConvergencePoint& c) {
    v("samples", c.samples);
    v("lipschitz", c.lipschitz);
    v("exactness_p99", c.exactnessP99);
    v("seconds", c.seconds);
}

template <class V> void fields(V& v, values::AuditReport& r) {
    v("verdict", r.verdict);
    v("reason", r.reason);
    v("flags", r.flags);
    v("lipschitz", r.lipschitz);
    v("lipschitz_max", r.lipschitzMax);
    v("lipschitz_uncertainty", r.lipschitzUncertainty);
    v("safe_step_factor", r.safeStepFactor);
    v("truncation_distance", r.truncationDistance);
    v("nan_fraction", r.nanFraction);
    v("nan_fraction_error", r.nanFractionError);
    v("discontinuities", r.discontinuities);
    v("discontinuity_share", r.discontinuityShare);
    v("eikonal_error_mean", r.eikonalMean);
    v("eikonal_error_p95", r.eikonalP95);
    v("surface_points", r.surfacePoints);
    v("surface_spacing", r.surfaceSpacing);
    v("exactness_error_p99", r.exactnessP99);
    v("exactness_error_max", r.exactnessMax);
    v("overestimate_share", r.overestimateShare);
    v("surface_gradient", r.surfaceGradient);
    v("noise_floor", r.noiseFloor);
    v("scales", r.scales);
    v("convergence", r.convergence);
    v("samples", r.samples);
    v("seconds", r.seconds);
}

template <class V> void fields(V& v, values::PlaneReadout& r) {
    v("resolution", r.resolution);
    v("points", r.points);
    v("minimum", r.minimum);
    v("maximum", r.maximum);
    v("lipschitz_max", r.lipschitzMax);
    v("lipschitz_p99", r.lipschitz99);
    v("share_above_one", r.shareAboveOne);
    v("truncation_distance", r.truncationDistance);
    v("discontinuities", r.discontinuities);
    v("nan_count", r.nanCount);
    v("histogram", r.histogram);
    v("safe_step_factor", r.safeStepFactor);
    v("flags", r.flags);
    v("seconds", r.seconds);
}

template <class V> void fields(V& v, values::ListItem& i) {
    v("name", i.name);
    v("category", i.category);
    v("declared_type", i.declaredType);
    v("animated", i.animated);
    v("path", i.path);
    v("author", i.author);
    v("license", i.license);
    v("notes", i.notes);
    v("measured_type", i.measuredType);
    v("render_ms", i.renderMilliseconds);
}

template <class V> void fields(V& v, values::ListReport& r) {
    v("sdfs", r.items);
    v("problems", r.problems);
    v("root", r.root);
    v("report", r.report);
    v("measured_on", r.measuredOn);
    v("measured_date", r.measuredDate);
}

template <class V> void fields(V& v, values::BenchReport& r) {
    v("markdown", r.markdown);
    v("csv_directory", r.csvDirectory);
    v("image_directory", r.imageDirectory);
    v("plotted", r.plotted);
}

} // namespace sdfwb::jobs::detail
