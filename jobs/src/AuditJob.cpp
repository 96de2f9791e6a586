// audit: the volume audit, or the readouts of one cutting plane.
#include <jobs/Jobs.h>

#include <sampling/FieldAudit.h>

namespace sdfwb::jobs {

JobResult<AuditJobReport> run(const AuditRequest& request, const ProgressSink& progress) {
    if (auto error = validate(request)) return *error;
    auto sdf = openSdf(request.sdf, "audit");
    if (!sdf) return sdf.error;
    AuditJobReport report;
    report.sdf = sdf->label;
    report.entry = sdf->prepared.signature.entry;
    report.probeDistance = request.probeDistance;
    if (request.plane) {
        auto readout =
            sampling::analysePlane(sdf->prepared, request.plane->normal, request.plane->offset, request.resolution, request.time);
        if (!readout) return JobError{Failure::Work, readout.error().message, {}};
        report.plane = request.plane;
        report.readout = std::move(*readout);
        return report;
    }
    sampling::AuditOptions options;
    options.samples = request.samples;
    options.seed = request.seed;
    options.time = request.time;
    options.probeDistance = request.probeDistance;
    auto volume = sampling::auditField(sdf->prepared, options, progress);
    if (progress.isCancelled()) return JobError{Failure::Cancelled, "audit: cancelled", {}};
    if (!volume) return JobError{Failure::Work, volume.error().message, {}};
    report.volume = std::move(*volume);
    return report;
}

} // namespace sdfwb::jobs
