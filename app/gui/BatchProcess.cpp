#include "BatchProcess.h"

#include <jobs/JobJson.h>

#include <QCoreApplication>
#include <QProcess>

namespace sdfwb::app {

QString BatchProcess::defaultExecutable() {
    const QString chosen = qEnvironmentVariable("SDFWB_BATCH_EXECUTABLE");
    return chosen.isEmpty() ? QCoreApplication::applicationFilePath() : chosen;
}

BatchProcess::BatchProcess(QObject* parent) : QObject(parent), m_executable(defaultExecutable()) {}

BatchProcess::~BatchProcess() {
    if (isRunning()) {
        m_process->terminate();
        m_process->waitForFinished(5000);
    }
}

bool BatchProcess::isRunning() const { return m_process && m_process->state() != QProcess::NotRunning; }

bool BatchProcess::start(const jobs::Request& request) {
    if (isRunning()) return false;
    m_process = new QProcess(this);
    m_errors.clear();
    m_pending.clear();
    connect(m_process, &QProcess::readyReadStandardError, this, &BatchProcess::readStandardError);
    connect(m_process, &QProcess::errorOccurred, this, [this](QProcess::ProcessError error) {
        if (error != QProcess::FailedToStart || !m_process) return;
        QProcess* process = m_process;
        m_process = nullptr;
        process->deleteLater();
        emit finished(false, false, {}, tr("cannot start %1").arg(m_executable));
    });
    connect(m_process, &QProcess::finished, this, [this](int exitCode, QProcess::ExitStatus status) {
        readStandardError();
        QProcess* process = m_process;
        m_process = nullptr;
        process->deleteLater();
        bool ok = status == QProcess::NormalExit && exitCode == 0;
        bool cancelled = status == QProcess::NormalExit && exitCode == 130;
        const std::string report = process->readAllStandardOutput().toStdString();
        QString message = m_errors.trimmed();
        if (cancelled)
            message = tr("Cancelled; nothing was written.");
        else if (status == QProcess::CrashExit)
            message = tr("The batch process crashed; nothing was written.");
        else if (!ok && message.isEmpty())
            message = tr("Failed (exit code %1).").arg(exitCode);
        emit finished(ok, cancelled, report, message);
    });
    m_process->start(m_executable, {"--batch", "request", "-", "--json", "--progress-lines"});
    const std::string json = jobs::toJson(request);
    m_process->write(json.data(), qint64(json.size()));
    m_process->closeWriteChannel();
    return true;
}

void BatchProcess::cancel() {
    if (isRunning()) m_process->terminate(); // SIGTERM: the batch command cancels and cleans up
}

void BatchProcess::readStandardError() {
    if (!m_process) return;
    m_pending += m_process->readAllStandardError();
    int newline;
    while ((newline = m_pending.indexOf('\n')) >= 0) {
        QByteArray line = m_pending.left(newline);
        m_pending.remove(0, newline + 1);
        if (line.startsWith("progress ")) {
            QList<QByteArray> parts = line.split(' ');
            if (parts.size() == 3) emit progress(parts[1].toULongLong(), parts[2].toULongLong());
        } else if (line.startsWith("sdfwb: ") || line.contains(": error:")) {
            m_errors += QString::fromLocal8Bit(line) + "\n";
        }
    }
}

} // namespace sdfwb::app
