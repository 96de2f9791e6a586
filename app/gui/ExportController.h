#pragma once
// Screenshots (F4: rendered in the viewport's context at any size, written through OpenImageIO)
// and animations (F6: `sdfwb --batch animate` as a child process with the viewport's camera and
// shading, so the UI stays responsive and Cancel leaves no file).

#include <values/Requests.h>

#include <QObject>
#include <QString>

#include <functional>

namespace sdfwb::widgets {
class ExportDialog;
class ViewportWidget;
} // namespace sdfwb::widgets

namespace sdfwb::app {

class BatchProcess;
class JobClient;
class SdfDocument;

class ExportController : public QObject {
    Q_OBJECT
public:
    ExportController(QWidget* window, widgets::ViewportWidget* viewport, SdfDocument* document, QObject* parent = nullptr);

    void setExecutable(const QString& path);
    // Its jobs, for what listens to every job (the Problems panel).
    JobClient* jobClient() const;
    // Where the clip's last-frame parameter values come from (empty: no keyframe).
    void setClipEnd(std::function<std::vector<shaders::ParameterValue>()> clipEnd) { m_clipEnd = std::move(clipEnd); }

    void showScreenshotDialog();
    void showVideoDialog();
    widgets::ExportDialog* screenshotDialog() const { return m_screenshotDialog; }
    widgets::ExportDialog* videoDialog() const { return m_videoDialog; }

    // Renders and writes a screenshot; returns an error message, empty on success.
    QString saveScreenshot(const QString& path, int width, int height);
    bool isExporting() const;
    // The animate request an export with `settings` starts: the document's frame (its shown SDF,
    // time and plane; the viewport's camera, shading, trace settings and markers).
    values::AnimateRequest videoRequest(const values::AnimateRequest& fromDialog) const; // on the document's frame

signals:
    void videoFinished(bool ok, const QString& message);

private:
    void startVideo(const values::AnimateRequest& fromDialog);

    QWidget* m_window;
    widgets::ViewportWidget* m_viewport;
    std::function<std::vector<shaders::ParameterValue>()> m_clipEnd;
    SdfDocument* m_document;
    BatchProcess* m_process;
    widgets::ExportDialog* m_screenshotDialog = nullptr;
    widgets::ExportDialog* m_videoDialog = nullptr;
};

} // namespace sdfwb::app
