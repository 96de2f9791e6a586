#include <renderer/SdfRenderer.h>

#include "SdfRendererImpl.h"

#include <core/Log.h>
#include <core/Parallel.h>
#include <meshfield/MeshQuery.h>
#include <renderer/GlInfo.h>

#include <glm/geometric.hpp>
#include <glm/mat4x4.hpp>
#include <glm/matrix.hpp>
#include <glm/trigonometric.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdlib>

namespace sdfwb::renderer {

// Whether a cone pass can serve these settings: not for the march debugger or the step heat
// map, which show each pixel's own march.
bool conesApply(const values::ShadingSettings& shading, const values::TraceSettings& trace) {
    return trace.coneTile > 0 && trace.cones != values::TraceSettings::Cones::Off && !shading.probe &&
           shading.mode != shaders::ShadingMode::Steps;
}

// Whether a frame may be drawn as the box's far faces over a cleared background (trace.vert),
// which leaves every pixel whose ray misses the box the background: not where the picture shows
// something else there (a background image, markers, the step heat map's misses, the measurement
// outputs, the march debugger). The cutting plane is drawn only inside the box (plane.glsl).
bool boxProxyApplies(const values::ShadingSettings& shading, const values::TraceSettings& trace) {
    return trace.boxProxy && shading.backgroundImage.empty() && shading.markers.empty() &&
           shading.mode != shaders::ShadingMode::Steps && !shading.statsOutput && !shading.probe;
}

// World to clip space for trace.vert's proxy box, for a frame of the given aspect: x and y as
// sdfwb_primaryRay spreads the rays over the frame, w the depth along the view, and z = w - wNear,
// which clips only what lies nearer than wNear / 2, where wNear is the least depth of a point at
// the near plane that the frame shows (at its corners). Nothing is clipped at the far side: the
// tracer clips the rays there.
glm::mat4 proxyClip(const values::Camera& camera, const values::CameraBasis& basis, float aspect) {
    const float tanHalf = std::tan(glm::radians(camera.fovYDegrees) * 0.5f);
    const float wNear = camera.nearPlane / std::sqrt(1.0f + tanHalf * tanHalf * (1.0f + aspect * aspect));
    auto row = [&camera](glm::vec3 axis) { return glm::vec4(axis, -glm::dot(axis, camera.position)); };
    const glm::vec4 w = row(basis.forward);
    return glm::transpose(
        glm::mat4(row(basis.right / (aspect * tanHalf)), row(basis.up / tanHalf), w - glm::vec4(0, 0, 0, wNear), w));
}

SdfRenderer::SdfRenderer() : m_impl(std::make_unique<Impl>()) {
    const char* blit = std::getenv("SDFWB_COMPUTE_BLIT");
    m_impl->computeViaBlit = blit && blit[0] == '1';
}

SdfRenderer::~SdfRenderer() {
    // GL names cannot be freed without the context; the owner calls releaseGl() first.
    m_impl->frameTimer.release();
    m_impl->frameQueries.release();
    for (auto& [text, variant] : m_impl->cache) variant.program.release();
    m_impl->vertexArray.release();
    m_impl->vertexProgram.release();
    m_impl->pipeline.release();
    m_impl->matcap.release();
    m_impl->background.release();
    m_impl->textures.release();
    m_impl->lowFramebuffer.release();
    m_impl->lowColor.release();
    m_impl->coneStarts.release();
    m_impl->computeColor.release();
    m_impl->computeFramebuffer.release();
    m_impl->planeField.release();
    m_impl->planeFieldMesh.reset();
}

std::vector<Diagnostic> SdfRenderer::setSdf(const shaders::PreparedSdf& sdf) {
    std::vector<Diagnostic> diagnostics = sdf.diagnostics;
    if (shaders::hasErrors(diagnostics)) return diagnostics;
    const bool separateBefore = m_impl->separateChosen, conesBefore = m_impl->conesChosen;
    const bool computeBefore = m_impl->computeChosen;
    m_impl->separateChosen = false; // a new SDF starts with the quickest code generation
    // An edit of the same file keeps the cone pass its last version kept (its code generation
    // costs next to nothing more, and a dear SDF's frames stay fast while it is edited).
    const bool sameFile = m_impl->sdf && m_impl->sdf->source.map.fileName(0) == sdf.source.map.fileName(0);
    m_impl->conesChosen = conesBefore && sameFile;
    m_impl->computeChosen = computeBefore && sameFile; // the same for the compute tracer
    Variant* variant = m_impl->build(sdf, m_impl->features(m_shading, m_trace, m_plane), diagnostics);
    if (!variant) {
        m_impl->separateChosen = separateBefore; // the last good SDF keeps its program
        m_impl->conesChosen = conesBefore;
        m_impl->computeChosen = computeBefore;
        return diagnostics;
    }
    m_impl->sdf = sdf;
    m_impl->current = variant;
    m_impl->settle = Impl::Settle::Open;
    return diagnostics;
}

bool SdfRenderer::fusedMarch() const { return m_impl->current && m_impl->current->fusedMarch; }

bool SdfRenderer::conePass() const { return m_impl->current && m_impl->current->cones; }

bool SdfRenderer::computeTracer() const { return m_impl->current && m_impl->current->compute; }

bool SdfRenderer::marchSettled() const { return m_impl->settle == Impl::Settle::Done; }

bool SdfRenderer::settleMarch(double fullFrameMilliseconds) {
    Impl& impl = *m_impl;
    if (!impl.sdf || !impl.current || impl.settle == Impl::Settle::Done) return false;
    auto rebuild = [&] {
        std::vector<Diagnostic> ignored;
        Variant* variant = impl.build(*impl.sdf, impl.features(m_shading, m_trace, m_plane), ignored);
        if (variant) impl.current = variant;
        return variant != nullptr;
    };
    auto milliseconds = [](double value) { return std::to_string(int(std::lround(value))); };
    // Starts a trial of the program `chosen` selects, drawn at the next full frame; false (the
    // program before stays, from the cache) when the driver refuses it.
    auto startTrial = [&](bool& chosen, Impl::Settle trying, const std::string& message) {
        chosen = true;
        if (!rebuild()) {
            chosen = false;
            rebuild();
            return false;
        }
        impl.settle = trying;
        log::info("render", "trying " + message);
        return true;
    };
    // Ends the open trial: the tried program stays when its full frame was no slower than the best
    // so far, else `chosen` is dropped and the program before comes back. Returns whether it stayed.
    auto endTrial = [&](bool& chosen, const char* what, const char* before) {
        const bool keep = fullFrameMilliseconds <= impl.bestMilliseconds;
        log::info("render", std::string(keep ? "keeping " : "dropping ") + what + ": " + milliseconds(fullFrameMilliseconds) +
                                " ms a full frame against " + milliseconds(impl.bestMilliseconds) + " " + before);
        if (keep) {
            impl.bestMilliseconds = fullFrameMilliseconds;
        } else {
            chosen = false;
            rebuild();
        }
        return keep;
    };
    // The last trial: the compute tracer instead of the fragment program chosen so far, where it
    // can draw these frames. Returns whether the program changed.
    auto tryCompute = [&] {
        impl.settle = Impl::Settle::Done;
        if (m_trace.tracer != values::TraceSettings::Tracer::Auto || impl.computeChosen || impl.current->compute) return false;
        impl.computeChosen = true;
        const bool applies = impl.features(m_shading, m_trace, m_plane).compute;
        impl.computeChosen = false;
        return applies && startTrial(impl.computeChosen, Impl::Settle::TryingCompute,
                                     "the compute tracer: a full frame took " + milliseconds(impl.bestMilliseconds) +
                                         " ms with the fragment tracer");
    };
    // The cone pass on the march chosen so far, then the compute tracer.
    auto tryCones = [&] {
        if (m_trace.cones != values::TraceSettings::Cones::Auto || !conesApply(m_shading, m_trace) || impl.conesChosen ||
            impl.current->meshRaycast || impl.current->compute)
            return tryCompute();
        return startTrial(impl.conesChosen, Impl::Settle::TryingCones,
                          "the cone pass: a full frame took " + milliseconds(impl.bestMilliseconds) + " ms without") ||
               tryCompute();
    };
    switch (impl.settle) {
    case Impl::Settle::Open:
        impl.bestMilliseconds = fullFrameMilliseconds;
        if (!forcedFusedMarch() && fusedMarch() && fullFrameMilliseconds < kTrySeparateMarchBelowMilliseconds &&
            startTrial(impl.separateChosen, Impl::Settle::TryingSeparate,
                       "the separate march: the fused one drew a full frame in " + milliseconds(fullFrameMilliseconds) + " ms"))
            return true;
        return tryCones();
    case Impl::Settle::ConesOpen:
        impl.bestMilliseconds = fullFrameMilliseconds;
        return tryCones();
    case Impl::Settle::TryingSeparate: {
        const bool keep = endTrial(impl.separateChosen, "the separate march", "fused");
        return tryCones() || !keep;
    }
    case Impl::Settle::TryingCones: {
        const bool keep = endTrial(impl.conesChosen, "the cone pass", "without");
        return tryCompute() || !keep;
    }
    case Impl::Settle::TryingCompute:
        impl.settle = Impl::Settle::Done;
        return !endTrial(impl.computeChosen, "the compute tracer", "with the fragment tracer");
    case Impl::Settle::Done:
        break;
    }
    return false;
}

std::vector<Diagnostic> SdfRenderer::setShading(const values::ShadingSettings& shading) {
    m_shading = shading;
    std::vector<Diagnostic> diagnostics;
    if (!m_impl->sdf) return diagnostics;
    if (Variant* variant = m_impl->build(*m_impl->sdf, m_impl->features(m_shading, m_trace, m_plane), diagnostics))
        m_impl->current = variant;
    return diagnostics;
}

bool SdfRenderer::hasProgram() const { return m_impl->current != nullptr; }

const std::string& SdfRenderer::fragmentSource() const {
    return m_impl->current ? m_impl->current->fragmentSource : m_impl->empty;
}

// The frame's uniforms: resolution, camera, trace settings, time, the SDF's parameters and
// textures, the plane, the light and the markers.
void SdfRenderer::Impl::setFrameUniforms(Variant& variant, const FrameInputs& in, int width, int height,
                                         const values::Camera& camera, const values::CameraBasis& basis, float time) {
    Variant* v = &variant;
    const values::TraceSettings& trace = in.trace;
    const values::ShadingSettings& shading = in.shading;
    const values::CuttingPlane& plane = in.plane;
    glUniform2f(v->location("sdfwb_resolution"), float(width), float(height));
    glUniform3f(v->location("sdfwb_cameraPosition"), camera.position.x, camera.position.y, camera.position.z);
    glUniform3f(v->location("sdfwb_cameraRight"), basis.right.x, basis.right.y, basis.right.z);
    glUniform3f(v->location("sdfwb_cameraUp"), basis.up.x, basis.up.y, basis.up.z);
    glUniform3f(v->location("sdfwb_cameraForward"), basis.forward.x, basis.forward.y, basis.forward.z);
    glUniform1f(v->location("sdfwb_tanHalfFovY"), std::tan(glm::radians(camera.fovYDegrees) * 0.5f));
    glUniform1f(v->location("sdfwb_nearPlane"), camera.nearPlane);
    glUniform1f(v->location("sdfwb_farPlane"), camera.farPlane);
    glUniform1i(v->location("sdfwb_maxSteps"), trace.maxSteps);
    if (GLint location = v->location("sdfwb_stepFactor"); location >= 0) glUniform1f(location, trace.stepFactor);
    glUniform1f(v->location("sdfwb_epsilonScale"), trace.epsilonScale);
    glUniform1f(v->location("sdfwb_boxMargin"), trace.boxMargin);
    glUniform3f(v->location("sdfwb_background"), shading.background.r, shading.background.g, shading.background.b);
    if (GLint location = v->location("sdfwb_time"); location >= 0) glUniform1f(location, time);
    for (const char* name : {"g3d_SceneTime", "iTime"}) // declared by the file, or uniforms its macro wraps
        if (GLint location = v->location(name); location >= 0) glUniform1f(location, time);
    applyParameters(in.parameters, [v](const char* name) { return v->location(name); });
    bindSdfTextures(v->program.id(), textures, sdf ? sdf->channels : decltype(sdf->channels){}, sdf ? sdf->mesh : nullptr);
    if (GLint location = v->location("sdfwb_relaxation"); location >= 0) glUniform1f(location, trace.overRelaxation);
    if (plane.enabled) {
        glm::vec3 normal = glm::length(plane.normal) > 0.0f ? glm::normalize(plane.normal) : glm::vec3(0, 0, 1);
        for (const char* name : {"sdfwb_planeNormal", "sdfwb_clipNormal"})
            if (GLint location = v->location(name); location >= 0) glUniform3f(location, normal.x, normal.y, normal.z);
        for (const char* name : {"sdfwb_planeOffset", "sdfwb_clipOffset"})
            if (GLint location = v->location(name); location >= 0) glUniform1f(location, plane.offset);
        if (GLint location = v->location("sdfwb_contourSpacing"); location >= 0)
            glUniform1f(location, std::max(plane.contourSpacing, 1e-6f));
        if (GLint location = v->location("sdfwb_rampDistance"); location >= 0)
            glUniform1f(location, std::max(plane.rampDistance, 1e-6f));
        if (GLint location = v->location("sdfwb_planeField"); location >= 0 && sdf && sdf->mesh) {
            ensurePlaneField(normal, plane.offset, trace.boxMargin);
            glActiveTexture(GL_TEXTURE3); // 0 to 2: the matcap, the background image, the cone starts
            glBindTexture(GL_TEXTURE_2D, planeField.id());
            glActiveTexture(GL_TEXTURE0);
            glUniform1i(location, 3);
            glUniform3fv(v->location("sdfwb_planeFieldOrigin"), 1, &planeFieldOrigin.x);
            glUniform3fv(v->location("sdfwb_planeFieldU"), 1, &planeFieldU.x);
            glUniform3fv(v->location("sdfwb_planeFieldV"), 1, &planeFieldV.x);
            glUniform1f(v->location("sdfwb_planeFieldHalfTexel"), 0.5f / float(kPlaneFieldSize));
        }
    }
    if (GLint location = v->location("sdfwb_lightDirection"); location >= 0) {
        glm::vec3 light = glm::normalize(shading.lightDirection);
        glUniform3f(location, light.x, light.y, light.z);
    }
    if (GLint location = v->location("sdfwb_curvatureScale"); location >= 0) glUniform1f(location, shading.curvatureScale);
    if (GLint location = v->location("sdfwb_markers"); location >= 0) {
        const GLsizei count = GLsizei(std::min<std::size_t>(shading.markers.size(), 16));
        if (count > 0) glUniform3fv(location, count, &shading.markers[0].x);
        glUniform1i(v->location("sdfwb_markerCount"), count);
    }
}

// The field of the mesh on the plane dot(normal, p) = offset, over the rectangle of the plane that
// holds the box's cross-section, on the CPU engine (MeshQuery: the same values as the field's
// samples): f, |f| and, on an open or non-manifold mesh, the winding number (plane.glsl hatches
// where it is near 1/2); computed again only when the plane, the box or the mesh changes.
void SdfRenderer::Impl::ensurePlaneField(const glm::vec3& normal, float offset, float margin) {
    const glm::vec4 plane(normal, offset);
    if (planeField && planeFieldMesh == sdf->mesh && planeFieldPlane == plane && planeFieldMargin == margin) return;
    const auto start = std::chrono::steady_clock::now();
    const glm::vec3 axis = std::abs(normal.x) < 0.6f ? glm::vec3(1, 0, 0) : glm::vec3(0, 1, 0);
    const glm::vec3 u = glm::normalize(glm::cross(normal, axis)), v = glm::cross(normal, u);
    const float half = 1.0f + margin;
    glm::vec2 lo(1e30f), hi(-1e30f);
    for (int corner = 0; corner < 8; ++corner) {
        const glm::vec3 c((corner & 1) ? half : -half, (corner & 2) ? half : -half, (corner & 4) ? half : -half);
        const glm::vec2 at(glm::dot(c, u), glm::dot(c, v));
        lo = glm::min(lo, at);
        hi = glm::max(hi, at);
    }
    constexpr int n = kPlaneFieldSize;
    const glm::vec2 step = (hi - lo) / float(n - 1);
    const glm::vec3 origin = normal * offset + lo.x * u + lo.y * v;
    std::vector<float> positions(std::size_t(n) * n * 3);
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
            const glm::vec3 p = origin + (float(i) * step.x) * u + (float(j) * step.y) * v;
            std::copy(&p.x, &p.x + 3, positions.begin() + (std::ptrdiff_t(j) * n + i) * 3);
        }
    std::vector<float> texels(std::size_t(n) * n * 4);
    const auto query = meshfield::meshQuery(sdf->mesh);
    meshfield::RowView rows;
    rows.positions = positions.data();
    rows.distances = texels.data();
    rows.distanceStride = 4;
    (void)query->evaluate(rows, std::size_t(n) * n, {});
    const bool windings = !sdf->mesh->closed();
    forEachChunk(std::size_t(n) * n, chunkCount(std::size_t(n) * n, 4096), [&](std::size_t, std::size_t begin, std::size_t end) {
        for (std::size_t k = begin; k < end; ++k) {
            float* texel = &texels[k * 4];
            texel[1] = std::abs(texel[0]);
            texel[2] = windings ? float(query->winding(glm::dvec3(positions[k * 3], positions[k * 3 + 1], positions[k * 3 + 2])))
                                : (texel[0] < 0.0f ? 1.0f : 0.0f);
        }
    });
    if (!planeField) {
        GLuint id = 0;
        glGenTextures(1, &id);
        planeField = GlTexture(id);
    }
    glBindTexture(GL_TEXTURE_2D, planeField.id());
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA32F, n, n, 0, GL_RGBA, GL_FLOAT, texels.data());
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    glBindTexture(GL_TEXTURE_2D, 0);
    planeFieldMesh = sdf->mesh;
    planeFieldPlane = plane;
    planeFieldMargin = margin;
    planeFieldOrigin = origin;
    planeFieldU = u / (step.x * float(n));
    planeFieldV = v / (step.y * float(n));
    const double milliseconds = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    planeFieldMilliseconds = milliseconds;
    log::info("render", "plane field: " + std::to_string(n) + "x" + std::to_string(n) + " points on the CPU engine in " +
                            std::to_string(int(std::lround(milliseconds))) + " ms");
}

