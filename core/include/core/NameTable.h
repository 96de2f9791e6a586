#pragma once
// An enum's names written once, as a table of (value, name) pairs: the name of a value and the
// value of a name (what the CLI, the job files and the reports read and write).

#include <cstddef>
#include <optional>
#include <string_view>
#include <utility>

namespace sdfwb {

template <class Enum, std::size_t N> constexpr const char* nameOf(const std::pair<Enum, const char*> (&table)[N], Enum value) {
    for (const auto& [entry, name] : table)
        if (entry == value) return name;
    return "?";
}

template <class Enum, std::size_t N>
constexpr std::optional<Enum> valueNamed(const std::pair<Enum, const char*> (&table)[N], std::string_view name) {
    for (const auto& [entry, text] : table)
        if (name == text) return entry;
    return std::nullopt;
}

} // namespace sdfwb
