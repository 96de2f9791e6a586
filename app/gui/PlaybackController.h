#pragma once
// Plays animated SDFs: advances the document's time (which the viewport draws with) at wall-clock
// speed while playing, and keeps the time bar in step. Owns its timer (UI thread).

#include <QElapsedTimer>
#include <QObject>
#include <QTimer>

namespace sdfwb::widgets {
class TimeBar;
} // namespace sdfwb::widgets

namespace sdfwb::app {

class SdfDocument;

class PlaybackController : public QObject {
    Q_OBJECT
public:
    PlaybackController(widgets::TimeBar* bar, SdfDocument* document, QObject* parent = nullptr);
    void setPlaying(bool playing);
    bool isPlaying() const { return m_timer.isActive(); }

private:
    widgets::TimeBar* m_bar;
    SdfDocument* m_document;
    QTimer m_timer;
    QElapsedTimer m_clock;
};

} // namespace sdfwb::app
