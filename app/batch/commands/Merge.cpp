// `sdfwb --batch merge`: shard files joined into the file one run would have written.
#include "Common.h"

#include <jobs/JobJson.h>

#include <cstdio>

namespace sdfwb::app {

int runMerge(const values::MergeRequest& request, const OutputOptions& output) {
    auto result = jobs::run(request, {});
    if (!result) return reportFailure(result.error);
    const values::MergeReport& r = *result;
    if (output.json)
        printReport(jobs::toJson(r), output);
    else if (!output.quiet)
        std::printf("wrote %s: %llu samples from %llu parts in %.2f s\n", r.output.c_str(), (unsigned long long)r.rows,
                    (unsigned long long)r.parts, r.seconds);
    return kExitOk;
}

} // namespace sdfwb::app
