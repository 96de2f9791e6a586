// `sdfwb --batch params`: the parameters an SDF declares (annotated uniforms).
#include "Common.h"

#include <jobs/JobJson.h>

#include <cstdio>
#include <string>

namespace sdfwb::app {
namespace {

std::string number(float value) {
    char text[32];
    std::snprintf(text, sizeof text, "%g", double(value));
    return text;
}

} // namespace

int runParams(const values::ParamsRequest& request, const OutputOptions& output) {
    auto result = jobs::run(request, {});
    if (!result) return reportFailure(result.error);
    const values::ParamsReport& r = *result;
    for (const std::string& warning : r.warnings) std::fprintf(stderr, "%s\n", warning.c_str());
    if (output.json) {
        printReport(jobs::toJson(r), output);
        return kExitOk;
    }
    if (output.quiet) return kExitOk;
    if (r.parameters.empty())
        std::printf("%s declares no parameters (uniform TYPE NAME = DEFAULT; // @range MIN MAX)\n", r.sdf.c_str());
    for (const values::ParamItem& p : r.parameters) {
        std::string value;
        for (float v : p.value) value += (value.empty() ? "" : ", ") + number(v);
        std::string range = p.minimum ? "[" + number(*p.minimum) + ", " + number(*p.maximum) + "]" : "(no range)";
        std::printf("%-20s %-5s default %-28s %s%s%s%s%s\n", p.name.c_str(), p.type.c_str(), value.c_str(), range.c_str(),
                    p.step ? (" step " + number(*p.step)).c_str() : "", p.logarithmic ? " log" : "", p.color ? " colour" : "",
                    p.label.empty() ? "" : ("  \"" + p.label + "\"").c_str());
    }
    return kExitOk;
}

} // namespace sdfwb::app
