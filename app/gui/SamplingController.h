#pragma once
// Runs sampling jobs for the workbench. Each job is a child `sdfwb --batch sample` process: the
// headless EGL path stays out of the GUI's GL context, a crash in a driver cannot take the
// editor down, and Cancel is a signal the batch command already handles (no partial file).

#include <QObject>
#include <QString>

#include <functional>

class QProcess;

namespace sdfwb::widgets {
class SamplingDialog;
struct SamplingSettings;
}

namespace sdfwb::app {

class SamplingController : public QObject {
    Q_OBJECT
public:
    // `currentSdf` returns the path of the SDF to sample (empty when the text was never saved).
    SamplingController(QWidget* window, std::function<QString()> currentSdf, QObject* parent = nullptr);
    ~SamplingController() override;

    // The sdfwb binary that runs the jobs (default: this executable).
    void setExecutable(const QString& path) { m_executable = path; }

    void showDialog();
    widgets::SamplingDialog* dialog() const { return m_dialog; }
    bool isRunning() const;

signals:
    void finished(bool ok, const QString& message);

private:
    void start(const widgets::SamplingSettings& settings);
    void cancel();
    void readProgress();

    QWidget* m_window;
    std::function<QString()> m_currentSdf;
    QString m_executable;
    widgets::SamplingDialog* m_dialog = nullptr;
    QProcess* m_process = nullptr;
    QString m_errors;
    QByteArray m_pendingStderr;
};

} // namespace sdfwb::app
