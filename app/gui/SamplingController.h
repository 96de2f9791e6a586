#pragma once
// Runs sampling jobs for the workbench through a BatchProcess (`sdfwb --batch sample` as a child).

#include <jobs/Requests.h>

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
    // `currentSdf` gives the SDF as the viewport shows it (saved or not).
    SamplingController(QWidget* window, std::function<jobs::SdfInput()> currentSdf, QObject* parent = nullptr);

    void setExecutable(const QString& path);

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
    std::function<jobs::SdfInput()> m_currentSdf;
    BatchProcess* m_process;
    widgets::SamplingDialog* m_dialog = nullptr;
};

} // namespace sdfwb::app