// The matcap and the background image, on texture units 0 and 1.
void SdfRenderer::Impl::bindShadingTextures(Variant& variant, const values::ShadingSettings& shading, int width, int height) {
    Variant* v = &variant;
    if (GLint location = v->location("sdfwb_matcap"); location >= 0) {
        ensureMatcap(shading.matcap);
        glActiveTexture(GL_TEXTURE0);
        glBindTexture(GL_TEXTURE_2D, matcap.id());
        glUniform1i(location, 0);
    }
    if (GLint location = v->location("sdfwb_backgroundImage"); location >= 0) {
        glActiveTexture(GL_TEXTURE1); // loading it binds on the active unit: not the matcap's
        ensureBackground(shading.backgroundImage, shading.background);
        glBindTexture(GL_TEXTURE_2D, background.id());
        glUniform1i(location, 1);
        glActiveTexture(GL_TEXTURE0);
        // Cover the frame, centred: the image's shorter side fits, the longer one is cropped.
        const float frameAspect = float(width) / float(std::max(height, 1));
        const float ratio = backgroundAspect / frameAspect;
        if (ratio < 1.0f)
            glUniform4f(v->location("sdfwb_backgroundFit"), 1.0f, ratio, 0.0f, 0.5f * (1.0f - ratio));
        else
            glUniform4f(v->location("sdfwb_backgroundFit"), 1.0f / ratio, 1.0f, 0.5f * (1.0f - 1.0f / ratio), 0.0f);
    }
}

