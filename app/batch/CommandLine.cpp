#include "CommandLine.h"

#include "BatchCommands.h"

#include <core/Log.h>

#include <CLI/CLI.hpp>

#include <cstdio>
#include <cstring>
#include <regex>
#include <string>
#include <vector>

namespace sdfwb::app {
namespace {

const char* const kOverview =
    "sdfwb " SDFWB_VERSION " - the SDF Workbench\n"
    "\n"
    "usage:\n"
    "  sdfwb [FILE.glsl]                  open the workbench on FILE (or on the default SDF)\n"
    "  sdfwb --batch <command> [options]  run headless (EGL, no display needed)\n"
    "  sdfwb --batch <command> --help     the options of one command\n"
    "  sdfwb --help | --version\n"
    "\n"
    "batch commands:\n"
    "  render   sphere-trace an SDF into an image (.png, .jpg, .exr)\n"
    "  list     list the dataset (name, category, declared type, animated)\n"
    "\n"
    "<SDF> arguments take a dataset name (any case) or a path to a .glsl file.\n"
    "exit codes: 0 success, 1 the work failed, 2 bad arguments, 3 no OpenGL 4.3 context\n";

struct Size {
    int width = 0, height = 0;
};

// "640x360" -> 640, 360 (1..16384 each).
std::optional<Size> parseSize(const std::string& text) {
    static const std::regex pattern(R"(^\s*(\d{1,5})\s*[xX]\s*(\d{1,5})\s*$)");
    std::smatch match;
    if (!std::regex_match(text, match, pattern)) return std::nullopt;
    Size size{std::stoi(match[1].str()), std::stoi(match[2].str())};
    if (size.width < 1 || size.height < 1 || size.width > 16384 || size.height > 16384) return std::nullopt;
    return size;
}

// "1.5,2,-3" -> vec3
std::optional<glm::vec3> parseVec3(const std::string& text) {
    float x, y, z;
    char tail;
    if (std::sscanf(text.c_str(), " %f , %f , %f %c", &x, &y, &z, &tail) != 3) return std::nullopt;
    return glm::vec3(x, y, z);
}

void addOutputFlags(CLI::App& app, OutputOptions& output) {
    app.add_flag("--quiet,-q", output.quiet, "print errors only");
    app.add_flag("--json", output.json, "print a machine-readable report on stdout");
}

// Runs CLI11 on argv[first..]; returns an exit code when parsing ends the run (help or error).
std::optional<int> parse(CLI::App& app, const std::string& context, int argc, char** argv, int first) {
    std::vector<std::string> arguments;
    for (int i = argc - 1; i >= first; --i) arguments.emplace_back(argv[i]);  // CLI11 wants reverse order
    try {
        app.parse(arguments);
    } catch (const CLI::CallForHelp&) {
        std::printf("%s", app.help().c_str());
        return kExitOk;
    } catch (const CLI::ParseError& error) {
        printError(context + ": " + error.what() + " (see sdfwb " + context + " --help)");
        return kExitUsage;
    }
    return std::nullopt;
}

int runRenderCommand(int argc, char** argv, int first) {
    CLI::App app("Sphere-trace an SDF into an image, without a display.", "sdfwb --batch render");
    RenderJob job;
    OutputOptions output;
    std::string size = "1280x720", shading = "normals", camera, target;
    app.add_option("--sdf", job.sdf, "dataset name or path to a .glsl file")->required();
    app.add_option("--output", job.output, "image file: .png, .jpg or .exr")->required();
    app.add_option("--size", size, "image size WxH")->capture_default_str();
    app.add_option("--time", job.time, "time in seconds for animated SDFs")->capture_default_str();
    app.add_option("--shading", shading, "shading mode: " + renderer::shadingModeNames())->capture_default_str();
    app.add_option("--camera", camera, "camera position X,Y,Z");
    app.add_option("--target", target, "point the camera looks at X,Y,Z (default 0,0,0)");
    app.add_option("--fov", job.camera.fovYDegrees, "vertical field of view in degrees")->capture_default_str()->check(CLI::Range(1.0f, 179.0f));
    app.add_option("--max-steps", job.trace.maxSteps, "sphere-tracing step budget per ray")->capture_default_str()->check(CLI::Range(1, 100000));
    app.add_option("--step-factor", job.trace.stepFactor, "scale each step (1/L for an L-Lipschitz field)")->capture_default_str()->check(CLI::Range(0.01f, 2.0f));
    addOutputFlags(app, output);
    if (auto exit = parse(app, "--batch render", argc, argv, first)) return *exit;

    auto parsedSize = parseSize(size);
    if (!parsedSize) { printError("--size: expected WxH with integers from 1 to 16384, got '" + size + "'"); return kExitUsage; }
    job.width = parsedSize->width;
    job.height = parsedSize->height;
    auto mode = renderer::parseShadingMode(shading);
    if (!mode) { printError("--shading: unknown mode '" + shading + "' (" + renderer::shadingModeNames() + ")"); return kExitUsage; }
    job.shading.mode = *mode;
    if (!camera.empty()) {
        auto position = parseVec3(camera);
        if (!position) { printError("--camera: expected X,Y,Z, got '" + camera + "'"); return kExitUsage; }
        job.camera.position = *position;
    }
    if (!target.empty()) {
        auto point = parseVec3(target);
        if (!point) { printError("--target: expected X,Y,Z, got '" + target + "'"); return kExitUsage; }
        job.camera.target = *point;
    }
    if (output.quiet) log::setMinimumLevel(log::Level::Warning);
    return runRender(job, output);
}

int runListCommand(int argc, char** argv, int first) {
    CLI::App app("List the dataset's SDFs.", "sdfwb --batch list");
    OutputOptions output;
    addOutputFlags(app, output);
    if (auto exit = parse(app, "--batch list", argc, argv, first)) return *exit;
    if (output.quiet || output.json) log::setMinimumLevel(log::Level::Warning);
    return runList(output);
}

} // namespace

std::optional<int> runCommandLine(int argc, char** argv) {
    if (argc < 2) return std::nullopt;
    const std::string first = argv[1];
    if (first == "--help" || first == "-h") { std::printf("%s", kOverview); return kExitOk; }
    if (first == "--version") { std::printf("sdfwb %s\n", SDFWB_VERSION); return kExitOk; }
    if (first == "--batch") {
        if (argc < 3) { printError("--batch: missing command (render, list); see sdfwb --help"); return kExitUsage; }
        const std::string command = argv[2];
        if (command == "render") return runRenderCommand(argc, argv, 3);
        if (command == "list") return runListCommand(argc, argv, 3);
        if (command == "--help" || command == "-h") { std::printf("%s", kOverview); return kExitOk; }
        printError("--batch: unknown command '" + command + "' (render, list); see sdfwb --help");
        return kExitUsage;
    }
    if (first.rfind("-", 0) == 0) {
        printError("unknown option '" + first + "'; see sdfwb --help");
        return kExitUsage;
    }
    if (argc > 2) {
        printError("unexpected argument '" + std::string(argv[2]) + "': the workbench opens one file; see sdfwb --help");
        return kExitUsage;
    }
    return std::nullopt;  // the workbench, on argv[1]
}

} // namespace sdfwb::app
