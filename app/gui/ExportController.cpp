#include "ExportController.h"

#include "BatchProcess.h"
#include "SdfDocument.h"

#include <core/Log.h>
#include <jobs/JobJson.h>
#include <renderer/ImageIO.h>
#include <widgets/ExportDialog.h>
#include <widgets/ViewportWidget.h>

#include <QElapsedTimer>

namespace sdfwb::app {

ExportController::ExportController(QWidget* window, widgets::ViewportWidget* viewport, SdfDocument* document, QObject* parent)
    : QObject(parent), m_window(window), m_viewport(viewport), m_document(document), m_process(new BatchProcess(this)) {
    connect(m_process, &BatchProcess::progress, this, [this](quint64 done, quint64 total) {
        if (m_videoDialog) m_videoDialog->setProgress(done, total);
    });
    connect(m_process, &BatchProcess::finished, this, [this](bool ok, bool, const std::string& json, const QString& error) {
        QString message = error;
        auto report = ok ? jobs::reportFromJson<values::AnimateReport>(json) : Expected<values::AnimateReport>(makeError(""));
        if (ok && !report) {
            ok = false;
            message = QString::fromStdString(report.error().message);
        }
        if (ok)
            message = tr("Wrote %1: %2 frames at %3 fps.")
                          .arg(QString::fromStdString(report->output))
                          .arg(report->frames)
                          .arg(report->framesPerSecond);
        if (m_videoDialog) {
            m_videoDialog->setRunning(false);
            m_videoDialog->setMessage(message, !ok);
        }
        log::write(ok ? log::Level::Info : log::Level::Warning, "export", message.toStdString());
        emit videoFinished(ok, message);
    });
}

void ExportController::setExecutable(const QString& path) { m_process->setExecutable(path); }

JobClient* ExportController::jobClient() const { return m_process; }

bool ExportController::isExporting() const { return m_process->isRunning(); }

QString ExportController::saveScreenshot(const QString& path, int width, int height) {
    QElapsedTimer timer;
    timer.start();
    // The viewport's frame settings draw it, the overlay (name, author, license) included as the
    // viewport shows it; EXR gets the float frame.
    const std::string label = m_viewport->frameSettings().overlay ? m_viewport->overlayText().toStdString() : std::string();
    Expected<void> written;
    if (renderer::isHighDynamicRange(path.toStdString())) {
        renderer::FloatImage image = m_viewport->renderFloatImage(width, height);
        if (image.width == 0) return tr("The viewport has no GL context yet.");
        if (!label.empty()) (void)renderer::drawLabel(image, label);
        written = renderer::writeImage(path.toStdString(), image);
    } else {
        renderer::Image image = m_viewport->renderImage(width, height);
        if (image.width == 0) return tr("The viewport has no GL context yet.");
        if (!label.empty()) (void)renderer::drawLabel(image, label);
        written = renderer::writeImage(path.toStdString(), image);
    }
    if (!written) return QString::fromStdString(written.error().message);
    log::info("export", "screenshot " + path.toStdString() + " (" + std::to_string(width) + "x" + std::to_string(height) +
                            ") in " + std::to_string(timer.elapsed()) + " ms");
    return {};
}

void ExportController::showScreenshotDialog() {
    if (!m_screenshotDialog) {
        m_screenshotDialog = new widgets::ExportDialog(widgets::ExportDialog::Kind::Screenshot, m_window);
        connect(m_screenshotDialog, &widgets::ExportDialog::startRequested, this, [this](const values::AnimateRequest& r) {
            const QString output = QString::fromStdString(r.output);
            QString error = saveScreenshot(output, r.frame.width, r.frame.height);
            m_screenshotDialog->setMessage(
                error.isEmpty() ? tr("Saved %1 (%2x%3).").arg(output).arg(r.frame.width).arg(r.frame.height) : error,
                !error.isEmpty());
        });
    }
    values::AnimateRequest shot = m_screenshotDialog->request();
    const qreal ratio = m_viewport->devicePixelRatioF();
    shot.frame.width = int(m_viewport->width() * ratio);
    shot.frame.height = int(m_viewport->height() * ratio);
    if (shot.output.empty()) shot.output = "screenshot.png";
    m_screenshotDialog->setRequest(shot);
    m_screenshotDialog->show();
    m_screenshotDialog->raise();
}

void ExportController::showVideoDialog() {
    if (!m_videoDialog) {
        m_videoDialog = new widgets::ExportDialog(widgets::ExportDialog::Kind::Video, m_window);
        connect(m_videoDialog, &widgets::ExportDialog::startRequested, this, &ExportController::startVideo);
        connect(m_videoDialog, &widgets::ExportDialog::cancelRequested, m_process, &BatchProcess::cancel);
        values::AnimateRequest first;
        first.output = "animation.mp4";
        first.turntable = true; // the workbench offers a turntable first: a still shape's clip would not move
        m_videoDialog->setRequest(first);
    }
    m_videoDialog->show();
    m_videoDialog->raise();
}

values::AnimateRequest ExportController::videoRequest(const values::AnimateRequest& fromDialog) const {
    values::AnimateRequest request = fromDialog;
    request.frame = m_document->frame(m_viewport->frameSettings(), fromDialog.frame.width, fromDialog.frame.height);
    if (m_clipEnd) request.paramsEnd = m_clipEnd();
    return request;
}

void ExportController::startVideo(const values::AnimateRequest& fromDialog) {
    m_videoDialog->setRunning(true);
    m_videoDialog->setMessage(tr("Exporting..."), false);
    m_process->start(videoRequest(fromDialog));
}

} // namespace sdfwb::app
