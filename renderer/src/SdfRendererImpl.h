#pragma once
// SdfRenderer's private state, shared by SdfRenderer.cpp (frames, uniforms, the march's settling)
// and SdfPrograms.cpp (composing, compiling and caching the tracer's programs; its textures).

#include <renderer/SdfRenderer.h>

#include "GlObjects.h"

#include <renderer/Image.h>
#include <shaders/TracerComposer.h>

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include <cstdint>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <unordered_map>
#include <vector>

namespace sdfwb::meshfield {
struct MeshField;
} // namespace sdfwb::meshfield

namespace sdfwb::renderer {

using shaders::Diagnostic;

// Texels a side of the plane's field: about 0.004 units apart on an axis-aligned plane
// (2.1 units across), a quarter of the default contour spacing (1/64).
inline constexpr int kPlaneFieldSize = 512;

struct Variant {
    GlProgram program;
    std::string fragmentSource;
    bool fusedMarch = false;
    bool cones = false;
    bool meshRaycast = false; // shaders::meshRaycastApplies: no march to choose, no cone pass
    bool compute = false;     // the compute tracer (dispatched, then blitted), not a fragment program
    std::uint64_t id = 0;     // which program this is (TimedFrame::currentProgram)
    std::unordered_map<std::string, GLint> uniforms;
    std::uint64_t lastUse = 0;

    GLint location(const char* name) {
        auto it = uniforms.find(name);
        if (it != uniforms.end()) return it->second;
        GLint found = glGetUniformLocation(program.id(), name);
        uniforms.emplace(name, found);
        return found;
    }
};

// Whether a cone pass can serve these settings (the march debugger and the step heat map show
// each pixel's own march).
bool conesApply(const values::ShadingSettings& shading, const values::TraceSettings& trace);
// SDFWB_FUSED_MARCH=0/1, for benchmarks: the march forced fused or separate.
std::optional<bool> forcedFusedMarch();

// Frames timed without waiting (SdfRenderer::setQueryTiming): a ring of GL_TIME_ELAPSED queries,
// read in order once their results are available.
class QueryRing {
public:
    static constexpr int kSlots = 4;
    // False (the frame goes untimed) when every slot is still out.
    bool begin(std::uint64_t serial, std::uint64_t program) {
        if (m_pending == kSlots || m_running) return false;
        if (!m_queries[m_head]) {
            GLuint id = 0;
            glGenQueries(1, &id);
            m_queries[m_head] = GlQuery(id);
        }
        glBeginQuery(GL_TIME_ELAPSED, m_queries[m_head].id());
        m_serials[m_head] = serial;
        m_programs[m_head] = program;
        m_running = true;
        return true;
    }
    void end() {
        if (!m_running) return;
        glEndQuery(GL_TIME_ELAPSED);
        m_running = false;
        m_head = (m_head + 1) % kSlots;
        ++m_pending;
    }
    // Calls done(serial, program, milliseconds) for each result that has come back, oldest first.
    template <class Done> void collect(Done done) {
        while (m_pending > 0) {
            const int slot = (m_head - m_pending + kSlots) % kSlots;
            GLuint available = 0;
            glGetQueryObjectuiv(m_queries[slot].id(), GL_QUERY_RESULT_AVAILABLE, &available);
            if (!available) return;
            GLuint64 nanoseconds = 0;
            glGetQueryObjectui64v(m_queries[slot].id(), GL_QUERY_RESULT, &nanoseconds);
            --m_pending;
            done(m_serials[slot], m_programs[slot], double(nanoseconds) * 1e-6);
        }
    }
    void reset() {
        for (GlQuery& query : m_queries) query.reset();
        m_head = m_pending = 0;
        m_running = false;
    }
    void release() {
        for (GlQuery& query : m_queries) query.release();
        m_head = m_pending = 0;
        m_running = false;
    }

private:
    GlQuery m_queries[kSlots];
    std::uint64_t m_serials[kSlots] = {}, m_programs[kSlots] = {};
    int m_head = 0, m_pending = 0;
    bool m_running = false;
};

struct SdfRenderer::Impl {
    std::optional<shaders::PreparedSdf> sdf; // the last SDF that compiled
    GpuTimer frameTimer;                     // a timed frame's GPU time (render(.., finish))
    bool queryTiming = false;                // setQueryTiming
    QueryRing frameQueries;                  // frames timed without waiting
    std::uint64_t frameSerial = 0;
    bool insideScaled = false; // renderScaled's own render(): timed as part of the scaled frame
    // Starts timing a frame without waiting when query timing is on; its serial, or 0.
    std::uint64_t beginQueryFrame(bool finish) {
        if (!queryTiming || finish || insideScaled) return 0;
        const std::uint64_t serial = ++frameSerial;
        return frameQueries.begin(serial, current ? current->id : 0) ? serial : 0;
    }
    // settleMarch(): where the choice between the fused and the separate march stands.
    // ConesOpen: the march is chosen; the cone pass is still to try (Cones::Auto chosen again).
    // TryingCompute: the compute tracer's full frame is being measured against bestMilliseconds.
    enum class Settle { Open, TryingSeparate, ConesOpen, TryingCones, TryingCompute, Done };
    Settle settle = Settle::Open;
    bool separateChosen = false;          // a long SDF marches separately (its frames were faster so)
    bool conesChosen = false;             // TraceSettings::Cones::Auto: the cone pass made full frames faster
    bool computeChosen = false;           // TraceSettings::Tracer::Auto: the compute tracer made full frames faster
    double bestMilliseconds = 0.0;        // the fastest full frame of the programs tried so far
    std::map<std::string, Variant> cache; // by composed fragment text
    Variant* current = nullptr;
    GlVertexArray vertexArray;
    // The vertex stage, one program for every variant (trace.vert): a program pipeline pairs it
    // with each variant's fragment program, so the driver generates its code once, not for every
    // new SDF (on llvmpipe about 16 ms of each edit's first frame).
    GlProgram vertexProgram;
    GlProgramPipeline pipeline;
    GLint proxyBox = -1, proxyClip = -1, proxyHalf = -1; // its uniforms
    std::uint64_t clock = 0;
    std::uint64_t programsBuilt = 0;
    std::string empty;

