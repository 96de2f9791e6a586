#include "BatchCommands.h"

#include <core/Log.h>
#include <core/Paths.h>
#include <dataset/Catalogue.h>
#include <renderer/HeadlessContext.h>
#include <renderer/ImageIO.h>
#include <renderer/OffscreenRenderer.h>
#include <renderer/SdfRenderer.h>
#include <shaders/SdfSource.h>

#include <nlohmann/json.hpp>

#include <chrono>
#include <cstdio>
#include <iostream>

namespace sdfwb::app {
namespace fs = std::filesystem;

void printError(const std::string& message) { std::fprintf(stderr, "sdfwb: %s\n", message.c_str()); }

namespace {

shaders::IncludeOptions includeOptions() {
    shaders::IncludeOptions options;
    options.libraryRoots = {paths::shaderLibraryRoot(), paths::datasetRoot()};
    return options;
}

void printDiagnostics(const std::vector<shaders::Diagnostic>& diagnostics) {
    for (const shaders::Diagnostic& d : diagnostics) std::fprintf(stderr, "%s\n", shaders::formatDiagnostic(d).c_str());
}

} // namespace

int runRender(const RenderJob& job, const OutputOptions& output) {
    auto start = std::chrono::steady_clock::now();
    dataset::Catalogue catalogue = dataset::Catalogue::scan(paths::datasetRoot());
    auto sdfPath = dataset::resolveSdfArgument(job.sdf, catalogue);
    if (!sdfPath) { printError("--sdf: " + sdfPath.error().message); return kExitUsage; }
    fs::path outputPath(job.output);
    if (!renderer::canWriteImageExtension(outputPath.extension().string())) {
        printError("--output: '" + job.output + "': unsupported image type '" + outputPath.extension().string() + "' (use .png, .jpg or .exr)");
        return kExitUsage;
    }
    std::error_code ec;
    fs::path folder = outputPath.parent_path().empty() ? fs::path(".") : outputPath.parent_path();
    if (!fs::is_directory(folder, ec)) { printError("--output: '" + job.output + "': folder '" + folder.string() + "' does not exist"); return kExitUsage; }

    shaders::PreparedSdf sdf = shaders::prepareSdfFile(*sdfPath, includeOptions());
    if (!sdf.ok()) {
        printDiagnostics(sdf.diagnostics);
        printError("render: " + sdfPath->string() + " has errors; nothing written");
        return kExitFailure;
    }
    auto context = renderer::HeadlessContext::create();
    if (!context) { printError(context.error().message); return kExitNoGl; }

    renderer::SdfRenderer sdfRenderer;
    sdfRenderer.setTrace(job.trace);
    (void)sdfRenderer.setShading(job.shading);
    auto diagnostics = sdfRenderer.setSdf(sdf);
    if (shaders::hasErrors(diagnostics)) {
        printDiagnostics(diagnostics);
        printError("render: the driver rejected " + sdfPath->string() + "; nothing written");
        return kExitFailure;
    }
    renderer::FrameStats stats;
    renderer::Image image;
    {
        renderer::OffscreenRenderer offscreen;
        image = offscreen.render(sdfRenderer, job.width, job.height, job.camera, job.time, &stats);
    }
    sdfRenderer.releaseGl();
    if (auto written = renderer::writeImage(outputPath, image); !written) {
        printError(written.error().message);
        return kExitFailure;
    }
    double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (output.json) {
        nlohmann::json report = {{"output", outputPath.string()}, {"sdf", sdfPath->string()},
                                 {"width", job.width}, {"height", job.height},
                                 {"shading", renderer::shadingModeName(job.shading.mode)},
                                 {"frame_ms", stats.cpuMilliseconds}, {"seconds", seconds},
                                 {"gl_renderer", context.value()->info().renderer}};
        std::cout << report.dump(2) << "\n";
    } else if (!output.quiet) {
        std::printf("wrote %s (%dx%d, %s shading, frame %.1f ms, total %.2f s)\n", outputPath.string().c_str(), job.width, job.height,
                    renderer::shadingModeName(job.shading.mode), stats.cpuMilliseconds, seconds);
    }
    return kExitOk;
}

int runList(const OutputOptions& output) {
    dataset::Catalogue catalogue = dataset::Catalogue::scan(paths::datasetRoot());
    for (const std::string& problem : catalogue.problems()) log::warning("dataset", problem);
    if (output.json) {
        nlohmann::json list = nlohmann::json::array();
        for (const dataset::Entry& entry : catalogue.entries())
            list.push_back({{"name", entry.metadata.name}, {"category", entry.metadata.category},
                            {"declared_type", dataset::declaredTypeName(entry.metadata.type)},
                            {"animated", entry.metadata.animated}, {"path", entry.path.string()},
                            {"author", entry.metadata.author}, {"license", entry.metadata.license}});
        std::cout << list.dump(2) << "\n";
    } else {
        for (const dataset::Entry& entry : catalogue.entries())
            std::printf("%-28s %-13s %-12s %s\n", entry.metadata.name.c_str(), entry.metadata.category.c_str(),
                        dataset::declaredTypeName(entry.metadata.type), entry.metadata.animated ? "animated" : "");
        if (!output.quiet) std::printf("%zu SDFs in %s\n", catalogue.entries().size(), paths::datasetRoot().string().c_str());
    }
    return catalogue.entries().empty() ? kExitFailure : kExitOk;
}

} // namespace sdfwb::app
