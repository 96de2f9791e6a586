#include "JobWorker.h"

#include <jobs/JobJson.h>

#include <QProcess>
#include <QTimer>

#include <algorithm>

namespace sdfwb::app {

JobWorker::JobWorker(QObject* parent)
    : QObject(parent), m_executable(BatchProcess::defaultExecutable()), m_watchdog(new QTimer(this)) {
    m_watchdog->setSingleShot(true);
    connect(m_watchdog, &QTimer::timeout, this, &JobWorker::hung);
}

JobWorker::~JobWorker() {
    if (!m_process) return;
    m_process->disconnect(this);
    m_process->closeWriteChannel(); // an idle worker ends when its input does
    if (!m_process->waitForFinished(2000)) {
        m_process->kill();
        m_process->waitForFinished(2000);
    }
}

void JobWorker::setExecutable(const QString& path) {
    if (path == m_executable) return;
    m_executable = path;
    if (!m_process || m_busy) return; // a busy one is replaced after its request (see finishCurrent)
    retire();
}

// Lets the idle worker end (its input closes) and forgets it; the next request starts another.
void JobWorker::retire() {
    QProcess* process = m_process;
    m_process = nullptr;
    process->disconnect(this);
    connect(process, &QProcess::finished, process, &QObject::deleteLater);
    process->closeWriteChannel();
}

qint64 JobWorker::processId() const { return m_process ? m_process->processId() : 0; }

void JobWorker::submit(JobChannel* channel, const values::Request& request) {
    m_queue.push_back({channel, jobs::toJson(request)});
    next();
}

void JobWorker::cancel(JobChannel* channel) {
    const auto queued = std::find_if(m_queue.begin(), m_queue.end(), [&](const Queued& q) { return q.channel == channel; });
    if (queued != m_queue.end()) {
        m_queue.erase(queued);
        channel->end(false, true, {}, tr("Cancelled; nothing was written."), {jobs::Failure::Cancelled, {}, {}, {}});
        return;
    }
    if (channel != m_current || !m_process || m_cancelling) return;
    m_cancelling = true;
    m_process->terminate(); // SIGTERM: the running job cancels and answers {"end":130}
}

void JobWorker::forget(JobChannel* channel) {
    m_queue.erase(std::remove_if(m_queue.begin(), m_queue.end(), [&](const Queued& q) { return q.channel == channel; }),
                  m_queue.end());
    if (m_current == channel) m_current = nullptr; // its answer is read and dropped
}

bool JobWorker::ensureProcess() {
    if (m_process && m_process->state() != QProcess::NotRunning) return true;
    if (m_process) {
        m_process->disconnect(this);
        m_process->deleteLater();
    }
    m_process = new QProcess(this);
    m_process->setStandardErrorFile(QProcess::nullDevice()); // log lines only: errors come as messages
    connect(m_process, &QProcess::readyReadStandardOutput, this, &JobWorker::readOutput);
    connect(m_process, &QProcess::finished, this, &JobWorker::processEnded);
    m_buffer.clear();
    m_process->start(m_executable, {"--batch", "request", "-", "--protocol", "--each-line", "--quiet"});
    ++m_starts;
    if (!m_process->waitForStarted(10000)) {
        m_process->deleteLater();
        m_process = nullptr;
        return false;
    }
    return true;
}

void JobWorker::next() {
    if (m_busy || m_queue.empty()) return;
    const Queued item = m_queue.front();
    m_queue.pop_front();
    m_current = item.channel;
    m_busy = true;
    m_cancelling = m_hung = false;
    m_outcome = {};
    if (!ensureProcess()) {
        finishCurrent(1, tr("cannot start %1").arg(m_executable));
        return;
    }
    const std::string line = item.line + "\n";
    m_process->write(line.data(), qint64(line.size()));
    m_watchdog->start(m_timeoutMs);
}

void JobWorker::readOutput() {
    if (!m_process) return;
    forEachMessage(*m_process, m_buffer, [this](const jobs::WorkerMessage& message) {
        if (message.kind == jobs::WorkerMessage::Kind::Other || !m_busy) return;
        m_watchdog->start(m_timeoutMs); // any message shows the worker alive
        if (message.kind == jobs::WorkerMessage::Kind::Progress && m_current)
            emit m_current->progress(message.done, message.total);
        else if (message.kind == jobs::WorkerMessage::Kind::End)
            finishCurrent(message.exitCode, {});
        else
            m_outcome.keep(message);
    });
}

void JobWorker::processEnded() {
    if (!m_busy) return; // an idle worker that was told to stop (setExecutable)
    QString reason;
    if (m_cancelling)
        reason = {};
    else if (m_hung)
        reason = tr("The worker process gave no answer for %1 s and was stopped; the next request starts a fresh one.")
                     .arg(m_timeoutMs / 1000.0, 0, 'g', 3);
    else
        reason = tr("The worker process crashed on this request; the next request starts a fresh one.");
    finishCurrent(m_cancelling ? 130 : 1, reason);
}

void JobWorker::hung() {
    if (!m_busy || !m_process) return;
    m_hung = true;
    m_process->kill(); // processEnded reports it
}

void JobWorker::finishCurrent(int exitCode, const QString& reason) {
    m_watchdog->stop();
    JobChannel* channel = m_current;
    m_current = nullptr;
    m_busy = false;
    if (channel) {
        const bool ok = exitCode == 0 && reason.isEmpty();
        const bool cancelled = exitCode == 130;
        jobs::JobError error = m_outcome.error;                  // its kind as the child decided it
        if (cancelled) error.failure = jobs::Failure::Cancelled; // also when it died of the SIGTERM
        QString message;
        if (cancelled)
            message = tr("Cancelled; nothing was written.");
        else if (!reason.isEmpty())
            message = reason;
        else if (!ok)
            message = m_outcome.hasError ? describeFailure(error) : tr("Failed (exit code %1).").arg(exitCode);
        if (!reason.isEmpty() && !cancelled) error.message = reason.toStdString();
        channel->end(ok, cancelled, ok ? m_outcome.report : std::string(), message, error);
    }
    if (m_process && m_process->state() == QProcess::NotRunning) {
        m_process->disconnect(this);
        m_process->deleteLater();
        m_process = nullptr;
    } else if (m_process && m_process->program() != m_executable) {
        retire(); // setExecutable while it ran
    }
    next();
}

JobChannel::JobChannel(JobWorker* worker, QObject* parent) : JobClient(parent), m_worker(worker) {}

void JobChannel::end(bool ok, bool cancelled, const std::string& report, const QString& message, const jobs::JobError& error) {
    m_running = false;
    conclude(ok, cancelled, report, message, error);
}

JobChannel::~JobChannel() {
    if (m_worker) m_worker->forget(this);
}

bool JobChannel::start(const values::Request& request) {
    if (m_running || !m_worker) return false;
    m_running = true;
    m_worker->submit(this, request);
    return true;
}

void JobChannel::cancel() {
    if (m_running && m_worker) m_worker->cancel(this);
}

} // namespace sdfwb::app