// The cone pass (trace_core.glsl): one cone per tile of coneTile^2 pixels finds where the picture's
// rays may start. Drawn into the target's lower-left corner, then copied into the texture the
// picture reads. It draws into the same framebuffer with the same state as the picture, so the
// driver compiles one variant of the program for both.
void SdfRenderer::Impl::drawConePass(Variant& variant, const values::TraceSettings& trace, const values::Camera& camera,
                                     int width, int height) {
    Variant* v = &variant;
    const GLuint vertexProgram = this->vertexProgram.id();
    const int coneTile = std::max(trace.coneTile, 1);
    const int tilesWide = (width + coneTile - 1) / coneTile, tilesHigh = (height + coneTile - 1) / coneTile;
    glActiveTexture(GL_TEXTURE2);                                         // units 0 and 1 hold the matcap and the background
    if (!coneStarts || coneWidth < tilesWide || coneHeight < tilesHigh) { // grown, never shrunk
        coneWidth = std::max(coneWidth, tilesWide);
        coneHeight = std::max(coneHeight, tilesHigh);
        coneStarts = makeColorTexture(coneWidth, coneHeight, GL_NEAREST);
    }
    glBindTexture(GL_TEXTURE_2D, coneStarts.id());
    glActiveTexture(GL_TEXTURE0);
    glUniform1i(v->location("sdfwb_coneStarts"), 2);
    glUniform1i(v->location("sdfwb_coneTile"), coneTile);
    // Past every point of the box (and its margin) seen from the camera.
    glUniform1f(v->location("sdfwb_coneRange"), glm::length(camera.position) + std::sqrt(3.0f) * (1.0f + trace.boxMargin) + 1.0f);
    glUniform1i(v->location("sdfwb_conePass"), 1);
    glProgramUniform1i(vertexProgram, proxyBox, 0); // every tile has its cone
    glViewport(0, 0, tilesWide, tilesHigh);
    glDrawArrays(GL_TRIANGLES, 0, 3);
    // Copied from the framebuffer just drawn, whatever the caller left bound for reading.
    GLint target = 0, reading = 0;
    glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &target);
    glGetIntegerv(GL_READ_FRAMEBUFFER_BINDING, &reading);
    glBindFramebuffer(GL_READ_FRAMEBUFFER, GLuint(target));
    glActiveTexture(GL_TEXTURE2);
    glCopyTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, 0, 0, tilesWide, tilesHigh);
    glActiveTexture(GL_TEXTURE0);
    glBindFramebuffer(GL_READ_FRAMEBUFFER, GLuint(reading));
    glViewport(0, 0, width, height);
    glUniform1i(v->location("sdfwb_conePass"), 0);
}

