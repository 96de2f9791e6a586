#pragma once
// Keeps the panel in step with the document's cutting plane (which the viewport draws), and refreshes the plane's
// readouts after each change (debounced) by running the plane audit request in the workbench's
// persistent worker (JobWorker), so the editor and the viewport never wait for the analysis.

#include <values/Requests.h>

#include <QObject>
#include <QTimer>

namespace sdfwb::widgets {
class PlanePanel;
class ViewportWidget;
} // namespace sdfwb::widgets

namespace sdfwb::app {

class JobChannel;
class JobClient;
class JobWorker;
class SdfDocument;

class PlaneController : public QObject {
    Q_OBJECT
public:
    // The wait after the plane's last move before its readouts are asked for. Short, as the warm
    // worker answers in about the job's own time (bench/bench_interactive.cpp); 250 ms when each
    // request started a process. While one runs, a newer plane waits for it (the newest wins).
    static constexpr int kDebounceMs = 10;

    // The readouts are of the document's shown SDF, at its time, on its plane.
    PlaneController(widgets::PlanePanel* panel, widgets::ViewportWidget* viewport, SdfDocument* document, JobWorker* worker,
                    QObject* parent = nullptr);
    void setExecutable(const QString& path);
    // Its jobs, for what listens to every job (the Problems panel).
    JobClient* jobClient() const;
    // Recomputes the readouts now (also called when the SDF changes).
    void refresh();
    // Recomputes them after the debounce delay (parameter drags: one child when the drag rests).
    void scheduleRefresh() { m_debounce.start(); }

signals:
    void readoutUpdated();
    void markersShown(int count);

private:
    widgets::PlanePanel* m_panel;
    widgets::ViewportWidget* m_viewport;
    SdfDocument* m_document;
    JobChannel* m_process; // on the workbench's persistent worker
    QTimer m_debounce;
    bool m_pending = false;
};

} // namespace sdfwb::app
