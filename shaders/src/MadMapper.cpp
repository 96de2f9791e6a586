#include "MadMapper.h"

#include <core/Regex.h>

#include "IsfHeader.h"
#include "Words.h"

#include <regex>

namespace sdfwb::shaders::detail {

std::vector<Edit> madMapperEdits(const std::string& text, const std::string& stripped) {
    if (!definesFunction(stripped, "materialColorForPixel") || definesFunction(stripped, "main") ||
        definesFunction(stripped, "mainImage"))
        return {};
    const IsfHeader header = readIsfHeader(text);
    std::vector<Edit> edits;
    // Its generators: `{"NAME": "mat_time", "TYPE": "time_base", ...}` in the header's GENERATORS.
    std::string declared;
    if (header.found)
        if (const std::size_t list = text.find("\"GENERATORS\""); list < header.end) {
            static const std::regex generator(R"re(\{[^{}]*?"NAME"\s*:\s*"(\w+)"[^{}]*?"TYPE"\s*:\s*"(\w+)")re", kLinearRegex);
            const std::string rest = text.substr(list, header.end - list);
            for (auto it = std::sregex_iterator(rest.begin(), rest.end(), generator); it != std::sregex_iterator(); ++it)
                declared += "float " + (*it)[1].str() + " = " + ((*it)[2].str() == "time_base" ? "iTime" : "0.0") + "; ";
        }
    if (!declared.empty()) edits.push_back({header.end, 0, " " + declared});
    // What its vertex stage hands over: plain globals.
    static const std::regex varying(R"((?:^|\n)[ \t]*((?:(?:flat|smooth|noperspective)\s+)?(?:in|varying)\s+)\w+\s+\w+\s*;)",
                                    kLinearRegex);
    for (auto it = std::sregex_iterator(stripped.begin(), stripped.end(), varying); it != std::sregex_iterator(); ++it)
        edits.push_back({std::size_t(it->position(1)), std::size_t(it->length(1)), std::string(std::size_t(it->length(1)), ' ')});
    // MadMapper's own MadCommon.glsl, which comes with the program: of what it gives, PI (the files
    // use it undefined), on its line.
    static const std::regex common(R"((?:^|\n)([ \t]*#[ \t]*include[ \t]*"MadCommon\.glsl"[^\n]*))", kLinearRegex);
    if (std::smatch include; std::regex_search(stripped, include, common))
        edits.push_back({std::size_t(include.position(1)), std::size_t(include.length(1)), piWhereUsed(stripped)});
    // The pixel over the frame, as MadMapper gives it, after the last function's body on its line.
    edits.push_back({stripped.rfind('}') + 1, 0,
                     " void mainImage(out vec4 materialColour, in vec2 materialPixel) { materialColour = "
                     "materialColorForPixel(materialPixel / iResolution.xy); }"});
    return edits;
}

} // namespace sdfwb::shaders::detail
