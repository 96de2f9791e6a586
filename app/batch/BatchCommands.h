#pragma once
// The headless commands behind `sdfwb --batch ...`. No Qt, no widgets: EGL for GL.
// Each returns a process exit code (see ExitCode) and prints its own messages.

#include <renderer/Camera.h>
#include <renderer/RenderSettings.h>

#include <cstdint>
#include <string>
#include <vector>

namespace sdfwb::app {

enum ExitCode : int {
    kExitOk = 0,
    kExitFailure = 1,     // the work failed: the SDF does not compile, a file cannot be written
    kExitUsage = 2,       // bad arguments: unknown option, malformed value, missing file
    kExitNoGl = 3,        // no OpenGL 4.3 context could be created
    kExitCancelled = 130, // interrupted (Ctrl-C); no partial output was left
};

struct OutputOptions {
    bool quiet = false;         // only errors
    bool json = false;          // machine-readable report on stdout
    bool progressLines = false; // "progress DONE TOTAL" lines on stderr, for front ends (the GUI)
};

struct RenderJob {
    std::string sdf;    // dataset name or path
    std::string entry;  // the SDF's function; empty: metadata `entry:`, sdf, or a conventional name
    std::string output; // .png, .jpg or .exr
    int width = 1280;
    int height = 720;
    float time = 0.0f;
    renderer::ShadingSettings shading;
    renderer::TraceSettings trace;
    renderer::Camera camera;
    renderer::CuttingPlane plane;
};

int runRender(const RenderJob& job, const OutputOptions& output);

struct AnimateJob {
    RenderJob frame; // SDF, output (.mp4), size, shading, camera; frame.time is the start time
    float seconds = 4.0f;
    int framesPerSecond = 30;
    bool turntable = false; // orbit the camera once around the Y axis over the clip
};

int runAnimate(const AnimateJob& job, const OutputOptions& output);

struct SampleCommand {
    std::string sdf;     // dataset name or path
    std::string entry;   // as in RenderJob
    std::string pattern; // built-in name or sampler path
    std::uint64_t count = 0;
    std::string output;
    std::string format; // empty: from the output's extension
    std::uint64_t seed = 0;
    float time = 0.0f;
    std::uint32_t shardIndex = 0;
    std::uint32_t shardCount = 1;
    std::uint32_t chunkSize = 1u << 18;
    float gradientStep = 1e-3f;
    float surfaceTolerance = 1e-5f; // |f| at which surface/near/metropolis rays stop
};

int runSample(const SampleCommand& command, const OutputOptions& output);
struct AuditCommand {
    std::string sdf;
    std::string entry; // as in RenderJob
    std::uint64_t samples = 100000;
    std::uint64_t seed = 0;
    float time = 0.0f;
    bool plane = false; // plane readouts instead of the volume audit
    float planeNormal[3] = {0.0f, 0.0f, 1.0f};
    float planeOffset = 0.0f;
    int resolution = 256;
    float probeDistance = 3.0f; // truncation: probe outward from the surface this far
};

int runAudit(const AuditCommand& command, const OutputOptions& output);

int runMerge(const std::string& outputFile, const std::string& format, const std::vector<std::string>& parts,
             const OutputOptions& output);
int runList(const OutputOptions& output);

struct BenchCommand {
    std::string outputDirectory = "docs/benchmarks"; // benchmarks.md, CSV tables, images/
    int repeats = 5;
    bool quick = false;
    bool noPlots = false;
};

// Error against run time for the tracer, the samplers, gradients and the audit (bench/Benchmarks.h).
int runBench(const BenchCommand& command, const OutputOptions& output);

// Prints "sdfwb: <message>" to stderr.
void printError(const std::string& message);

} // namespace sdfwb::app
