#pragma once
// What a workbench controller holds to run its jobs: a one-shot child (BatchProcess) or a channel
// on the persistent worker (JobChannel, JobWorker.h). Both read the worker protocol
// (jobs/Protocol.h) and answer through these signals, so the controllers and the Problems panel
// treat them alike.

#include <jobs/Jobs.h>
#include <values/Requests.h>

#include <QObject>
#include <QString>

#include <string>
#include <vector>

namespace sdfwb::app {

class JobClient : public QObject {
    Q_OBJECT
public:
    using QObject::QObject;

    // Starts (or queues) the request. False when one of this client's is queued or running.
    virtual bool start(const values::Request& request) = 0;
    virtual void cancel() = 0;
    virtual bool isRunning() const = 0;
    // The last request's failure as the child reported it (kind, message, the diagnostics); empty
    // after a success.
    const jobs::JobError& error() const { return m_error; }

signals:
    void progress(quint64 done, quint64 total);
    // Each request's diagnostics (the SDF's or its sampler's, with file and line), sent just before
    // finished; empty when it succeeded or reported none, so a list of them clears.
    void diagnosticsReported(const std::vector<shaders::Diagnostic>& diagnostics);
    // ok: exit code 0; report: the report's JSON (read it with jobs::reportFromJson); message: the
    // failure as the user reads it (describeFailure, BatchProcess.h), or why it stopped.
    void finished(bool ok, bool cancelled, const std::string& report, const QString& message);

protected:
    // Ends a request: keeps its error (cleared when ok), then emits diagnosticsReported and finished.
    void conclude(bool ok, bool cancelled, const std::string& report, const QString& message, const jobs::JobError& error);

private:
    jobs::JobError m_error;
};

} // namespace sdfwb::app
