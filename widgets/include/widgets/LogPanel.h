#pragma once
// The Log dock: the lines of the workbench's log file (GL vendor, renderer and version, shader
// compile times, frame times, jobs, errors), newest last, warnings in orange and errors in red,
// with a filter by level and the file's path. It shows lines it is given. UI thread only.

#include <QString>
#include <QWidget>

class QComboBox;
class QLabel;
class QPlainTextEdit;

namespace sdfwb::widgets {

class LogPanel : public QWidget {
    Q_OBJECT
public:
    explicit LogPanel(QWidget* parent = nullptr);

    void setFilePath(const QString& path);
    // One line as the log file holds it: "TIME [level] category: message".
    void appendLine(const QString& line);
    int lineCount() const { return m_lines.size(); }
    QString text() const; // the lines shown (after the filter)

private:
    void refilter();
    bool shown(const QString& line) const;

    QLabel* m_path = nullptr;
    QComboBox* m_level = nullptr;
    QPlainTextEdit* m_view = nullptr;
    QStringList m_lines;
};

} // namespace sdfwb::widgets
