#pragma once
// Runs one job (a typed request, jobs/Requests.h) as a child process for the workbench:
// `sdfwb --batch request - --protocol` with the request's JSON on stdin, so long jobs stay off the
// UI thread and out of the GUI's GL context, and Cancel is a signal the batch commands already
// handle (they leave no partial file). Progress, the structured error and the report come back as
// worker-protocol messages (jobs/Protocol.h); no text is parsed. Interactive requests go to the
// persistent JobWorker instead.

#include "JobClient.h"

#include <jobs/Protocol.h>

#include <QByteArray>
#include <QString>

#include <functional>
#include <string>

class QProcess;

namespace sdfwb::app {

// A failure as the user reads it: the SDF's diagnostics ("file:line:column: error: ..."), then the message.
QString describeFailure(const jobs::JobError& error);

// What one request's worker-protocol messages (jobs/Protocol.h) leave: its error and its report.
struct RequestOutcome {
    jobs::JobError error;
    bool hasError = false;
    std::string report;
    // Keeps an error or a report message; ignores the others.
    void keep(const jobs::WorkerMessage& message);
};

// The complete lines `process` has written to stdout, as messages (a partial line waits in
// `pending` for the rest).
void forEachMessage(QProcess& process, QByteArray& pending, const std::function<void(const jobs::WorkerMessage&)>& handle);

class BatchProcess : public JobClient {
    Q_OBJECT
public:
    explicit BatchProcess(QObject* parent = nullptr);
    ~BatchProcess() override;

    // The sdfwb binary that runs the jobs (default: $SDFWB_BATCH_EXECUTABLE, else this executable).
    static QString defaultExecutable();
    void setExecutable(const QString& path) { m_executable = path; }
    const QString& executable() const { return m_executable; }

    // Starts the request in a child. False when one is running.
    bool start(const values::Request& request) override;
    void cancel() override;
    bool isRunning() const override;

private:
    void readOutput();

    QString m_executable;
    QProcess* m_process = nullptr;
    QByteArray m_pending;
    RequestOutcome m_outcome;
};

} // namespace sdfwb::app
