#pragma once
// The march debugger: the viewport's probe tool clicks a pixel, and this runs the probe request
// on that pixel in the workbench's persistent worker (JobWorker) with exactly what the viewport shows (the document's text and
// parameters, camera, trace settings, shading, plane, time, frame size), then fills the probe dock.
// A click while a probe runs replaces it (the newest pixel wins).

#include <values/Requests.h>

#include <QObject>

#include <functional>
#include <optional>

namespace sdfwb::widgets {
class ProbePanel;
class ViewportWidget;
} // namespace sdfwb::widgets

namespace sdfwb::app {

class JobChannel;
class JobClient;
class JobWorker;
class SdfDocument;

class ProbeController : public QObject {
    Q_OBJECT
public:
    ProbeController(widgets::ProbePanel* panel, widgets::ViewportWidget* viewport, SdfDocument* document, JobWorker* worker,
                    QObject* parent = nullptr);
    void setExecutable(const QString& path);
    // Its jobs, for what listens to every job (the Problems panel).
    JobClient* jobClient() const;
    // Probes pixel (x, y), top row 0, of a width x height frame of the viewport's view.
    void probe(int x, int y, int width, int height);
    // The request such a click sends: the document's frame (the viewport's frame settings whole).
    values::ProbeRequest request(int x, int y, int width, int height) const;
    bool isRunning() const;

signals:
    void probed(bool ok); // the dock shows the march (ok) or why there is none

private:
    widgets::ProbePanel* m_panel;
    widgets::ViewportWidget* m_viewport;
    SdfDocument* m_document;
    JobChannel* m_process;                      // on the workbench's persistent worker
    std::optional<values::ProbeRequest> m_next; // clicked while one ran
};

} // namespace sdfwb::app
