// The tracer's programs for SdfRenderer: composed from the SDF and the frame's features,
// compiled, cached by their text (kMaxCachedVariants, least recently used out), and the textures
// the shading reads (matcap, background image).

#include "SdfRendererImpl.h"

#include <core/Log.h>
#include <core/Paths.h>
#include <renderer/ImageIO.h>
#include <shaders/DiagnosticParser.h>
#include <shaders/ShaderComposer.h>

#include <algorithm>
#include <cctype>
#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <string_view>

namespace sdfwb::renderer {
namespace {

constexpr std::size_t kMaxCachedVariants = 16;
constexpr std::ptrdiff_t kFusedMarchFromCharacters = 1000;
// Below this many characters of code, and without loops, an SDF's normal taps are unrolled
// (TracerFeatures::unrolledTaps): the primitives (a box is about 200), whose four more inlined
// copies cost code generation a few milliseconds, draw a full frame about 7 % faster (bench_tracer,
// llvmpipe).
constexpr std::ptrdiff_t kUnrolledTapsBelowCharacters = 400;

// Whether a mesh's own field is drawn by one walk of its hierarchy a pixel (the default) or
// marched like any field: SDFWB_MESH_TRACE=march, for benchmarks (bench/bench_tracer --mesh).
bool meshRaycastEnabled() {
    const char* forced = std::getenv("SDFWB_MESH_TRACE");
    return !(forced && std::string_view(forced) == "march");
}

// Whether the code has a loop (for or while followed by a parenthesis): a loop with a constant
// count is unrolled by the driver, so a short text can still be a large program.
bool hasLoop(const std::string& code) {
    auto identifier = [](char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; };
    for (const std::string_view keyword : {"for", "while"})
        for (std::size_t at = code.find(keyword); at != std::string::npos; at = code.find(keyword, at + 1)) {
            std::size_t next = at + keyword.size();
            while (next < code.size() && std::isspace(static_cast<unsigned char>(code[next]))) ++next;
            if ((at == 0 || !identifier(code[at - 1])) && next < code.size() && code[next] == '(') return true;
        }
    return false;
}

// How the SDF's code is compiled, from its size (with what it includes: a library's helpers reach
// the driver too and cost it time; without comments and white space) and its loops.
struct CodeShape {
    bool fusedMarch = false;   // TracerFeatures::fusedMarch (before settleMarch's trade)
    bool unrolledTaps = false; // TracerFeatures::unrolledTaps: tiny SDFs without loops
};

CodeShape codeShape(const shaders::PreparedSdf& prepared) {
    const std::string code = shaders::stripComments(prepared.source.text);
    const auto characters =
        std::count_if(code.begin(), code.end(), [](char c) { return !std::isspace(static_cast<unsigned char>(c)); });
    CodeShape shape;
    shape.fusedMarch = forcedFusedMarch().value_or(characters > kFusedMarchFromCharacters);
    shape.unrolledTaps = !shape.fusedMarch && characters < kUnrolledTapsBelowCharacters && !hasLoop(code);
    return shape;
}

} // namespace

// Whether the picture marches through sdfwb_traceWithNormal (one call of the SDF for march and
// normal) rather than through the separate march and normal (three calls, each inlined by the
// driver). The fused loop's control costs more per evaluation than the cheapest SDFs do, and
// saves the driver two copies of an SDF: past about a thousand characters of code it pays in
// (bench/bench_tracer, bench/bench_cold_edit). SDFWB_FUSED_MARCH=0/1 overrides, for benchmarks.
std::optional<bool> forcedFusedMarch() {
    const char* forced = std::getenv("SDFWB_FUSED_MARCH");
    if (!forced || !*forced) return std::nullopt;
    return forced[0] == '1';
}

shaders::TracerFeatures tracerFeatures(const values::ShadingSettings& shading, const values::TraceSettings& trace,
                                       const values::CuttingPlane& plane) {
    shaders::TracerFeatures features;
    features.shading = shading.mode;
    features.ambientOcclusion = shading.ambientOcclusion;
    features.overRelaxation = trace.overRelaxation > 1.0f;
    features.stepFactor = trace.stepFactor != 1.0f;
    features.statsOutput = shading.statsOutput;
    features.probe = shading.probe;
    features.backgroundImage = !shading.backgroundImage.empty();
    features.markers = !shading.markers.empty();
    features.cuttingPlane = plane.enabled;
    features.planeClipsSurface = plane.enabled && plane.clipSurface;
    features.planeLipschitzOverlay = plane.enabled && plane.lipschitzOverlay;
    return features;
}

// An image as a linear-filtered, edge-clamped texture.
GlTexture SdfRenderer::Impl::uploadTexture(const Image& image) {
    GLuint id = 0;
    glGenTextures(1, &id);
    GlTexture texture(id);
    glBindTexture(GL_TEXTURE_2D, id);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, image.width, image.height, 0, GL_RGBA, GL_UNSIGNED_BYTE, image.rgba.data());
    glPixelStorei(GL_UNPACK_ALIGNMENT, 4); // the default, which others sharing the context assume (Qt's glyph cache)
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    glBindTexture(GL_TEXTURE_2D, 0);
    return texture;
}

