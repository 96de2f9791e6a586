#include <core/Parallel.h>

#include <cstdlib>

namespace sdfwb {

unsigned workerThreads() {
    if (const char* text = std::getenv("SDFWB_THREADS")) {
        char* end = nullptr;
        const long n = std::strtol(text, &end, 10);
        if (end != text && *end == '\0' && n >= 1) return unsigned(std::min(n, 1024L));
    }
    // Asked once: the library reads the CPU list from /sys on every call.
    static const unsigned hardware = std::max(1u, std::thread::hardware_concurrency());
    return hardware;
}

} // namespace sdfwb
