#pragma once
// The problems list: one row per diagnostic (file:line:column, severity, message). Activating a
// row emits the location so the editor can jump there (opening an included file if needed).

#include <shaders/Diagnostic.h>

#include <QWidget>

#include <vector>

class QListWidget;

namespace sdfwb::widgets {

class ProblemsPanel : public QWidget {
    Q_OBJECT
public:
    explicit ProblemsPanel(QWidget* parent = nullptr);
    void setDiagnostics(const std::vector<shaders::Diagnostic>& diagnostics);
    int count() const;
    // Activates row `row` as a click would (tests).
    void activate(int row);

signals:
    void locationActivated(const QString& file, int line, int column);

private:
    QListWidget* m_list = nullptr;
    std::vector<shaders::Diagnostic> m_diagnostics;
};

} // namespace sdfwb::widgets
