#pragma once
// Hosts the sphere tracer in a QOpenGLWidget. All drawing is forwarded to renderer::SdfRenderer;
// this class only turns mouse input into camera moves. UI thread only. The renderer's GL objects
// are freed when Qt destroys the context (floating a dock re-creates it) and rebuilt lazily.

#include <renderer/Camera.h>
#include <renderer/RenderSettings.h>
#include <shaders/Diagnostic.h>
#include <shaders/SdfSource.h>

#include <QOpenGLWidget>
#include <QPoint>

#include <memory>
#include <vector>

namespace sdfwb::renderer {
class SdfRenderer;
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

    void setShading(const renderer::ShadingSettings& shading);
    const renderer::Camera& camera() const { return m_camera; }
    void setCamera(const renderer::Camera& camera);
    void resetCamera();

    double lastFrameMilliseconds() const { return m_lastFrameMilliseconds; }
    QString glDescription() const { return m_glDescription; }

signals:
    void frameRendered(double milliseconds);
    void glReady(const QString& description);

protected:
    void initializeGL() override;
    void paintGL() override;
    void mousePressEvent(QMouseEvent* event) override;
    void mouseMoveEvent(QMouseEvent* event) override;
    void wheelEvent(QWheelEvent* event) override;

private:
    void releaseGl();

    std::unique_ptr<renderer::SdfRenderer> m_renderer;
    std::unique_ptr<shaders::PreparedSdf> m_pendingSdf;
    renderer::ShadingSettings m_shading;
    renderer::Camera m_camera;
    QPoint m_lastMouse;
    double m_lastFrameMilliseconds = 0.0;
    QString m_glDescription;
};

} // namespace sdfwb::widgets
