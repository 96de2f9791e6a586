#include "SamplingController.h"

#include "BatchProcess.h"

#include <core/Log.h>
#include <widgets/SamplingDialog.h>

namespace sdfwb::app {

SamplingController::SamplingController(QWidget* window, std::function<QString()> currentSdf, QObject* parent)
    : QObject(parent), m_window(window), m_currentSdf(std::move(currentSdf)), m_process(new BatchProcess(this)) {
    connect(m_process, &BatchProcess::progress, this, [this](quint64 done, quint64 total) {
        if (m_dialog) m_dialog->setProgress(done, total);
        emit progress(done, total);
    });
    connect(m_process, &BatchProcess::finished, this, [this](bool ok, bool, const QJsonObject& report, const QString& error) {
        QString message = error;
        if (ok) {
            message = tr("Wrote %1: %2 samples, %3 bad rows, %4 s (%5 M samples/s).")
                          .arg(report["output"].toString())
                          .arg(report["rows"].toInteger())
                          .arg(report["bad_rows"].toInteger())
                          .arg(report["seconds"].toDouble(), 0, 'f', 2)
                          .arg(report["samples_per_second"].toDouble() / 1e6, 0, 'f', 2);
            m_dialog->setProgress(1, 1);
        }
        m_dialog->setRunning(false);
        m_dialog->setMessage(message, !ok);
        log::write(ok ? log::Level::Info : log::Level::Warning, "sampling", message.toStdString());
        emit finished(ok, message);
    });
}

void SamplingController::setExecutable(const QString& path) { m_process->setExecutable(path); }

void SamplingController::setSdfArguments(std::function<QStringList()> provider) {
    m_process->setSdfArguments(std::move(provider));
}

bool SamplingController::isRunning() const { return m_process->isRunning(); }

void SamplingController::showDialog() {
    if (!m_dialog) {
        const QStringList patterns = {"surface", "near", "rand", "grid", "image", "jitter", "metropolis", "metropolis_curvature"};
        m_dialog = new widgets::SamplingDialog(patterns, m_window);
        connect(m_dialog, &widgets::SamplingDialog::startRequested, this, &SamplingController::start);
        connect(m_dialog, &widgets::SamplingDialog::cancelRequested, m_process, &BatchProcess::cancel);
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
    QStringList arguments = {"sample",
                             "--sdf",
                             sdf,
                             "--pattern",
                             settings.pattern,
                             "-n",
                             QString::number(settings.count),
                             "--seed",
                             QString::number(settings.seed),
                             "--time",
                             QString::number(settings.time, 'g', 9),
                             "--output",
                             settings.output};
    if (!settings.format.isEmpty()) arguments << "--format" << settings.format;
    m_dialog->setRunning(true);
    m_dialog->setMessage(tr("Sampling..."), false);
    m_process->start(arguments);
}

} // namespace sdfwb::app
