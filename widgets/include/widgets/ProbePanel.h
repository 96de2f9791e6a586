#pragma once
// The march debugger's dock: one pixel's ray as a table of every event of its march (position,
// f, the step taken, |grad f|, oversteps and fallbacks marked) and as a plot of f along the ray
// with the evaluation points marked; a line above says how the ray ended and why. It shows what
// the probe job returns (values::ProbeReport, from values/). UI thread only.

#include <values/Requests.h>

#include <QString>
#include <QWidget>

#include <vector>

class QLabel;
class QTableWidget;

namespace sdfwb::widgets {

class MarchPlot;

class ProbePanel : public QWidget {
    Q_OBJECT
public:
    explicit ProbePanel(QWidget* parent = nullptr);

    void setReport(const values::ProbeReport& report);
    // A line instead of a march: "click a pixel", "probing...", or why the probe failed.
    void setMessage(const QString& message);
    const values::ProbeReport& report() const { return m_report; }
    QTableWidget* table() const { return m_table; }
    MarchPlot* plot() const { return m_plot; }
    QString summary() const;

private:
    QLabel* m_summary = nullptr;
    MarchPlot* m_plot = nullptr;
    QTableWidget* m_table = nullptr;
    values::ProbeReport m_report;
};

// f(t) along the probed ray: the field at every evaluation as a polyline with a marker per
// evaluation (red: an overstep, orange: a fallback, green: the hit), the zero line, and the row
// selected in the table ringed.
class MarchPlot : public QWidget {
    Q_OBJECT
public:
    explicit MarchPlot(QWidget* parent = nullptr);
    void setEvents(const std::vector<values::ProbeStep>& events);
    void setSelected(int row);
    int markerCount() const { return int(m_points.size()); }
    QSize sizeHint() const override { return {360, 180}; }

protected:
    void paintEvent(QPaintEvent* event) override;

private:
    struct Point {
        float t, f;
        int row;
        QColor colour;
    };
    std::vector<Point> m_points;
    int m_selected = -1;
};

} // namespace sdfwb::widgets
