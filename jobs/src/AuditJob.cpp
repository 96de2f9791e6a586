// audit: the volume audit, or the readouts of one cutting plane.
#include <jobs/Jobs.h>

#include <sampling/FieldAudit.h>

namespace sdfwb::jobs {

JobResult<values::AuditJobReport> run(const values::AuditRequest& request, const ProgressSink& progress) {
    if (auto error = validate(request)) return *error;
    auto sdf = openSdf(request.sdf, "audit");
    if (!sdf) return sdf.error;
    values::AuditJobReport report;
    sdf->describe(report);
    report.truncationReach = request.truncationReach;
    std::vector<shaders::Diagnostic> diagnostics; // the compiler's, when the SDF does not compile
    if (request.plane) {
        auto readout = sampling::analysePlane(sdf->prepared, request.plane->normal, request.plane->offset, request.resolution,
                                              request.time, sdf->parameters, &diagnostics);
        if (!readout) return JobError{Failure::Work, readout.error().message, diagnostics, {}};
        report.parameters = shaders::valuesOf(sdf->parameters);
        report.plane = request.plane;
        report.readout = std::move(*readout);
        return report;
    }
    sampling::AuditOptions options;
    options.samples = request.samples;
    options.seed = request.seed;
    options.time = request.time;
    options.truncationReach = request.truncationReach;
    options.diagnostics = &diagnostics;
    if (request.family.empty()) {
        options.parameters = sdf->parameters;
        auto volume = sampling::auditField(sdf->prepared, options, progress);
        if (progress.isCancelled()) return JobError{Failure::Cancelled, "audit: cancelled", {}, {}};
        if (!volume) return JobError{Failure::Work, volume.error().message, diagnostics, {}};
        report.parameters = shaders::valuesOf(sdf->parameters);
        report.volume = std::move(*volume);
        return report;
    }
    // A family: the volume audit of each instance, summarised one line each.
    auto instances = shaders::familyInstances(sdf->prepared.parameters, request.sdf.params, request.family.sweeps,
                                              request.family.randomize, request.seed);
    if (!instances)
        return usageError((request.family.randomize ? key("randomize") : key("sweep")) + ": " + instances.error().message);
    options.convergence = false; // one estimate per instance; the convergence study is the single audit's
    for (std::size_t k = 0; k < instances->size(); ++k) {
        auto resolved = shaders::resolveParameters(sdf->prepared.parameters, (*instances)[k]);
        if (!resolved) return usageError(key("params") + ": " + sdf->label + ": " + resolved.error().message);
        options.parameters = resolved->settings;
        ProgressSink step{progress.report
                              ? ProgressFunction([&](std::uint64_t, std::uint64_t) { progress(k, instances->size()); })
                              : ProgressFunction(),
                          progress.cancel};
        auto volume = sampling::auditField(sdf->prepared, options, step);
        if (progress.isCancelled()) return JobError{Failure::Cancelled, "audit: cancelled", {}, {}};
        if (!volume) return workError(volume.error().keyed());
        values::AuditInstance instance;
        instance.parameters = shaders::valuesOf(resolved->settings);
        instance.verdict = volume->verdict;
        instance.reason = volume->reason;
        for (const values::AuditFlag& flag : volume->flags) instance.flags.push_back(flag.finding);
        instance.lipschitz = volume->lipschitz;
        instance.lipschitzMax = volume->lipschitzMax;
        instance.exactnessP99 = volume->exactnessP99;
        instance.seconds = volume->seconds;
        report.family.push_back(std::move(instance));
        progress(k + 1, instances->size());
    }
    return report;
}

} // namespace sdfwb::jobs
