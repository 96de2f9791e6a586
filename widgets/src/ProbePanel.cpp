#include <widgets/ProbePanel.h>

#include <QHeaderView>
#include <QLabel>
#include <QPainter>
#include <QPainterPath>
#include <QSplitter>
#include <QTableWidget>
#include <QVBoxLayout>

#include <algorithm>
#include <cmath>

namespace sdfwb::widgets {
namespace {

QString number(float value) { return std::isfinite(value) ? QString::number(double(value), 'g', 6) : QString("nan"); }

} // namespace

ProbePanel::ProbePanel(QWidget* parent) : QWidget(parent) {
    setObjectName("ProbePanel");
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(2, 2, 2, 2);
    m_summary = new QLabel(tr("Turn on Tools > Probe pixel (P) and click the viewport: every step of that pixel's march."));
    m_summary->setObjectName("probeSummary");
    m_summary->setWordWrap(true);
    m_summary->setTextInteractionFlags(Qt::TextSelectableByMouse);
    m_plot = new MarchPlot;
    m_table = new QTableWidget(0, 9);
    m_table->setObjectName("probeTable");
    m_table->setHorizontalHeaderLabels(
        {tr("#"), tr("event"), tr("t"), tr("x"), tr("y"), tr("z"), tr("f"), tr("step"), tr("|grad f|")});
    m_table->verticalHeader()->hide();
    m_table->setEditTriggers(QAbstractItemView::NoEditTriggers);
    m_table->setSelectionBehavior(QAbstractItemView::SelectRows);
    m_table->setSelectionMode(QAbstractItemView::SingleSelection);
    m_table->horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
    auto* splitter = new QSplitter(Qt::Vertical);
    splitter->addWidget(m_plot);
    splitter->addWidget(m_table);
    splitter->setStretchFactor(1, 1);
    layout->addWidget(m_summary);
    layout->addWidget(splitter, 1);
    connect(m_table, &QTableWidget::currentCellChanged, this, [this](int row) { m_plot->setSelected(row); });
}

void ProbePanel::setMessage(const QString& message) { m_summary->setText(message); }

QString ProbePanel::summary() const { return m_summary->text(); }

void ProbePanel::setReport(const values::ProbeReport& report) {
    m_report = report;
    QString text = tr("<b>Pixel (%1, %2)</b> of %3x%4: <b>%5</b>. %6<br>%7 steps, %8 oversteps, %9 fallbacks; probed in %10 s.")
                       .arg(report.x)
                       .arg(report.y)
                       .arg(report.width)
                       .arg(report.height)
                       .arg(QString(values::marchEventName(report.outcome)).toHtmlEscaped(),
                            QString::fromStdString(report.reason).toHtmlEscaped())
                       .arg(report.steps)
                       .arg(qulonglong(report.oversteps))
                       .arg(qulonglong(report.fallbacks))
                       .arg(report.seconds, 0, 'f', 2);
    if (report.oversteps > 0)
        text += tr("<br><span style='color:#d03030'>Oversteps: steps longer than the distance to the surface (f changed "
                   "sign). Lower the step factor or fix the field's Lipschitz bound.</span>");
    m_summary->setText(text);
    m_table->setRowCount(int(report.events.size()));
    for (int r = 0; r < int(report.events.size()); ++r) {
        const values::ProbeStep& row = report.events[std::size_t(r)];
        const QString event = values::marchEventName(row.event);
        const QStringList cells = {QString::number(r),
                                   row.overstep ? event + tr(" (overstep)") : event,
                                   number(row.t),
                                   number(row.position.x),
                                   number(row.position.y),
                                   number(row.position.z),
                                   values::evaluatesField(row.event) ? number(row.f) : QString(),
                                   row.step != 0.0f ? number(row.step) : QString(),
                                   values::evaluatesField(row.event) ? number(row.gradientLength) : QString()};
        for (int c = 0; c < cells.size(); ++c) {
            auto* item = new QTableWidgetItem(cells[c]);
            if (row.overstep)
                item->setForeground(QColor(210, 40, 40));
            else if (row.event == values::MarchEvent::Fallback)
                item->setForeground(QColor(220, 130, 20));
            else if (row.event == values::MarchEvent::Hit)
                item->setForeground(QColor(30, 150, 60));
            m_table->setItem(r, c, item);
        }
    }
    m_plot->setEvents(report.events);
}

MarchPlot::MarchPlot(QWidget* parent) : QWidget(parent) {
    setObjectName("marchPlot");
    setMinimumHeight(120);
}

void MarchPlot::setEvents(const std::vector<values::ProbeStep>& events) {
    m_points.clear();
    for (int r = 0; r < int(events.size()); ++r) {
        const values::ProbeStep& row = events[std::size_t(r)];
        if (!values::evaluatesField(row.event) || !std::isfinite(row.f) || !std::isfinite(row.t)) continue;
        using Event = values::MarchEvent;
        const bool refine = row.event == Event::Refine || row.event == Event::RefineUndone;
        QColor colour = row.overstep                   ? QColor(220, 40, 40)
                        : row.event == Event::Fallback ? QColor(235, 140, 20)
                        : row.event == Event::Hit      ? QColor(30, 170, 70)
                        : refine                       ? QColor(120, 120, 200)
                                                       : QColor(40, 90, 200);
        m_points.push_back({row.t, row.f, r, colour});
    }
    m_selected = -1;
    update();
}

void MarchPlot::setSelected(int row) {
    m_selected = row;
    update();
}

void MarchPlot::paintEvent(QPaintEvent*) {
    QPainter painter(this);
    painter.setRenderHint(QPainter::Antialiasing);
    painter.fillRect(rect(), palette().base());
    const QRectF area = QRectF(rect()).adjusted(46, 10, -10, -22);
    painter.setPen(palette().text().color());
    if (m_points.empty()) {
        painter.drawText(rect(), Qt::AlignCenter, tr("f(t) along the probed ray"));
        return;
    }
    float tMin = m_points.front().t, tMax = tMin, fMin = 0.0f, fMax = 0.0f;
    for (const Point& p : m_points) {
        tMin = std::min(tMin, p.t);
        tMax = std::max(tMax, p.t);
        fMin = std::min(fMin, p.f);
        fMax = std::max(fMax, p.f);
    }
    if (tMax - tMin < 1e-6f) tMax = tMin + 1e-6f;
    if (fMax - fMin < 1e-6f) fMax = fMin + 1e-6f;
    auto at = [&](float t, float f) {
        return QPointF(area.left() + double((t - tMin) / (tMax - tMin)) * area.width(),
                       area.bottom() - double((f - fMin) / (fMax - fMin)) * area.height());
    };
    // Axes: the zero line (the surface) and the value range.
    painter.setPen(QPen(QColor(128, 128, 128), 1, Qt::DashLine));
    painter.drawLine(at(tMin, 0.0f), at(tMax, 0.0f));
    painter.setPen(palette().text().color());
    painter.drawText(QRectF(0, area.top() - 6, 44, 14), Qt::AlignRight, QString::number(double(fMax), 'g', 3));
    painter.drawText(QRectF(0, area.bottom() - 8, 44, 14), Qt::AlignRight, QString::number(double(fMin), 'g', 3));
    painter.drawText(QRectF(area.left(), area.bottom() + 4, 120, 16), Qt::AlignLeft,
                     QString("t = %1").arg(double(tMin), 0, 'g', 4));
    painter.drawText(QRectF(area.right() - 120, area.bottom() + 4, 120, 16), Qt::AlignRight,
                     QString("t = %1").arg(double(tMax), 0, 'g', 4));
    painter.drawText(QRectF(area.left(), area.bottom() + 4, area.width(), 16), Qt::AlignHCenter, tr("f along the ray"));
    QPainterPath path(at(m_points.front().t, m_points.front().f));
    for (const Point& p : m_points) path.lineTo(at(p.t, p.f));
    painter.setPen(QPen(QColor(90, 90, 90), 1.2));
    painter.drawPath(path);
    for (const Point& p : m_points) {
        painter.setPen(Qt::NoPen);
        painter.setBrush(p.colour);
        painter.drawEllipse(at(p.t, p.f), 3.5, 3.5);
        if (p.row == m_selected) {
            painter.setBrush(Qt::NoBrush);
            painter.setPen(QPen(palette().highlight().color(), 2));
            painter.drawEllipse(at(p.t, p.f), 7.0, 7.0);
        }
    }
}

} // namespace sdfwb::widgets
