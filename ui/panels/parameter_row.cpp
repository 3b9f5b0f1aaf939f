#include "parameter_row.h"

#include "value_spin_box.h"

#include <QHBoxLayout>
#include <QLabel>
#include <QSignalBlocker>
#include <QSlider>
#include <QWheelEvent>
#include <cmath>

namespace ui {

namespace {

// a slider that takes the mouse wheel only once it has focus: turned to scroll the dock, the wheel
// scrolls the dock (it set gravity x to -0.24 in two notches before)
class ParameterSlider : public QSlider {
public:
    explicit ParameterSlider(QWidget *parent) : QSlider(Qt::Horizontal, parent) { setFocusPolicy(Qt::StrongFocus); }

protected:
    void wheelEvent(QWheelEvent *event) override
    {
        if (!hasFocus()) {
            event->ignore();  // to the scroll area around it
            return;
        }
        QSlider::wheelEvent(event);
    }
};

}  // namespace

ParameterRow::ParameterRow(const core::ParameterInfo &info, const QString &label, bool integral, QWidget *parent)
    : QWidget(parent), m_info(info), m_scale(sliderScale(info)), m_integral(integral),
      m_label(new QLabel(label, this)), m_slider(new ParameterSlider(this)),
      m_spinBox(new ValueSpinBox(m_scale, this)), m_unit(new QLabel(QString::fromUtf8(info.unit.data(),
                                                                                       qsizetype(info.unit.size())),
                                                                     this))
{
    // label, slider, spin box, unit
    const QString tooltip = QString::fromUtf8(info.tooltip.data(), qsizetype(info.tooltip.size()));
    setToolTip(tooltip);
    m_slider->setRange(0, m_scale.positions);
    m_slider->setPageStep(m_scale.positions / 10);
    m_slider->setMinimumWidth(100);
    m_spinBox->setMinimumWidth(90);
    m_unit->setMinimumWidth(40);
    m_label->setBuddy(m_spinBox);
    auto *layout = new QHBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(m_slider, 1);
    layout->addWidget(m_spinBox);
    layout->addWidget(m_unit);

    // either control offers its value; the row checks it before anyone hears of it
    connect(m_slider, &QSlider::valueChanged, this, [this](int position) {
        const double value = m_scale.valueAt(position);
        offer(m_integral ? std::round(value) : value);
    });
    connect(m_spinBox, &QDoubleSpinBox::valueChanged, this, [this](double value) { offer(value); });
    setValue(info.defaultValue);
}

void ParameterRow::setValue(double value)
{
    m_value = value;
    const QSignalBlocker blockSlider(m_slider);
    const QSignalBlocker blockSpin(m_spinBox);
    m_slider->setValue(m_scale.positionOf(value));
    m_spinBox->setValue(value);
}

void ParameterRow::offer(double value)
{
    // refused: say why, and show the last good value again
    QString problem;
    if (const std::optional<std::string> outOfRange = core::checkParameter(m_info.parameter, value))
        problem = QString::fromStdString(*outOfRange);
    else if (m_integral && value != std::round(value))
        problem = tr("must be a whole number (got %1)").arg(value, 0, 'g', 6);
    if (!problem.isEmpty()) {
        setValue(m_value);
        emit valueRefused(tr("%1 %2; not applied").arg(m_label->text(), problem));
        return;
    }
    if (value == m_value) {
        setValue(value);
        return;
    }
    setValue(value);
    emit valueEdited(value);
}

}  // namespace ui
