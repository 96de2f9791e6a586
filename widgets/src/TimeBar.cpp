#include <widgets/TimeBar.h>

#include <QDoubleSpinBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QSlider>
#include <QStyle>
#include <QToolButton>

#include <cmath>

namespace sdfwb::widgets {

TimeBar::TimeBar(QWidget* parent) : QWidget(parent) {
    setObjectName("TimeBar");
    auto* layout = new QHBoxLayout(this);
    layout->setContentsMargins(4, 2, 4, 2);
    m_play = new QToolButton;
    m_play->setCheckable(true);
    m_play->setIcon(style()->standardIcon(QStyle::SP_MediaPlay));
    m_play->setToolTip(tr("Play / pause (Space in the viewport menu)"));
    m_play->setObjectName("play");
    m_slider = new QSlider(Qt::Horizontal);
    m_slider->setRange(0, 1000);
    m_slider->setObjectName("scrub");
    m_value = new QDoubleSpinBox;
    m_value->setRange(0.0, 1e6);
    m_value->setDecimals(2);
    m_value->setSuffix(" s");
    m_value->setKeyboardTracking(false);
    m_duration = new QDoubleSpinBox;
    m_duration->setRange(0.1, 1e5);
    m_duration->setValue(10.0);
    m_duration->setSuffix(" s");
    m_duration->setToolTip(tr("Length of the scrubber"));
    layout->addWidget(m_play);
    layout->addWidget(new QLabel(tr("Time")));
    layout->addWidget(m_slider, 1);
    layout->addWidget(m_value);
    layout->addWidget(new QLabel(tr("of")));
    layout->addWidget(m_duration);

    connect(m_play, &QToolButton::toggled, this, [this](bool playing) {
        m_play->setIcon(style()->standardIcon(playing ? QStyle::SP_MediaPause : QStyle::SP_MediaPlay));
        if (!m_updating) emit playToggled(playing);
    });
    connect(m_slider, &QSlider::valueChanged, this, [this](int value) {
        if (m_updating) return;
        m_time = duration() * value / 1000.0;
        setTime(m_time);
        emit timeEdited(m_time);
    });
    connect(m_value, &QDoubleSpinBox::valueChanged, this, [this](double value) {
        if (m_updating) return;
        setTime(value);
        emit timeEdited(value);
    });
    connect(m_duration, &QDoubleSpinBox::valueChanged, this, [this] { setTime(m_time); });
}

double TimeBar::duration() const { return m_duration->value(); }

void TimeBar::setTime(double seconds) {
    m_updating = true;
    m_time = seconds;
    m_value->setValue(seconds);
    m_slider->setValue(int(std::lround(1000.0 * std::fmod(std::max(seconds, 0.0), duration()) / duration())));
    m_updating = false;
}

void TimeBar::setPlaying(bool playing) {
    m_updating = true;
    m_play->setChecked(playing);
    m_updating = false;
}

} // namespace sdfwb::widgets
