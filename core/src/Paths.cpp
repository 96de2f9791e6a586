#include <core/Paths.h>

#include "InstallPrefix.h"

#include <algorithm>
#include <cstdlib>
#include <system_error>

#include <dlfcn.h>

#ifndef SDFWB_SOURCE_DIR
#error "SDFWB_SOURCE_DIR must be defined by the build"
#endif

namespace sdfwb::paths {
namespace fs = std::filesystem;

namespace {

// The file that holds this code: the sdfwb binary, or the Python module sdfwb/_native*.so loaded
// into an interpreter (where /proc/self/exe is the interpreter, not sdfwb).
fs::path codeFile() {
    Dl_info info{};
    if (dladdr(reinterpret_cast<const void*>(&codeFile), &info) != 0 && info.dli_fname && info.dli_fname[0] == '/')
        return fs::path(info.dli_fname);
    std::error_code ec;
    fs::path exe = fs::read_symlink("/proc/self/exe", ec);
    return ec ? fs::path() : exe;
}

// The install prefix the code file lies in: <prefix>/bin/sdfwb, or
// <prefix>/lib/python3/dist-packages/sdfwb/_native*.so; empty for anything else.
fs::path prefixOf(const fs::path& code) {
    const fs::path folder = code.parent_path();
    const std::string packages = folder.parent_path().filename().string();
    if (folder.filename() == "sdfwb" && (packages == "dist-packages" || packages == "site-packages"))
        return folder.parent_path().parent_path().parent_path().parent_path();
    if (folder.filename() == "bin") return folder.parent_path();
    return {};
}

} // namespace

fs::path detail::installPrefix() { return prefixOf(codeFile()); }

fs::path dataRoot() {
    if (const char* env = std::getenv("SDFWB_DATA_DIR"); env && *env) return fs::path(env);
    // An installed sdfwb uses its own prefix's data; a build tree's binary or module, the source
    // tree it was built from, whatever is installed elsewhere on the machine.
    if (const fs::path prefix = detail::installPrefix(); !prefix.empty()) {
        std::error_code ec;
        fs::path installed = prefix / "share" / "sdfwb";
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
