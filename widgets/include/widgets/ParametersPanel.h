#pragma once
// The Parameters dock: one row per parameter the SDF declares (annotated uniforms): a slider and
// a number (drag horizontally on the number to change it; Shift x10, Ctrl x0.1) for floats and
// ints, a checkbox for bools, a number per component for vectors, a colour button for @color,
// and a reset per row. Values are uniforms: changing them never recompiles. "Save as defaults"
// and the clip-end keyframe are requests the owner carries out.

#include <shaders/Parameters.h>

#include <QWidget>

#include <vector>

class QGridLayout;
class QLabel;
class QPushButton;

namespace sdfwb::widgets {

class ParametersPanel : public QWidget {
    Q_OBJECT
public:
    explicit ParametersPanel(QWidget* parent = nullptr);
    ~ParametersPanel() override;

    // New declarations (after each good compile). Rows are rebuilt when the set of names, types
    // or annotations changed; a parameter that keeps its name and type keeps its value.
    void setDeclarations(const std::vector<shaders::Parameter>& declared);
    const std::vector<shaders::Parameter>& declarations() const { return m_declared; }

    // Every declared parameter's current value, in declaration order.
    const std::vector<shaders::ParameterSetting>& values() const { return m_values; }
    // Sets the named values (unknown names are ignored) and updates the controls.
    void setValues(const std::vector<shaders::ParameterValue>& values);
    void resetAll();

    // The values at the clip's last frame (empty: no keyframe): an MP4 export moves linearly
    // from values() to these.
    const std::vector<shaders::ParameterValue>& clipEnd() const { return m_clipEnd; }

signals:
    void valuesChanged();
    void saveDefaultsRequested();

private:
    struct Row;
    void rebuild();
    void setComponent(std::size_t index, int component, float value);
    void refreshRow(std::size_t index);
    void updateClipEndLabel();

    std::vector<shaders::Parameter> m_declared;
    std::vector<shaders::ParameterSetting> m_values;
    std::vector<shaders::ParameterValue> m_clipEnd;
    std::vector<Row*> m_rows;
    QWidget* m_rowsHost = nullptr;
    QGridLayout* m_grid = nullptr;
    QLabel* m_empty = nullptr;
    QLabel* m_clipEndLabel = nullptr;
    QPushButton* m_saveDefaults = nullptr;
    bool m_updating = false;
};

} // namespace sdfwb::widgets
