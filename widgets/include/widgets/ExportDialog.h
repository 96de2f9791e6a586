#pragma once
// Export settings for a screenshot (F4) or an animation (F6): file, size and, for video, length,
// frame rate and turntable. Shows progress; the controller that owns it does the work.

#include <QDialog>

class QCheckBox;
class QDoubleSpinBox;
class QLabel;
class QLineEdit;
class QProgressBar;
class QPushButton;
class QSpinBox;

namespace sdfwb::widgets {

struct ExportSettings {
    QString output;
    int width = 1280;
    int height = 720;
    double seconds = 4.0;     // video only
    int framesPerSecond = 30; // video only
    bool turntable = true;    // video only
};

class ExportDialog : public QDialog {
    Q_OBJECT
public:
    enum class Kind { Screenshot, Video };
    ExportDialog(Kind kind, QWidget* parent = nullptr);

    void setSettings(const ExportSettings& settings);
    ExportSettings settings() const;
    void setRunning(bool running);
    void setProgress(quint64 done, quint64 total);
    void setMessage(const QString& message, bool error);

signals:
    void startRequested(const sdfwb::widgets::ExportSettings& settings);
    void cancelRequested();

private:
    Kind m_kind;
    QLineEdit* m_output = nullptr;
    QSpinBox* m_width = nullptr;
    QSpinBox* m_height = nullptr;
    QDoubleSpinBox* m_seconds = nullptr;
    QSpinBox* m_fps = nullptr;
    QCheckBox* m_turntable = nullptr;
    QProgressBar* m_progress = nullptr;
    QLabel* m_message = nullptr;
    QPushButton* m_start = nullptr;
    QPushButton* m_cancel = nullptr;
};

} // namespace sdfwb::widgets
