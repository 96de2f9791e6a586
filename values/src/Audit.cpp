#include <values/Audit.h>

namespace sdfwb::values {

std::vector<std::pair<const char*, float>> namedFigures(const AuditFlag& flag) {
    if (flag.finding == Finding::Truncated) return {{"value", flag.value}, {"start", flag.start}};
    if (flag.finding == Finding::Discontinuous) return {{"jump", flag.value}, {"jump_max", flag.maximum}};
    if (flag.finding == Finding::NonConservative) return {{"lipschitz", flag.value}, {"lipschitz_max", flag.maximum}};
    return {};
}

const AuditFlag* findFlag(const std::vector<AuditFlag>& flags, Finding finding) {
    for (const AuditFlag& flag : flags)
        if (flag.finding == finding) return &flag;
    return nullptr;
}

} // namespace sdfwb::values
