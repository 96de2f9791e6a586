#pragma once
// Hosts the sphere tracer in a QOpenGLWidget. All drawing is forwarded to renderer::SdfRenderer;
// this class turns input into camera moves and decides the frame's resolution. UI thread only.
// The renderer's GL objects are freed when Qt destroys the context (floating a dock re-creates
// it) and rebuilt lazily.
//
// Camera: left drag orbits (Ctrl + left drag moves the cutting plane), wheel dollies; right drag looks around (first person) and,
// while the right button is held, W/A/S/D move, Z/C go down/up, Shift is faster, Alt slower. While the camera moves, frames
// render at a reduced scale chosen to stay within the frame budget; shortly after it stops, a full-resolution frame follows.

#include <renderer/FrameScaler.h>
#include <renderer/Image.h>
#include <shaders/Diagnostic.h>
#include <shaders/Parameters.h>
#include <shaders/SdfSource.h>
#include <values/Camera.h>
#include <values/FrameSettings.h>
#include <values/RenderSettings.h>

#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include <QElapsedTimer>
#include <QOpenGLWidget>
#include <QPoint>
#include <QSet>
#include <QTimer>

#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <vector>

namespace sdfwb::renderer {
class MeshOverlay;
class PointCloudOverlay;
class SdfRenderer;
class ShadertoyPicture;
} // namespace sdfwb::renderer

namespace sdfwb::sampling {
class FieldEvaluator;
}

namespace sdfwb::widgets {

class ViewportWidget : public QOpenGLWidget {
    Q_OBJECT
public:
    explicit ViewportWidget(QWidget* parent = nullptr);
    ~ViewportWidget() override;

    // Compiles `sdf` in this widget's context (the last good SDF stays on screen on failure).
    // Before the context exists the SDF is kept and compiled at initializeGL.
    std::vector<shaders::Diagnostic> setSdf(const shaders::PreparedSdf& sdf);

    // The frame settings this viewport draws with (shading, trace, camera, whether the credits
    // show): the one value screenshots, videos and the probe take.
    const values::FrameSettings& frameSettings() const { return m_frame; }
    void setShading(const values::ShadingSettings& shading);
    const values::ShadingSettings& shading() const { return m_frame.shading; }
    void setTrace(const values::TraceSettings& trace);
    // Ctrl + left drag moves an enabled plane along its normal.
    void setPlane(const values::CuttingPlane& plane);
    const values::CuttingPlane& plane() const { return m_plane; }
    // The SDF's parameter values: uniforms, no recompile; frames follow at the moving rate.
    void setParameters(const std::vector<shaders::ParameterSetting>& parameters);
    const std::vector<shaders::ParameterSetting>& parameters() const { return m_parameters; }
    const values::TraceSettings& trace() const { return m_frame.trace; }
    const values::Camera& camera() const { return m_frame.camera; }
    void setCamera(const values::Camera& camera);
    void resetCamera();
    void setTime(float seconds);
    // Drops every compiled variant; the next frame rebuilds from the current SDF (F5).
    void reloadShaders();
    float time() const { return m_time; }

    // Frames while moving aim to take at most this long (default 33 ms).
    void setFrameBudget(double milliseconds) { m_scaler.setFrameBudget(milliseconds); }
    // No frame may hold the UI longer than about this (default 1500 ms). A new SDF is first drawn
    // at 5 % resolution; if the full frame would exceed the limit (a runaway loop, a huge
    // fractal), frames are capped at the resolution that fits, and if even the timing frame is
    // over it the previous SDF comes back. performanceWarning() says which.
    void setStallLimit(double milliseconds) { m_scaler.setStallLimit(milliseconds); }
    // The largest scale frames are drawn at now (1 without a cap).
    float resolutionCap() const;
    double lastFrameMilliseconds() const { return m_lastFrameMilliseconds; }
    float lastFrameScale() const { return m_lastScale; }
    bool isInteracting() const { return m_interacting; }
    // Whether the picture marches through the fused loop (see SdfRenderer::settleMarch: a long SDF
    // starts so and may trade it for the separate march a while after a full frame at rest).
    bool fusedMarch() const;
    // Whether the picture draws the cone pass first (tried and kept at rest when frames got faster).
    bool conePass() const;
    // Whether the compute tracer draws the picture (tried and kept at rest when frames got faster).
    bool computeTracer() const;
    // Whether those choices are made for the current SDF.
    bool marchSettled() const;
    // The full-frame time those choices are made from, given the program's march (fused or not),
    // its cone pass, its tracer (compute or fragment) and the time measured: tests set it to decide with known timings instead of
    // a wall clock's. Unset (the default): the measured time.
    using SettleTiming = std::function<double(bool fusedMarch, bool conePass, bool computeTracer, double measuredMilliseconds)>;
    void setSettleTiming(SettleTiming timing) { m_settleTiming = std::move(timing); }
    // How a frame's cost is measured. Finish: glFinish after each frame (llvmpipe, where the CPU
    // draws the frame anyway and timer queries end before the work). Query: a timer query read at
    // a later paint, so the CPU does not wait for a GPU (its default). Only a new SDF's timing
    // frames always finish. SDFWB_FRAME_TIMING=finish|query overrides the driver's default.
    enum class FrameTiming { Finish, Query };
    void setFrameTiming(FrameTiming timing);
    FrameTiming frameTiming() const { return m_frameTiming; }
    // Paints whose frame was drawn to glFinish so far (a new SDF's timing frames not counted).
    std::uint64_t finishedFrames() const { return m_finishedFrames; }

