#pragma once
// The cutting plane panel: on/off, axis presets and a free normal, offset slider, contour
// spacing, clipping and overlays; and the plane's readouts (value range, Lipschitz estimate,
// share above 1, truncation, discontinuities, NaN/Inf, a |grad f| histogram, the safe step factor
// with a button that applies it to the tracer). UI thread only.

#include <sampling/FieldAudit.h>
#include <values/RenderSettings.h>

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

class PlanePanel : public QWidget {
    Q_OBJECT
public:
    explicit PlanePanel(QWidget* parent = nullptr);
    void setPlane(const values::CuttingPlane& plane); // no signal
    values::CuttingPlane plane() const;
    // Shows the plane audit's report as the job returned it (nothing is copied into a view struct).
    void setReadout(const values::PlaneReadout& readout);
    void setReadoutMessage(const QString& message);
    const values::PlaneReadout& readout() const { return m_readout; }

signals:
    void planeEdited(const sdfwb::values::CuttingPlane& plane);
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
    values::PlaneReadout m_readout;
};

} // namespace sdfwb::widgets
