#pragma once
// The march debugger's dock: one pixel's ray as a table of every event of its march (position,
// f, the step taken, |grad f|, oversteps and fallbacks marked) and as a plot of f along the ray
// with the evaluation points marked; a line above says how the ray ended and why. It shows what
// the controller gives it (a GL-free view of jobs::ProbeReport). UI thread only.

#include <glm/vec3.hpp>

#include <QString>
#include <QWidget>

#include <optional>
#include <vector>

class QLabel;
class QTableWidget;

namespace sdfwb::widgets {

class MarchPlot;

struct ProbeRowView {
    QString event; // step, relaxed step, fallback, hit, refine, refine undone, left the box, ...
    float t = 0.0f;
    glm::vec3 position{0.0f};
    float f = 0.0f;
    float step = 0.0f;
    float gradientLength = 0.0f;
    bool overstep = false;
};

struct ProbeView {
    int x = 0, y = 0, width = 0, height = 0;
    QString outcome; // hit, left the box, out of steps, not finite, missed the box
    QString reason;  // the outcome in a sentence
    int steps = 0;
    std::optional<float> hitT, hitResidual;
    float footprint = 0.0f;
    int oversteps = 0, fallbacks = 0;
    double seconds = 0.0;
    std::vector<ProbeRowView> rows;
};

class ProbePanel : public QWidget {
    Q_OBJECT
public:
    explicit ProbePanel(QWidget* parent = nullptr);

    void setView(const ProbeView& view);
    // A line instead of a march: "click a pixel", "probing...", or why the probe failed.
    void setMessage(const QString& message);
    const ProbeView& view() const { return m_view; }
    QTableWidget* table() const { return m_table; }
    MarchPlot* plot() const { return m_plot; }
    QString summary() const;

private:
    QLabel* m_summary = nullptr;
    MarchPlot* m_plot = nullptr;
    QTableWidget* m_table = nullptr;
    ProbeView m_view;
};

// f(t) along the probed ray: the field at every evaluation as a polyline with a marker per
// evaluation (red: an overstep, orange: a fallback, green: the hit), the zero line, and the row
// selected in the table ringed.
class MarchPlot : public QWidget {
    Q_OBJECT
public:
    explicit MarchPlot(QWidget* parent = nullptr);
    void setRows(const std::vector<ProbeRowView>& rows);
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