    // Renders one full-quality frame at width x height (screenshots). Empty image without GL.
    renderer::Image renderImage(int width, int height);
    // The same in floating point (EXR): values above 1 are kept.
    renderer::FloatImage renderFloatImage(int width, int height);

    // The probe tool: while on, a left click does not orbit but emits pixelProbed for the pixel
    // under the cursor (in the device pixels of a frame of this widget's size).
    void setProbeTool(bool on);
    bool probeTool() const { return m_probeTool; }
    // A cross-hair over the probed pixel (device pixels); (-1, -1) hides it.
    void setProbeMark(QPoint pixel);

    // The sampled cloud over the surface (3 floats per point each; NaN rows are not drawn), each
    // point coloured by its gradient; empty positions hide it.
    void setPointCloud(const std::vector<float>& positions, const std::vector<float>& gradients);
    std::uint64_t pointCloudSize() const; // points drawn
    void setPointSize(float pixels);
    float pointSize() const { return m_pointSize; }

    // The field on the cutting plane under `position` (widget coordinates): false when the plane
    // is off or the ray misses it within the box. Evaluates the shown SDF (compiled once per SDF).
    struct PlaneValue {
        glm::vec3 position{0.0f};
        float value = 0.0f;
        float gradientLength = 0.0f;
    };
    bool planeValueAt(QPointF position, PlaneValue& out);

    // A mesh drawn over the surface, coloured per pixel by the shown SDF's value at the mesh's own
    // point (grey on the zero set, red outside, blue inside, full colour at |f| >= scale): where
    // an exported or loaded mesh strays from the field. Empty indices hide it.
    void setMeshOverlay(const std::vector<float>& positions, const std::vector<std::uint32_t>& indices, float scale);
    bool hasMeshOverlay() const;
    float meshOverlayScale() const { return m_meshScale; }

    // The Shadertoy picture: instead of sdfwb's tracer, the viewport runs the file's own
    // mainImage (a whole Shadertoy shader) with the scene time, a frame count and the mouse (a
    // left drag sets iMouse as Shadertoy does; the camera stays). Returns the diagnostics of
    // compiling it (an SDF without mainImage is an error, and the tracer stays).
    std::vector<shaders::Diagnostic> setShadertoyPicture(bool on);
    bool shadertoyPicture() const { return m_showPicture; }
    glm::vec4 shadertoyMouse() const { return m_shadertoyMouse; }

    // Text drawn in the lower-left corner (name, author, license); empty hides it.
    void setOverlayText(const QString& text);
    const QString& overlayText() const { return m_overlay; }