// The picture: over the box's far faces (only the pixels whose ray meets the box run the tracer)
// when the box proxy applies, else over the whole frame. Returns whether the proxy applied.
bool SdfRenderer::Impl::drawPicture(const values::ShadingSettings& shading, const values::TraceSettings& trace,
                                    const values::Camera& camera, const values::CameraBasis& basis, int width, int height) {
    const GLuint vertexProgram = this->vertexProgram.id();
    const bool boxProxy = boxProxyApplies(shading, trace);
    glProgramUniform1i(vertexProgram, proxyBox, boxProxy ? 1 : 0);
    if (boxProxy) {
        // Only the pixels whose ray meets the box run the tracer (the box's far faces: one
        // fragment a pixel, wherever the camera is); the rest are the background already.
        // Cleared where this frame draws (a scaled frame: the target's corner).
        glEnable(GL_SCISSOR_TEST);
        glScissor(0, 0, width, height);
        glClearColor(shading.background.r, shading.background.g, shading.background.b, 1.0f);
        glClear(GL_COLOR_BUFFER_BIT);
        glDisable(GL_SCISSOR_TEST);
        const glm::mat4 clip = renderer::proxyClip(camera, basis, float(width) / float(std::max(height, 1)));
        glProgramUniformMatrix4fv(vertexProgram, proxyClip, 1, GL_FALSE, &clip[0][0]);
        // A little over the traced box, so that no pixel on its outline is lost to rounding.
        glProgramUniform1f(vertexProgram, proxyHalf, (1.0f + trace.boxMargin) * 1.001f);
        glEnable(GL_CULL_FACE);
        glCullFace(GL_FRONT);
        glFrontFace(GL_CCW);
        glDrawArrays(GL_TRIANGLES, 0, 36);
        glCullFace(GL_BACK);
        glDisable(GL_CULL_FACE);
    } else {
        glDrawArrays(GL_TRIANGLES, 0, 3);
    }
    return boxProxy;
}

