#pragma once
// The headless commands behind `sdfwb --batch ...`. No Qt, no widgets: EGL for GL.
// Each returns a process exit code (see ExitCode) and prints its own messages.

#include <renderer/Camera.h>
#include <renderer/RenderSettings.h>

#include <string>

namespace sdfwb::app {

enum ExitCode : int {
    kExitOk = 0,
    kExitFailure = 1,       // the work failed: the SDF does not compile, a file cannot be written
    kExitUsage = 2,         // bad arguments: unknown option, malformed value, missing file
    kExitNoGl = 3,          // no OpenGL 4.3 context could be created
};

struct OutputOptions {
    bool quiet = false;  // only errors
    bool json = false;   // machine-readable report on stdout
};

struct RenderJob {
    std::string sdf;      // dataset name or path
    std::string output;   // .png, .jpg or .exr
    int width = 1280;
    int height = 720;
    float time = 0.0f;
    renderer::ShadingSettings shading;
    renderer::TraceSettings trace;
    renderer::Camera camera;
};

int runRender(const RenderJob& job, const OutputOptions& output);
int runList(const OutputOptions& output);

// Prints "sdfwb: <message>" to stderr.
void printError(const std::string& message);

} // namespace sdfwb::app
