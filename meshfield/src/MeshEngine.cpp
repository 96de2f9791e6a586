// The process-wide cache of mesh queries (a query built once per field) and the choice of the
// engine that evaluates a mesh's own field.
#include <meshfield/MeshQuery.h>

#include <core/Log.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <deque>
#include <map>
#include <mutex>
#include <string>

namespace sdfwb::meshfield {

std::shared_ptr<const MeshQuery> meshQuery(const std::shared_ptr<const MeshField>& field) {
    if (!field) return nullptr;
    // Queries live as long as someone holds them; each holds its field (the deleter's copy).
    static std::mutex mutex;
    static std::map<const MeshField*, std::weak_ptr<const MeshQuery>> cache;
    std::lock_guard lock(mutex);
    for (auto it = cache.begin(); it != cache.end();) it = it->second.expired() ? cache.erase(it) : std::next(it);
    if (auto held = cache[field.get()].lock()) return held;
    const auto start = std::chrono::steady_clock::now();
    std::shared_ptr<const MeshQuery> query(new MeshQuery(*field), [keep = field](const MeshQuery* q) { delete q; });
    cache[field.get()] = query;
    // The last few queries stay built between calls (a script that evaluates a mesh again and again
    // keeps its layout and its sign cache).
    static std::deque<std::shared_ptr<const MeshQuery>> recent;
    recent.push_back(query);
    if (recent.size() > 2) recent.pop_front();
    char line[256];
    std::snprintf(line, sizeof line, "%s: CPU engine layout %.1f MB (sign cache included), built in %.3f s", field->name.c_str(),
                  double(query->bytes()) / 1e6, std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
    log::info("meshfield", line);
    return query;
}

MeshEngine chooseMeshEngine(const std::string& glRenderer) {
    if (const char* forced = std::getenv("SDFWB_MESH_ENGINE")) {
        const std::string text = forced;
        if (text == "cpu") return MeshEngine::Cpu;
        if (text == "gpu") return MeshEngine::Gpu;
    }
    const bool software = glRenderer.find("llvmpipe") != std::string::npos || glRenderer.find("softpipe") != std::string::npos;
    return software ? MeshEngine::Cpu : MeshEngine::Gpu;
}

const char* meshEngineName(MeshEngine engine) { return engine == MeshEngine::Cpu ? "cpu" : "gpu"; }

} // namespace sdfwb::meshfield
