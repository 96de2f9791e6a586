#include "PlaybackController.h"

#include "SdfDocument.h"

#include <widgets/TimeBar.h>

namespace sdfwb::app {

PlaybackController::PlaybackController(widgets::TimeBar* bar, SdfDocument* document, QObject* parent)
    : QObject(parent), m_bar(bar), m_document(document) {
    m_timer.setInterval(16);
    connect(&m_timer, &QTimer::timeout, this,
            [this] { m_document->setTime(float(m_document->time() + m_clock.restart() / 1000.0)); });
    // Whoever sets the time (playback, the bar, a session restored), the bar shows it.
    connect(m_document, &SdfDocument::timeChanged, m_bar, [this](float seconds) { m_bar->setTime(seconds); });
    connect(m_bar, &widgets::TimeBar::playToggled, this, &PlaybackController::setPlaying);
    connect(m_bar, &widgets::TimeBar::timeEdited, this, [this](double seconds) { m_document->setTime(float(seconds)); });
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
