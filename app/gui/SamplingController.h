#pragma once
// Runs sampling jobs for the workbench through a BatchProcess (`sdfwb --batch sample` as a child).

#include <values/Requests.h>

#include <QObject>
#include <QString>

#include <functional>

namespace sdfwb::widgets {
class SamplingDialog;
} // namespace sdfwb::widgets

namespace sdfwb::app {

class BatchProcess;
class JobClient;

class SamplingController : public QObject {
    Q_OBJECT
public:
    // `currentSdf` gives the SDF as the viewport shows it (saved or not).
    SamplingController(QWidget* window, std::function<values::SdfInput()> currentSdf, QObject* parent = nullptr);
    ~SamplingController() override;

    void setExecutable(const QString& path);
    // Its jobs, for what listens to every job (the Problems panel).
    JobClient* jobClient() const;

    void showDialog();
    widgets::SamplingDialog* dialog() const { return m_dialog; }
    bool isRunning() const;

signals:
    void finished(bool ok, const QString& message);
    // A sample file to look at in the viewport: a preview's (temporary) or a finished run's.
    void cloudReady(const QString& path, const QString& what);
    void pointSizeChanged(int pixels);
    // Samples written so far by the running job (its progress lines).
    void progress(quint64 done, quint64 total);

private:
    void start(const values::SampleRequest& fromDialog);
    void preview(const values::SampleRequest& fromDialog);
    values::SampleRequest requestFor(const values::SampleRequest& fromDialog) const; // the dialog's, on the current SDF

    QWidget* m_window;
    std::function<values::SdfInput()> m_currentSdf;
    BatchProcess* m_process;
    widgets::SamplingDialog* m_dialog = nullptr;
    QString m_previewFolder; // a temporary folder for previews, removed with the controller
    bool m_previewing = false;
};

} // namespace sdfwb::app
