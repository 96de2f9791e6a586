#include <widgets/ParametersPanel.h>

#include <QApplication>
#include <QCheckBox>
#include <QColorDialog>
#include <QDoubleSpinBox>
#include <QEvent>
#include <QGridLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QMouseEvent>
#include <QPushButton>
#include <QScrollArea>
#include <QSlider>
#include <QVBoxLayout>

#include <algorithm>
#include <cmath>

namespace sdfwb::widgets {
namespace {

constexpr int kSliderSteps = 1000;

bool sameDeclaration(const shaders::Parameter& a, const shaders::Parameter& b) {
    return a.name == b.name && a.type == b.type && a.minimum == b.minimum && a.maximum == b.maximum && a.step == b.step &&
           a.logarithmic == b.logarithmic && a.color == b.color && a.label == b.label;
}

// Drag horizontally on the number to change it: one step per 2 pixels (Shift x10, Ctrl x0.1). A
// press without a drag edits the text as usual.
class DragNumber : public QObject {
public:
    DragNumber(QDoubleSpinBox* box) : QObject(box), m_box(box) {
        if (auto* edit = box->findChild<QLineEdit*>()) edit->installEventFilter(this);
    }

protected:
    bool eventFilter(QObject*, QEvent* event) override {
        switch (event->type()) {
        case QEvent::MouseButtonPress: {
            auto* mouse = static_cast<QMouseEvent*>(event);
            if (mouse->button() != Qt::LeftButton) return false;
            m_pressX = mouse->position().x();
            m_startValue = m_box->value();
            m_pressed = true;
            m_dragging = false;
            return false;
        }
        case QEvent::MouseMove: {
            auto* mouse = static_cast<QMouseEvent*>(event);
            if (!m_pressed) return false;
            const double dx = mouse->position().x() - m_pressX;
            if (!m_dragging && std::abs(dx) < 4.0) return false;
            m_dragging = true;
            double step = m_box->singleStep();
            if (mouse->modifiers() & Qt::ShiftModifier) step *= 10.0;
            if (mouse->modifiers() & Qt::ControlModifier) step *= 0.1;
            m_box->setValue(m_startValue + std::round(dx / 2.0) * step);
            return true;
        }
        case QEvent::MouseButtonRelease: {
            const bool dragged = m_dragging;
            m_pressed = m_dragging = false;
            return dragged;
        }
        default:
            return false;
        }
    }

private:
    QDoubleSpinBox* m_box;
    double m_pressX = 0.0, m_startValue = 0.0;
    bool m_pressed = false, m_dragging = false;
};

QColor toColor(const std::array<float, 4>& v, bool alpha) {
    auto channel = [](float x) { return std::clamp(int(std::lround(x * 255.0f)), 0, 255); };
    return QColor(channel(v[0]), channel(v[1]), channel(v[2]), alpha ? channel(v[3]) : 255);
}

} // namespace

struct ParametersPanel::Row {
    QLabel* label = nullptr;
    QSlider* slider = nullptr;
    std::vector<QDoubleSpinBox*> numbers;
    QCheckBox* check = nullptr;
    QPushButton* color = nullptr;
    QPushButton* reset = nullptr;
};

ParametersPanel::ParametersPanel(QWidget* parent) : QWidget(parent) {
    setObjectName("ParametersPanel");
    auto* layout = new QVBoxLayout(this);
    m_empty = new QLabel(tr("This SDF declares no parameters. Declare one as an annotated uniform:\n"
                            "uniform float radius = 0.5; // @range 0.1 1.0"),
                         this);
    m_empty->setWordWrap(true);
    layout->addWidget(m_empty);
    auto* scroll = new QScrollArea(this);
    scroll->setWidgetResizable(true);
    scroll->setFrameShape(QFrame::NoFrame);
    m_rowsHost = new QWidget;
    m_grid = new QGridLayout(m_rowsHost);
    m_grid->setColumnStretch(1, 1);
    scroll->setWidget(m_rowsHost);
    layout->addWidget(scroll, 1);
    auto* buttons = new QHBoxLayout;
    auto* resetAll = new QPushButton(tr("Reset all"), this);
    resetAll->setObjectName("resetAllParameters");
    connect(resetAll, &QPushButton::clicked, this, &ParametersPanel::resetAll);
    m_saveDefaults = new QPushButton(tr("Save values as defaults"), this);
    m_saveDefaults->setObjectName("saveParameterDefaults");
    m_saveDefaults->setToolTip(tr("Write the current values into the file's initializers (undoable in the editor)"));
    connect(m_saveDefaults, &QPushButton::clicked, this, &ParametersPanel::saveDefaultsRequested);
    buttons->addWidget(resetAll);
    buttons->addWidget(m_saveDefaults);
    layout->addLayout(buttons);
    auto* keyframes = new QHBoxLayout;
    auto* setEnd = new QPushButton(tr("Set as clip end"), this);
    setEnd->setObjectName("setClipEnd");
    setEnd->setToolTip(tr("MP4 exports move linearly from the values at export time to these at the last frame"));
    auto* clearEnd = new QPushButton(tr("Clear"), this);
    clearEnd->setObjectName("clearClipEnd");
    m_clipEndLabel = new QLabel(this);
    m_clipEndLabel->setObjectName("clipEndLabel");
    m_clipEndLabel->setWordWrap(true);
    connect(setEnd, &QPushButton::clicked, this, [this] {
        m_clipEnd = shaders::valuesOf(m_values);
        updateClipEndLabel();
    });
    connect(clearEnd, &QPushButton::clicked, this, [this] {
        m_clipEnd.clear();
        updateClipEndLabel();
    });
    keyframes->addWidget(setEnd);
    keyframes->addWidget(clearEnd);
    layout->addLayout(keyframes);
    layout->addWidget(m_clipEndLabel);
    updateClipEndLabel();
    rebuild();
}

void ParametersPanel::updateClipEndLabel() {
    QString text;
    for (const shaders::ParameterValue& v : m_clipEnd) text += QString::fromStdString(shaders::formatParameterValue(v)) + " ";
    m_clipEndLabel->setText(m_clipEnd.empty() ? tr("Clip end: none (exports keep the values)") : tr("Clip end: %1").arg(text));
}

void ParametersPanel::setDeclarations(const std::vector<shaders::Parameter>& declared) {
    const bool same =
        declared.size() == m_declared.size() && std::equal(declared.begin(), declared.end(), m_declared.begin(), sameDeclaration);
    std::vector<shaders::ParameterSetting> values;
    for (const shaders::Parameter& p : declared) {
        shaders::ParameterSetting setting{p.name, p.type, p.defaultValue};
        for (std::size_t i = 0; i < m_values.size(); ++i)
            if (m_values[i].name == p.name && m_values[i].type == p.type && i < m_declared.size() &&
                m_values[i].value != m_declared[i].defaultValue)
                setting.value = m_values[i].value; // the user's value survives edits elsewhere in the file
        values.push_back(setting);
    }
    const bool changedValues = values != m_values;
    m_declared = declared;
    m_values = std::move(values);
    if (!same)
        rebuild();
    else
        for (std::size_t i = 0; i < m_rows.size(); ++i) refreshRow(i);
    if (changedValues) emit valuesChanged();
}

void ParametersPanel::setValues(const std::vector<shaders::ParameterValue>& values) {
    bool changed = false;
    for (const shaders::ParameterValue& v : values)
        for (std::size_t i = 0; i < m_values.size(); ++i) {
            if (m_values[i].name != v.name || v.value.empty()) continue;
            const int n = shaders::componentCount(m_values[i].type);
            for (int k = 0; k < n; ++k) {
                const float x =
                    v.value.size() == 1 ? v.value[0] : v.value[std::min<std::size_t>(std::size_t(k), v.value.size() - 1)];
                changed = changed || m_values[i].value[std::size_t(k)] != x;
                m_values[i].value[std::size_t(k)] = x;
            }
            refreshRow(i);
        }
    if (changed) emit valuesChanged();
}

void ParametersPanel::resetAll() {
    bool changed = false;
    for (std::size_t i = 0; i < m_values.size(); ++i) {
        changed = changed || m_values[i].value != m_declared[i].defaultValue;
        m_values[i].value = m_declared[i].defaultValue;
        refreshRow(i);
    }
    if (changed) emit valuesChanged();
}

// The rows' widgets are children of the rows' host, which Qt deletes; the rows themselves are ours.
ParametersPanel::~ParametersPanel() {
    for (Row* row : m_rows) delete row;
}

void ParametersPanel::rebuild() {
    for (Row* row : m_rows) {
        delete row->label;
        delete row->slider;
        for (QDoubleSpinBox* n : row->numbers) delete n;
        delete row->check;
        delete row->color;
        delete row->reset;
        delete row;
    }
    m_rows.clear();
    // The number boxes of a row sit in a plain container widget per row.
    while (QLayoutItem* item = m_grid->takeAt(0)) {
        delete item->widget();
        delete item;
    }
    m_empty->setVisible(m_declared.empty());
    m_saveDefaults->setEnabled(!m_declared.empty());
    for (std::size_t i = 0; i < m_declared.size(); ++i) {
        const shaders::Parameter& p = m_declared[i];
        auto* row = new Row;
        const int line = int(i);
        row->label = new QLabel(QString::fromStdString(p.label.empty() ? p.name : p.label), m_rowsHost);
        row->label->setToolTip(
            tr("%1 %2 (line %3)").arg(shaders::parameterTypeName(p.type), QString::fromStdString(p.name)).arg(p.line));
        m_grid->addWidget(row->label, line, 0);
        const int n = shaders::componentCount(p.type);
        const bool ranged = p.minimum && p.maximum && *p.maximum > *p.minimum;
        if (p.type == shaders::ParameterType::Bool) {
            row->check = new QCheckBox(m_rowsHost);
            row->check->setObjectName(QString::fromStdString("param_" + p.name));
            connect(row->check, &QCheckBox::toggled, this, [this, i](bool on) { setComponent(i, 0, on ? 1.0f : 0.0f); });
            m_grid->addWidget(row->check, line, 1);
        } else {
            if (n == 1 && ranged) {
                row->slider = new QSlider(Qt::Horizontal, m_rowsHost);
                row->slider->setObjectName(QString::fromStdString("slider_" + p.name));
                if (p.type == shaders::ParameterType::Int)
                    row->slider->setRange(int(std::ceil(*p.minimum)), int(std::floor(*p.maximum)));
                else
                    row->slider->setRange(0, kSliderSteps);
                connect(row->slider, &QSlider::valueChanged, this, [this, i](int position) {
                    if (m_updating) return;
                    const shaders::Parameter& q = m_declared[i];
                    float value = float(position);
                    if (q.type != shaders::ParameterType::Int) {
                        const double t = double(position) / kSliderSteps;
                        value = q.logarithmic ? float(*q.minimum * std::pow(double(*q.maximum) / *q.minimum, t))
                                              : float(*q.minimum + t * (double(*q.maximum) - *q.minimum));
                        if (q.step && *q.step > 0.0f) value = *q.minimum + std::round((value - *q.minimum) / *q.step) * *q.step;
                    }
                    setComponent(i, 0, value);
                });
                m_grid->addWidget(row->slider, line, 1);
            }
            auto* numbers = new QWidget(m_rowsHost);
            auto* box = new QHBoxLayout(numbers);
            box->setContentsMargins(0, 0, 0, 0);
            for (int k = 0; k < n; ++k) {
                auto* number = new QDoubleSpinBox(numbers);
                number->setObjectName(QString::fromStdString("number_" + p.name + (n > 1 ? "_" + std::to_string(k) : "")));
                number->setKeyboardTracking(false);
                const bool isInt = p.type == shaders::ParameterType::Int;
                number->setDecimals(isInt ? 0 : 4);
                // The range bounds the slider; typed values may go beyond it (the batch warns).
                number->setRange(-1e6, 1e6);
                const double span = ranged ? double(*p.maximum) - *p.minimum : 1.0;
                number->setSingleStep(p.step ? double(*p.step) : isInt ? 1.0 : span / 100.0);
                number->setToolTip(tr("Drag sideways to change (Shift x10, Ctrl x0.1), or type a value"));
                new DragNumber(number);
                connect(number, &QDoubleSpinBox::valueChanged, this, [this, i, k](double value) {
                    if (!m_updating) setComponent(i, k, float(value));
                });
                box->addWidget(number);
                row->numbers.push_back(number);
            }
            if (p.color) {
                row->color = new QPushButton(m_rowsHost);
                row->color->setObjectName(QString::fromStdString("color_" + p.name));
                row->color->setFixedWidth(36);
                connect(row->color, &QPushButton::clicked, this, [this, i] {
                    const bool alpha = m_values[i].type == shaders::ParameterType::Vec4;
                    const QColor chosen =
                        QColorDialog::getColor(toColor(m_values[i].value, alpha), this, tr("Colour"),
                                               alpha ? QColorDialog::ShowAlphaChannel : QColorDialog::ColorDialogOptions());
                    if (!chosen.isValid()) return;
                    m_updating = true;
                    m_values[i].value[0] = float(chosen.redF());
                    m_values[i].value[1] = float(chosen.greenF());
                    m_values[i].value[2] = float(chosen.blueF());
                    if (alpha) m_values[i].value[3] = float(chosen.alphaF());
                    m_updating = false;
                    refreshRow(i);
                    emit valuesChanged();
                });
                box->addWidget(row->color);
            }
            m_grid->addWidget(numbers, line, row->slider ? 2 : 1, 1, row->slider ? 1 : 2);
        }
        row->reset = new QPushButton(tr("Reset"), m_rowsHost);
        row->reset->setObjectName(QString::fromStdString("reset_" + p.name));
        connect(row->reset, &QPushButton::clicked, this, [this, i] {
            if (m_values[i].value == m_declared[i].defaultValue) return;
            m_values[i].value = m_declared[i].defaultValue;
            refreshRow(i);
            emit valuesChanged();
        });
        m_grid->addWidget(row->reset, line, 3);
        m_rows.push_back(row);
        refreshRow(i);
    }
    m_grid->setRowStretch(int(m_declared.size()), 1);
}

void ParametersPanel::setComponent(std::size_t index, int component, float value) {
    if (m_updating || index >= m_values.size()) return;
    float& slot = m_values[index].value[std::size_t(component)];
    if (slot == value) return;
    slot = value;
    refreshRow(index); // the other controls of the row follow
    emit valuesChanged();
}

void ParametersPanel::refreshRow(std::size_t index) {
    if (index >= m_rows.size()) return;
    Row* row = m_rows[index];
    const shaders::Parameter& p = m_declared[index];
    const std::array<float, 4>& v = m_values[index].value;
    m_updating = true;
    if (row->check) row->check->setChecked(v[0] != 0.0f);
    if (row->slider) {
        int position = int(std::lround(v[0]));
        if (p.type != shaders::ParameterType::Int) {
            const double t = p.logarithmic ? std::log(double(std::max(v[0], *p.minimum)) / *p.minimum) /
                                                 std::log(double(*p.maximum) / *p.minimum)
                                           : (double(v[0]) - *p.minimum) / (double(*p.maximum) - *p.minimum);
            position = int(std::lround(std::clamp(t, 0.0, 1.0) * kSliderSteps));
        }
        row->slider->setValue(position);
    }
    for (std::size_t k = 0; k < row->numbers.size(); ++k) row->numbers[k]->setValue(double(v[k]));
    if (row->color) row->color->setStyleSheet(QString("background-color: %1").arg(toColor(v, false).name()));
    const bool atDefault = v == p.defaultValue;
    row->reset->setEnabled(!atDefault);
    QFont font = row->label->font();
    font.setBold(!atDefault); // changed values stand out
    row->label->setFont(font);
    m_updating = false;
}

} // namespace sdfwb::widgets
