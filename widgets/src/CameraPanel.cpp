#include <widgets/CameraPanel.h>

#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QPushButton>

namespace sdfwb::widgets {
namespace {

QDoubleSpinBox* spin(double minimum, double maximum, int decimals, double step) {
    auto* box = new QDoubleSpinBox;
    box->setRange(minimum, maximum);
    box->setDecimals(decimals);
    box->setSingleStep(step);
    box->setKeyboardTracking(false);
    return box;
}

} // namespace

CameraPanel::CameraPanel(QWidget* parent) : QWidget(parent) {
    setObjectName("CameraPanel");
    auto* form = new QFormLayout(this);
    const char* axes[3] = {"x", "y", "z"};
    auto* positionRow = new QHBoxLayout;
    auto* targetRow = new QHBoxLayout;
    for (int i = 0; i < 3; ++i) {
        m_position[i] = spin(-1e4, 1e4, 3, 0.1);
        m_position[i]->setObjectName(QString("position_") + axes[i]);
        m_target[i] = spin(-1e4, 1e4, 3, 0.1);
        m_target[i]->setObjectName(QString("target_") + axes[i]);
        positionRow->addWidget(m_position[i]);
        targetRow->addWidget(m_target[i]);
    }
    form->addRow(tr("Position"), positionRow);
    form->addRow(tr("Target"), targetRow);
    m_fov = spin(1.0, 179.0, 1, 1.0);
    m_fov->setSuffix(QString::fromUtf8("°"));
    m_fov->setObjectName("fov");
    form->addRow(tr("Field of view"), m_fov);
    m_near = spin(1e-5, 1e3, 5, 0.01);
    form->addRow(tr("Near"), m_near);
    m_far = spin(1e-3, 1e6, 2, 10.0);
    form->addRow(tr("Far"), m_far);
    auto* reset = new QPushButton(tr("Reset camera"));
    form->addRow(reset);
    connect(reset, &QPushButton::clicked, this, &CameraPanel::resetRequested);

    auto edited = [this] {
        if (m_updating) return;
        m_camera = camera();
        emit cameraEdited(m_camera);
    };
    for (QDoubleSpinBox* box :
         {m_position[0], m_position[1], m_position[2], m_target[0], m_target[1], m_target[2], m_fov, m_near, m_far})
        connect(box, &QDoubleSpinBox::valueChanged, this, edited);
    setCamera(values::Camera{});
}

void CameraPanel::setCamera(const values::Camera& camera) {
    m_updating = true;
    m_camera = camera;
    for (int i = 0; i < 3; ++i) {
        m_position[i]->setValue(camera.position[i]);
        m_target[i]->setValue(camera.target[i]);
    }
    m_fov->setValue(camera.fovYDegrees);
    m_near->setValue(camera.nearPlane);
    m_far->setValue(camera.farPlane);
    m_updating = false;
}

values::Camera CameraPanel::camera() const {
    values::Camera camera = m_camera;
    for (int i = 0; i < 3; ++i) {
        camera.position[i] = float(m_position[i]->value());
        camera.target[i] = float(m_target[i]->value());
    }
    camera.fovYDegrees = float(m_fov->value());
    camera.nearPlane = float(m_near->value());
    camera.farPlane = float(m_far->value());
    return camera;
}

} // namespace sdfwb::widgets
