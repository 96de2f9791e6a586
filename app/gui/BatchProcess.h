#pragma once
// Runs one job (a typed request, jobs/Requests.h) as a child process for the workbench:
// `sdfwb --batch request - --json --progress-lines` with the request's JSON on stdin, so long jobs
// stay off the UI thread and out of the GUI's GL context, and Cancel is a signal the batch
// commands already handle (they leave no partial file). The report comes back as its JSON.

#include <jobs/Requests.h>

#include <QObject>
#include <QString>

#include <string>

class QProcess;

namespace sdfwb::app {

class BatchProcess : public QObject {
    Q_OBJECT
public:
    explicit BatchProcess(QObject* parent = nullptr);
    ~BatchProcess() override;

    // The sdfwb binary that runs the jobs (default: $SDFWB_BATCH_EXECUTABLE, else this executable).
    static QString defaultExecutable();
    void setExecutable(const QString& path) { m_executable = path; }
    const QString& executable() const { return m_executable; }

    // Starts the request in a child. False when one is running.
    bool start(const jobs::Request& request);
    void cancel();
    bool isRunning() const;

signals:
    void progress(quint64 done, quint64 total);
    // ok: exit code 0; report: the report's JSON (read it with jobs::reportFromJson); message: the
    // child's error lines, or why it stopped.
    void finished(bool ok, bool cancelled, const std::string& report, const QString& message);

private:
    void readStandardError();

    QString m_executable;
    QProcess* m_process = nullptr;
    QString m_errors;
    QByteArray m_pending;
};

} // namespace sdfwb::app
