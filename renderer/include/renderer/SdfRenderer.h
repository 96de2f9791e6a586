#pragma once
// Sphere-traces an SDF into the currently bound draw framebuffer. The same object serves the
// Qt viewport (Qt's context) and headless rendering (EGL). Every method needs the GL context that
// was current at the first call to be current now; call releaseGl() before that context goes away.
//
// Programs are specialised per scene (shading mode and other features become defines) and cached,
// so switching back to a variant is instant. A shader that fails to compile leaves the last good
// program in place.

#include <shaders/Diagnostic.h>
#include <shaders/Parameters.h>
#include <shaders/SdfSource.h>
#include <values/Camera.h>
#include <values/RenderSettings.h>

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace sdfwb::renderer {

struct FrameStats {
    double cpuMilliseconds = 0.0;  // time spent in render(), including glFinish when asked
    double gpuMilliseconds = -1.0; // the frame's GPU time (a timer query) when glFinish was asked, else -1
    bool boxProxy = false;         // only the pixels whose ray meets the box ran the tracer
    bool storedInTarget = false;   // the compute tracer stored into the target's own texture (no blit)
    std::uint64_t serial = 0;      // a frame timed by a query read later (setQueryTiming): its number, else 0
};

// A frame's GPU time from a timer query read after it came back (SdfRenderer::timedFrames).
struct TimedFrame {
    std::uint64_t serial = 0;     // FrameStats::serial of the frame
    double gpuMilliseconds = 0.0; // GL_TIME_ELAPSED around its draws
    bool currentProgram = false;  // drawn by the program that is current now
};

// The tracer variant these settings select (what SdfRenderer composes and the driver compiles), so
// a checker can run glslang on exactly that text.
shaders::TracerFeatures tracerFeatures(const values::ShadingSettings& shading, const values::TraceSettings& trace,
                                       const values::CuttingPlane& plane);

class SdfRenderer {
public:
    SdfRenderer();
    ~SdfRenderer();
    SdfRenderer(const SdfRenderer&) = delete;
    SdfRenderer& operator=(const SdfRenderer&) = delete;

    // Compiles the SDF for the current settings. On failure returns the diagnostics (resolver,
    // compiler or linker, mapped to the user's files) and keeps drawing the last good SDF.
    std::vector<shaders::Diagnostic> setSdf(const shaders::PreparedSdf& sdf);

    // Changing settings may compile a new variant (cached). Returns its diagnostics, if any.
    std::vector<shaders::Diagnostic> setShading(const values::ShadingSettings& shading);
    // Over-relaxation on/off and a step factor of 1 or not select another variant; the other
    // fields are uniforms.
    std::vector<shaders::Diagnostic> setTrace(const values::TraceSettings& trace);

    const values::ShadingSettings& shading() const { return m_shading; }
    // Turning the plane, clipping or the overlay on or off selects another variant; the plane's
    // position and contour spacing are uniforms (no recompile while dragging).
    std::vector<shaders::Diagnostic> setPlane(const values::CuttingPlane& plane);
    const values::CuttingPlane& plane() const { return m_plane; }
    // The SDF's parameter values (uniforms: no recompile; a slider drag redraws at frame rate).
    // Parameters not listed keep the values their initializers give.
    void setParameters(std::vector<shaders::ParameterSetting> parameters);
    const std::vector<shaders::ParameterSetting>& parameters() const { return m_parameters; }
    const values::TraceSettings& trace() const { return m_trace; }
    bool hasProgram() const;
    // Programs compiled and linked so far (variant cache misses): what a change cost.
    std::uint64_t programsBuilt() const;
    // How long the cutting plane's field of a mesh (computed once per plane on the CPU engine)
    // took the last time; 0 before any.
    double planeFieldMilliseconds() const;

    // The frame-speed choices at rest. A long SDF is first drawn with the fused march (one copy of
    // the SDF for the driver: the quickest code generation after an edit). When its full frame
    // took under kTrySeparateMarchBelowMilliseconds, it is traded once for the separate march and
    // normal, which draws SDFs that are cheap per evaluation faster; the next full frame's time
    // decides which program stays. Then (TraceSettings::Cones::Auto) the cone pass is tried the
    // same way: it pays when steps are dear; and last (TraceSettings::Tracer::Auto) the compute
    // tracer, which pays on GPUs that run few graphics units. Call with the time of a full-resolution frame at rest
    // (never a program's first draw, which includes code generation). Returns true when the
    // program changed and the caller should draw again; false once the choice is made. setSdf()
    // starts over, except that an edit of the same file keeps the cone pass if it was kept.
    static constexpr double kTrySeparateMarchBelowMilliseconds = 100.0;
    bool settleMarch(double fullFrameMilliseconds);
    // Whether the current program marches through the fused loop.
    bool fusedMarch() const;
    // Whether the current program draws the cone pass first (TraceSettings::cones).
    bool conePass() const;
    // Whether the current program is the compute tracer (TraceSettings::tracer).
    bool computeTracer() const;
    // Whether settleMarch() has made its choices for this SDF (no trial is open or to come).
    bool marchSettled() const;

    // The composed source of the current variant: the fragment shader's, or the compute shader's
    // for the compute tracer (for tests and the log).
    const std::string& fragmentSource() const;

    // Draws a width x height frame into the bound framebuffer. Without a good program, clears to
    // the background. `finish` waits for the GPU so the stats measure the whole frame.
    FrameStats render(int width, int height, const values::Camera& camera, float time, bool finish = false);

    // Renders at `scale` (0 < scale <= 1) of width x height into an internal framebuffer and
    // stretches the result over the bound framebuffer: cheap frames while the camera moves.
    FrameStats renderScaled(int width, int height, float scale, const values::Camera& camera, float time, bool finish = false);

    // With query timing on, a frame drawn without `finish` is timed by a timer query that is read
    // later, once it has come back, so the CPU never waits for the GPU (FrameStats::serial names
    // it; a frame drawn while four earlier ones are still out is not timed). timedFrames() hands
    // over the times that have come back, oldest first. For GPUs: on llvmpipe the timers end
    // before the work they time (softwareRasteriser), and only `finish` measures a frame.
    void setQueryTiming(bool on);
    std::vector<TimedFrame> timedFrames();

    // Frees every GL object; the context must be current. The renderer can be used again later.
    void releaseGl();

private:
    struct Impl;
    std::unique_ptr<Impl> m_impl;
    values::ShadingSettings m_shading;
    values::TraceSettings m_trace;
    values::CuttingPlane m_plane;
    std::vector<shaders::ParameterSetting> m_parameters;
};

} // namespace sdfwb::renderer
