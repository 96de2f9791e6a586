#pragma once
// Play/pause and a scrubber for animated SDFs. It shows and edits a time; the controller that
// owns playback advances it. UI thread only.

#include <QWidget>

class QDoubleSpinBox;
class QSlider;
class QToolButton;

namespace sdfwb::widgets {

class TimeBar : public QWidget {
    Q_OBJECT
public:
    explicit TimeBar(QWidget* parent = nullptr);

    void setTime(double seconds); // no signal
    double time() const { return m_time; }
    double duration() const;
    void setPlaying(bool playing); // no signal

signals:
    void timeEdited(double seconds);
    void playToggled(bool playing);

private:
    QToolButton* m_play = nullptr;
    QSlider* m_slider = nullptr;
    QDoubleSpinBox* m_value = nullptr;
    QDoubleSpinBox* m_duration = nullptr;
    double m_time = 0.0;
    bool m_updating = false;
};

} // namespace sdfwb::widgets
