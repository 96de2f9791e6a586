#include "ProbeController.h"

#include "JobWorker.h"
#include "SdfDocument.h"

#include <core/Log.h>
#include <jobs/JobJson.h>
#include <widgets/ProbePanel.h>
#include <widgets/ViewportWidget.h>

namespace sdfwb::app {

ProbeController::ProbeController(widgets::ProbePanel* panel, widgets::ViewportWidget* viewport, SdfDocument* document,
                                 JobWorker* worker, QObject* parent)
    : QObject(parent), m_panel(panel), m_viewport(viewport), m_document(document), m_process(new JobChannel(worker, this)) {
    connect(m_viewport, &widgets::ViewportWidget::pixelProbed, this, &ProbeController::probe);
    connect(m_process, &JobChannel::finished, this, [this](bool ok, bool, const std::string& json, const QString& message) {
        if (m_next) { // a newer click: show that one
            values::ProbeRequest next = *m_next;
            m_next.reset();
            m_process->start(next);
            return;
        }
        auto report = ok ? jobs::reportFromJson<values::ProbeReport>(json)
                         : Expected<values::ProbeReport>(makeError(message.toStdString()));
        if (!report) {
            m_panel->setMessage(tr("Probe failed: %1").arg(QString::fromStdString(report.error().message)));
            log::warning("probe", report.error().message);
            emit probed(false);
            return;
        }
        m_panel->setReport(*report);
        log::info("probe", "pixel " + std::to_string(report->x) + "," + std::to_string(report->y) + ": " +
                               values::marchEventName(report->outcome) + " after " + std::to_string(report->steps) + " steps, " +
                               std::to_string(report->oversteps) + " oversteps");
        emit probed(true);
    });
}

void ProbeController::setExecutable(const QString& path) { m_process->worker()->setExecutable(path); }

JobClient* ProbeController::jobClient() const { return m_process; }

bool ProbeController::isRunning() const { return m_process->isRunning(); }

values::ProbeRequest ProbeController::request(int x, int y, int width, int height) const {
    values::ProbeRequest request;
    request.frame = m_document->frame(m_viewport->frameSettings(), width, height);
    request.x = x;
    request.y = y;
    return request;
}

void ProbeController::probe(int x, int y, int width, int height) {
    const values::ProbeRequest request = this->request(x, y, width, height);
    m_viewport->setProbeMark(QPoint(x, y));
    m_panel->setMessage(tr("Probing pixel (%1, %2)...").arg(x).arg(y));
    if (m_process->isRunning()) {
        m_next = request;
        return;
    }
    m_process->start(request);
}

} // namespace sdfwb::app
