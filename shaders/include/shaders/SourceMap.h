#pragma once
// The files that make up one composed GLSL string. Index i in `files` is GLSL source-string
// number i: `#line L i` directives in the text point back to files[i], so compiler messages
// can be mapped to the file and line a user knows.

#include <string>
#include <string_view>
#include <vector>

namespace sdfwb::shaders {

struct SourceFile {
    std::string name; // shown in diagnostics: a path, "<editor>", or "sdfwb:tracer/trace.frag"
    std::string text; // original text, used to find columns
};

struct SourceMap {
    std::vector<SourceFile> files;

    // Text of a 1-based line of file `index`, or empty when out of range.
    std::string_view lineText(int index, int line) const;
    std::string fileName(int index) const;
};

} // namespace sdfwb::shaders
