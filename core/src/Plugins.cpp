#include <core/Plugins.h>

#include "InstallPrefix.h"

#include <cstdlib>
#include <map>
#include <mutex>

#include <dlfcn.h>

#ifndef SDFWB_PLUGIN_BUILD_DIR
#error "SDFWB_PLUGIN_BUILD_DIR must be defined by the build"
#endif

namespace sdfwb::plugins {
namespace fs = std::filesystem;

fs::path folder() {
    if (const char* env = std::getenv("SDFWB_PLUGIN_DIR"); env && *env) return fs::path(env);
    if (const fs::path prefix = paths::detail::installPrefix(); !prefix.empty()) return prefix / "lib" / "sdfwb";
    return fs::path(SDFWB_PLUGIN_BUILD_DIR);
}

Expected<void*> symbol(const std::string& file, const std::string& name) {
    static std::mutex mutex;
    static std::map<std::string, Expected<void*>> modules; // file -> dlopen handle or why not
    std::lock_guard lock(mutex);
    auto it = modules.find(file);
    if (it == modules.end()) {
        const fs::path path = folder() / file;
        dlerror();
        void* handle = dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL);
        Expected<void*> loaded =
            handle ? Expected<void*>(handle) : Expected<void*>(makeError(dlerror())); // names the file and why
        it = modules.emplace(file, std::move(loaded)).first;
    }
    if (!it->second) return it->second.error();
    dlerror();
    void* address = dlsym(*it->second, name.c_str());
    if (!address) return makeError((folder() / file).string() + ": has no symbol " + name);
    return address;
}

} // namespace sdfwb::plugins
