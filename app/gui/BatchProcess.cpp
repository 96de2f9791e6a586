#include "BatchProcess.h"

#include <jobs/JobJson.h>

#include <QCoreApplication>
#include <QProcess>

namespace sdfwb::app {

QString BatchProcess::defaultExecutable() {
    const QString chosen = qEnvironmentVariable("SDFWB_BATCH_EXECUTABLE");
    return chosen.isEmpty() ? QCoreApplication::applicationFilePath() : chosen;
}

BatchProcess::BatchProcess(QObject* parent) : JobClient(parent), m_executable(defaultExecutable()) {}

BatchProcess::~BatchProcess() {
    if (isRunning()) {
        m_process->terminate();
        m_process->waitForFinished(5000);
    }
}

bool BatchProcess::isRunning() const { return m_process && m_process->state() != QProcess::NotRunning; }

QString describeFailure(const jobs::JobError& error) {
    QString text;
    for (const shaders::Diagnostic& d : error.diagnostics) text += QString::fromStdString(shaders::formatDiagnostic(d)) + "\n";
    return text + QString::fromStdString(error.message);
}

bool BatchProcess::start(const values::Request& request) {
    if (isRunning()) return false;
    m_process = new QProcess(this);
    m_pending.clear();
    m_outcome = {};
    m_process->setStandardErrorFile(QProcess::nullDevice()); // log lines only: errors come as messages
    connect(m_process, &QProcess::readyReadStandardOutput, this, &BatchProcess::readOutput);
    connect(m_process, &QProcess::errorOccurred, this, [this](QProcess::ProcessError error) {
        if (error != QProcess::FailedToStart || !m_process) return;
        QProcess* process = m_process;
        m_process = nullptr;
        process->deleteLater();
        const QString message = tr("cannot start %1").arg(m_executable);
        conclude(false, false, {}, message, jobs::workError(message.toStdString()));
    });
    connect(m_process, &QProcess::finished, this, [this](int exitCode, QProcess::ExitStatus status) {
        readOutput();
        QProcess* process = m_process;
        m_process = nullptr;
        process->deleteLater();
        const bool ok = status == QProcess::NormalExit && exitCode == 0;
        const bool cancelled = status == QProcess::NormalExit && exitCode == 130;
        jobs::JobError error = m_outcome.error;
        QString message = m_outcome.hasError ? describeFailure(m_outcome.error) : QString();
        if (cancelled) {
            error.failure = jobs::Failure::Cancelled;
            message = tr("Cancelled; nothing was written.");
        } else if (status == QProcess::CrashExit) {
            message = tr("The batch process crashed; nothing was written.");
            error.message = message.toStdString();
        } else if (!ok && message.isEmpty()) {
            message = tr("Failed (exit code %1).").arg(exitCode);
            error.message = message.toStdString();
        }
        conclude(ok, cancelled, ok ? m_outcome.report : std::string(), message, error);
    });
    m_process->start(m_executable, {"--batch", "request", "-", "--protocol"});
    const std::string json = jobs::toJson(request);
    m_process->write(json.data(), qint64(json.size()));
    m_process->closeWriteChannel();
    return true;
}

void BatchProcess::cancel() {
    if (isRunning()) m_process->terminate(); // SIGTERM: the batch command cancels and cleans up
}

void BatchProcess::readOutput() {
    if (!m_process) return;
    forEachMessage(*m_process, m_pending, [this](const jobs::WorkerMessage& message) {
        if (message.kind == jobs::WorkerMessage::Kind::Progress) emit progress(message.done, message.total);
        m_outcome.keep(message);
    });
}

void RequestOutcome::keep(const jobs::WorkerMessage& message) {
    if (message.kind == jobs::WorkerMessage::Kind::Error) {
        error = message.error;
        hasError = true;
    } else if (message.kind == jobs::WorkerMessage::Kind::Report) {
        report = message.report;
    }
}

void forEachMessage(QProcess& process, QByteArray& pending, const std::function<void(const jobs::WorkerMessage&)>& handle) {
    pending += process.readAllStandardOutput();
    int newline;
    while ((newline = pending.indexOf('\n')) >= 0) {
        const std::string line = pending.left(newline).toStdString();
        pending.remove(0, newline + 1);
        handle(jobs::readWorkerMessage(line));
    }
}

} // namespace sdfwb::app
