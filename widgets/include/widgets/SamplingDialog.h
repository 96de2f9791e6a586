#pragma once
// The sampling dialog: pattern, count, seed, time, output file and format, with progress and
// Cancel. It fills a values::SampleRequest (values/) and shows progress; the controller that owns it
// names the SDF and runs the job. UI thread only.

#include <core/KeyedText.h>
#include <values/Requests.h>

#include <QDialog>
#include <QString>

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

class QComboBox;
class QDoubleSpinBox;
class QLabel;
class QLineEdit;
class QProgressBar;
class QPushButton;
class QSpinBox;

namespace sdfwb::widgets {

class SamplingDialog : public QDialog {
    Q_OBJECT
public:
    SamplingDialog(const QStringList& patterns, QWidget* parent = nullptr);

    void setSdfName(const QString& name);
    // The request the fields make: pattern, count, seed, time, output and format (its SDF empty).
    values::SampleRequest request() const;
    void setRequest(const values::SampleRequest& request);

    // Controller feedback.
    void setRunning(bool running);
    void setProgress(std::uint64_t done, std::uint64_t total);
    void setMessage(const QString& message, bool error);
    // A failure whose text names request keys (`keys`: where, core/KeyedText.h): each key worded
    // as this form's label ("Samples (N)" for n), its field marked and the first one focused. The
    // marks go with the next message.
    void setFailure(const std::string& message, const std::vector<KeyMention>& keys);

    // Preview: the same pattern, seed and time, at most this many points, shown in the viewport.
    static constexpr std::uint64_t kPreviewPoints = 100000;
    int pointSize() const;

signals:
    void startRequested(const sdfwb::values::SampleRequest& request);
    void previewRequested(const sdfwb::values::SampleRequest& request);
    void pointSizeChanged(int pixels);
    void cancelRequested();

private:
    QLabel* m_sdf = nullptr;
    QComboBox* m_pattern = nullptr;
    QLineEdit* m_count = nullptr;
    QLineEdit* m_seed = nullptr;
    QDoubleSpinBox* m_time = nullptr;
    QLineEdit* m_output = nullptr;
    QComboBox* m_format = nullptr;
    QProgressBar* m_progress = nullptr;
    QLabel* m_message = nullptr;
    QPushButton* m_start = nullptr;
    QPushButton* m_preview = nullptr;
    QSpinBox* m_pointSize = nullptr;
    QPushButton* m_cancel = nullptr;
    std::vector<QWidget*> m_marked; // fields a failure names

    // The field that sets the request key at `path`, with its label; null for the keys no field sets.
    std::pair<QWidget*, QString> field(const std::string& path) const;
};

} // namespace sdfwb::widgets
