// sample, merge and list: sample files written through the compute sampler, shards joined, the
// dataset listed.
#include <jobs/Jobs.h>

#include <core/Log.h>
#include <core/Paths.h>
#include <core/TextFile.h>
#include <dataset/Catalogue.h>
#include <jobs/JobJson.h>
#include <renderer/GlInfo.h>
#include <renderer/SampleCompute.h>
#include <sampling/SampleFile.h>
#include <sampling/Sampler.h>
#include <sampling/SamplerLibrary.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>

namespace sdfwb::jobs {

namespace {

// OUTPUT's stem + _00000 (five digits, more when needed) + its extension, in OUTPUT's folder.
std::string instancePath(const std::string& output, std::size_t index, std::size_t count) {
    const std::filesystem::path path(output);
    std::string number = std::to_string(index);
    const std::size_t digits = std::max<std::size_t>(5, std::to_string(count - 1).size());
    number.insert(0, digits - number.size(), '0');
    return (path.parent_path() / (path.stem().string() + "_" + number + path.extension().string())).string();
}

std::string indexPath(const std::string& output) {
    const std::filesystem::path path(output);
    return (path.parent_path() / (path.stem().string() + "_index.json")).string();
}

} // namespace

JobResult<values::SampleReport> run(const values::SampleRequest& request, const ProgressSink& progress) {
    const auto start = std::chrono::steady_clock::now();
    if (auto error = validate(request)) return *error;
    if (request.output.empty()) return usageError(key("output") + ": no output file given");
    auto sampler = sampling::findSampler(request.pattern, sampling::samplerFolders());
    if (!sampler) return usageError(key("pattern") + ": " + sampler.error().message);
    const sampling::SampleFormat format =
        *(request.format.empty() ? sampling::formatFromPath(request.output) : sampling::parseFormat(request.format));
    auto sdf = openSdf(request.sdf, "sample");
    if (!sdf) return sdf.error;
    // The instances to write: one (the request's values), or the family's.
    std::vector<std::vector<shaders::ParameterValue>> instances{request.sdf.params};
    if (!request.family.empty()) {
        auto family = shaders::familyInstances(sdf->prepared.parameters, request.sdf.params, request.family.sweeps,
                                               request.family.randomize, request.seed);
        if (!family)
            return usageError((request.family.randomize ? key("randomize") : key("sweep")) + ": " + family.error().message);
        instances = std::move(*family);
    }
    std::vector<std::vector<shaders::ParameterSetting>> settings;
    values::SampleReport report;
    sdf->describe(report);
    report.sdf = request.sdf.sdf; // the name as given (a sample file's metadata says the same)
    for (const auto& values : instances) {
        auto resolved = shaders::resolveParameters(sdf->prepared.parameters, values);
        if (!resolved) return usageError(key("params") + ": " + sdf->label + ": " + resolved.error().message);
        settings.push_back(std::move(resolved->settings));
    }
    renderer::SampleCompute compute;
    auto diagnostics = compute.build(sdf->prepared, *sampler);
    if (shaders::hasErrors(diagnostics))
        return JobError{Failure::Work,
                        "sample: " + sdf->label + " with pattern '" + request.pattern + "' does not compile; nothing written",
                        diagnostics,
                        {}};
    report.setupSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    sampling::SamplingJob job = samplingJob(request);
    sampling::SampleMetadata metadata;
    metadata.sdf = request.sdf.sdf;
    // The pattern as run: near's mixture and truncation are part of it (e.g. "near 0.005:0.8,0.05:0.2 truncate 3").
    metadata.pattern = request.pattern;
    if (!request.nearWidths.empty()) metadata.pattern += " " + request.nearWidths;
    if (request.nearTruncation > 0.0f) metadata.pattern += " truncate " + std::to_string(request.nearTruncation);
    metadata.version = SDFWB_VERSION;
    metadata.mesh = sdf->meshSource().json;
    if (const shaders::PreparedSdf::Frame& frame = sdf->prepared.frame; !(frame == shaders::PreparedSdf::Frame{})) {
        char numbers[200];
        std::snprintf(numbers, sizeof numbers, "\"centre\": [%.9g, %.9g, %.9g], \"scale\": %.9g, \"level\": %.9g",
                      frame.centre[0], frame.centre[1], frame.centre[2], frame.scale, frame.level);
        metadata.frame = "{\"normalize\": \"" + request.sdf.normalize + "\", " + numbers + "}";
    }
    const bool family = !request.family.empty();
    const std::uint64_t total = job.rows() * instances.size();
    std::vector<std::string> written;
    auto removeWritten = [&] {
        std::error_code ec;
        for (const std::string& path : written) std::filesystem::remove(path, ec);
        if (format == sampling::SampleFormat::Bin)
            for (const std::string& path : written) std::filesystem::remove(path + ".json", ec);
    };
    for (std::size_t k = 0; k < instances.size(); ++k) {
        job.sdfParameters = settings[k];
        metadata.parameters = shaders::parametersJson(settings[k]);
        const std::string output = family ? instancePath(request.output, k, instances.size()) : request.output;
        const std::uint64_t before = job.rows() * k;
        ProgressSink step{progress.report
                              ? ProgressFunction([&](std::uint64_t done, std::uint64_t) { progress(before + done, total); })
                              : ProgressFunction(),
                          progress.cancel};
        auto result = sampling::sampleToFile(compute, job, output, format, metadata, step);
        if (!result) {
            compute.releaseGl();
            removeWritten();
            return workError(result.error().keyed());
        }
        if (result->cancelled) {
            compute.releaseGl();
            removeWritten();
            return JobError{Failure::Cancelled,
                            "sample: cancelled after " + std::to_string(before + result->rows) + " of " + std::to_string(total) +
                                " samples; nothing written",
                            {},
                            {}};
        }
        written.push_back(output);
        report.rows += result->rows;
        report.badRows += result->badRows;
        report.seconds += result->seconds;
        report.kernelSeconds = result->kernelSeconds < 0.0 || (k > 0 && report.kernelSeconds < 0.0)
                                   ? -1.0
                                   : std::max(report.kernelSeconds, 0.0) + result->kernelSeconds;
        report.firstIndex = result->firstIndex;
        if (family)
            report.instances.push_back({output, shaders::valuesOf(settings[k]), result->rows, result->badRows, result->seconds});
        else
            report.parameters = shaders::valuesOf(settings[k]);
    }
    compute.releaseGl();
    report.output = request.output;
    report.format = sampling::formatName(format);
    report.pattern = request.pattern;
    report.count = job.count;
    report.seed = job.seed;
    report.time = job.time;
    report.samplesPerSecond = report.seconds > 0.0 ? double(report.rows) / report.seconds : 0.0;
    report.glRenderer = renderer::queryGlInfo().renderer;
    if (family) {
        report.index = indexPath(request.output);
        if (auto ok = writeFileAtomically(report.index, toJson(report, 2) + "\n"); !ok) {
            removeWritten();
            return workError(ok.error().keyed());
        }
    }
    return report;
}

JobResult<values::MergeReport> run(const values::MergeRequest& request, const ProgressSink&) {
    if (auto error = validate(request)) return *error;
    const sampling::SampleFormat format =
        *(request.format.empty() ? sampling::formatFromPath(request.output) : sampling::parseFormat(request.format));
    std::vector<std::filesystem::path> parts(request.parts.begin(), request.parts.end());
    const auto start = std::chrono::steady_clock::now();
    auto merged = sampling::mergeSampleFiles(request.output, format, parts);
    if (!merged) return workError(merged.error().keyed());
    values::MergeReport report;
    report.output = request.output;
    report.rows = merged->rows;
    report.parts = merged->parts;
    report.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return report;
}

JobResult<values::ListReport> run(const values::ListRequest& request, const ProgressSink&) {
    dataset::Catalogue catalogue = dataset::Catalogue::scan(paths::datasetRoot());
    values::ListReport report;
    report.root = paths::datasetRoot().string();
    report.problems = catalogue.problems();
    for (const std::string& problem : report.problems) log::warning("dataset", problem);
    for (const dataset::Entry& entry : catalogue.entries()) {
        const dataset::Metadata& m = entry.metadata;
        report.items.push_back({m.name, m.category, dataset::declaredTypeName(m.type), entry.path.string(), m.author, m.license,
                                m.notes, m.animated});
    }
    if (report.items.empty()) return workError("list: no SDFs found in " + report.root);
    // The measured types and render times, from the dataset report when there is one.
    const std::filesystem::path measured =
        request.report.empty() ? paths::datasetRoot() / "report.json" : std::filesystem::path(request.report);
    if (auto text = readTextFile(measured)) {
        if (auto added = addDatasetMeasurements(*text, report); !added)
            report.problems.push_back(measured.string() + ": " + added.error().message);
        else
            report.report = measured.string();
    } else if (!request.report.empty()) {
        report.problems.push_back(text.error().message);
    }
    return report;
}

} // namespace sdfwb::jobs
