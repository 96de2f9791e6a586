#pragma once
// Runs sampling jobs for the workbench through a BatchProcess (`sdfwb --batch sample` as a child).

#include <QObject>
#include <QString>

#include <functional>

namespace sdfwb::widgets {
class SamplingDialog;
struct SamplingSettings;
} // namespace sdfwb::widgets

namespace sdfwb::app {

class BatchProcess;

class SamplingController : public QObject {
    Q_OBJECT
public:
    // `currentSdf` returns the path of the SDF to sample (empty when the text was never saved).
    SamplingController(QWidget* window, std::function<QString()> currentSdf, QObject* parent = nullptr);

    void setExecutable(const QString& path);

    // Extra arguments for commands that name the SDF (the entry point).

    void setSdfArguments(std::function<QStringList()> provider);
    void showDialog();
    widgets::SamplingDialog* dialog() const { return m_dialog; }
    bool isRunning() const;

signals:
    void finished(bool ok, const QString& message);
    // Samples written so far by the running job (its progress lines).
    void progress(quint64 done, quint64 total);

private:
    void start(const widgets::SamplingSettings& settings);

    QWidget* m_window;
    std::function<QString()> m_currentSdf;
    BatchProcess* m_process;
    widgets::SamplingDialog* m_dialog = nullptr;
};

} // namespace sdfwb::app
