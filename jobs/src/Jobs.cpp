// The shared steps of every job: opening the SDF and the pure checks of each request.
#include <jobs/Jobs.h>

#include "FieldFrame.h"

#include <core/Log.h>
#include <core/Paths.h>
#include <core/TextFile.h>
#include <dataset/Catalogue.h>
#include <meshfield/MeshField.h>
#include <renderer/ImageIO.h>
#include <sampling/SampleFile.h>
#include <sampling/Sampler.h>
#include <shaders/Parameters.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <variant>

namespace sdfwb::jobs {
namespace fs = std::filesystem;

namespace {

std::string formatLevel(float level) {
    char text[32];
    std::snprintf(text, sizeof text, "%.9g", double(level));
    return text;
}

JobError usage(const KeyedText& message) { return usageError(message); }

// Resolves `input.sdf` to a file; with source text a name that is not a file is kept as a label.
// Its errors are about the key 'sdf'.
Expected<fs::path> resolve(const values::SdfInput& input) {
    if (!input.source.empty()) {
        std::error_code ec;
        if (input.sdf.empty()) return fs::path();
        if (fs::is_regular_file(input.sdf, ec)) return fs::path(input.sdf);
        auto path = dataset::resolveSdfArgument(input.sdf, paths::datasetRoot());
        return path ? *path : fs::path(input.sdf);
    }
    if (input.sdf.empty()) return makeError(key("sdf") + ": no SDF given (a dataset name or a path to a .glsl file)");
    auto path = dataset::resolveSdfArgument(input.sdf, paths::datasetRoot());
    if (!path) return makeError(key("sdf") + ": " + path.error().message);
    return *path;
}

std::optional<JobError> checkSdf(const values::SdfInput& input) {
    if (!input.entry.empty()) {
        std::string lower;
        for (char c : input.entry) lower += char(std::tolower(static_cast<unsigned char>(c)));
        bool identifier = !input.entry.empty() && !std::isdigit(static_cast<unsigned char>(input.entry[0]));
        for (char c : input.entry) identifier = identifier && (std::isalnum(static_cast<unsigned char>(c)) || c == '_');
        if (!identifier) return usage(key("entry") + ": expected a GLSL function name, got '" + input.entry + "'");
        if (lower == "main" || lower.rfind("gl_", 0) == 0 || lower.rfind("sdfwb_", 0) == 0)
            return usage(key("entry") + ": '" + input.entry + "' is reserved (main, gl_*, sdfwb_*): name your own function");
    }
    if (input.channels.size() > std::size_t(shaders::kShadertoyChannels))
        return usage(key("channels") + ": Shadertoy has iChannel0 to iChannel3, got " + std::to_string(input.channels.size()) +
                     " channels");
    for (std::size_t n = 0; n < input.channels.size(); ++n) {
        if (input.channels[n].empty()) continue;
        const std::string what = "--channel " + std::to_string(n) + "=" + input.channels[n] + ": ";
        std::error_code ec;
        if (!fs::is_regular_file(input.channels[n], ec)) return usage(what + "no such file");
        if (auto image = renderer::readImage(input.channels[n]); !image) return usage(what + image.error().message);
    }
    if (isFrameBox(input.normalize)) {
        if (auto problem = frameBoxProblem(input.normalize)) return usage(key("normalize") + ": " + *problem);
    } else if (!input.normalize.empty() && input.normalize != "none" && input.normalize != "unit-cube" &&
               input.normalize != "unit-sphere") {
        return usage(key("normalize") + ": expected none, unit-cube, unit-sphere or a box X0,Y0,Z0,X1,Y1,Z1, got '" +
                     input.normalize + "'");
    } else if (auto mesh = meshfield::parseMeshFieldOptions(input.sign, input.normalize); !mesh) {
        return usage(keyedSubject(mesh.error().message));
    }
    if (!std::isfinite(input.level)) return usage(key("level") + ": must be a finite number");
    for (const shaders::ParameterValue& p : input.params) {
        // The text form checks the name and the values (1 to 4 finite numbers).
        if (auto ok = shaders::parseParameterValue(shaders::formatParameterValue(p)); !ok || !(*ok == p))
            return usage(key("params") + ": '" + shaders::formatParameterValue(p) +
                         "': expected NAME=VALUE with 1 to 4 finite numbers");
        for (const shaders::ParameterValue& other : input.params)
            if (&other != &p && other.name == p.name) return usage(key("params") + ": '" + p.name + "' is given twice");
    }
    if (auto path = resolve(input); !path) return usage(path.error().keyed());
    return std::nullopt;
}

std::optional<JobError> checkFamily(const values::FamilySpec& family) {
    if (family.randomize > 100000) return usage(key("randomize") + ": at most 100000 instances");
    if (family.randomize > 0 && !family.sweeps.empty())
        return usage(key("sweep") + " and " + key("randomize") + " cannot be combined");
    std::uint64_t total = 1;
    for (const shaders::ParameterSweep& sweep : family.sweeps) {
        if (auto ok = shaders::parseParameterSweep(shaders::formatParameterSweep(sweep)); !ok || !(*ok == sweep))
            return usage(key("sweep") + ": '" + shaders::formatParameterSweep(sweep) + "': expected NAME=FROM:TO:COUNT");
        total *= std::uint64_t(sweep.count);
        if (total > 100000) return usage(key("sweep") + ": more than 100000 instances in the grid");
    }
    return std::nullopt;
}

std::optional<JobError> checkOutputFolder(const std::string& output) {
    if (output.empty()) return usage(key("output") + ": no output file given");
    fs::path folder = fs::path(output).parent_path().empty() ? fs::path(".") : fs::path(output).parent_path();
    std::error_code ec;
    if (!fs::is_directory(folder, ec))
        return usage(key("output") + ": '" + output + "': folder '" + folder.string() + "' does not exist");
    return std::nullopt;
}

bool inRange(double value, double low, double high) { return std::isfinite(value) && value >= low && value <= high; }

std::string text(double value) {
    char buffer[32];
    std::snprintf(buffer, sizeof buffer, "%g", value);
    return buffer;
}

std::optional<JobError> checkFrame(const values::FrameRequest& frame) {
    if (frame.width < 1 || frame.height < 1 || frame.width > 16384 || frame.height > 16384)
        return usage(keys({"width", "height"}) + ": expected WxH with integers from 1 to 16384, got '" +
                     std::to_string(frame.width) + "x" + std::to_string(frame.height) + "'");
    if (!std::isfinite(frame.time)) return usage(key("time") + ": expected a finite number");
    if (!inRange(frame.camera.fovYDegrees, 1.0, 179.0))
        return usage(key("camera.fov") + ": must be 1..179, got " + text(frame.camera.fovYDegrees));
    if (frame.trace.maxSteps < 1 || frame.trace.maxSteps > 100000)
        return usage(key("trace.max_steps") + ": must be 1..100000, got " + std::to_string(frame.trace.maxSteps));
    if (!inRange(frame.trace.stepFactor, 0.01, 2.0))
        return usage(key("trace.step_factor") + ": must be 0.01..2, got " + text(frame.trace.stepFactor));
    if (!inRange(frame.trace.overRelaxation, 1.0, 1.95))
        return usage(key("trace.over_relaxation") + ": must be 1..1.95, got " + text(frame.trace.overRelaxation));
    if (!inRange(frame.trace.epsilonScale, 1e-6, 100.0)) return usage(key("trace.epsilon_scale") + ": must be 1e-6..100");
    if (frame.trace.coneTile < 0 || frame.trace.coneTile > 64)
        return usage(key("trace.cone_tile") + ": must be 0..64 pixels (0: no cone pass), got " +
                     std::to_string(frame.trace.coneTile));
    if (!inRange(frame.plane.contourSpacing, 1e-5, 10.0))
        return usage(key("plane.contour_spacing") + ": must be 1e-5..10, got " + text(frame.plane.contourSpacing));
    if (frame.plane.enabled && frame.plane.normal == glm::vec3(0.0f))
        return usage(key("plane") + ": expected NX,NY,NZ,OFFSET with a non-zero normal");
    for (float c : {frame.camera.position.x, frame.camera.position.y, frame.camera.position.z, frame.camera.target.x,
                    frame.camera.target.y, frame.camera.target.z, frame.plane.offset})
        if (!std::isfinite(c))
            return usage(key("camera.position") + "/" + key("camera.target") + "/" + key("plane") + ": expected finite numbers");
    if (frame.shading.markers.size() > 16) return usage(key("shading.markers") + ": at most 16 points");
    for (float c : {frame.shading.background.r, frame.shading.background.g, frame.shading.background.b})
        if (!std::isfinite(c) || c < 0.0f) return usage(key("shading.background") + ": expected finite values >= 0");
    if (!frame.shading.backgroundImage.empty() && !fs::is_regular_file(frame.shading.backgroundImage))
        return usage(key("shading.background_image") + ": '" + frame.shading.backgroundImage + "': no such file");
    return checkSdf(frame.sdf);
}

} // namespace

JobError usageError(const KeyedText& message) { return {Failure::Usage, message.text(), {}, message.keys()}; }
JobError workError(const KeyedText& message) { return {Failure::Work, message.text(), {}, message.keys()}; }

values::MeshSource OpenedSdf::meshSource() const {
    return prepared.mesh ? values::MeshSource{prepared.mesh->provenanceJson()} : values::MeshSource{};
}

void OpenedSdf::describe(values::SdfHeader& report) const {
    report = values::SdfHeader{label, prepared.signature.entry, meshSource(), warnings};
}

renderer::FileMetadata OpenedSdf::fileMetadata() const {
    if (!prepared.mesh) return {};
    return {{"sdfwb_mesh_source", prepared.mesh->provenanceJson()}};
}

JobResult<OpenedSdf> openSdf(const values::SdfInput& input, const std::string& what) {
    if (!std::isfinite(input.level)) return usage(key("level") + ": must be a finite number"); // callers that skip checkSdf
    auto path = resolve(input);
    if (!path) return usage(path.error().keyed());
    shaders::IncludeOptions options;
    options.libraryRoots = {paths::shaderLibraryRoot(), paths::datasetRoot()};
    shaders::PreparedSdf sdf;
    const bool mesh = !path->empty() && meshfield::isMeshPath(*path);
    if (!mesh && !input.sign.empty())
        return usage(key("sign") + ": applies to mesh files (.obj .ply .stl .off .glb), not '" + path->string() + "'");
    if (mesh && input.level != 0.0f)
        return usage(key("level") + ": sets the surface of a GLSL field; a mesh's surface is its triangles");
    if (mesh && isFrameBox(input.normalize))
        return usage(key("normalize") + ": a box frames a GLSL field; a mesh takes none, unit-cube or unit-sphere");
    if (mesh) {
        auto meshOptions = meshfield::parseMeshFieldOptions(input.sign, input.normalize);
        if (!meshOptions) return usage(keyedSubject(meshOptions.error().message));
        const meshfield::MeshFieldOptions& options = *meshOptions;
        auto field = meshfield::loadMeshField(*path, options);
        if (!field) return workError(what + ": " + field.error().message);
        log::info(what, (*field)->summary());
        if (options.normalize == meshfield::Normalization::None && !(*field)->bounds.insideUnitBox())
            log::warning(what, path->string() + ": the mesh reaches beyond [-1, 1]^3, the default box; --normalize unit-cube "
                                                "or unit-sphere scales it into the box");
        sdf = shaders::prepareMeshSdf(std::move(*field), *path, input.source, input.entry);
    } else if (!input.source.empty()) {
        const std::string name = path->empty() ? std::string("<source>") : path->filename().string();
        sdf = shaders::prepareSdf(input.source, name, *path, options, input.entry);
    } else {
        sdf = shaders::prepareSdfFile(*path, options, input.entry);
    }
    const std::string label = path->empty() ? std::string("<source>") : path->string();
    for (std::size_t n = 0; n < input.channels.size() && n < sdf.channels.size(); ++n) sdf.channels[n] = input.channels[n];
    if (!sdf.ok())
        return JobError{Failure::Work,
                        what + ": " + label + " has errors" + (what == "audit" ? "" : "; nothing written"),
                        sdf.diagnostics,
                        {}};
    if (!sdf.host.empty()) log::info(what, label + ": read as " + shaders::hostDescription(sdf.host));
    if (sdf.entrySource == shaders::EntrySource::March) log::info(what, label + ": entry automatic: " + sdf.entryReason);
    for (const shaders::Diagnostic& d : sdf.diagnostics)
        if (d.severity == shaders::Severity::Warning) log::warning(what, shaders::formatDiagnostic(d));
    auto resolved = shaders::resolveParameters(sdf.parameters, input.params);
    if (!resolved) return usage(key("params") + ": " + label + ": " + resolved.error().message);
    for (const std::string& warning : resolved->warnings) log::warning(what, warning);
    if (!mesh) {
        sdf.frame.level = input.level;
        if (input.level != 0.0f) log::info(what, label + ": the surface is where the field equals " + formatLevel(input.level));
        if (auto error = frameField(sdf, input.normalize, resolved->settings, label, what)) return *error;
    }
    // A pasted Shadertoy scene built around its own camera: without a surface in the unit box its
    // pictures are empty and its samples never change sign. Said, not changed: the frame is asked for.
    // With a level given the user has chosen the surface (a thin one may escape the search's lattice).
    if (!mesh && sdf.shadertoyMainImage && (input.normalize.empty() || input.normalize == "none") && input.level == 0.0f) {
        const PastedView view = decidePastedView(sdf, resolved->settings);
        if (!view.floor.empty())
            log::warning(what, label + ": [-1, 1]^3 holds only the plane " + view.floor +
                                   " of this scene; what stands on it lies in the box " + view.box +
                                   ": --normalize unit-cube frames it (or --normalize " + view.box + ")");
        else if (!view.box.empty())
            log::warning(what, label +
                                   (view.cut ? ": [-1, 1]^3 cuts the scene; it lies whole in the box "
                                             : ": the field has no surface in [-1, 1]^3; it lies in the box ") +
                                   view.box + ": --normalize unit-cube frames it (or --normalize " + view.box + ")");
        else if (!view.noSurface.empty())
            log::warning(what, label + ": " + view.noSurface);
    }
    return OpenedSdf{std::move(sdf), label, std::move(resolved->settings), std::move(resolved->warnings)};
}

std::optional<JobError> validate(const values::RenderRequest& request) {
    if (auto error = checkFrame(request.frame)) return error;
    const std::string extension = fs::path(request.output).extension().string();
    auto writable = renderer::canWriteImageExtension(extension);
    if (!writable) return workError(key("output") + ": '" + request.output + "': " + writable.error().message);
    if (!*writable)
        return usage(key("output") + ": '" + request.output + "': unsupported image type '" + extension +
                     "' (use .png, .jpg or .exr)");
    return checkOutputFolder(request.output);
}

std::optional<JobError> validate(const values::ProbeRequest& request) {
    if (auto error = checkFrame(request.frame)) return error;
    if (request.x < 0 || request.y < 0 || request.x >= request.frame.width || request.y >= request.frame.height)
        return usage(keys({"x", "y"}) + ": " + std::to_string(request.x) + "," + std::to_string(request.y) +
                     " lies outside the " + std::to_string(request.frame.width) + "x" + std::to_string(request.frame.height) +
                     " frame");
    return std::nullopt;
}

std::optional<JobError> validate(const values::AnimateRequest& request) {
    if (auto error = checkFrame(request.frame)) return error;
    if (fs::path(request.output).extension() != ".mp4")
        return usage(key("output") + ": '" + request.output + "': animations are written as .mp4 (H.264)");
    if (!(request.seconds > 0.0f) || request.seconds > 3600.0f) return usage(key("seconds") + ": must be in (0, 3600]");
    if (request.framesPerSecond < 1 || request.framesPerSecond > 240) return usage(key("fps") + ": must be 1..240");
    return checkOutputFolder(request.output);
}

sampling::SamplingJob samplingJob(const values::SampleRequest& request) {
    sampling::SamplingJob job;
    job.count = request.count;
    job.seed = request.seed;
    job.time = request.time;
    job.shardIndex = request.shardIndex;
    job.shardCount = request.shardCount;
    job.chunkSize = request.chunkSize;
    job.gradientStep = request.gradientStep > 0.0f ? request.gradientStep : 1e-3f;
    job.meshGradientTaps = request.gradientStep > 0.0f;
    job.surfaceTolerance = request.surfaceTolerance;
    if (auto mixture = nearMixture(request.nearWidths); mixture && !mixture->empty()) {
        float total = 0.0f;
        for (const auto& [width, weight] : *mixture) total += weight;
        float cumulative = 0.0f;
        for (std::size_t c = 0; c < mixture->size(); ++c) {
            cumulative += (*mixture)[c].second / total;
            job.parameters[c] = (*mixture)[c].first;
            job.parameters[4 + c] = c + 1 == mixture->size() ? 1.0f : cumulative;
        }
        job.parameters[8] = request.nearTruncation;
    }
    return job;
}

Expected<std::vector<std::pair<float, float>>> nearMixture(const std::string& text) {
    std::vector<std::pair<float, float>> mixture;
    if (text.empty()) return mixture;
    std::size_t start = 0;
    while (start <= text.size()) {
        const std::size_t end = std::min(text.find(',', start), text.size());
        const std::string item = text.substr(start, end - start);
        const std::size_t colon = item.find(':');
        float width = 0.0f, weight = 1.0f;
        try {
            std::size_t used = 0;
            width = std::stof(item.substr(0, colon), &used);
            if (used != item.substr(0, colon).size()) throw std::invalid_argument(item);
            if (colon != std::string::npos) {
                weight = std::stof(item.substr(colon + 1), &used);
                if (used != item.size() - colon - 1) throw std::invalid_argument(item);
            }
        } catch (const std::exception&) {
            return makeError(key("near_widths") + ": '" + item + "' is not WIDTH or WIDTH:WEIGHT (e.g. 0.005:0.8,0.05:0.2)");
        }
        if (!(width > 0.0f) || !std::isfinite(width) || !(weight > 0.0f) || !std::isfinite(weight))
            return makeError(key("near_widths") + ": '" + item + "': widths and weights must be positive");
        mixture.emplace_back(width, weight);
        start = end + 1;
    }
    if (mixture.size() > 4)
        return makeError(key("near_widths") + ": at most 4 components, got " + std::to_string(mixture.size()));
    return mixture;
}

std::optional<JobError> validate(const values::SampleRequest& request) {
    if (request.pattern.empty()) return usage(key("pattern") + ": no sampling pattern given");
    if (!std::isfinite(request.time)) return usage(key("time") + ": expected a finite number");
    if (!(request.gradientStep >= 0.0f) || !std::isfinite(request.gradientStep))
        return usage(key("gradient_step") + ": must be positive (or 0: the default)");
    if (!(request.surfaceTolerance > 0.0f) || !std::isfinite(request.surfaceTolerance))
        return usage(key("surface_tolerance") + ": must be positive");
    if (request.shardCount == 0 || request.shardIndex >= request.shardCount)
        return usage(keys({"shard_index", "shard_count"}) + ": expected K/COUNT with 0 <= K < COUNT, got '" +
                     std::to_string(request.shardIndex) + "/" + std::to_string(request.shardCount) + "'");
    if (auto mixture = nearMixture(request.nearWidths); !mixture) return usage(mixture.error().keyed());
    if (!request.nearWidths.empty() && request.pattern != "near")
        return usage(key("near_widths") + ": only the near pattern takes widths (the pattern is '" + request.pattern + "')");
    if (!(request.nearTruncation >= 0.0f) || !std::isfinite(request.nearTruncation))
        return usage(key("near_truncation") + ": expected 0 (none) or a positive number of standard deviations");
    if (request.nearTruncation > 0.0f && request.nearWidths.empty())
        return usage(key("near_truncation") + ": needs " + key("near_widths"));
    if (auto error = checkFamily(request.family)) return error;
    if (!request.family.empty() && request.shardCount > 1)
        return usage(keys({"shard_index", "shard_count"}) + " cannot be combined with " + key("sweep") + " or " +
                     key("randomize"));
    const sampling::SamplingJob job = samplingJob(request);
    if (auto ok = sampling::validate(job); !ok) return usage(ok.error().keyed());
    if (!request.output.empty()) {
        std::optional<sampling::SampleFormat> format =
            request.format.empty() ? sampling::formatFromPath(request.output) : sampling::parseFormat(request.format);
        if (!format)
            return usage(request.format.empty()
                             ? key("output") + ": '" + request.output +
                                   "': unknown sample file type (use .bin, .npz or .ply, or " + key("format") + ")"
                             : key("format") + ": unknown format '" + request.format + "' (bin, npz, ply)");
        if (job.rows() > sampling::maxRows(*format))
            return usage(key("n") + ": " + std::to_string(job.rows()) + " rows exceed the ." + sampling::formatName(*format) +
                         " limit of " + std::to_string(sampling::maxRows(*format)));
        if (auto error = checkOutputFolder(request.output)) return error;
    }
    return checkSdf(request.sdf);
}

std::optional<JobError> validate(const values::AuditRequest& request) {
    if (request.samples < 64 || request.samples > 100000000) return usage(key("samples") + ": must be 64..100000000");
    if (!std::isfinite(request.time)) return usage(key("time") + ": expected a finite number");
    if (!inRange(request.truncationReach, 0.1, 100.0)) return usage(key("truncation_reach") + ": must be 0.1..100");
    if (request.resolution < 2 || request.resolution > 4096) return usage(key("resolution") + ": must be 2..4096");
    if (request.plane) {
        const values::PlaneSpec& plane = *request.plane;
        if (plane.normal == glm::vec3(0.0f) || !std::isfinite(plane.offset) || !std::isfinite(plane.normal.x) ||
            !std::isfinite(plane.normal.y) || !std::isfinite(plane.normal.z))
            return usage(key("plane") + ": expected NX,NY,NZ,OFFSET with a non-zero normal");
    }
    if (auto error = checkFamily(request.family)) return error;
    if (!request.family.empty() && request.plane)
        return usage(key("plane") + " cannot be combined with " + key("sweep") + " or " + key("randomize"));
    return checkSdf(request.sdf);
}

std::optional<JobError> validate(const values::MergeRequest& request) {
    std::optional<sampling::SampleFormat> format =
        request.format.empty() ? sampling::formatFromPath(request.output) : sampling::parseFormat(request.format);
    if (!format)
        return usage(request.format.empty() ? key("output") + ": '" + request.output +
                                                  "': unknown sample file type (use .bin, .npz or .ply, or " + key("format") + ")"
                                            : key("format") + ": unknown format '" + request.format + "' (bin, npz, ply)");
    if (request.parts.empty()) return usage(key("parts") + ": no shard files given");
    return std::nullopt;
}

std::optional<JobError> validate(const values::ParamsRequest& request) { return checkSdf(request.sdf); }

JobResult<values::ParamsReport> run(const values::ParamsRequest& request, const ProgressSink&) {
    if (auto error = validate(request)) return *error;
    auto path = resolve(request.sdf);
    if (!path) return usage(path.error().keyed());
    const std::string label = path->empty() ? std::string("<source>") : path->string();
    std::string text = request.sdf.source;
    if (text.empty()) {
        auto read = readTextFile(*path);
        if (!read) return workError(read.error().keyed());
        text = std::move(*read);
    }
    shaders::ParameterScan scan = shaders::parseParameters(text, label);
    if (shaders::hasErrors(scan.diagnostics))
        return JobError{Failure::Work, "params: " + label + " declares parameters with errors", scan.diagnostics, {}};
    values::ParamsReport report;
    report.sdf = label;
    for (const shaders::Diagnostic& d : scan.diagnostics) report.warnings.push_back(shaders::formatDiagnostic(d));
    for (const shaders::Parameter& p : scan.parameters) {
        values::ParamItem item;
        item.name = p.name;
        item.type = shaders::parameterTypeName(p.type);
        item.value.assign(p.defaultValue.begin(), p.defaultValue.begin() + shaders::componentCount(p.type));
        item.minimum = p.minimum;
        item.maximum = p.maximum;
        item.step = p.step;
        item.logarithmic = p.logarithmic;
        item.color = p.color;
        item.label = p.label;
        item.line = p.line;
        item.column = p.column;
        report.parameters.push_back(std::move(item));
    }
    return report;
}

std::optional<JobError> validate(const values::BenchRequest& request) {
    if (request.repeats < 1 || request.repeats > 100) return usage(key("repeats") + ": must be 1..100");
    if (request.outputDirectory.empty()) return usage(key("output") + ": no report folder given");
    return std::nullopt;
}

} // namespace sdfwb::jobs
