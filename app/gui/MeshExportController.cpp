#include "MeshExportController.h"

#include "BatchProcess.h"

#include <core/Log.h>
#include <jobs/JobJson.h>

#include <QDialog>
#include <QFileDialog>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QProgressBar>
#include <QPushButton>
#include <QSpinBox>
#include <QVBoxLayout>

namespace sdfwb::app {

MeshExportController::MeshExportController(QWidget* window, std::function<values::SdfInput()> currentSdf, QObject* parent)
    : QObject(parent), m_window(window), m_currentSdf(std::move(currentSdf)), m_process(new BatchProcess(this)) {
    connect(m_process, &BatchProcess::progress, this, [this](quint64 done, quint64 total) {
        if (m_bar && total > 0) {
            m_bar->setRange(0, int(total));
            m_bar->setValue(int(done));
        }
        emit progress(done, total);
    });
    connect(m_process, &BatchProcess::finished, this,
            [this](bool ok, bool cancelled, const std::string& json, const QString& error) {
                QString message = error;
                auto report = ok ? jobs::reportFromJson<values::MeshReport>(json) : Expected<values::MeshReport>(makeError(""));
                if (ok && !report) {
                    ok = false;
                    message = QString::fromStdString(report.error().message);
                }
                if (ok) {
                    message = tr("Wrote %1: %2 triangles, %3; Hausdorff %4 against the field; %5 s.")
                                  .arg(QString::fromStdString(report->output))
                                  .arg(report->triangles)
                                  .arg(report->watertight ? tr("watertight")
                                                          : tr("%1 boundary and %2 non-manifold edges")
                                                                .arg(report->boundaryEdges)
                                                                .arg(report->nonManifoldEdges))
                                  .arg(double(report->hausdorff.value_or(0.0f)), 0, 'g', 3)
                                  .arg(report->seconds, 0, 'f', 2);
                } else if (cancelled) {
                    message = tr("Cancelled; nothing written.");
                }
                if (m_dialog) {
                    m_export->setEnabled(true);
                    m_cancel->setEnabled(false);
                    m_message->setText(message);
                    m_message->setStyleSheet(ok || cancelled ? QString() : QString("color: #c03030"));
                    if (ok) m_bar->setValue(m_bar->maximum());
                }
                log::write(ok ? log::Level::Info : log::Level::Warning, "mesh", message.toStdString());
                emit finished(ok, cancelled, message);
                if (ok) emit meshWritten(QString::fromStdString(report->output));
            });
}

void MeshExportController::setExecutable(const QString& path) { m_process->setExecutable(path); }

JobClient* MeshExportController::jobClient() const { return m_process; }

bool MeshExportController::isRunning() const { return m_process->isRunning(); }

values::MeshRequest MeshExportController::request(const QString& output, int resolution, int refine) const {
    values::MeshRequest request;
    request.sdf = m_currentSdf();
    request.output = output.toStdString();
    request.resolution = resolution;
    request.refine = refine;
    request.errorSamples = 20000;
    return request;
}

void MeshExportController::showDialog() {
    if (!m_dialog) {
        m_dialog = new QDialog(m_window);
        m_dialog->setObjectName("MeshExportDialog");
        m_dialog->setWindowTitle(tr("Export mesh"));
        auto* layout = new QVBoxLayout(m_dialog);
        auto* form = new QFormLayout;
        auto* pathRow = new QHBoxLayout;
        m_output = new QLineEdit(m_dialog);
        m_output->setObjectName("meshOutput");
        m_output->setPlaceholderText(tr("mesh.ply (.ply, .obj, .stl or .glb)"));
        auto* browse = new QPushButton(tr("Browse..."), m_dialog);
        connect(browse, &QPushButton::clicked, this, [this] {
            const QString path = QFileDialog::getSaveFileName(m_dialog, tr("Export mesh"), m_output->text(),
                                                              tr("Meshes (*.ply *.obj *.stl *.glb)"));
            if (!path.isEmpty()) m_output->setText(path);
        });
        pathRow->addWidget(m_output, 1);
        pathRow->addWidget(browse);
        form->addRow(tr("File:"), pathRow);
        m_resolution = new QSpinBox(m_dialog);
        m_resolution->setObjectName("meshResolution");
        m_resolution->setRange(8, 2048);
        m_resolution->setValue(128);
        m_resolution->setToolTip(tr("Cells along each axis of the [-1,1]^3 box (dual contouring keeps sharp edges)"));
        form->addRow(tr("Resolution:"), m_resolution);
        m_refine = new QSpinBox(m_dialog);
        m_refine->setObjectName("meshRefine");
        m_refine->setRange(0, 4);
        m_refine->setValue(0);
        m_refine->setToolTip(tr("Times every triangle is cut into four, the new vertices put on the surface: on smooth "
                                "shapes each level quarters the error, as doubling the resolution would, at far less cost"));
        form->addRow(tr("Refine:"), m_refine);
        layout->addLayout(form);
        m_bar = new QProgressBar(m_dialog);
        m_bar->setObjectName("meshProgress");
        m_bar->setRange(0, 1);
        m_bar->setValue(0);
        layout->addWidget(m_bar);
        m_message = new QLabel(m_dialog);
        m_message->setObjectName("meshMessage");
        m_message->setWordWrap(true);
        layout->addWidget(m_message);
        auto* buttons = new QHBoxLayout;
        m_export = new QPushButton(tr("Export"), m_dialog);
        m_export->setObjectName("meshExport");
        m_cancel = new QPushButton(tr("Cancel"), m_dialog);
        m_cancel->setObjectName("meshCancel");
        m_cancel->setEnabled(false);
        buttons->addStretch(1);
        buttons->addWidget(m_export);
        buttons->addWidget(m_cancel);
        layout->addLayout(buttons);
        connect(m_export, &QPushButton::clicked, this, &MeshExportController::start);
        connect(m_cancel, &QPushButton::clicked, m_process, &BatchProcess::cancel);
    }
    m_dialog->show();
    m_dialog->raise();
}

void MeshExportController::start() {
    if (isRunning()) return;
    const QString output = m_output->text().trimmed();
    if (output.isEmpty()) {
        m_message->setText(tr("Choose a file to write (.ply, .obj, .stl or .glb)."));
        return;
    }
    m_bar->setRange(0, 1);
    m_bar->setValue(0);
    m_message->setText(tr("Meshing..."));
    m_message->setStyleSheet(QString());
    if (!m_process->start(request(output, m_resolution->value(), m_refine->value()))) return;
    m_export->setEnabled(false);
    m_cancel->setEnabled(true);
}

} // namespace sdfwb::app
