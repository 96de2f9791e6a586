#include "PlaneController.h"

#include "BatchProcess.h"

#include <widgets/PlanePanel.h>
#include <widgets/ViewportWidget.h>

#include <QJsonArray>

#include <glm/geometric.hpp>

namespace sdfwb::app {

PlaneController::PlaneController(widgets::PlanePanel* panel, widgets::ViewportWidget* viewport,
                                 std::function<QString()> currentSdf, QObject* parent)
    : QObject(parent), m_panel(panel), m_viewport(viewport), m_currentSdf(std::move(currentSdf)),
      m_process(new BatchProcess(this)) {
    m_debounce.setSingleShot(true);
    m_debounce.setInterval(250);
    connect(&m_debounce, &QTimer::timeout, this, &PlaneController::refresh);
    connect(m_panel, &widgets::PlanePanel::planeEdited, this, [this](const renderer::CuttingPlane& plane) {
        m_viewport->setPlane(plane);
        m_debounce.start();
    });
    connect(m_viewport, &widgets::ViewportWidget::planeDragged, this, [this](const renderer::CuttingPlane& plane) {
        m_panel->setPlane(plane);
        m_debounce.start();
    });
    connect(m_panel, &widgets::PlanePanel::applyStepFactor, this, [this](float factor) {
        renderer::TraceSettings trace = m_viewport->trace();
        trace.stepFactor = std::clamp(factor, 0.01f, 1.0f);
        m_viewport->setTrace(trace);
    });
    // Show where: ring the examples, move the plane through the first (the readouts follow).
    connect(m_panel, &widgets::PlanePanel::showWhere, this, [this](const std::vector<glm::vec3>& examples) {
        if (examples.empty()) return;
        renderer::ShadingSettings shading = m_viewport->shading();
        shading.markers = examples;
        m_viewport->setShading(shading);
        renderer::CuttingPlane plane = m_viewport->plane();
        plane.offset = glm::dot(glm::normalize(plane.normal), examples.front());
        m_panel->setPlane(plane);
        m_viewport->setPlane(plane);
        m_debounce.start();
        emit markersShown(int(examples.size()));
    });
    connect(m_process, &BatchProcess::finished, this, [this](bool ok, bool, const QJsonObject& report, const QString& message) {
        if (!ok) {
            m_panel->setReadoutMessage(message);
        } else {
            widgets::PlaneReadoutView view;
            view.minimum = float(report["minimum"].toDouble());
            view.maximum = float(report["maximum"].toDouble());
            view.lipschitzMax = float(report["lipschitz_max"].toDouble());
            view.lipschitz99 = float(report["lipschitz_p99"].toDouble());
            view.shareAboveOne = report["share_above_one"].toDouble();
            if (report["truncation_distance"].isDouble())
                view.truncationDistance = float(report["truncation_distance"].toDouble());
            view.discontinuities = quint64(report["discontinuities"].toInteger());
            view.nanCount = quint64(report["nan_count"].toInteger());
            view.points = quint64(report["points"].toInteger());
            for (const QJsonValue& bin : report["histogram"].toArray()) view.histogram.push_back(quint64(bin.toInteger()));
            view.safeStepFactor = float(report["safe_step_factor"].toDouble());
            view.seconds = report["seconds"].toDouble();
            for (const QJsonValue& item : report["flags"].toArray()) {
                widgets::FindingView finding;
                finding.name = item["flag"].toString();
                finding.evidence = item["evidence"].toString();
                for (const QJsonValue& point : item["examples"].toArray()) {
                    const QJsonArray xyz = point.toArray();
                    finding.examples.push_back(
                        glm::vec3(float(xyz[0].toDouble()), float(xyz[1].toDouble()), float(xyz[2].toDouble())));
                }
                view.findings.push_back(std::move(finding));
            }
            m_panel->setReadout(view);
            emit readoutUpdated();
        }
        if (m_pending) {
            m_pending = false;
            refresh();
        }
    });
}

void PlaneController::setExecutable(const QString& path) { m_process->setExecutable(path); }

void PlaneController::setSdfArguments(std::function<QStringList()> provider) { m_process->setSdfArguments(std::move(provider)); }

void PlaneController::refresh() {
    renderer::CuttingPlane plane = m_viewport->plane();
    if (!plane.enabled) return;
    QString sdf = m_currentSdf();
    if (sdf.isEmpty()) {
        m_panel->setReadoutMessage(tr("Save the SDF to get plane readouts."));
        return;
    }
    if (m_process->isRunning()) {
        m_pending = true; // one more run with the newest plane when this one ends
        return;
    }
    QString spec = QString("%1,%2,%3,%4")
                       .arg(plane.normal.x, 0, 'g', 9)
                       .arg(plane.normal.y, 0, 'g', 9)
                       .arg(plane.normal.z, 0, 'g', 9)
                       .arg(plane.offset, 0, 'g', 9);
    m_process->start(
        {"audit", "--sdf", sdf, "--plane", spec, "--resolution", "192", "--time", QString::number(m_viewport->time(), 'g', 9)});
}

} // namespace sdfwb::app
