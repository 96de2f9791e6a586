#pragma once
// Numeric camera editor: position, target, vertical field of view, near and far. Edits emit
// cameraEdited(); setCamera() updates the fields without emitting. UI thread only.

#include <values/Camera.h>

#include <QWidget>

class QDoubleSpinBox;

namespace sdfwb::widgets {

class CameraPanel : public QWidget {
    Q_OBJECT
public:
    explicit CameraPanel(QWidget* parent = nullptr);
    void setCamera(const values::Camera& camera);
    values::Camera camera() const;

signals:
    void cameraEdited(const sdfwb::values::Camera& camera);
    void resetRequested();

private:
    QDoubleSpinBox* m_position[3] = {};
    QDoubleSpinBox* m_target[3] = {};
    QDoubleSpinBox* m_fov = nullptr;
    QDoubleSpinBox* m_near = nullptr;
    QDoubleSpinBox* m_far = nullptr;
    bool m_updating = false;
    values::Camera m_camera;
};

} // namespace sdfwb::widgets
