#pragma once
// A screenshot (F4) or an animation (F6): file, size and, for video, length, frame rate and
// turntable, as a values::AnimateRequest (values/; a screenshot uses its output and frame size). Shows
// progress; the controller that owns it fills in the frame and does the work.

#include <values/Requests.h>

#include <QDialog>

class QCheckBox;
class QDoubleSpinBox;
class QLabel;
class QLineEdit;
class QProgressBar;
class QPushButton;
class QSpinBox;

namespace sdfwb::widgets {

class ExportDialog : public QDialog {
    Q_OBJECT
public:
    enum class Kind { Screenshot, Video };
    ExportDialog(Kind kind, QWidget* parent = nullptr);

    void setRequest(const values::AnimateRequest& request);
    // The fields' output, frame size and (video) clip; the frame's SDF, camera and the rest default.
    values::AnimateRequest request() const;
    void setRunning(bool running);
    void setProgress(quint64 done, quint64 total);
    void setMessage(const QString& message, bool error);

signals:
    void startRequested(const sdfwb::values::AnimateRequest& request);
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