    QString contextDescription() const { return m_contextDescription; }
    // Shader programs this viewport's renderer compiled so far (parameter changes add none).
    std::uint64_t programsBuilt() const;

signals:
    void frameRendered(double milliseconds, float scale);
    void cameraChanged(const sdfwb::values::Camera& camera);
    void planeDragged(const sdfwb::values::CuttingPlane& plane);
    void contextReady(const QString& description);
    // A new SDF passed its timing frame (it stays on screen), or would stall even at 5 % resolution
    // and the last one that passed is back (sdfReverted, after performanceWarning).
    void sdfTimed();
    void sdfReverted();
    // A frame would take too long: `message` says what was done (resolution capped, SDF reverted).
    void performanceWarning(const QString& message);
    // The probe tool's click: pixel (x, y), top row 0, of a width x height frame.
    void pixelProbed(int x, int y, int width, int height);
    // The cursor over the cutting plane (f and |grad f| there), or off it (valid false).
    void planeHovered(bool valid, const sdfwb::widgets::ViewportWidget::PlaneValue& value);

protected:
    void initializeGL() override;
    void paintGL() override;
    void mousePressEvent(QMouseEvent* event) override;
    void mouseReleaseEvent(QMouseEvent* event) override;
    void mouseMoveEvent(QMouseEvent* event) override;
    void shadertoyMouseEvent(QMouseEvent* event, bool press, bool release);
    void wheelEvent(QWheelEvent* event) override;
    void keyPressEvent(QKeyEvent* event) override;
    void keyReleaseEvent(QKeyEvent* event) override;
    void focusOutEvent(QFocusEvent* event) override;
    void leaveEvent(QEvent* event) override;

private:
    // Times a new SDF at kTimingScale and sets the resolution cap (or reverts to the last good
    // SDF). For an SDF whose full frame would take longer than the frame budget, the last timing frame's
    // picture is its first frame (returned); otherwise the paint that called it draws that frame.
    struct TimingFrame {
        float scale;
        double milliseconds;
    };
    std::optional<TimingFrame> timeNewSdf(int width, int height);
    void releaseGl();
    void interacted(); // a camera move happened: render cheaply now, refine later
    void flyStep();

    std::unique_ptr<renderer::SdfRenderer> m_renderer;
    std::unique_ptr<renderer::ShadertoyPicture> m_picture;
    std::unique_ptr<shaders::PreparedSdf> m_pictureSource; // the SDF the picture is compiled from
    bool m_showPicture = false;
    int m_pictureFrame = 0;
    glm::vec4 m_shadertoyMouse{0.0f};
    std::unique_ptr<renderer::MeshOverlay> m_meshOverlay;
    std::unique_ptr<renderer::PointCloudOverlay> m_pointCloud;
    float m_pointSize = 3.0f;
    bool m_probeTool = false;
    bool m_probeClick = false; // the left button went down with the probe tool: no orbit
    QPoint m_probeMark{-1, -1};
    // The shown SDF at single points (the plane readout under the cursor), built per SDF.
    std::unique_ptr<sampling::FieldEvaluator> m_fieldAtPoint;
    std::uint64_t m_fieldGeneration = 0;
    bool m_fieldBroken = false;
    float m_meshScale = 0.0f;
    std::uint64_t m_sdfGeneration = 0;     // counts SDFs that passed their timing frame
    std::uint64_t m_overlayGeneration = 0; // the SDF the overlay's shader was built for
    std::unique_ptr<shaders::PreparedSdf> m_pendingSdf;
    std::unique_ptr<shaders::PreparedSdf> m_currentSdf;  // compiled, waiting for its timing frame
    std::unique_ptr<shaders::PreparedSdf> m_lastGoodSdf; // passed its timing frame
    bool m_needsTiming = false;
    renderer::FrameScaler m_scaler; // resolution while moving, and the cap for slow SDFs
    values::FrameSettings m_frame;
    values::CuttingPlane m_plane;
    std::vector<shaders::ParameterSetting> m_parameters;
    float m_time = 0.0f;
    QPoint m_lastMouse;
    QSet<int> m_keys;
    QTimer m_flyTimer;
    QElapsedTimer m_flyClock;
    QTimer m_refineTimer;
    // A while after a full frame at rest: SdfRenderer::settleMarch() with that frame's time.
    QTimer m_settleTimer;
    double m_settleFrameMilliseconds = 0.0; // -1: the frame's query has not come back yet
    SettleTiming m_settleTiming;
    FrameTiming m_frameTiming = FrameTiming::Finish;
    std::optional<FrameTiming> m_forcedFrameTiming;
    std::uint64_t m_finishedFrames = 0;
    // Frames timed by queries that have not come back: what each was.
    struct PendingFrame {
        std::uint64_t serial;
        int width, height;
        float scale;
        bool interacting;
    };
    std::vector<PendingFrame> m_pendingFrames;
    // A frame's cost, measured: the scale choice, the status line and the march's settling.
    void frameCost(int width, int height, float scale, double milliseconds, bool interacting, bool currentProgram);
    // The query-timed frames that have come back, through frameCost (context current).
    void collectTimedFrames();
    bool m_warmProgram = false; // a new program: a small draw takes its code generation first
    bool m_interacting = false;
    float m_lastScale = 1.0f;
    double m_lastFrameMilliseconds = 0.0;
    QString m_contextDescription;
    QString m_overlay;
};

} // namespace sdfwb::widgets
