#pragma once
// File > Export mesh: the document's current text (and parameter values) meshed by
// `sdfwb --batch mesh` in a child process, with a resolution, progress and Cancel; a cancelled or
// failed export leaves no file. The dialog shows the report: size, topology, error and seconds.

#include <values/Requests.h>

#include <QObject>
#include <QString>

#include <functional>

class QDialog;
class QLabel;
class QLineEdit;
class QProgressBar;
class QPushButton;
class QSpinBox;
class QWidget;

namespace sdfwb::app {

class BatchProcess;
class JobClient;

class MeshExportController : public QObject {
    Q_OBJECT
public:
    MeshExportController(QWidget* window, std::function<values::SdfInput()> currentSdf, QObject* parent = nullptr);

    void setExecutable(const QString& path);
    // Its jobs, for what listens to every job (the Problems panel).
    JobClient* jobClient() const;
    void showDialog();
    QDialog* dialog() const { return m_dialog; }
    bool isRunning() const;
    // The request an export with these settings starts.
    values::MeshRequest request(const QString& output, int resolution, int refine = 0) const;

signals:
    void progress(quint64 done, quint64 total);
    void finished(bool ok, bool cancelled, const QString& message);
    // After a successful export: the file written (the window shows it over the surface).
    void meshWritten(const QString& path);

private:
    void start();

    QWidget* m_window;
    std::function<values::SdfInput()> m_currentSdf;
    BatchProcess* m_process;
    QDialog* m_dialog = nullptr;
    QLineEdit* m_output = nullptr;
    QSpinBox* m_resolution = nullptr;
    QSpinBox* m_refine = nullptr;
    QProgressBar* m_bar = nullptr;
    QLabel* m_message = nullptr;
    QPushButton* m_export = nullptr;
    QPushButton* m_cancel = nullptr;
};

} // namespace sdfwb::app
