#pragma once
// One persistent child, `sdfwb --batch request - --protocol --each-line --quiet`, for the
// workbench's interactive requests (plane readouts, the march probe): its start-up (a process, an
// EGL context) is paid once rather than on every drag or click. Requests queue and run one at a
// time in the worker protocol (jobs/Protocol.h); each caller holds a JobChannel, which has
// BatchProcess's interface. The worker starts with the first request, and again after a crash or a
// hang (no message for timeout(): it is killed): the request then running fails with a message that
// says so, and the next one runs in a fresh worker. Cancel drops a queued request; the running one
// gets SIGTERM, which its job takes as cancel (it answers {"end":130} and the worker reads on).

#include "BatchProcess.h"
#include "JobClient.h"

#include <QObject>
#include <QPointer>
#include <QString>

#include <deque>
#include <string>

class QProcess;
class QTimer;

namespace sdfwb::app {

class JobChannel;

class JobWorker : public QObject {
    Q_OBJECT
public:
    explicit JobWorker(QObject* parent = nullptr);
    ~JobWorker() override;

    // The sdfwb binary (default: BatchProcess::defaultExecutable()); a change applies to the next
    // worker started, and stops an idle one.
    void setExecutable(const QString& path);
    const QString& executable() const { return m_executable; }
    // How long a request may go without any message (progress, report, end) before the worker is
    // taken as hung and killed. Default 60 s.
    void setTimeout(int milliseconds) { m_timeoutMs = milliseconds; }
    int timeout() const { return m_timeoutMs; }
    // The running worker's process id (0: none), and how many workers have been started.
    qint64 processId() const;
    int starts() const { return m_starts; }

private:
    friend class JobChannel;
    struct Queued {
        JobChannel* channel;
        std::string line; // the request's JSON
    };
    void submit(JobChannel* channel, const values::Request& request);
    void cancel(JobChannel* channel);
    void forget(JobChannel* channel);
    void next();
    bool ensureProcess();
    void readOutput();
    void processEnded();
    void hung();
    void retire();
    // Ends the current request: hands the outcome to its channel and starts the next.
    void finishCurrent(int exitCode, const QString& reason);

    QString m_executable;
    int m_timeoutMs = 60000;
    int m_starts = 0;
    QProcess* m_process = nullptr;
    QTimer* m_watchdog;
    QByteArray m_buffer;
    std::deque<Queued> m_queue;
    JobChannel* m_current = nullptr;
    bool m_busy = false; // a request was written and its end is awaited (its channel may be gone)
    bool m_cancelling = false, m_hung = false;
    RequestOutcome m_outcome; // the current request's error and report
};

// One caller's requests to a JobWorker, one at a time.
class JobChannel : public JobClient {
    Q_OBJECT
public:
    JobChannel(JobWorker* worker, QObject* parent = nullptr);
    ~JobChannel() override;

    JobWorker* worker() const { return m_worker; }
    // Queues the request. False when one of this channel's is queued or running.
    bool start(const values::Request& request) override;
    void cancel() override;
    bool isRunning() const override { return m_running; }

private:
    friend class JobWorker;
    // The worker ends this channel's request.
    void end(bool ok, bool cancelled, const std::string& report, const QString& message, const jobs::JobError& error);

    QPointer<JobWorker> m_worker;
    bool m_running = false;
};

} // namespace sdfwb::app
