#pragma once
// Syntax flags for every std::regex that reads text from outside (files, command lines).
//
// libstdc++'s default executor backtracks and recurses once per character that a repeat such as
// `\s*` or `[^)]*` consumes, so a few ten thousand matching characters overflow the stack: a
// 60 KB .npy header or a long run of spaces in a shader crashed sdfwb (fuzz/README.md, "Findings").
// Its Thompson-NFA executor, chosen by the `__polynomial` extension flag, recurses
// no deeper than the pattern and runs in time linear in the text. Patterns built with these
// flags must not use back-references (libstdc++ then throws regex_error at construction).

#include <regex>

namespace sdfwb {

inline constexpr std::regex_constants::syntax_option_type kLinearRegex =
#if defined(__GLIBCXX__)
    std::regex_constants::ECMAScript | std::regex_constants::__polynomial;
#else
    std::regex_constants::ECMAScript;
#endif

} // namespace sdfwb