    GlTexture matcap;
    SdfTextures textures; // g3d_uniformRandom and iChannel0..3, made when a program reads them
    std::string matcapName;
    GlTexture background; // ShadingSettings::backgroundImage
    std::string backgroundName;
    float backgroundAspect = 1.0f;
    GlFramebuffer lowFramebuffer;
    GlTexture lowColor;
    int lowWidth = 0, lowHeight = 0;
    GlTexture coneStarts; // the cone pass's starts, copied out of the target
    // The compute tracer's image (RGBA32F, grown, never shrunk) and a framebuffer to blit it from,
    // for targets it cannot store into (a frame into a texture target is stored there directly;
    // SDFWB_COMPUTE_BLIT=1 at the renderer's making always blits, for tests and benchmarks).
    bool computeViaBlit = false;
    GlTexture computeColor;
    GlFramebuffer computeFramebuffer;
    int computeWidth = 0, computeHeight = 0;
    int coneWidth = 0, coneHeight = 0;
    // A mesh's own field on the cutting plane (SDFWB_PLANE_FIELD), and what it was computed for.
    GlTexture planeField;
    std::shared_ptr<const meshfield::MeshField> planeFieldMesh;
    glm::vec4 planeFieldPlane{0.0f}; // normal, offset
    float planeFieldMargin = -1.0f;
    double planeFieldMilliseconds = 0.0;
    glm::vec3 planeFieldOrigin{0.0f}, planeFieldU{0.0f}, planeFieldV{0.0f};
    void ensurePlaneField(const glm::vec3& normal, float offset, float margin);

    // render()'s steps, each one named thing.
    struct FrameInputs {
        const values::ShadingSettings& shading;
        const values::TraceSettings& trace;
        const values::CuttingPlane& plane;
        const std::vector<shaders::ParameterSetting>& parameters;
    };
    void setFrameUniforms(Variant& variant, const FrameInputs& in, int width, int height, const values::Camera& camera,
                          const values::CameraBasis& basis, float time);
    void bindShadingTextures(Variant& variant, const values::ShadingSettings& shading, int width, int height);
    void drawConePass(Variant& variant, const values::TraceSettings& trace, const values::Camera& camera, int width, int height);
    bool drawPicture(const values::ShadingSettings& shading, const values::TraceSettings& trace, const values::Camera& camera,
                     const values::CameraBasis& basis, int width, int height);
    // The compute tracer's frame: dispatched into computeColor (made or grown first by
    // ensureComputeTarget), then blitted over the bound draw framebuffer's lower-left width x
    // height pixels.
    void ensureComputeTarget(int width, int height);
    void traceCompute(int width, int height);

    shaders::TracerFeatures features(const values::ShadingSettings& shading, const values::TraceSettings& trace,
                                     const values::CuttingPlane& plane) const {
        shaders::TracerFeatures result = tracerFeatures(shading, trace, plane);
        result.cones = conesApply(shading, trace) && (trace.cones == values::TraceSettings::Cones::On ||
                                                      (trace.cones == values::TraceSettings::Cones::Auto && conesChosen));
        // The compute tracer draws without the cone pass (when it applies, it replaces it).
        shaders::TracerFeatures compute = result;
        compute.cones = false;
        compute.compute = true;
        const bool wanted = trace.tracer == values::TraceSettings::Tracer::Compute ||
                            (trace.tracer == values::TraceSettings::Tracer::Auto && computeChosen);
        return wanted && shaders::computeTracerApplies(compute) ? compute : result;
    }

    // An image as a linear-filtered, edge-clamped texture.
    static GlTexture uploadTexture(const Image& image);
    // Loads the matcap image (a name in resources/matcaps or a path) into a texture, once.
    void ensureMatcap(const std::string& name);
    // Loads the background image once per path; an unreadable one shows the background colour.
    void ensureBackground(const std::string& path, const glm::vec3& colour);

    // Builds (or finds) the program for `sdf` with `features`. Null on failure, with diagnostics.
    Variant* build(const shaders::PreparedSdf& prepared, shaders::TracerFeatures tracerFeatures,
                   std::vector<Diagnostic>& diagnostics);
    // The vertex program and the pipeline, made once per context. False, with diagnostics, when
    // the driver refuses them.
    bool ensureVertexStage(std::vector<Diagnostic>& diagnostics);
    // Drops the least recently used programs past kMaxCachedVariants (never the current one).
    void evictIfFull();
};

} // namespace sdfwb::renderer
