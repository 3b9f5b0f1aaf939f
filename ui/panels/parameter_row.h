#pragma once
// ParameterRow: one row of the parameters panel, made from one entry of the parameter table: a
// slider on the parameter's scale, a spin box for the exact value, and the unit. A value that
// core::checkParameter refuses is never emitted: the row says why and goes back to the last good
// value. The panel makes one row per parameter; nothing here knows which parameter it shows.

#include "slider_scale.h"

#include "core/model/parameters.h"

#include <QWidget>

class QLabel;
class QSlider;

namespace ui {

class ValueSpinBox;

class ParameterRow : public QWidget {
    Q_OBJECT

public:
    // integral: only whole numbers are accepted (substeps)
    ParameterRow(const core::ParameterInfo &info, const QString &label, bool integral, QWidget *parent = nullptr);

    // shows a value without emitting anything
    void setValue(double value);
    double value() const { return m_value; }

    const core::ParameterInfo &info() const { return m_info; }
    QLabel *label() const { return m_label; }
    QSlider *slider() const { return m_slider; }
    ValueSpinBox *spinBox() const { return m_spinBox; }

signals:
    // the user chose an accepted value
    void valueEdited(double value);
    // the user typed a value the parameter does not allow: "Stiffness must be at most ..."
    void valueRefused(const QString &message);

private:
    void offer(double value);

    const core::ParameterInfo &m_info;
    SliderScale m_scale;
    bool m_integral = false;
    double m_value = 0.0;
    QLabel *m_label = nullptr;
    QSlider *m_slider = nullptr;
    ValueSpinBox *m_spinBox = nullptr;
    QLabel *m_unit = nullptr;
};

}  // namespace ui
