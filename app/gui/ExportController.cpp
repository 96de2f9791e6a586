#include "ExportController.h"

#include "BatchProcess.h"

#include <core/Log.h>
#include <renderer/ImageIO.h>
#include <widgets/ExportDialog.h>
#include <widgets/ViewportWidget.h>

#include <QElapsedTimer>

namespace sdfwb::app {

ExportController::ExportController(QWidget* window, widgets::ViewportWidget* viewport, std::function<QString()> currentSdf,
                                   QObject* parent)
    : QObject(parent), m_window(window), m_viewport(viewport), m_currentSdf(std::move(currentSdf)),
      m_process(new BatchProcess(this)) {
    connect(m_process, &BatchProcess::progress, this, [this](quint64 done, quint64 total) {
        if (m_videoDialog) m_videoDialog->setProgress(done, total);
    });
    connect(m_process, &BatchProcess::finished, this, [this](bool ok, bool, const QJsonObject& report, const QString& error) {
        QString message = ok ? tr("Wrote %1: %2 frames at %3 fps.")
                                   .arg(report["output"].toString())
                                   .arg(report["frames"].toInt())
                                   .arg(report["fps"].toInt())
                             : error;
        if (m_videoDialog) {
            m_videoDialog->setRunning(false);
            m_videoDialog->setMessage(message, !ok);
        }
        log::write(ok ? log::Level::Info : log::Level::Warning, "export", message.toStdString());
        emit videoFinished(ok, message);
    });
}

void ExportController::setExecutable(const QString& path) { m_process->setExecutable(path); }

void ExportController::setSdfArguments(std::function<QStringList()> provider) { m_process->setSdfArguments(std::move(provider)); }
bool ExportController::isExporting() const { return m_process->isRunning(); }

QString ExportController::saveScreenshot(const QString& path, int width, int height) {
    QElapsedTimer timer;
    timer.start();
    renderer::Image image = m_viewport->renderImage(width, height);
    if (image.width == 0) return tr("The viewport has no GL context yet.");
    auto written = renderer::writeImage(path.toStdString(), image);
    if (!written) return QString::fromStdString(written.error().message);
    log::info("export", "screenshot " + path.toStdString() + " (" + std::to_string(width) + "x" + std::to_string(height) +
                            ") in " + std::to_string(timer.elapsed()) + " ms");
    return {};
}

void ExportController::showScreenshotDialog() {
    if (!m_screenshotDialog) {
        m_screenshotDialog = new widgets::ExportDialog(widgets::ExportDialog::Kind::Screenshot, m_window);
        connect(m_screenshotDialog, &widgets::ExportDialog::startRequested, this, [this](const widgets::ExportSettings& s) {
            QString error = saveScreenshot(s.output, s.width, s.height);
            m_screenshotDialog->setMessage(
                error.isEmpty() ? tr("Saved %1 (%2x%3).").arg(s.output).arg(s.width).arg(s.height) : error, !error.isEmpty());
        });
    }
    widgets::ExportSettings settings = m_screenshotDialog->settings();
    const qreal ratio = m_viewport->devicePixelRatioF();
    settings.width = int(m_viewport->width() * ratio);
    settings.height = int(m_viewport->height() * ratio);
    if (settings.output.isEmpty()) settings.output = "screenshot.png";
    m_screenshotDialog->setSettings(settings);
    m_screenshotDialog->show();
    m_screenshotDialog->raise();
}

void ExportController::showVideoDialog() {
    if (!m_videoDialog) {
        m_videoDialog = new widgets::ExportDialog(widgets::ExportDialog::Kind::Video, m_window);
        connect(m_videoDialog, &widgets::ExportDialog::startRequested, this, &ExportController::startVideo);
        connect(m_videoDialog, &widgets::ExportDialog::cancelRequested, m_process, &BatchProcess::cancel);
        widgets::ExportSettings settings;
        settings.output = "animation.mp4";
        m_videoDialog->setSettings(settings);
    }
    m_videoDialog->show();
    m_videoDialog->raise();
}

void ExportController::startVideo(const widgets::ExportSettings& s) {
    QString sdf = m_currentSdf();
    if (sdf.isEmpty()) {
        m_videoDialog->setMessage(tr("Save the SDF first: the export reads the file."), true);
        return;
    }
    const renderer::Camera& camera = m_viewport->camera();
    const renderer::ShadingSettings& shading = m_viewport->shading();
    auto vec = [](const glm::vec3& v) { return QString("%1,%2,%3").arg(v.x, 0, 'g', 9).arg(v.y, 0, 'g', 9).arg(v.z, 0, 'g', 9); };
    QStringList arguments = {"animate",
                             "--sdf",
                             sdf,
                             "--output",
                             s.output,
                             "--size",
                             QString("%1x%2").arg(s.width).arg(s.height),
                             "--seconds",
                             QString::number(s.seconds, 'g', 9),
                             "--fps",
                             QString::number(s.framesPerSecond),
                             "--shading",
                             shaders::shadingModeName(shading.mode),
                             "--matcap",
                             QString::fromStdString(shading.matcap),
                             "--camera",
                             vec(camera.position),
                             "--target",
                             vec(camera.target),
                             "--fov",
                             QString::number(camera.fovYDegrees, 'g', 9),
                             "--time",
                             QString::number(m_viewport->time(), 'g', 9)};
    if (s.turntable) arguments << "--turntable";
    if (shading.ambientOcclusion) arguments << "--ao";
    m_videoDialog->setRunning(true);
    m_videoDialog->setMessage(tr("Exporting..."), false);
    m_process->start(arguments);
}

} // namespace sdfwb::app
