#pragma once
// The problems list: one row per diagnostic (file:line:column, severity, message), the document's
// checks first, then what each job reported (a sampling job's sampler file, a compute stage's
// error), each row of a job's named by it. Activating a row emits the location so the editor can
// jump there (opening an included file if needed).

#include <shaders/Diagnostic.h>

#include <QString>
#include <QWidget>

#include <utility>
#include <vector>

class QListWidget;

namespace sdfwb::widgets {

class ProblemsPanel : public QWidget {
    Q_OBJECT
public:
    explicit ProblemsPanel(QWidget* parent = nullptr);
    // The document's diagnostics (replacing the last ones).
    void setDiagnostics(const std::vector<shaders::Diagnostic>& diagnostics);
    // What the job `job` ("Sampling") reported last, replacing what it reported before; none clears its rows.
    void setJobDiagnostics(const QString& job, const std::vector<shaders::Diagnostic>& diagnostics);
    int count() const;
    QString rowText(int row) const;
    // Activates row `row` as a click would (tests).
    void activate(int row);

signals:
    void locationActivated(const QString& file, int line, int column);

private:
    void rebuild();

    QListWidget* m_list = nullptr;
    std::vector<shaders::Diagnostic> m_document;
    std::vector<std::pair<QString, std::vector<shaders::Diagnostic>>> m_jobs; // in the order they first reported
    std::vector<shaders::Diagnostic> m_rows;                                  // every row's, as listed
};

} // namespace sdfwb::widgets
