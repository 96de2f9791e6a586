#pragma once
// Runs one `sdfwb --batch ...` command as a child process for the workbench: long jobs (sampling,
// video export) stay off the UI thread and out of the GUI's GL context, and Cancel is a signal
// the batch commands already handle (they leave no partial file).

#include <QJsonObject>
#include <QObject>
#include <QString>
#include <QStringList>

#include <functional>

class QProcess;

namespace sdfwb::app {

class BatchProcess : public QObject {
    Q_OBJECT
public:
    explicit BatchProcess(QObject* parent = nullptr);
    ~BatchProcess() override;

    // The sdfwb binary that runs the jobs (default: this executable).
    void setExecutable(const QString& path) { m_executable = path; }
    const QString& executable() const { return m_executable; }

    // Starts `sdfwb --batch <arguments> --json --progress-lines`. False when one is running.
    bool start(const QStringList& arguments);
    // Arguments added to every command that names an SDF (--sdf): the document's --entry.
    void setSdfArguments(std::function<QStringList()> provider) { m_sdfArguments = std::move(provider); }
    void cancel();
    bool isRunning() const;

signals:
    void progress(quint64 done, quint64 total);
    // ok: exit code 0; report: the command's --json output; message: its error lines, or why it stopped.
    void finished(bool ok, bool cancelled, const QJsonObject& report, const QString& message);

private:
    void readStandardError();

    QString m_executable;
    std::function<QStringList()> m_sdfArguments;
    QProcess* m_process = nullptr;
    QString m_errors;
    QByteArray m_pending;
};

} // namespace sdfwb::app
