#pragma once
// The cutting plane panel: on/off, axis presets and a free normal, offset slider, contour
// spacing, clipping and overlays; and the plane's readouts (value range, Lipschitz estimate,
// share above 1, truncation, discontinuities, NaN/Inf, a |grad f| histogram, the safe step factor
// with a button that applies it to the tracer). UI thread only.

#include <renderer/RenderSettings.h>

#include <QString>
#include <QWidget>

#include <cstdint>
#include <optional>
#include <vector>

class QCheckBox;
class QComboBox;
class QDoubleSpinBox;
class QLabel;
class QPushButton;
class QSlider;

namespace sdfwb::widgets {

class HistogramView;

// One of the audit's findings on the plane (non-conservative, truncated, discontinuous, nan).
struct FindingView {
    QString name;
    QString evidence;
    std::vector<glm::vec3> examples; // where it holds (at most 16 points)
};

struct PlaneReadoutView {
    float minimum = 0, maximum = 0, lipschitzMax = 0, lipschitz99 = 0;
    double shareAboveOne = 0;
    std::optional<float> truncationDistance;
    std::uint64_t discontinuities = 0, nanCount = 0, points = 0;
    std::vector<std::uint64_t> histogram;
    float safeStepFactor = 1;
    std::vector<FindingView> findings; // most severe first
    double seconds = 0;
};

class PlanePanel : public QWidget {
    Q_OBJECT
public:
    explicit PlanePanel(QWidget* parent = nullptr);
    void setPlane(const renderer::CuttingPlane& plane); // no signal
    renderer::CuttingPlane plane() const;
    void setReadout(const PlaneReadoutView& readout);
    void setReadoutMessage(const QString& message);
    const PlaneReadoutView& readout() const { return m_readout; }

signals:
    void planeEdited(const sdfwb::renderer::CuttingPlane& plane);
    void applyStepFactor(float factor);
    // "Show where": the example points of the finding chosen in the list.
    void showWhere(const std::vector<glm::vec3>& examples);

private:
    void emitEdited();

    QCheckBox* m_enabled = nullptr;
    QDoubleSpinBox* m_normal[3] = {};
    QSlider* m_offset = nullptr;
    QLabel* m_offsetLabel = nullptr;
    QDoubleSpinBox* m_spacing = nullptr;
    QCheckBox* m_clip = nullptr;
    QCheckBox* m_lipschitz = nullptr;
    QLabel* m_readoutText = nullptr;
    HistogramView* m_histogram = nullptr;
    QPushButton* m_apply = nullptr;
    QComboBox* m_findings = nullptr;
    QPushButton* m_showWhere = nullptr;
    bool m_updating = false;
    PlaneReadoutView m_readout;
};

} // namespace sdfwb::widgets
