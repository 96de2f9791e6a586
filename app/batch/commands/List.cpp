// `sdfwb --batch list`: the dataset's SDFs.
#include "Common.h"

#include <jobs/JobJson.h>

#include <cstdio>

namespace sdfwb::app {

int runList(const values::ListRequest& request, const OutputOptions& output) {
    auto result = jobs::run(request, {});
    if (!result) return reportFailure(result.error);
    const values::ListReport& r = *result;
    if (output.json) {
        printReport(jobs::toJson(r), output);
        return kExitOk;
    }
    for (const values::ListItem& item : r.items)
        std::printf("%-28s %-13s %-12s %s\n", item.name.c_str(), item.category.c_str(), item.declaredType.c_str(),
                    item.animated ? "animated" : "");
    if (!output.quiet) std::printf("%zu SDFs in %s\n", r.items.size(), r.root.c_str());
    return kExitOk;
}

} // namespace sdfwb::app
