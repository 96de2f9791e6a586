#pragma once
// What the foreign-code GL tests share: the corpus folder and opening a file as a user would.

#include <shaders/SdfSource.h>

#include "common/FirstError.h"

#include <filesystem>
#include <string>

namespace sdfwb::testing {

inline const std::filesystem::path kFolder = std::filesystem::path(SDFWB_SOURCE_DIR) / "tests" / "foreign";

inline shaders::PreparedSdf prepare(const std::filesystem::path& file, const std::string& entry = {}) {
    shaders::IncludeOptions options;
    options.libraryRoots = {std::filesystem::path(SDFWB_SOURCE_DIR) / "shaders" / "lib"};
    return shaders::prepareSdfFile(file, options, entry);
}

inline std::string firstError(const shaders::PreparedSdf& sdf) { return firstErrorText(sdf.diagnostics); }

} // namespace sdfwb::testing
