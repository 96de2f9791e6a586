#pragma once
// An OpenGL 4.3 core context without any window system: EGL on the NVIDIA device platform when a
// hardware EGL device exists, else Mesa's surfaceless platform (llvmpipe without a GPU).
// $SDFWB_EGL_PLATFORM=surfaceless|device forces one. Used by the batch CLI, tests and Python.

#include <core/Expected.h>
#include <renderer/GlInfo.h>

#include <memory>
#include <string>

namespace sdfwb::renderer {

class HeadlessContext {
public:
    // Creates the context, makes it current on the calling thread, logs the GL info and checks
    // requireGl43(). Failure messages say which EGL step failed and what the driver offers.
    static Expected<std::unique_ptr<HeadlessContext>> create();

    ~HeadlessContext();
    HeadlessContext(const HeadlessContext&) = delete;
    HeadlessContext& operator=(const HeadlessContext&) = delete;

    // Makes the context current on the calling thread (one thread at a time).
    bool makeCurrent();
    // Releases the context from the calling thread, so another thread may make it current.
    void doneCurrent();
    // Whether an EGL context (this class's or another's) is current on the calling thread: GL work
    // a caller may skip (a search that only informs) checks it rather than abort in the loader.
    static bool anyCurrent();

    const GlInfo& info() const { return m_info; }
    const std::string& platform() const { return m_platform; } // "surfaceless" or "device"

private:
    HeadlessContext() = default;
    void* m_display = nullptr;
    void* m_context = nullptr;
    GlInfo m_info;
    std::string m_platform;
};

} // namespace sdfwb::renderer
