#include <core/Paths.h>

#include <algorithm>
#include <cstdlib>
#include <system_error>

#ifndef SDFWB_SOURCE_DIR
#error "SDFWB_SOURCE_DIR must be defined by the build"
#endif

namespace sdfwb::paths {
namespace fs = std::filesystem;

fs::path dataRoot() {
    if (const char* env = std::getenv("SDFWB_DATA_DIR"); env && *env) return fs::path(env);
    std::error_code ec;
    fs::path exe = fs::read_symlink("/proc/self/exe", ec);
    if (!ec) {
        fs::path installed = exe.parent_path().parent_path() / "share" / "sdfwb";
        if (fs::is_directory(installed / "dataset", ec)) return installed;
    }
    return fs::path(SDFWB_SOURCE_DIR);
}

fs::path datasetRoot() { return dataRoot() / "dataset"; }

fs::path shaderLibraryRoot() { return dataRoot() / "shaders" / "lib"; }

bool isInsideRoots(const fs::path& path, const std::vector<fs::path>& roots) {
    std::error_code ec;
    fs::path resolved = fs::weakly_canonical(path, ec);
    if (ec) return false;
    for (const fs::path& root : roots) {
        fs::path canonicalRoot = fs::weakly_canonical(root, ec);
        if (ec) continue;
        auto [rootEnd, pathIt] = std::mismatch(canonicalRoot.begin(), canonicalRoot.end(), resolved.begin(), resolved.end());
        (void)pathIt;
        if (rootEnd == canonicalRoot.end()) return true;
    }
    return false;
}

} // namespace sdfwb::paths
