#include "SamplingController.h"

#include "BatchProcess.h"

#include <core/Log.h>
#include <jobs/JobJson.h>
#include <widgets/SamplingDialog.h>

#include <QDir>
#include <QStandardPaths>
#include <QTemporaryDir>

namespace sdfwb::app {

SamplingController::SamplingController(QWidget* window, std::function<values::SdfInput()> currentSdf, QObject* parent)
    : QObject(parent), m_window(window), m_currentSdf(std::move(currentSdf)), m_process(new BatchProcess(this)) {
    connect(m_process, &BatchProcess::progress, this, [this](quint64 done, quint64 total) {
        if (m_dialog) m_dialog->setProgress(done, total);
        emit progress(done, total);
    });
    connect(m_process, &BatchProcess::finished, this, [this](bool ok, bool, const std::string& json, const QString& error) {
        QString message = error;
        auto report = ok ? jobs::reportFromJson<values::SampleReport>(json) : Expected<values::SampleReport>(makeError(""));
        if (ok && !report) {
            ok = false;
            message = QString::fromStdString(report.error().message);
        }
        if (ok && m_previewing) {
            message = tr("Preview: %1 samples (%2 bad rows, not drawn) in %3 s; nothing written.")
                          .arg(report->rows)
                          .arg(report->badRows)
                          .arg(report->seconds, 0, 'f', 2);
            m_dialog->setRunning(false);
            m_dialog->setMessage(message, false);
            m_previewing = false;
            emit cloudReady(QString::fromStdString(report->output), tr("preview"));
            return;
        }
        m_previewing = false;
        if (ok) {
            message = tr("Wrote %1: %2 samples, %3 bad rows, %4 s (%5 M samples/s).")
                          .arg(QString::fromStdString(report->output))
                          .arg(report->rows)
                          .arg(report->badRows)
                          .arg(report->seconds, 0, 'f', 2)
                          .arg(report->samplesPerSecond / 1e6, 0, 'f', 2);
            m_dialog->setProgress(1, 1);
        }
        m_dialog->setRunning(false);
        const jobs::JobError& failure = m_process->error();
        if (!ok && !failure.keys.empty() && failure.diagnostics.empty())
            m_dialog->setFailure(failure.message, failure.keys); // in the form's words, the fields marked
        else
            m_dialog->setMessage(message, !ok);
        log::write(ok ? log::Level::Info : log::Level::Warning, "sampling", message.toStdString());
        emit finished(ok, message);
        if (ok) emit cloudReady(QString::fromStdString(report->output), tr("written"));
    });
}

void SamplingController::setExecutable(const QString& path) { m_process->setExecutable(path); }

JobClient* SamplingController::jobClient() const { return m_process; }

bool SamplingController::isRunning() const { return m_process->isRunning(); }

void SamplingController::showDialog() {
    if (!m_dialog) {
        const QStringList patterns = {"surface", "near", "rand", "grid", "image", "jitter", "metropolis", "metropolis_curvature"};
        m_dialog = new widgets::SamplingDialog(patterns, m_window);
        connect(m_dialog, &widgets::SamplingDialog::startRequested, this, &SamplingController::start);
        connect(m_dialog, &widgets::SamplingDialog::previewRequested, this, &SamplingController::preview);
        connect(m_dialog, &widgets::SamplingDialog::pointSizeChanged, this, &SamplingController::pointSizeChanged);
        connect(m_dialog, &widgets::SamplingDialog::cancelRequested, m_process, &BatchProcess::cancel);
    }
    const values::SdfInput sdf = m_currentSdf();
    m_dialog->setSdfName(sdf.sdf.empty() ? tr("untitled (the editor's text)") : QString::fromStdString(sdf.sdf));
    m_dialog->show();
    m_dialog->raise();
}

values::SampleRequest SamplingController::requestFor(const values::SampleRequest& fromDialog) const {
    values::SampleRequest request = fromDialog;
    request.sdf = m_currentSdf();
    return request;
}

void SamplingController::preview(const values::SampleRequest& fromDialog) {
    if (isRunning()) return;
    if (m_previewFolder.isEmpty()) {
        QTemporaryDir folder(QDir::temp().filePath("sdfwb-preview-XXXXXX"));
        folder.setAutoRemove(false);
        if (!folder.isValid()) {
            m_dialog->setMessage(tr("Preview: cannot make a temporary folder: %1").arg(folder.errorString()), true);
            return;
        }
        m_previewFolder = folder.path();
    }
    values::SampleRequest request = requestFor(fromDialog);
    // Rows depend on the seed and their index only, so a preview shows the first points the file
    // will hold (grid and image size their lattice by N: theirs is a coarser lattice).
    request.count = std::min<std::uint64_t>(fromDialog.count, widgets::SamplingDialog::kPreviewPoints);
    request.output = QDir(m_previewFolder).filePath("preview.npz").toStdString();
    request.format.clear();
    m_previewing = true;
    m_dialog->setRunning(true);
    m_dialog->setMessage(tr("Previewing %1 samples...").arg(request.count), false);
    m_process->start(request);
}

SamplingController::~SamplingController() {
    if (!m_previewFolder.isEmpty()) QDir(m_previewFolder).removeRecursively();
}

void SamplingController::start(const values::SampleRequest& fromDialog) {
    if (isRunning()) return;
    const values::SampleRequest request = requestFor(fromDialog);
    m_dialog->setRunning(true);
    m_dialog->setMessage(tr("Sampling..."), false);
    m_process->start(request);
}

} // namespace sdfwb::app