// The compute tracer's frame (trace_main.frag, SDFWB_COMPUTE): one invocation a pixel in 8x8
// groups, into a float image, then blitted over the bound draw framebuffer, whose format rounds
// (or keeps) the values as the fragment tracer's output would be.
void SdfRenderer::Impl::ensureComputeTarget(int width, int height) {
    if (computeColor && computeWidth >= width && computeHeight >= height) return; // grown, never shrunk
    GLint reading = 0;
    glGetIntegerv(GL_READ_FRAMEBUFFER_BINDING, &reading);
    computeWidth = std::max(computeWidth, width);
    computeHeight = std::max(computeHeight, height);
    computeColor = makeColorTexture(computeWidth, computeHeight, GL_NEAREST, GL_RGBA32F);
    GLuint id = 0;
    glGenFramebuffers(1, &id);
    computeFramebuffer = GlFramebuffer(id);
    glBindFramebuffer(GL_READ_FRAMEBUFFER, id);
    glFramebufferTexture2D(GL_READ_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, computeColor.id(), 0);
    glBindFramebuffer(GL_READ_FRAMEBUFFER, GLuint(reading));
}

namespace {

// The bound draw framebuffer's colour texture, when the compute tracer can store into it as an
// image: a single-sampled 2D texture (or a layer of one) of a format whose stores round as a draw
// would (RGBA8, RGBA16F, RGBA32F). format 0: none (the default framebuffer, a renderbuffer, a
// multisampled or sRGB target, or a driver without the queries), and the frame goes through the
// float image and a blit.
struct ImageTarget {
    GLuint texture = 0;
    GLint level = 0, layer = 0;
    GLenum format = 0;
};

ImageTarget drawTargetImage() {
    GLint framebuffer = 0, samples = 0;
    glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &framebuffer);
    if (framebuffer == 0) return {};
    static const bool queries = epoxy_gl_version() >= 45 || epoxy_has_gl_extension("GL_ARB_direct_state_access");
    if (!queries) return {};
    glGetIntegerv(GL_SAMPLES, &samples);
    // The blit writes where glDrawBuffers points; the store writes attachment 0.
    GLint drawBuffer = 0;
    glGetIntegerv(GL_DRAW_BUFFER0, &drawBuffer);
    if (drawBuffer != GL_COLOR_ATTACHMENT0) return {};
    GLint type = 0, name = 0, layered = 0, cubeFace = 0;
    auto attachment = [](GLenum what, GLint* value) {
        glGetFramebufferAttachmentParameteriv(GL_DRAW_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, what, value);
    };
    attachment(GL_FRAMEBUFFER_ATTACHMENT_OBJECT_TYPE, &type);
    if (samples != 0 || type != GL_TEXTURE) return {};
    ImageTarget image;
    attachment(GL_FRAMEBUFFER_ATTACHMENT_OBJECT_NAME, &name);
    attachment(GL_FRAMEBUFFER_ATTACHMENT_TEXTURE_LEVEL, &image.level);
    attachment(GL_FRAMEBUFFER_ATTACHMENT_TEXTURE_LAYER, &image.layer);
    attachment(GL_FRAMEBUFFER_ATTACHMENT_LAYERED, &layered);
    attachment(GL_FRAMEBUFFER_ATTACHMENT_TEXTURE_CUBE_MAP_FACE, &cubeFace);
    GLint target = 0, format = 0, immutable = 0, filter = 0, base = 0;
    glGetTextureParameteriv(GLuint(name), GL_TEXTURE_TARGET, &target);
    glGetTextureLevelParameteriv(GLuint(name), image.level, GL_TEXTURE_INTERNAL_FORMAT, &format);
    // Stores into a texture that is not complete do nothing: one of immutable storage, or one
    // whose filter reads no mipmaps (a framebuffer library's usual texture) drawn at its base level.
    glGetTextureParameteriv(GLuint(name), GL_TEXTURE_IMMUTABLE_FORMAT, &immutable);
    glGetTextureParameteriv(GLuint(name), GL_TEXTURE_MIN_FILTER, &filter);
    glGetTextureParameteriv(GLuint(name), GL_TEXTURE_BASE_LEVEL, &base);
    const bool complete = immutable || ((filter == GL_NEAREST || filter == GL_LINEAR) && image.level == base);
    const bool planar = (target == GL_TEXTURE_2D || target == GL_TEXTURE_2D_ARRAY) && !layered && cubeFace == 0;
    if (!planar || !complete || (format != GL_RGBA8 && format != GL_RGBA16F && format != GL_RGBA32F)) return {};
    image.texture = GLuint(name);
    image.format = GLenum(format);
    return image;
}

