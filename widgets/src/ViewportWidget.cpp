#include <widgets/ViewportWidget.h>

#include <core/Log.h>
#include <renderer/GlInfo.h>
#include <renderer/SdfRenderer.h>

#include <QMouseEvent>
#include <QOpenGLContext>
#include <QWheelEvent>

#include <cmath>

namespace sdfwb::widgets {

ViewportWidget::ViewportWidget(QWidget* parent)
    : QOpenGLWidget(parent), m_renderer(std::make_unique<renderer::SdfRenderer>()) {
    setMinimumSize(64, 64);
    setFocusPolicy(Qt::StrongFocus);
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
    doneCurrent();
    update();
    return diagnostics;
}

void ViewportWidget::setShading(const renderer::ShadingSettings& shading) {
    m_shading = shading;
    if (context() && isValid()) {
        makeCurrent();
        (void)m_renderer->setShading(shading);
        doneCurrent();
    }
    update();
}

void ViewportWidget::setCamera(const renderer::Camera& camera) {
    m_camera = camera;
    update();
}

void ViewportWidget::resetCamera() { setCamera(renderer::Camera{}); }

void ViewportWidget::initializeGL() {
    connect(context(), &QOpenGLContext::aboutToBeDestroyed, this, [this] {
        makeCurrent();
        releaseGl();
        doneCurrent();
    }, Qt::DirectConnection);
    renderer::GlInfo info = renderer::queryGlInfo();
    m_glDescription = QString::fromStdString(renderer::describe(info));
    log::info("gl", "viewport context: " + renderer::describe(info));
    if (auto ok = renderer::requireGl43(info); !ok) log::error("gl", ok.error().message);
    (void)m_renderer->setShading(m_shading);
    if (m_pendingSdf) {
        auto diagnostics = m_renderer->setSdf(*m_pendingSdf);
        for (const auto& d : diagnostics) log::warning("shaders", shaders::formatDiagnostic(d));
        m_pendingSdf.reset();
    }
    emit glReady(m_glDescription);
}

void ViewportWidget::paintGL() {
    const qreal ratio = devicePixelRatioF();
    int width = int(std::lround(this->width() * ratio));
    int height = int(std::lround(this->height() * ratio));
    // finish: the status bar shows what the frame really cost, not the time to queue it.
    renderer::FrameStats stats = m_renderer->render(width, height, m_camera, 0.0f, true);
    m_lastFrameMilliseconds = stats.cpuMilliseconds;
    emit frameRendered(stats.cpuMilliseconds);
}

void ViewportWidget::releaseGl() { m_renderer->releaseGl(); }

void ViewportWidget::mousePressEvent(QMouseEvent* event) { m_lastMouse = event->position().toPoint(); }

void ViewportWidget::mouseMoveEvent(QMouseEvent* event) {
    QPoint position = event->position().toPoint();
    QPoint delta = position - m_lastMouse;
    m_lastMouse = position;
    if (event->buttons() & Qt::LeftButton) {
        renderer::orbit(m_camera, -float(delta.x()) * 0.01f, float(delta.y()) * 0.01f);
        update();
    }
}

void ViewportWidget::wheelEvent(QWheelEvent* event) {
    float notches = float(event->angleDelta().y()) / 120.0f;
    renderer::dolly(m_camera, std::pow(0.9f, notches));
    update();
}

} // namespace sdfwb::widgets
