#include "SamplingController.h"

#include <core/Log.h>
#include <widgets/SamplingDialog.h>

#include <QCoreApplication>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>

namespace sdfwb::app {

SamplingController::SamplingController(QWidget* window, std::function<QString()> currentSdf, QObject* parent)
    : QObject(parent), m_window(window), m_currentSdf(std::move(currentSdf)), m_executable(QCoreApplication::applicationFilePath()) {}

SamplingController::~SamplingController() {
    if (isRunning()) {
        m_process->terminate();
        m_process->waitForFinished(5000);
    }
}

bool SamplingController::isRunning() const { return m_process && m_process->state() != QProcess::NotRunning; }

void SamplingController::showDialog() {
    if (!m_dialog) {
        const QStringList patterns = {"surface", "near", "rand", "grid", "image", "jitter", "metropolis", "metropolis_curvature"};
        m_dialog = new widgets::SamplingDialog(patterns, m_window);
        connect(m_dialog, &widgets::SamplingDialog::startRequested, this, &SamplingController::start);
        connect(m_dialog, &widgets::SamplingDialog::cancelRequested, this, &SamplingController::cancel);
    }
    QString sdf = m_currentSdf();
    m_dialog->setSdfName(sdf.isEmpty() ? tr("(save the SDF first)") : sdf);
    m_dialog->show();
    m_dialog->raise();
}

void SamplingController::start(const widgets::SamplingSettings& settings) {
    if (isRunning()) return;
    QString sdf = m_currentSdf();
    if (sdf.isEmpty()) {
        m_dialog->setMessage(tr("The SDF has never been saved: save it first, sampling reads the file."), true);
        return;
    }
    QStringList arguments = {"--batch", "sample", "--sdf", sdf, "--pattern", settings.pattern, "-n", QString::number(settings.count),
                             "--seed", QString::number(settings.seed), "--time", QString::number(settings.time, 'g', 9),
                             "--output", settings.output, "--json", "--progress-lines"};
    if (!settings.format.isEmpty()) arguments << "--format" << settings.format;
    m_process = new QProcess(this);
    m_errors.clear();
    m_pendingStderr.clear();
    connect(m_process, &QProcess::readyReadStandardError, this, &SamplingController::readProgress);
    connect(m_process, &QProcess::finished, this, [this](int exitCode, QProcess::ExitStatus status) {
        readProgress();
        QProcess* process = m_process;
        m_process = nullptr;
        process->deleteLater();
        m_dialog->setRunning(false);
        bool ok = status == QProcess::NormalExit && exitCode == 0;
        QString message;
        if (ok) {
            QJsonObject report = QJsonDocument::fromJson(process->readAllStandardOutput()).object();
            message = tr("Wrote %1: %2 samples, %3 bad rows, %4 s (%5 M samples/s).")
                          .arg(report["output"].toString())
                          .arg(report["rows"].toInteger())
                          .arg(report["bad_rows"].toInteger())
                          .arg(report["seconds"].toDouble(), 0, 'f', 2)
                          .arg(report["samples_per_second"].toDouble() / 1e6, 0, 'f', 2);
            m_dialog->setProgress(1, 1);
        } else if (exitCode == 130 || status == QProcess::CrashExit) {
            message = exitCode == 130 ? tr("Cancelled; nothing was written.") : tr("The sampling process crashed; nothing was written.");
        } else {
            message = m_errors.trimmed().isEmpty() ? tr("Sampling failed (exit code %1).").arg(exitCode) : m_errors.trimmed();
        }
        m_dialog->setMessage(message, !ok);
        log::write(ok ? log::Level::Info : log::Level::Warning, "sampling", message.toStdString());
        emit finished(ok, message);
    });
    m_dialog->setRunning(true);
    m_dialog->setMessage(tr("Sampling..."), false);
    m_process->start(m_executable, arguments);
}

void SamplingController::cancel() {
    if (isRunning()) m_process->terminate();  // SIGTERM: the batch command cancels and removes its temporary file
}

void SamplingController::readProgress() {
    if (!m_process) return;
    m_pendingStderr += m_process->readAllStandardError();
    int newline;
    while ((newline = m_pendingStderr.indexOf('\n')) >= 0) {
        QByteArray line = m_pendingStderr.left(newline);
        m_pendingStderr.remove(0, newline + 1);
        if (line.startsWith("progress ")) {
            QList<QByteArray> parts = line.split(' ');
            if (parts.size() == 3) m_dialog->setProgress(parts[1].toULongLong(), parts[2].toULongLong());
        } else if (line.startsWith("sdfwb: ") || line.contains(": error:")) {
            m_errors += QString::fromLocal8Bit(line) + "\n";
        }
    }
}

} // namespace sdfwb::app