// Loads the matcap image (a name in resources/matcaps or a path) into a texture, once.
void SdfRenderer::Impl::ensureMatcap(const std::string& name) {
    if (matcap && matcapName == name) return;
    std::filesystem::path path = name;
    std::error_code ec;
    if (!std::filesystem::is_regular_file(path, ec)) path = paths::dataRoot() / "resources" / "matcaps" / (name + ".png");
    Image image;
    auto loaded = readImage(path);
    if (loaded) {
        image = std::move(*loaded);
    } else {
        log::warning("render", "matcap '" + name + "': " + loaded.error().message + "; using grey");
        image.width = image.height = 1;
        image.rgba = {160, 160, 160, 255};
    }
    matcap = uploadTexture(image);
    matcapName = name;
}

// Loads the background image once per path; an unreadable one shows the background colour.
void SdfRenderer::Impl::ensureBackground(const std::string& path, const glm::vec3& colour) {
    if (background && backgroundName == path) return;
    Image image;
    auto loaded = readImage(path);
    if (loaded) {
        image = std::move(*loaded);
    } else {
        log::warning("render", "background image: " + loaded.error().message + "; using the background colour");
        image.width = image.height = 1;
        image.rgba = {std::uint8_t(std::clamp(colour.r, 0.0f, 1.0f) * 255.0f),
                      std::uint8_t(std::clamp(colour.g, 0.0f, 1.0f) * 255.0f),
                      std::uint8_t(std::clamp(colour.b, 0.0f, 1.0f) * 255.0f), 255};
    }
    background = uploadTexture(image);
    backgroundName = path;
    backgroundAspect = float(image.width) / float(std::max(image.height, 1));
}