// The compute tracer's frame stored straight into the draw framebuffer's texture.
void traceInto(const ImageTarget& image, int width, int height) {
    glBindImageTexture(0, image.texture, image.level, GL_FALSE, image.layer, GL_WRITE_ONLY, image.format);
    glDispatchCompute(GLuint((width + 7) / 8), GLuint((height + 7) / 8), 1);
    glMemoryBarrier(GL_FRAMEBUFFER_BARRIER_BIT | GL_TEXTURE_FETCH_BARRIER_BIT | GL_TEXTURE_UPDATE_BARRIER_BIT);
    glBindImageTexture(0, 0, 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA32F);
}

} // namespace

void SdfRenderer::Impl::traceCompute(int width, int height) {
    GLint target = 0, reading = 0;
    glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &target);
    glGetIntegerv(GL_READ_FRAMEBUFFER_BINDING, &reading);
    glBindImageTexture(0, computeColor.id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA32F);
    glDispatchCompute(GLuint((width + 7) / 8), GLuint((height + 7) / 8), 1);
    glMemoryBarrier(GL_FRAMEBUFFER_BARRIER_BIT | GL_TEXTURE_FETCH_BARRIER_BIT);
    glBindImageTexture(0, 0, 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA32F);
    glBindFramebuffer(GL_READ_FRAMEBUFFER, computeFramebuffer.id());
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, GLuint(target));
    glBlitFramebuffer(0, 0, width, height, 0, 0, width, height, GL_COLOR_BUFFER_BIT, GL_NEAREST);
    glBindFramebuffer(GL_READ_FRAMEBUFFER, GLuint(reading));
}

