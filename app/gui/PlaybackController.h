#pragma once
// Plays animated SDFs: advances the viewport's time at wall-clock speed while playing, and keeps
// the time bar in step. Owns its timer (UI thread).

#include <QElapsedTimer>
#include <QObject>
#include <QTimer>

namespace sdfwb::widgets {
class TimeBar;
class ViewportWidget;
} // namespace sdfwb::widgets

namespace sdfwb::app {

class PlaybackController : public QObject {
    Q_OBJECT
public:
    PlaybackController(widgets::TimeBar* bar, widgets::ViewportWidget* viewport, QObject* parent = nullptr);
    void setPlaying(bool playing);
    bool isPlaying() const { return m_timer.isActive(); }

private:
    widgets::TimeBar* m_bar;
    widgets::ViewportWidget* m_viewport;
    QTimer m_timer;
    QElapsedTimer m_clock;
};

} // namespace sdfwb::app