// Builds (or finds) the program for `sdf` with `features`. Null on failure, with diagnostics.
Variant* SdfRenderer::Impl::build(const shaders::PreparedSdf& prepared, shaders::TracerFeatures tracerFeatures,
                                  std::vector<Diagnostic>& diagnostics) {
    const CodeShape shape = codeShape(prepared);
    tracerFeatures.meshRaycast = meshRaycastEnabled();
    const bool meshRaycast = shaders::meshRaycastApplies(prepared, tracerFeatures);
    tracerFeatures.fusedMarch = shape.fusedMarch && !separateChosen && !meshRaycast;
    tracerFeatures.unrolledTaps = shape.unrolledTaps;
    if (meshRaycast) tracerFeatures.cones = false;
    auto fragment = shaders::composeTracer(prepared, tracerFeatures);
    if (!fragment) {
        diagnostics.push_back({"<sdfwb>", 0, 0, shaders::Severity::Error, fragment.error().message});
        return nullptr;
    }
    if (auto it = cache.find(fragment->text); it != cache.end()) {
        it->second.lastUse = ++clock;
        return &it->second;
    }
    const bool compute = fragment->stage == shaders::Stage::Compute;
    if (!compute && !ensureVertexStage(diagnostics)) return nullptr;
    auto start = std::chrono::steady_clock::now();
    CompiledShader fs = compileShader(compute ? GL_COMPUTE_SHADER : GL_FRAGMENT_SHADER, *fragment);
    diagnostics.insert(diagnostics.end(), fs.diagnostics.begin(), fs.diagnostics.end());
    if (shaders::hasErrors(diagnostics)) return nullptr;
    for (shaders::Diagnostic& warning : driverLoopWarnings(prepared, *fragment)) diagnostics.push_back(std::move(warning));

    std::string log;
    GlProgram program = linkProgram({fs.shader.id()}, log, true);
    if (!program) {
        auto linkDiagnostics = shaders::parseInfoLog(log, fragment->map);
        if (!shaders::hasErrors(linkDiagnostics))
            linkDiagnostics.push_back({fragment->map.fileName(0), 0, 0, shaders::Severity::Error, "link failed: " + log});
        diagnostics.insert(diagnostics.end(), linkDiagnostics.begin(), linkDiagnostics.end());
        return nullptr;
    }
    double milliseconds = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    log::info("shaders", "compiled " + prepared.source.map.fileName(0) + " (" + shaders::shadingModeName(tracerFeatures.shading) +
                             (tracerFeatures.ambientOcclusion ? ", AO" : "") + (compute ? ", compute tracer" : "") + ") in " +
                             std::to_string(int(milliseconds)) + " ms");

    ++programsBuilt;
    evictIfFull();
    Variant& variant = cache[fragment->text];
    variant.id = programsBuilt;
    variant.program = std::move(program);
    variant.fragmentSource = fragment->text;
    variant.fusedMarch = tracerFeatures.fusedMarch;
    variant.cones = tracerFeatures.cones;
    variant.meshRaycast = meshRaycast;
    variant.compute = compute;
    variant.lastUse = ++clock;
    return &variant;
}

// The vertex program and the pipeline, made once per context. False, with diagnostics, when
// the driver refuses them.
bool SdfRenderer::Impl::ensureVertexStage(std::vector<Diagnostic>& diagnostics) {
    if (vertexProgram) return true;
    auto vertex = shaders::composeTracerVertex();
    if (!vertex) {
        diagnostics.push_back({"<sdfwb>", 0, 0, shaders::Severity::Error, vertex.error().message});
        return false;
    }
    CompiledShader vs = compileShader(GL_VERTEX_SHADER, *vertex);
    diagnostics.insert(diagnostics.end(), vs.diagnostics.begin(), vs.diagnostics.end());
    if (shaders::hasErrors(vs.diagnostics)) return false;
    std::string log;
    vertexProgram = linkProgram({vs.shader.id()}, log, true);
    if (!vertexProgram) {
        diagnostics.push_back({"<sdfwb>", 0, 0, shaders::Severity::Error, "the tracer's vertex stage did not link: " + log});
        return false;
    }
    GLuint id = 0;
    glGenProgramPipelines(1, &id);
    pipeline = GlProgramPipeline(id);
    glUseProgramStages(id, GL_VERTEX_SHADER_BIT, vertexProgram.id());
    proxyBox = glGetUniformLocation(vertexProgram.id(), "sdfwb_proxyBox");
    proxyClip = glGetUniformLocation(vertexProgram.id(), "sdfwb_proxyClip");
    proxyHalf = glGetUniformLocation(vertexProgram.id(), "sdfwb_proxyHalf");
    return true;
}

void SdfRenderer::Impl::evictIfFull() {
    while (cache.size() >= kMaxCachedVariants) {
        auto oldest = cache.end();
        for (auto it = cache.begin(); it != cache.end(); ++it)
            if (&it->second != current && (oldest == cache.end() || it->second.lastUse < oldest->second.lastUse)) oldest = it;
        if (oldest == cache.end()) return;
        cache.erase(oldest);
    }
}

} // namespace sdfwb::renderer