FrameStats SdfRenderer::render(int width, int height, const values::Camera& camera, float time, bool finish) {
    auto start = std::chrono::steady_clock::now();
    FrameStats stats;
    if (finish) m_impl->frameTimer.begin();
    stats.serial = m_impl->beginQueryFrame(finish);
    glViewport(0, 0, width, height);
    glDisable(GL_DEPTH_TEST);
    glDisable(GL_BLEND);
    if (!m_impl->current && m_impl->sdf) {
        // After releaseGl() (a new context): rebuild the last good variant.
        std::vector<Diagnostic> ignored;
        m_impl->current = m_impl->build(*m_impl->sdf, m_impl->features(m_shading, m_trace, m_plane), ignored);
    }
    if (!m_impl->current) {
        // Nothing to trace: the background.
        glClearColor(m_shading.background.r, m_shading.background.g, m_shading.background.b, 1.0f);
        glClear(GL_COLOR_BUFFER_BIT);
    }
    if (Variant* v = m_impl->current) {
        if (!m_impl->vertexArray) {
            GLuint id = 0;
            glGenVertexArrays(1, &id);
            m_impl->vertexArray = GlVertexArray(id);
        }
        const values::CameraBasis basis = cameraBasis(camera);
        if (v->compute) {
            // The float image, when the frame needs one, is made first: making it rebinds the
            // active texture unit.
            const ImageTarget image = m_impl->computeViaBlit ? ImageTarget{} : drawTargetImage();
            if (!image.format) m_impl->ensureComputeTarget(width, height);
            glBindProgramPipeline(0);
            glUseProgram(v->program.id());
            m_impl->setFrameUniforms(*v, {m_shading, m_trace, m_plane, m_parameters}, width, height, camera, basis, time);
            m_impl->bindShadingTextures(*v, m_shading, width, height);
            stats.storedInTarget = image.format != 0;
            if (image.format)
                traceInto(image, width, height);
            else
                m_impl->traceCompute(width, height);
            glUseProgram(0);
        } else {
            // The variant's fragment program with the shared vertex program; glUniform* reach the
            // fragment program (the active one), the vertex stage's uniforms are set by name.
            const GLuint pipeline = m_impl->pipeline.id();
            glUseProgram(0);
            glBindProgramPipeline(pipeline);
            glUseProgramStages(pipeline, GL_FRAGMENT_SHADER_BIT, v->program.id());
            glActiveShaderProgram(pipeline, v->program.id());
            m_impl->setFrameUniforms(*v, {m_shading, m_trace, m_plane, m_parameters}, width, height, camera, basis, time);
            m_impl->bindShadingTextures(*v, m_shading, width, height);
            glBindVertexArray(m_impl->vertexArray.id());
            // Blending that changes nothing (source times one, plus zero): llvmpipe generates an
            // opaque draw's fragment code twice (for whole tiles and for edge tiles), a blended one
            // once, which halves a new program's first-draw stall (trefoil knot 177 ms to 96, torus 78
            // to 45) for about 3 % on the cheapest SDFs' frames.
            glEnable(GL_BLEND);
            glBlendEquation(GL_FUNC_ADD);
            glBlendFunc(GL_ONE, GL_ZERO);
            if (v->cones) m_impl->drawConePass(*v, m_trace, camera, width, height);
            stats.boxProxy = m_impl->drawPicture(m_shading, m_trace, camera, basis, width, height);
            glDisable(GL_BLEND);
            glBindVertexArray(0);
            glBindProgramPipeline(0);
        }
    }
    if (finish) {
        m_impl->frameTimer.end();
        glFinish();
    }
    if (stats.serial) m_impl->frameQueries.end();
    logGlErrors("a frame");
    stats.cpuMilliseconds = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    if (finish) stats.gpuMilliseconds = m_impl->frameTimer.milliseconds(stats.cpuMilliseconds);
    return stats;
}

FrameStats SdfRenderer::renderScaled(int width, int height, float scale, const values::Camera& camera, float time, bool finish) {
    if (scale >= 0.999f) return render(width, height, camera, time, finish);
    auto start = std::chrono::steady_clock::now();
    if (finish) m_impl->frameTimer.begin();
    const std::uint64_t serial = m_impl->beginQueryFrame(finish);
    int lowWidth = std::max(1, int(std::lround(width * scale)));
    int lowHeight = std::max(1, int(std::lround(height * scale)));
    GLint target = 0;
    glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &target);
    Impl& impl = *m_impl;
    if (!impl.lowFramebuffer || impl.lowWidth != lowWidth || impl.lowHeight != lowHeight) {
        makeColorTarget(lowWidth, lowHeight, GL_LINEAR, impl.lowColor, impl.lowFramebuffer);
        impl.lowWidth = lowWidth;
        impl.lowHeight = lowHeight;
    }
    // Traced into the target itself (its lower-left corner), then copied out and stretched over
    // it: the draw sees the very framebuffer a full frame does (formats, depth and stencil), so
    // the driver reuses one compiled variant of the program for every scale. (llvmpipe
    // generates code per framebuffer configuration: a separate low-resolution target made it
    // compile every SDF twice, once for the timing frame and once for the full one.)
    glBindFramebuffer(GL_FRAMEBUFFER, GLuint(target));
    impl.insideScaled = true;
    const FrameStats low = render(lowWidth, lowHeight, camera, time, false);
    impl.insideScaled = false;
    glBindTexture(GL_TEXTURE_2D, impl.lowColor.id());
    glCopyTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, 0, 0, lowWidth, lowHeight);
    glBindTexture(GL_TEXTURE_2D, 0);
    glBindFramebuffer(GL_READ_FRAMEBUFFER, impl.lowFramebuffer.id());
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, GLuint(target));
    glViewport(0, 0, width, height);
    glBlitFramebuffer(0, 0, lowWidth, lowHeight, 0, 0, width, height, GL_COLOR_BUFFER_BIT, GL_LINEAR);
    glBindFramebuffer(GL_FRAMEBUFFER, GLuint(target));
    if (finish) {
        m_impl->frameTimer.end();
        glFinish();
    }
    if (serial) m_impl->frameQueries.end();
    FrameStats stats;
    stats.boxProxy = low.boxProxy;
    stats.storedInTarget = low.storedInTarget;
    stats.serial = serial;
    stats.cpuMilliseconds = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    if (finish) stats.gpuMilliseconds = m_impl->frameTimer.milliseconds(stats.cpuMilliseconds);
    return stats;
}

