#include <widgets/ViewportWidget.h>

#include <core/Log.h>
#include <renderer/GlInfo.h>
#include <renderer/MeshOverlay.h>
#include <renderer/OffscreenRenderer.h>
#include <renderer/PointCloudOverlay.h>
#include <renderer/SdfRenderer.h>
#include <renderer/ShadertoyPicture.h>
#include <sampling/FieldEvaluator.h>
#include <shaders/ShaderComposer.h>

#include <glm/geometric.hpp>

#include <QGuiApplication>
#include <QKeyEvent>
#include <QMouseEvent>
#include <QOpenGLContext>
#include <QPainter>
#include <QWheelEvent>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <string>
#include <string_view>

namespace sdfwb::widgets {

ViewportWidget::ViewportWidget(QWidget* parent)
    : QOpenGLWidget(parent), m_renderer(std::make_unique<renderer::SdfRenderer>()),
      m_picture(std::make_unique<renderer::ShadertoyPicture>()), m_meshOverlay(std::make_unique<renderer::MeshOverlay>()),
      m_pointCloud(std::make_unique<renderer::PointCloudOverlay>()) {
    setMinimumSize(64, 64);
    setFocusPolicy(Qt::StrongFocus);
    setMouseTracking(true); // the plane readout under the cursor
    m_refineTimer.setSingleShot(true);
    m_refineTimer.setInterval(200);
    connect(&m_refineTimer, &QTimer::timeout, this, [this] {
        m_interacting = false;
        update();
    });
    // Long enough that the next edit while typing (each valid one draws a new full frame, which
    // restarts this) or a camera drag comes first: trading the march or trying the cone pass costs
    // a stall for the driver's code generation (tens to a few hundred milliseconds).
    m_settleTimer.setSingleShot(true);
    m_settleTimer.setInterval(1500);
    connect(&m_settleTimer, &QTimer::timeout, this, [this] {
        if (m_interacting || m_needsTiming || !context() || !isValid()) return;
        makeCurrent();
        collectTimedFrames();
        if (m_settleFrameMilliseconds < 0.0) { // the full frame's time is not back yet
            doneCurrent();
            m_settleTimer.start();
            return;
        }
        const bool changed = m_renderer->settleMarch(m_settleFrameMilliseconds);
        doneCurrent();
        if (changed) {
            m_warmProgram = true;
            update();
        }
    });
    m_flyTimer.setInterval(16);
    connect(&m_flyTimer, &QTimer::timeout, this, &ViewportWidget::flyStep);
}

ViewportWidget::~ViewportWidget() {
    if (context()) {
        // The base class destroys the context after our members are gone: no callback then.
        disconnect(context(), nullptr, this, nullptr);
        makeCurrent();
        releaseGl();
        doneCurrent();
    }
}

std::vector<shaders::Diagnostic> ViewportWidget::setSdf(const shaders::PreparedSdf& sdf) {
    if (!context() || !isValid()) {
        m_pendingSdf = std::make_unique<shaders::PreparedSdf>(sdf);
        return sdf.diagnostics;
    }
    makeCurrent();
    auto diagnostics = m_renderer->setSdf(sdf);
    if (m_showPicture && !shaders::hasErrors(diagnostics)) {
        // The author's picture follows the edit; a file that lost its mainImage shows the tracer.
        // Its errors are the picture's, not the SDF's: the tracer takes over, and the log says why.
        auto picture = m_picture->setSdf(sdf);
        for (const auto& d : picture) log::warning("shadertoy", shaders::formatDiagnostic(d));
        if (shaders::hasErrors(picture)) m_showPicture = false;
    }
    doneCurrent();
    if (!shaders::hasErrors(diagnostics)) m_pictureSource = std::make_unique<shaders::PreparedSdf>(sdf);
    if (!shaders::hasErrors(diagnostics)) {
        m_currentSdf = std::make_unique<shaders::PreparedSdf>(sdf);
        m_needsTiming = true;
        m_scaler.clearCap();
    }
    update();
    return diagnostics;
}

bool ViewportWidget::fusedMarch() const { return m_renderer->fusedMarch(); }

bool ViewportWidget::conePass() const { return m_renderer->conePass(); }

bool ViewportWidget::computeTracer() const { return m_renderer->computeTracer(); }

void ViewportWidget::setFrameTiming(FrameTiming timing) {
    m_forcedFrameTiming = timing;
    m_frameTiming = timing;
    m_renderer->setQueryTiming(timing == FrameTiming::Query);
}

void ViewportWidget::frameCost(int width, int height, float scale, double milliseconds, bool interacting, bool currentProgram) {
    m_lastFrameMilliseconds = milliseconds;
    if (m_scaler.frameDone(width, height, scale, milliseconds, interacting)) {
        // A view that became expensive (camera, time, plane): the next frames are capped.
        emit performanceWarning(tr("A full frame took %1 s: frames are drawn at %2 % resolution from now on")
                                    .arg(milliseconds / 1000.0, 0, 'f', 1)
                                    .arg(int(resolutionCap() * 100.0f)));
    }
    if (scale >= 1.0f && !interacting && currentProgram)
        m_settleFrameMilliseconds =
            m_settleTiming ? m_settleTiming(fusedMarch(), conePass(), computeTracer(), milliseconds) : milliseconds;
}

void ViewportWidget::collectTimedFrames() {
    for (const renderer::TimedFrame& timed : m_renderer->timedFrames()) {
        auto it = std::find_if(m_pendingFrames.begin(), m_pendingFrames.end(),
                               [&](const PendingFrame& frame) { return frame.serial == timed.serial; });
        if (it == m_pendingFrames.end()) continue;
        const PendingFrame frame = *it;
        m_pendingFrames.erase(m_pendingFrames.begin(), it + 1); // older ones never come back
        frameCost(frame.width, frame.height, frame.scale, timed.gpuMilliseconds, frame.interacting, timed.currentProgram);
    }
}

bool ViewportWidget::marchSettled() const { return m_renderer->marchSettled(); }

void ViewportWidget::setShading(const values::ShadingSettings& shading) {
    m_frame.shading = shading;
    if (context() && isValid()) {
        makeCurrent();
        for (const auto& d : m_renderer->setShading(shading)) log::warning("shaders", shaders::formatDiagnostic(d));
        doneCurrent();
    }
    update();
}

void ViewportWidget::setTrace(const values::TraceSettings& trace) {
    m_frame.trace = trace;
    if (context() && isValid()) {
        makeCurrent();
        for (const auto& d : m_renderer->setTrace(trace)) log::warning("shaders", shaders::formatDiagnostic(d));
        doneCurrent();
    }
    update();
}

void ViewportWidget::setPlane(const values::CuttingPlane& plane) {
    m_plane = plane;
    if (context() && isValid()) {
        makeCurrent();
        for (const auto& d : m_renderer->setPlane(plane)) log::warning("shaders", shaders::formatDiagnostic(d));
        doneCurrent();
    }
    update();
}

void ViewportWidget::setParameters(const std::vector<shaders::ParameterSetting>& parameters) {
    if (parameters == m_parameters) return;
    // The same parameters with new values is a slider drag: cheap frames now, the full frame when
    // it stops. Another set (a new SDF's declarations) is not an interaction: one full frame.
    const bool drag = parameters.size() == m_parameters.size() &&
                      std::equal(parameters.begin(), parameters.end(), m_parameters.begin(),
                                 [](const auto& a, const auto& b) { return a.name == b.name && a.type == b.type; });
    m_parameters = parameters;
    m_renderer->setParameters(parameters);
    if (drag)
        interacted();
    else
        update();
}

std::uint64_t ViewportWidget::programsBuilt() const { return m_renderer->programsBuilt(); }

void ViewportWidget::setCamera(const values::Camera& camera) {
    m_frame.camera = camera;
    update();
}

void ViewportWidget::resetCamera() {
    setCamera(values::Camera{});
    emit cameraChanged(m_frame.camera);
}

void ViewportWidget::setTime(float seconds) {
    m_time = seconds;
    update();
}

void ViewportWidget::reloadShaders() {
    if (context() && isValid()) {
        makeCurrent();
        m_renderer->releaseGl();
        doneCurrent();
    }
    update();
}

void ViewportWidget::setOverlayText(const QString& text) {
    m_overlay = text;
    m_frame.overlay = !text.isEmpty();
    update();
}

renderer::Image ViewportWidget::renderImage(int width, int height) {
    if (!context() || !isValid()) return {};
    makeCurrent();
    renderer::Image image;
    {
        renderer::OffscreenRenderer offscreen;
        image = offscreen.render(*m_renderer, width, height, m_frame.camera, m_time);
    }
    doneCurrent();
    return image;
}

renderer::FloatImage ViewportWidget::renderFloatImage(int width, int height) {
    if (!context() || !isValid()) return {};
    makeCurrent();
    renderer::FloatImage image;
    {
        renderer::OffscreenRenderer offscreen;
        image = offscreen.renderFloat(*m_renderer, width, height, m_frame.camera, m_time);
    }
    doneCurrent();
    return image;
}

void ViewportWidget::setProbeTool(bool on) {
    m_probeTool = on;
    setCursor(on ? Qt::CrossCursor : Qt::ArrowCursor);
}

void ViewportWidget::setProbeMark(QPoint pixel) {
    m_probeMark = pixel;
    update();
}

void ViewportWidget::setPointCloud(const std::vector<float>& positions, const std::vector<float>& gradients) {
    m_pointCloud->setPoints(positions, gradients);
    update();
}

std::uint64_t ViewportWidget::pointCloudSize() const { return m_pointCloud->pointCount(); }

void ViewportWidget::setPointSize(float pixels) {
    m_pointSize = std::clamp(pixels, 1.0f, 64.0f);
    update();
}

bool ViewportWidget::planeValueAt(QPointF position, PlaneValue& out) {
    if (!m_plane.enabled || !m_lastGoodSdf || !context() || !isValid()) return false;
    const qreal ratio = devicePixelRatioF();
    const int width = int(std::lround(this->width() * ratio)), height = int(std::lround(this->height() * ratio));
    const int x = std::clamp(int(position.x() * ratio), 0, width - 1), y = std::clamp(int(position.y() * ratio), 0, height - 1);
    // The tracer's own ray through the pixel, and the plane the way tracer/plane.glsl meets it.
    const glm::vec3 direction = glm::vec3(values::primaryRayDirection(m_frame.camera, x, y, width, height));
    const glm::vec3 normal = glm::length(m_plane.normal) > 0.0f ? glm::normalize(m_plane.normal) : glm::vec3(0, 0, 1);
    const float denominator = glm::dot(direction, normal);
    if (std::abs(denominator) < 1e-8f) return false;
    const float t = (m_plane.offset - glm::dot(m_frame.camera.position, normal)) / denominator;
    const glm::vec3 p = m_frame.camera.position + t * direction;
    const float bound = 1.0f + m_frame.trace.boxMargin;
    if (t <= 0.0f || std::abs(p.x) > bound || std::abs(p.y) > bound || std::abs(p.z) > bound) return false;
    makeCurrent();
    if (!m_fieldAtPoint || m_fieldGeneration != m_sdfGeneration) {
        m_fieldAtPoint = std::make_unique<sampling::FieldEvaluator>();
        m_fieldBroken = shaders::hasErrors(m_fieldAtPoint->build(*m_lastGoodSdf));
        m_fieldGeneration = m_sdfGeneration;
    }
    bool ok = false;
    if (!m_fieldBroken) {
        sampling::FieldSettings settings;
        settings.time = m_time;
        settings.gradientStep = 1e-4f;
        settings.parameters = m_parameters;
        float value = 0.0f, gradient[3] = {0, 0, 0};
        ok = bool(m_fieldAtPoint->evaluate(&p.x, 1, &value, gradient, settings));
        out = {p, value, std::sqrt(gradient[0] * gradient[0] + gradient[1] * gradient[1] + gradient[2] * gradient[2])};
    }
    doneCurrent();
    return ok;
}

void ViewportWidget::initializeGL() {
    connect(
        context(), &QOpenGLContext::aboutToBeDestroyed, this,
        [this] {
            makeCurrent();
            releaseGl();
            doneCurrent();
        },
        Qt::DirectConnection);
    renderer::GlInfo info = renderer::queryGlInfo();
    m_contextDescription = QString::fromStdString(renderer::describe(info));
    log::info("gl", "viewport context: " + renderer::describe(info));
    if (auto ok = renderer::requireGl43(info); !ok) log::error("gl", ok.error().message);
    if (!m_forcedFrameTiming) {
        const char* forced = std::getenv("SDFWB_FRAME_TIMING");
        const std::string_view name = forced ? forced : "";
        m_frameTiming = name == "query"                  ? FrameTiming::Query
                        : name == "finish"               ? FrameTiming::Finish
                        : renderer::softwareRasteriser() ? FrameTiming::Finish
                                                         : FrameTiming::Query;
    }
    m_renderer->setQueryTiming(m_frameTiming == FrameTiming::Query);
    log::info("gl", std::string("viewport frames timed ") +
                        (m_frameTiming == FrameTiming::Query ? "by timer queries read later (no glFinish)" : "to glFinish"));
    (void)m_renderer->setShading(m_frame.shading);
    (void)m_renderer->setTrace(m_frame.trace);
    (void)m_renderer->setPlane(m_plane);
    if (m_pendingSdf) {
        auto diagnostics = m_renderer->setSdf(*m_pendingSdf);
        for (const auto& d : diagnostics) log::warning("shaders", shaders::formatDiagnostic(d));
        if (!shaders::hasErrors(diagnostics)) {
            m_currentSdf = std::move(m_pendingSdf);
            m_needsTiming = true;
            m_scaler.clearCap();
        }
        m_pendingSdf.reset();
    }
    emit contextReady(m_contextDescription);
}

std::vector<shaders::Diagnostic> ViewportWidget::setShadertoyPicture(bool on) {
    std::vector<shaders::Diagnostic> diagnostics;
    if (on) {
        const shaders::PreparedSdf* source = m_pictureSource ? m_pictureSource.get() : m_pendingSdf.get();
        if (!source || !context() || !isValid())
            return {{"<viewport>", 0, 0, shaders::Severity::Error, "no SDF shown yet: open a Shadertoy shader first"}};
        makeCurrent();
        diagnostics = m_picture->setSdf(*source);
        doneCurrent();
        if (shaders::hasErrors(diagnostics)) on = false;
    }
    m_showPicture = on;
    m_pictureFrame = 0;
    update();
    return diagnostics;
}

void ViewportWidget::paintGL() {
    const qreal ratio = devicePixelRatioF();
    int width = int(std::lround(this->width() * ratio));
    int height = int(std::lround(this->height() * ratio));
    if (m_showPicture && m_picture->hasProgram()) {
        renderer::ShadertoyInputs inputs;
        inputs.time = m_time;
        inputs.frame = m_pictureFrame++;
        inputs.mouse = m_shadertoyMouse;
        m_picture->setParameters(m_parameters);
        m_lastFrameMilliseconds = m_picture->render(width, height, inputs, true);
        m_lastScale = 1.0f;
        emit frameRendered(m_lastFrameMilliseconds, 1.0f);
        return;
    }
    // A new SDF: the timing frame sizes its first frame, which follows in this same paint (a second
    // paint request would wait for the next update cycle, 15 to 30 ms here). For a slow SDF the
    // last timing frame drawn is this paint's frame, and the full-resolution frame comes in the next.
    const std::optional<TimingFrame> timingFrame = m_needsTiming ? timeNewSdf(width, height) : std::nullopt;
    if (m_warmProgram) { // settleMarch() changed the program: its code generation on a tiny draw
        m_warmProgram = false;
        m_renderer->renderScaled(width, height, renderer::FrameScaler::kTimingScale, m_frame.camera, m_time, true);
    }
    renderer::FrameStats stats;
    float scale = 1.0f;
    if (timingFrame) {
        stats.cpuMilliseconds = timingFrame->milliseconds;
        scale = timingFrame->scale;
    } else {
        scale = m_scaler.scaleFor(width, height, m_interacting);
        // The status bar and the scale choice see what the frame really cost: measured to
        // glFinish, or by a query read at a later paint (FrameTiming).
        const bool finish = m_frameTiming == FrameTiming::Finish;
        stats = m_renderer->renderScaled(width, height, scale, m_frame.camera, m_time, finish);
        if (finish) {
            ++m_finishedFrames;
            frameCost(width, height, scale, stats.cpuMilliseconds, m_interacting, true);
        } else {
            if (scale >= 1.0f && !m_interacting) m_settleFrameMilliseconds = -1.0; // until its query is back
            if (stats.serial) m_pendingFrames.push_back({stats.serial, width, height, scale, m_interacting});
            if (m_pendingFrames.size() > 64) m_pendingFrames.erase(m_pendingFrames.begin());
            collectTimedFrames();
        }
    }
    m_lastScale = scale;
    if (timingFrame) {
        m_lastFrameMilliseconds = stats.cpuMilliseconds;
        if (scale >= 1.0f && !m_interacting)
            m_settleFrameMilliseconds = m_settleTiming
                                            ? m_settleTiming(fusedMarch(), conePass(), computeTracer(), stats.cpuMilliseconds)
                                            : stats.cpuMilliseconds;
    }
    if (scale >= 1.0f && !m_interacting) m_settleTimer.start();
    if (m_meshOverlay->hasMesh() && m_lastGoodSdf) {
        if (m_overlayGeneration != m_sdfGeneration) {
            for (const auto& d : m_meshOverlay->setSdf(*m_lastGoodSdf)) log::warning("mesh", shaders::formatDiagnostic(d));
            m_overlayGeneration = m_sdfGeneration;
        }
        m_meshOverlay->draw(width, height, m_frame.camera, m_time, m_parameters, m_meshScale);
    }
    if (m_pointCloud->hasPoints()) m_pointCloud->draw(width, height, m_frame.camera, m_pointSize * float(devicePixelRatioF()));
    if (m_probeTool && m_probeMark.x() >= 0) {
        QPainter painter(this);
        const QPointF centre = QPointF(m_probeMark) / devicePixelRatioF() + QPointF(0.5, 0.5);
        painter.setRenderHint(QPainter::Antialiasing);
        for (const auto& [colour, width] : {std::pair{QColor(0, 0, 0, 160), 3.0}, std::pair{QColor(255, 230, 0), 1.2}}) {
            painter.setPen(QPen(colour, width));
            painter.drawEllipse(centre, 6.0, 6.0);
            painter.drawLine(centre + QPointF(-12, 0), centre + QPointF(-7, 0));
            painter.drawLine(centre + QPointF(7, 0), centre + QPointF(12, 0));
            painter.drawLine(centre + QPointF(0, -12), centre + QPointF(0, -7));
            painter.drawLine(centre + QPointF(0, 7), centre + QPointF(0, 12));
        }
    }
    if (!m_overlay.isEmpty()) {
        QPainter painter(this);
        painter.setRenderHint(QPainter::TextAntialiasing);
        QFont font = painter.font();
        font.setPointSizeF(9.0);
        painter.setFont(font);
        QRect box = painter.fontMetrics().boundingRect(QRect(0, 0, this->width() - 16, 200), Qt::TextWordWrap, m_overlay);
        box.moveBottomLeft(QPoint(8, this->height() - 8));
        painter.fillRect(box.adjusted(-4, -3, 4, 3), QColor(0, 0, 0, 120));
        painter.setPen(QColor(235, 235, 235));
        painter.drawText(box, Qt::TextWordWrap, m_overlay);
    }
    emit frameRendered(m_lastFrameMilliseconds, scale);
    if (timingFrame && !m_refineTimer.isActive()) update(); // the full-resolution frame (not while the camera moves)
}

float ViewportWidget::resolutionCap() const {
    const qreal ratio = devicePixelRatioF();
    return m_scaler.cap(int(std::lround(width() * ratio)), int(std::lround(height() * ratio)));
}

std::optional<ViewportWidget::TimingFrame> ViewportWidget::timeNewSdf(int width, int height) {
    m_needsTiming = false;
    // 5 % of the side, 0.25 % of the pixels: cheap even for a shader that loops for long. The
    // first draw of a program includes the driver's code generation (llvmpipe compiles lazily):
    // draw twice and time the second.
    constexpr float kTimingScale = renderer::FrameScaler::kTimingScale;
    const double stallLimit = m_scaler.stallLimit();
    renderer::FrameStats timing = m_renderer->renderScaled(width, height, kTimingScale, m_frame.camera, m_time, true);
    float timingScale = kTimingScale; // of the last timing frame drawn
    if (timing.cpuMilliseconds <= stallLimit)
        timing = m_renderer->renderScaled(width, height, kTimingScale, m_frame.camera, m_time, true);
    double estimate = renderer::FrameScaler::estimateFullFrame(timing.cpuMilliseconds);
    if (estimate > m_scaler.frameBudget() && timing.cpuMilliseconds <= stallLimit) {
        // Small frames are dominated by fixed costs (stretching, synchronisation): measure at 3x
        // the side too and extrapolate from the cost per pixel.
        constexpr float kLarger = 3.0f * kTimingScale;
        renderer::FrameStats larger = m_renderer->renderScaled(width, height, kLarger, m_frame.camera, m_time, true);
        estimate = renderer::FrameScaler::estimateFullFrame(timing.cpuMilliseconds, std::pair{kLarger, larger.cpuMilliseconds});
        timing = larger;
        timingScale = kLarger;
    }
    if (timing.cpuMilliseconds > stallLimit && m_lastGoodSdf) {
        // Even the timing frame is over the limit: this SDF cannot be drawn interactively here.
        (void)m_renderer->setSdf(*m_lastGoodSdf);
        m_currentSdf.reset();
        m_scaler.clearCap();
        emit performanceWarning(tr("The new SDF needs %1 s for a frame at 5 % resolution (a runaway loop?): the previous SDF is "
                                   "back on screen; fix the loop or render it with sdfwb --batch render")
                                    .arg(timing.cpuMilliseconds / 1000.0, 0, 'f', 1));
        emit sdfReverted();
        return std::nullopt; // the previous SDF's frame is drawn in this paint
    }
    m_lastGoodSdf = std::move(m_currentSdf);
    emit sdfTimed();
    ++m_sdfGeneration;
    if (estimate > stallLimit) {
        m_scaler.capFromEstimate(width, height, estimate);
        emit performanceWarning(tr("A full frame of this SDF would take about %1 s: drawn at %2 % resolution (screenshots and "
                                   "exports still render in full)")
                                    .arg(estimate / 1000.0, 0, 'f', 1)
                                    .arg(int(resolutionCap() * 100.0f)));
    }
    emit frameRendered(timing.cpuMilliseconds, kTimingScale);
    if (estimate > m_scaler.frameBudget() && !m_interacting) {
        // A slow SDF: the last timing frame (its picture fills the frame) is its first frame, the
        // full-resolution one comes right after it. Moving frames start from the scale that costs
        // half the frame budget.
        m_scaler.seedScale(estimate);
        return TimingFrame{timingScale, timing.cpuMilliseconds};
    }
    return std::nullopt;
}

void ViewportWidget::releaseGl() {
    m_renderer->releaseGl();
    m_picture->releaseGl();
    m_meshOverlay->releaseGl();
    m_pointCloud->releaseGl();
    if (m_fieldAtPoint) m_fieldAtPoint->releaseGl();
    m_fieldAtPoint.reset();
}

void ViewportWidget::setMeshOverlay(const std::vector<float>& positions, const std::vector<std::uint32_t>& indices, float scale) {
    m_meshOverlay->setMesh(positions, indices);
    m_meshScale = scale;
    update();
}

bool ViewportWidget::hasMeshOverlay() const { return m_meshOverlay->hasMesh(); }

void ViewportWidget::interacted() {
    if (!m_interacting) {
        m_interacting = true;
        m_scaler.startInteraction();
    }
    m_refineTimer.start();
    m_settleTimer.stop();
    update();
    emit cameraChanged(m_frame.camera);
}

// Shadertoy's iMouse: xy the pointer while the left button is down, zw where it was pressed (z
// negative once released, w negative after the press's first frame), in pixels from the lower left.
void ViewportWidget::shadertoyMouseEvent(QMouseEvent* event, bool press, bool release) {
    const qreal ratio = devicePixelRatioF();
    const float x = float(event->position().x() * ratio);
    const float y = float((height() - event->position().y()) * ratio);
    if (press) {
        m_shadertoyMouse = glm::vec4(x, y, x, y);
    } else if (release) {
        m_shadertoyMouse.z = -std::abs(m_shadertoyMouse.z);
        m_shadertoyMouse.w = -std::abs(m_shadertoyMouse.w);
    } else {
        m_shadertoyMouse.x = x;
        m_shadertoyMouse.y = y;
        m_shadertoyMouse.w = -std::abs(m_shadertoyMouse.w);
    }
    update();
}

void ViewportWidget::mousePressEvent(QMouseEvent* event) {
    m_lastMouse = event->position().toPoint();
    setFocus();
    if (m_showPicture) {
        if (event->button() == Qt::LeftButton) shadertoyMouseEvent(event, true, false);
        return;
    }
    m_probeClick = m_probeTool && event->button() == Qt::LeftButton;
    if (m_probeClick) {
        const qreal ratio = devicePixelRatioF();
        const int width = int(std::lround(this->width() * ratio)), height = int(std::lround(this->height() * ratio));
        emit pixelProbed(std::clamp(int(event->position().x() * ratio), 0, width - 1),
                         std::clamp(int(event->position().y() * ratio), 0, height - 1), width, height);
    }
}

void ViewportWidget::leaveEvent(QEvent* event) {
    emit planeHovered(false, {});
    QOpenGLWidget::leaveEvent(event);
}

void ViewportWidget::mouseReleaseEvent(QMouseEvent* event) {
    if (m_showPicture && event->button() == Qt::LeftButton) shadertoyMouseEvent(event, false, true);
    if (event->button() == Qt::LeftButton) m_probeClick = false;
    if (event->button() == Qt::RightButton) {
        m_keys.clear();
        m_flyTimer.stop();
    }
}

void ViewportWidget::mouseMoveEvent(QMouseEvent* event) {
    QPoint position = event->position().toPoint();
    QPoint delta = position - m_lastMouse;
    m_lastMouse = position;
    if (m_showPicture) {
        if (event->buttons() & Qt::LeftButton) shadertoyMouseEvent(event, false, false);
    } else if (event->buttons() == Qt::NoButton) {
        if (m_plane.enabled) {
            PlaneValue value;
            const bool valid = planeValueAt(event->position(), value);
            emit planeHovered(valid, value);
        }
    } else if ((event->buttons() & Qt::LeftButton) && m_probeClick) {
        // the probe tool's click: the camera stays
    } else if ((event->buttons() & Qt::LeftButton) && (event->modifiers() & Qt::ControlModifier) && m_plane.enabled) {
        m_plane.offset = std::clamp(m_plane.offset - float(delta.y()) * 0.004f, -1.0f, 1.0f);
        setPlane(m_plane);
        emit planeDragged(m_plane);
    } else if (event->buttons() & Qt::LeftButton) {
        values::orbit(m_frame.camera, -float(delta.x()) * 0.01f, float(delta.y()) * 0.01f);
        interacted();
    } else if (event->buttons() & Qt::RightButton) {
        values::turn(m_frame.camera, -float(delta.x()) * 0.005f, -float(delta.y()) * 0.005f);
        interacted();
    }
}

void ViewportWidget::wheelEvent(QWheelEvent* event) {
    float notches = float(event->angleDelta().y()) / 120.0f;
    values::dolly(m_frame.camera, std::pow(0.9f, notches));
    interacted();
}

void ViewportWidget::keyPressEvent(QKeyEvent* event) {
    static const QSet<int> movement = {Qt::Key_W, Qt::Key_A, Qt::Key_S, Qt::Key_D, Qt::Key_Z, Qt::Key_C};
    if (!movement.contains(event->key())) return QOpenGLWidget::keyPressEvent(event);
    m_keys.insert(event->key());
    if (!m_flyTimer.isActive()) {
        m_flyClock.start();
        m_flyTimer.start();
    }
}

void ViewportWidget::keyReleaseEvent(QKeyEvent* event) {
    if (event->isAutoRepeat()) return;
    m_keys.remove(event->key());
    if (m_keys.isEmpty()) m_flyTimer.stop();
}

void ViewportWidget::focusOutEvent(QFocusEvent* event) {
    m_keys.clear();
    m_flyTimer.stop();
    QOpenGLWidget::focusOutEvent(event);
}

void ViewportWidget::flyStep() {
    double seconds = std::min(m_flyClock.restart() / 1000.0, 0.1);
    if (m_keys.isEmpty()) return;
    Qt::KeyboardModifiers modifiers = QGuiApplication::queryKeyboardModifiers();
    float speed = 0.8f * (modifiers & Qt::ShiftModifier ? 4.0f : 1.0f) * (modifiers & Qt::AltModifier ? 0.25f : 1.0f);
    glm::vec3 move(0.0f);
    if (m_keys.contains(Qt::Key_W)) move.z += 1.0f;
    if (m_keys.contains(Qt::Key_S)) move.z -= 1.0f;
    if (m_keys.contains(Qt::Key_D)) move.x += 1.0f;
    if (m_keys.contains(Qt::Key_A)) move.x -= 1.0f;
    if (m_keys.contains(Qt::Key_C)) move.y += 1.0f;
    if (m_keys.contains(Qt::Key_Z)) move.y -= 1.0f;
    values::fly(m_frame.camera, move * speed * float(seconds));
    interacted();
}

} // namespace sdfwb::widgets
