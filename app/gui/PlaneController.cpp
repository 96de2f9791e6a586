#include "PlaneController.h"

#include "JobWorker.h"
#include "SdfDocument.h"

#include <widgets/PlanePanel.h>
#include <widgets/ViewportWidget.h>

#include <jobs/JobJson.h>

#include <glm/geometric.hpp>

namespace sdfwb::app {

PlaneController::PlaneController(widgets::PlanePanel* panel, widgets::ViewportWidget* viewport, SdfDocument* document,
                                 JobWorker* worker, QObject* parent)
    : QObject(parent), m_panel(panel), m_viewport(viewport), m_document(document), m_process(new JobChannel(worker, this)) {
    m_debounce.setSingleShot(true);
    m_debounce.setInterval(kDebounceMs);
    connect(&m_debounce, &QTimer::timeout, this, &PlaneController::refresh);
    connect(m_panel, &widgets::PlanePanel::planeEdited, m_document, &SdfDocument::setPlane);
    connect(m_document, &SdfDocument::planeChanged, this, [this](const values::CuttingPlane& plane) {
        m_panel->setPlane(plane); // no planeEdited: the panel only tells of the user's edits
        m_debounce.start();
    });
    connect(m_panel, &widgets::PlanePanel::applyStepFactor, this, [this](float factor) {
        values::TraceSettings trace = m_viewport->trace();
        trace.stepFactor = std::clamp(factor, 0.01f, 1.0f);
        m_viewport->setTrace(trace);
    });
    // Show where: ring the examples, move the plane through the first (the readouts follow).
    connect(m_panel, &widgets::PlanePanel::showWhere, this, [this](const std::vector<glm::vec3>& examples) {
        if (examples.empty()) return;
        values::ShadingSettings shading = m_viewport->shading();
        shading.markers = examples;
        m_viewport->setShading(shading);
        values::CuttingPlane plane = m_document->plane();
        plane.offset = glm::dot(glm::normalize(plane.normal), examples.front());
        m_document->setPlane(plane);
        emit markersShown(int(examples.size()));
    });
    connect(m_process, &JobChannel::finished, this, [this](bool ok, bool, const std::string& json, const QString& message) {
        auto report = ok ? jobs::reportFromJson<values::AuditJobReport>(json)
                         : Expected<values::AuditJobReport>(makeError(message.toStdString()));
        if (report && !report->readout) report = makeError("plane readouts: the report holds no readout");
        if (!report) {
            m_panel->setReadoutMessage(QString::fromStdString(report.error().message));
        } else {
            m_panel->setReadout(*report->readout);
            emit readoutUpdated();
        }
        if (m_pending) {
            m_pending = false;
            refresh();
        }
    });
}

void PlaneController::setExecutable(const QString& path) { m_process->worker()->setExecutable(path); }

JobClient* PlaneController::jobClient() const { return m_process; }

void PlaneController::refresh() {
    const values::CuttingPlane& plane = m_document->plane();
    if (!plane.enabled) return;
    if (m_process->isRunning()) {
        m_pending = true; // one more run with the newest plane when this one ends
        return;
    }
    values::AuditRequest request;
    request.sdf = m_document->input();
    request.plane = values::PlaneSpec{plane.normal, plane.offset};
    request.resolution = 192;
    request.time = m_document->time();
    m_process->start(request);
}

} // namespace sdfwb::app