void SdfRenderer::setQueryTiming(bool on) { m_impl->queryTiming = on; }

std::vector<TimedFrame> SdfRenderer::timedFrames() {
    std::vector<TimedFrame> frames;
    const std::uint64_t current = m_impl->current ? m_impl->current->id : 0;
    m_impl->frameQueries.collect([&](std::uint64_t serial, std::uint64_t program, double milliseconds) {
        frames.push_back({serial, milliseconds, program != 0 && program == current});
    });
    return frames;
}

void SdfRenderer::releaseGl() {
    m_impl->frameTimer.reset();
    m_impl->frameQueries.reset();
    m_impl->lowFramebuffer.reset();
    m_impl->lowColor.reset();
    m_impl->lowWidth = m_impl->lowHeight = 0;
    m_impl->coneStarts.reset();
    m_impl->coneWidth = m_impl->coneHeight = 0;
    m_impl->computeColor.reset();
    m_impl->computeFramebuffer.reset();
    m_impl->computeWidth = m_impl->computeHeight = 0;
    m_impl->planeField.reset();
    m_impl->planeFieldMesh.reset();
    m_impl->current = nullptr;
    m_impl->cache.clear();
    m_impl->vertexArray.reset();
    m_impl->pipeline.reset();
    m_impl->vertexProgram.reset();
    m_impl->matcap.reset();
    m_impl->background.reset();
    m_impl->textures.reset();
}

std::uint64_t SdfRenderer::programsBuilt() const { return m_impl->programsBuilt; }

double SdfRenderer::planeFieldMilliseconds() const { return m_impl->planeFieldMilliseconds; }

void SdfRenderer::setParameters(std::vector<shaders::ParameterSetting> parameters) { m_parameters = std::move(parameters); }

std::vector<Diagnostic> SdfRenderer::setPlane(const values::CuttingPlane& plane) {
    bool variantChanges = plane.enabled != m_plane.enabled || plane.clipSurface != m_plane.clipSurface ||
                          plane.lipschitzOverlay != m_plane.lipschitzOverlay;
    m_plane = plane;
    std::vector<Diagnostic> diagnostics;
    if (!variantChanges || !m_impl->sdf) return diagnostics;
    if (Variant* variant = m_impl->build(*m_impl->sdf, m_impl->features(m_shading, m_trace, m_plane), diagnostics))
        m_impl->current = variant;
    return diagnostics;
}

std::vector<Diagnostic> SdfRenderer::setTrace(const values::TraceSettings& trace) {
    const bool relaxationOrFactorChanges = (trace.overRelaxation > 1.0f) != (m_trace.overRelaxation > 1.0f) ||
                                           (trace.stepFactor != 1.0f) != (m_trace.stepFactor != 1.0f);
    if (trace.cones != m_trace.cones && m_impl->settle == Impl::Settle::Done) {
        // Back to Auto: the cone pass is tried again at rest; On and Off end a trial.
        m_impl->conesChosen = false;
        if (trace.cones == values::TraceSettings::Cones::Auto) m_impl->settle = Impl::Settle::ConesOpen;
    }
    if (trace.tracer != m_trace.tracer && m_impl->settle == Impl::Settle::Done) {
        // The same for the compute tracer (its trial follows the cone pass's).
        m_impl->computeChosen = false;
        if (trace.tracer == values::TraceSettings::Tracer::Auto) m_impl->settle = Impl::Settle::ConesOpen;
    }
    m_trace = trace;
    std::vector<Diagnostic> diagnostics;
    const shaders::TracerFeatures wanted = m_impl->features(m_shading, m_trace, m_plane);
    const bool programChanges =
        m_impl->current && (wanted.cones != m_impl->current->cones || wanted.compute != m_impl->current->compute);
    if (!(relaxationOrFactorChanges || programChanges) || !m_impl->sdf) return diagnostics;
    if (Variant* variant = m_impl->build(*m_impl->sdf, m_impl->features(m_shading, m_trace, m_plane), diagnostics))
        m_impl->current = variant;
    return diagnostics;
}

} // namespace sdfwb::renderer
