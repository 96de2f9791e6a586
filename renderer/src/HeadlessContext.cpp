#include <renderer/HeadlessContext.h>

#include <core/Log.h>

#include <epoxy/egl.h>
#include <epoxy/gl.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <vector>

namespace sdfwb::renderer {
namespace {

bool hasExtension(const char* list, const char* name) {
    if (!list) return false;
    std::size_t length = std::strlen(name);
    for (const char* p = list; (p = std::strstr(p, name)); p += length)
        if ((p == list || p[-1] == ' ') && (p[length] == ' ' || p[length] == '\0')) return true;
    return false;
}

std::string eglErrorText() {
    char buffer[32];
    std::snprintf(buffer, sizeof buffer, "EGL error 0x%04x", unsigned(eglGetError()));
    return buffer;
}

// A hardware EGL device (not Mesa's software device), or EGL_NO_DEVICE_EXT.
EGLDeviceEXT findHardwareDevice(const char* clientExtensions) {
    // NVIDIA's EGL lists EGL_EXT_device_base, which includes device enumeration, and not
    // EGL_EXT_device_enumeration itself (seen with driver 580 on an H100).
    const bool enumerates =
        hasExtension(clientExtensions, "EGL_EXT_device_enumeration") || hasExtension(clientExtensions, "EGL_EXT_device_base");
    if (!enumerates || !hasExtension(clientExtensions, "EGL_EXT_platform_device")) return EGL_NO_DEVICE_EXT;
    EGLint count = 0;
    if (!eglQueryDevicesEXT(0, nullptr, &count) || count <= 0) return EGL_NO_DEVICE_EXT;
    std::vector<EGLDeviceEXT> devices(static_cast<std::size_t>(count));
    if (!eglQueryDevicesEXT(count, devices.data(), &count)) return EGL_NO_DEVICE_EXT;
    for (EGLint i = 0; i < count; ++i) {
        const char* deviceExtensions = eglQueryDeviceStringEXT(devices[std::size_t(i)], EGL_EXTENSIONS);
        if (!hasExtension(deviceExtensions, "EGL_MESA_device_software")) return devices[std::size_t(i)];
    }
    return EGL_NO_DEVICE_EXT;
}

} // namespace

Expected<std::unique_ptr<HeadlessContext>> HeadlessContext::create() {
    const auto start = std::chrono::steady_clock::now();
    const char* clientExtensions = eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
    if (!hasExtension(clientExtensions, "EGL_EXT_platform_base"))
        return makeError("renderer: EGL lacks EGL_EXT_platform_base; cannot create a headless OpenGL context");

    const char* forced = std::getenv("SDFWB_EGL_PLATFORM");
    std::string wanted = forced ? forced : "";
    EGLDisplay display = EGL_NO_DISPLAY;
    std::string platform;
    if (wanted.empty() || wanted == "device") {
        EGLDeviceEXT device = findHardwareDevice(clientExtensions);
        if (device != EGL_NO_DEVICE_EXT) {
            display = eglGetPlatformDisplayEXT(EGL_PLATFORM_DEVICE_EXT, device, nullptr);
            platform = "device";
        } else if (wanted == "device") {
            return makeError("renderer: SDFWB_EGL_PLATFORM=device but no hardware EGL device was found");
        }
    }
    if (display == EGL_NO_DISPLAY) {
        if (!hasExtension(clientExtensions, "EGL_MESA_platform_surfaceless"))
            return makeError("renderer: EGL has neither a hardware device nor Mesa's surfaceless platform");
        display = eglGetPlatformDisplayEXT(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
        platform = "surfaceless";
    }
    if (display == EGL_NO_DISPLAY)
        return makeError("renderer: eglGetPlatformDisplay(" + platform + ") failed: " + eglErrorText());

    EGLint eglMajor = 0, eglMinor = 0;
    if (!eglInitialize(display, &eglMajor, &eglMinor))
        return makeError("renderer: eglInitialize(" + platform + ") failed: " + eglErrorText());
    if (!eglBindAPI(EGL_OPENGL_API)) {
        eglTerminate(display);
        return makeError("renderer: this EGL cannot bind desktop OpenGL: " + eglErrorText());
    }

    const char* displayExtensions = eglQueryString(display, EGL_EXTENSIONS);
    EGLConfig config = EGL_NO_CONFIG_KHR;
    if (!hasExtension(displayExtensions, "EGL_KHR_no_config_context")) {
        const EGLint configAttributes[] = {EGL_SURFACE_TYPE, EGL_PBUFFER_BIT, EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT, EGL_NONE};
        EGLint found = 0;
        if (!eglChooseConfig(display, configAttributes, &config, 1, &found) || found < 1) {
            eglTerminate(display);
            return makeError("renderer: no EGL config for desktop OpenGL on the " + platform + " platform");
        }
    }
    const EGLint contextAttributes[] = {
        EGL_CONTEXT_MAJOR_VERSION,           4,       EGL_CONTEXT_MINOR_VERSION, 3, EGL_CONTEXT_OPENGL_PROFILE_MASK,
        EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT, EGL_NONE};
    EGLContext context = eglCreateContext(display, config, EGL_NO_CONTEXT, contextAttributes);
    if (context == EGL_NO_CONTEXT) {
        std::string error = eglErrorText();
        // Say what the driver does offer, if anything.
        std::string offered = "nothing";
        EGLContext fallback = eglCreateContext(display, config, EGL_NO_CONTEXT, nullptr);
        if (fallback != EGL_NO_CONTEXT && eglMakeCurrent(display, EGL_NO_SURFACE, EGL_NO_SURFACE, fallback)) {
            offered = "OpenGL " + queryGlInfo().version;
            eglMakeCurrent(display, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
        }
        if (fallback != EGL_NO_CONTEXT) eglDestroyContext(display, fallback);
        eglTerminate(display);
        return makeError("renderer: cannot create an OpenGL 4.3 core context on the " + platform + " platform (" + error +
                         "); the driver offers " + offered);
    }
    if (!eglMakeCurrent(display, EGL_NO_SURFACE, EGL_NO_SURFACE, context)) {
        std::string error = eglErrorText();
        eglDestroyContext(display, context);
        eglTerminate(display);
        return makeError("renderer: eglMakeCurrent without a surface failed (" + error + ")");
    }

    std::unique_ptr<HeadlessContext> result(new HeadlessContext());
    result->m_display = display;
    result->m_context = context;
    result->m_platform = platform;
    result->m_info = queryGlInfo();
    // The time it took (the driver's loading, Mesa's LLVM among it, is most of a short job's start).
    const double milliseconds = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    char took[32];
    std::snprintf(took, sizeof took, " (context in %.1f ms)", milliseconds);
    log::info("gl", "EGL " + std::to_string(eglMajor) + "." + std::to_string(eglMinor) + " " + platform + ": " +
                        describe(result->m_info) + took);
    if (auto ok = requireGl43(result->m_info); !ok) return ok.error();
    return result;
}

HeadlessContext::~HeadlessContext() {
    if (!m_display) return;
    eglMakeCurrent(m_display, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
    if (m_context) eglDestroyContext(m_display, m_context);
    // The display is not terminated: Mesa shares it per process, and other contexts
    // (another HeadlessContext in the same process) may still use it.
}

void HeadlessContext::doneCurrent() { eglMakeCurrent(m_display, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT); }

bool HeadlessContext::anyCurrent() { return eglGetCurrentContext() != EGL_NO_CONTEXT; }

bool HeadlessContext::makeCurrent() { return eglMakeCurrent(m_display, EGL_NO_SURFACE, EGL_NO_SURFACE, m_context) == EGL_TRUE; }

} // namespace sdfwb::renderer
