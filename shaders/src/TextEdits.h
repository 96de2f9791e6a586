#pragma once
// Edits of a shader's text by offset, for the host adaptations (ForeignHosts.cpp, Synesthesia.cpp)
// and the composer's rewrites (ZeroInit.cpp), and where a host's declarations go. Private to shaders/.

#include <algorithm>
#include <string>
#include <vector>

namespace sdfwb::shaders::detail {

// text[offset, offset + length) becomes `replacement` (length 0: an insertion before offset).
struct Edit {
    std::size_t offset = 0, length = 0;
    std::string replacement;
};

// The text with non-overlapping edits applied, in order of offset; edits at the same offset keep
// the order they were given in, and an edit overlapping one before it is dropped.
inline std::string applyEdits(const std::string& text, std::vector<Edit> edits) {
    std::stable_sort(edits.begin(), edits.end(), [](const Edit& a, const Edit& b) { return a.offset < b.offset; });
    std::string out;
    std::size_t from = 0;
    for (const Edit& e : edits) {
        if (e.offset < from) continue;
        out.append(text, from, e.offset - from);
        out += e.replacement;
        from = e.offset + e.length;
    }
    out.append(text, from, std::string::npos);
    return out;
}

// The offset of the first line of code in `stripped` (comments blanked): not blank, not a directive;
// the text's size when there is none.
inline std::size_t firstCodeOffset(const std::string& stripped) {
    for (std::size_t start = 0; start < stripped.size();) {
        const std::size_t stop = std::min(stripped.find('\n', start), stripped.size());
        const std::size_t k = stripped.find_first_not_of(" \t\r", start);
        if (k < stop && stripped[k] != '#') return k;
        start = stop + 1;
    }
    return stripped.size();
}

} // namespace sdfwb::shaders::detail
