// sample, merge and list: sample files written through the compute sampler, shards joined, the
// dataset listed.
#include <jobs/Jobs.h>

#include <core/Log.h>
#include <core/Paths.h>
#include <dataset/Catalogue.h>
#include <renderer/GlInfo.h>
#include <renderer/SampleCompute.h>
#include <sampling/SampleFile.h>
#include <sampling/Sampler.h>
#include <sampling/SamplerLibrary.h>

#include <chrono>

namespace sdfwb::jobs {

JobResult<SampleReport> run(const SampleRequest& request, const ProgressSink& progress) {
    if (auto error = validate(request)) return *error;
    if (request.output.empty()) return JobError{Failure::Usage, "--output: no output file given", {}};
    auto sampler = sampling::findSampler(request.pattern, sampling::samplerFolders());
    if (!sampler) return JobError{Failure::Usage, "--pattern: " + sampler.error().message, {}};
    const sampling::SampleFormat format =
        *(request.format.empty() ? sampling::formatFromPath(request.output) : sampling::parseFormat(request.format));
    auto sdf = openSdf(request.sdf, "sample");
    if (!sdf) return sdf.error;
    renderer::SampleCompute compute;
    auto diagnostics = compute.build(sdf->prepared, *sampler);
    if (shaders::hasErrors(diagnostics))
        return JobError{Failure::Work,
                        "sample: " + sdf->label + " with pattern '" + request.pattern + "' does not compile; nothing written",
                        diagnostics};
    const sampling::SamplingJob job = samplingJob(request);
    sampling::SampleMetadata metadata;
    metadata.sdf = request.sdf.sdf;
    metadata.pattern = request.pattern;
    metadata.version = SDFWB_VERSION;
    auto written = sampling::sampleToFile(compute, job, request.output, format, metadata, progress);
    compute.releaseGl();
    if (!written) return JobError{Failure::Work, written.error().message, {}};
    if (written->cancelled)
        return JobError{Failure::Cancelled,
                        "sample: cancelled after " + std::to_string(written->rows) + " of " + std::to_string(job.rows()) +
                            " samples; nothing written",
                        {}};
    SampleReport report;
    report.output = request.output;
    report.format = sampling::formatName(format);
    report.sdf = request.sdf.sdf;
    report.pattern = request.pattern;
    report.count = job.count;
    report.rows = written->rows;
    report.firstIndex = written->firstIndex;
    report.seed = job.seed;
    report.time = job.time;
    report.badRows = written->badRows;
    report.seconds = written->seconds;
    report.samplesPerSecond = written->seconds > 0.0 ? double(written->rows) / written->seconds : 0.0;
    report.glRenderer = renderer::queryGlInfo().renderer;
    return report;
}

JobResult<MergeReport> run(const MergeRequest& request, const ProgressSink&) {
    if (auto error = validate(request)) return *error;
    const sampling::SampleFormat format =
        *(request.format.empty() ? sampling::formatFromPath(request.output) : sampling::parseFormat(request.format));
    std::vector<std::filesystem::path> parts(request.parts.begin(), request.parts.end());
    const auto start = std::chrono::steady_clock::now();
    auto merged = sampling::mergeSampleFiles(request.output, format, parts);
    if (!merged) return JobError{Failure::Work, merged.error().message, {}};
    MergeReport report;
    report.output = request.output;
    report.rows = merged->rows;
    report.parts = merged->parts;
    report.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return report;
}

JobResult<ListReport> run(const ListRequest&, const ProgressSink&) {
    dataset::Catalogue catalogue = dataset::Catalogue::scan(paths::datasetRoot());
    ListReport report;
    report.root = paths::datasetRoot().string();
    report.problems = catalogue.problems();
    for (const std::string& problem : report.problems) log::warning("dataset", problem);
    for (const dataset::Entry& entry : catalogue.entries()) {
        const dataset::Metadata& m = entry.metadata;
        report.items.push_back({m.name, m.category, dataset::declaredTypeName(m.type), entry.path.string(), m.author, m.license,
                                m.notes, m.animated});
    }
    if (report.items.empty()) return JobError{Failure::Work, "list: no SDFs found in " + report.root, {}};
    return report;
}

} // namespace sdfwb::jobs
