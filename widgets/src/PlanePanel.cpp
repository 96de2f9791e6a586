#include <widgets/PlanePanel.h>

#include <QCheckBox>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QPainter>
#include <QPushButton>
#include <QSlider>
#include <QVBoxLayout>

#include <algorithm>
#include <cmath>

namespace sdfwb::widgets {

// Bars of the |grad f| histogram; bins above 1 in red, the last bin (>= 2) darker.
class HistogramView : public QWidget {
public:
    explicit HistogramView(QWidget* parent = nullptr) : QWidget(parent) { setMinimumHeight(70); }
    void setBins(std::vector<std::uint64_t> bins) {
        m_bins = std::move(bins);
        update();
    }

protected:
    void paintEvent(QPaintEvent*) override {
        QPainter painter(this);
        painter.fillRect(rect(), palette().base());
        if (m_bins.empty()) return;
        std::uint64_t top = std::max<std::uint64_t>(1, *std::max_element(m_bins.begin(), m_bins.end()));
        const int count = int(m_bins.size());
        const double barWidth = double(this->width() - 2) / count;
        for (int i = 0; i < count; ++i) {
            // square-root scale: small counts stay visible next to the |grad f| = 1 peak
            double height = std::sqrt(double(m_bins[std::size_t(i)]) / double(top)) * (this->height() - 14);
            // bin 20 is |grad f| = 1 +- 0.025; above it the field is steeper than a distance
            QColor color = i > 20 ? (i == count - 1 ? QColor(120, 0, 0) : QColor(200, 40, 40)) : QColor(70, 110, 190);
            painter.fillRect(QRectF(1 + i * barWidth, this->height() - 12 - height, std::max(barWidth - 1, 1.0), height), color);
        }
        painter.setPen(palette().text().color());
        QFont font = painter.font();
        font.setPointSizeF(7.5);
        painter.setFont(font);
        painter.drawText(QRect(0, height() - 12, width() / 2, 12), Qt::AlignLeft, "|grad f| 0");
        painter.drawText(QRect(0, height() - 12, width(), 12), Qt::AlignHCenter, "1");
        painter.drawText(QRect(width() / 2, height() - 12, width() / 2, 12), Qt::AlignRight, ">=2");
    }

private:
    std::vector<std::uint64_t> m_bins;
};

PlanePanel::PlanePanel(QWidget* parent) : QWidget(parent) {
    setObjectName("PlanePanel");
    auto* layout = new QVBoxLayout(this);
    auto* form = new QFormLayout;
    m_enabled = new QCheckBox(tr("Show the cutting plane"));
    m_enabled->setObjectName("enabled");
    form->addRow(m_enabled);
    auto* presets = new QHBoxLayout;
    const char* names[3] = {"X", "Y", "Z"};
    for (int axis = 0; axis < 3; ++axis) {
        auto* button = new QPushButton(names[axis]);
        button->setObjectName(QString("axis_") + names[axis]);
        button->setToolTip(tr("Plane perpendicular to %1").arg(names[axis]));
        presets->addWidget(button);
        connect(button, &QPushButton::clicked, this, [this, axis] {
            m_updating = true;
            for (int i = 0; i < 3; ++i) m_normal[i]->setValue(i == axis ? 1.0 : 0.0);
            m_enabled->setChecked(true);
            m_updating = false;
            emitEdited();
        });
    }
    form->addRow(tr("Axis"), presets);
    auto* normalRow = new QHBoxLayout;
    for (int i = 0; i < 3; ++i) {
        m_normal[i] = new QDoubleSpinBox;
        m_normal[i]->setRange(-1.0, 1.0);
        m_normal[i]->setDecimals(3);
        m_normal[i]->setSingleStep(0.05);
        m_normal[i]->setKeyboardTracking(false);
        normalRow->addWidget(m_normal[i]);
        connect(m_normal[i], &QDoubleSpinBox::valueChanged, this, [this] { emitEdited(); });
    }
    form->addRow(tr("Normal"), normalRow);
    auto* offsetRow = new QHBoxLayout;
    m_offset = new QSlider(Qt::Horizontal);
    m_offset->setRange(-1000, 1000);
    m_offset->setObjectName("offset");
    m_offsetLabel = new QLabel("0.000");
    m_offsetLabel->setMinimumWidth(48);
    offsetRow->addWidget(m_offset, 1);
    offsetRow->addWidget(m_offsetLabel);
    form->addRow(tr("Offset"), offsetRow);
    connect(m_offset, &QSlider::valueChanged, this, [this](int value) {
        m_offsetLabel->setText(QString::number(value / 1000.0, 'f', 3));
        emitEdited();
    });
    m_spacing = new QDoubleSpinBox;
    m_spacing->setRange(0.001, 1.0);
    m_spacing->setDecimals(4);
    m_spacing->setSingleStep(1.0 / 128.0);
    m_spacing->setValue(1.0 / 64.0);
    m_spacing->setKeyboardTracking(false);
    form->addRow(tr("Contour spacing"), m_spacing);
    connect(m_spacing, &QDoubleSpinBox::valueChanged, this, [this] { emitEdited(); });
    m_clip = new QCheckBox(tr("Cut the surface away in front of the plane"));
    m_clip->setChecked(true);
    m_lipschitz = new QCheckBox(tr("Lipschitz overlay (red: |grad f| > 1, grey: ~0)"));
    m_lipschitz->setChecked(true);
    form->addRow(m_clip);
    form->addRow(m_lipschitz);
    for (QCheckBox* box : {m_enabled, m_clip, m_lipschitz}) connect(box, &QCheckBox::toggled, this, [this] { emitEdited(); });
    layout->addLayout(form);

    m_readoutText = new QLabel(tr("Readouts appear when the plane is on."));
    m_readoutText->setObjectName("readouts");
    m_readoutText->setWordWrap(true);
    m_readoutText->setTextInteractionFlags(Qt::TextSelectableByMouse);
    layout->addWidget(m_readoutText);
    {
        auto* row = new QHBoxLayout;
        m_findings = new QComboBox;
        m_findings->setObjectName("findings");
        m_findings->setEnabled(false);
        m_showWhere = new QPushButton(tr("Show where"));
        m_showWhere->setObjectName("show_where");
        m_showWhere->setToolTip(tr("Ring the finding's example points in the viewport and move the plane through the first"));
        m_showWhere->setEnabled(false);
        row->addWidget(m_findings, 1);
        row->addWidget(m_showWhere);
        layout->addLayout(row);
        connect(m_showWhere, &QPushButton::clicked, this, [this] {
            const int index = m_findings->currentIndex();
            if (index >= 0 && std::size_t(index) < m_readout.flags.size())
                emit showWhere(m_readout.flags[std::size_t(index)].examples);
        });
    }
    m_histogram = new HistogramView;
    layout->addWidget(m_histogram);
    m_apply = new QPushButton(tr("Apply the safe step factor to the tracer"));
    m_apply->setObjectName("apply_step_factor");
    m_apply->setEnabled(false);
    layout->addWidget(m_apply);
    connect(m_apply, &QPushButton::clicked, this, [this] { emit applyStepFactor(m_readout.safeStepFactor); });
    layout->addStretch(1);
    setPlane(values::CuttingPlane{});
}

void PlanePanel::emitEdited() {
    if (!m_updating) emit planeEdited(plane());
}

void PlanePanel::setPlane(const values::CuttingPlane& plane) {
    m_updating = true;
    m_enabled->setChecked(plane.enabled);
    for (int i = 0; i < 3; ++i) m_normal[i]->setValue(plane.normal[i]);
    m_offset->setValue(int(std::lround(plane.offset * 1000.0f)));
    m_offsetLabel->setText(QString::number(plane.offset, 'f', 3));
    m_spacing->setValue(plane.contourSpacing);
    m_clip->setChecked(plane.clipSurface);
    m_lipschitz->setChecked(plane.lipschitzOverlay);
    m_updating = false;
}

values::CuttingPlane PlanePanel::plane() const {
    values::CuttingPlane plane;
    plane.enabled = m_enabled->isChecked();
    plane.normal = {float(m_normal[0]->value()), float(m_normal[1]->value()), float(m_normal[2]->value())};
    if (plane.normal == glm::vec3(0.0f)) plane.normal = {0.0f, 0.0f, 1.0f};
    plane.offset = float(m_offset->value()) / 1000.0f;
    plane.contourSpacing = float(m_spacing->value());
    plane.clipSurface = m_clip->isChecked();
    plane.lipschitzOverlay = m_lipschitz->isChecked();
    return plane;
}

namespace {

// Every finding with its evidence, most severe first; "no findings" when there are none.
QString findingsHtml(const std::vector<values::AuditFlag>& findings) {
    if (findings.empty()) return QObject::tr("<p>No findings: no NaN/Inf, jump, plateau or |grad f| &gt; 1.05 on the plane.</p>");
    QString html = "<p>";
    for (const values::AuditFlag& finding : findings)
        html += "<b>" + QString::fromUtf8(values::findingName(finding.finding)).toHtmlEscaped() +
                "</b>: " + QString::fromStdString(finding.evidence).toHtmlEscaped() + "<br>";
    return html + "</p>";
}

} // namespace

void PlanePanel::setReadout(const values::PlaneReadout& r) {
    m_readout = r;
    QString truncation = r.truncationDistance ? QString::number(*r.truncationDistance, 'g', 4) : tr("none");
    m_readoutText->setText(tr("<table>"
                              "<tr><td>value range</td><td>[%1, %2]</td></tr>"
                              "<tr><td>Lipschitz (|grad f|)</td><td>max %3, 99th pct %4</td></tr>"
                              "<tr><td>plane with |grad f| &gt; 1</td><td>%5 %</td></tr>"
                              "<tr><td>truncation</td><td>%6</td></tr>"
                              "<tr><td>discontinuities</td><td>%7</td></tr>"
                              "<tr><td>NaN / Inf</td><td>%8 of %9 points</td></tr>"
                              "<tr><td>safe step factor 1/L</td><td>%10</td></tr>"
                              "</table>%12<small>%11 s</small>")
                               .arg(r.minimum, 0, 'g', 4)
                               .arg(r.maximum, 0, 'g', 4)
                               .arg(r.lipschitzMax, 0, 'g', 4)
                               .arg(r.lipschitz99, 0, 'g', 4)
                               .arg(100.0 * r.shareAboveOne, 0, 'f', 2)
                               .arg(truncation)
                               .arg(r.discontinuities)
                               .arg(r.nanCount)
                               .arg(r.points)
                               .arg(r.safeStepFactor, 0, 'g', 4)
                               .arg(r.seconds, 0, 'f', 2)
                               .arg(findingsHtml(r.flags)));
    m_findings->clear();
    for (const values::AuditFlag& finding : r.flags) m_findings->addItem(QString::fromUtf8(values::findingName(finding.finding)));
    m_findings->setEnabled(!r.flags.empty());
    m_showWhere->setEnabled(!r.flags.empty());
    m_histogram->setBins(r.histogram);
    m_apply->setEnabled(true);
}

void PlanePanel::setReadoutMessage(const QString& message) { m_readoutText->setText(message); }

} // namespace sdfwb::widgets
