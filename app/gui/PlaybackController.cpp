#include "PlaybackController.h"

#include <widgets/TimeBar.h>
#include <widgets/ViewportWidget.h>

namespace sdfwb::app {

PlaybackController::PlaybackController(widgets::TimeBar* bar, widgets::ViewportWidget* viewport, QObject* parent)
    : QObject(parent), m_bar(bar), m_viewport(viewport) {
    m_timer.setInterval(16);
    connect(&m_timer, &QTimer::timeout, this, [this] {
        double seconds = m_viewport->time() + m_clock.restart() / 1000.0;
        m_viewport->setTime(float(seconds));
        m_bar->setTime(seconds);
    });
    connect(m_bar, &widgets::TimeBar::playToggled, this, &PlaybackController::setPlaying);
    connect(m_bar, &widgets::TimeBar::timeEdited, this, [this](double seconds) { m_viewport->setTime(float(seconds)); });
}

void PlaybackController::setPlaying(bool playing) {
    m_bar->setPlaying(playing);
    if (playing) {
        m_clock.start();
        m_timer.start();
    } else {
        m_timer.stop();
    }
}

} // namespace sdfwb::app
