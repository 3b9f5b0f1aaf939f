#pragma once
// ValueSpinBox: a QDoubleSpinBox for physical values from 1e-5 to 1e9. It shows six significant
// digits (with an exponent when needed) instead of fixed decimals, accepts any number typed, even
// one outside the parameter's range, so that the row can refuse it with a message instead of
// silently clamping it, and steps along the slider's scale (so arrows step by a factor on a log
// scale). It takes the mouse wheel only when focused (a click or Tab gives it focus), so that
// scrolling the dock over it scrolls the dock.

#include "slider_scale.h"

#include <QDoubleSpinBox>

namespace ui {

class ValueSpinBox : public QDoubleSpinBox {
    Q_OBJECT

public:
    ValueSpinBox(const SliderScale &scale, QWidget *parent = nullptr);

    QString textFromValue(double value) const override;
    double valueFromText(const QString &text) const override;
    QValidator::State validate(QString &input, int &pos) const override;
    void fixup(QString &input) const override;
    void stepBy(int steps) override;

protected:
    // the wheel only once the box has focus: a wheel turned to scroll a dock must not change a value
    void wheelEvent(QWheelEvent *event) override;

private:
    QLocale numberLocale() const;

    SliderScale m_scale;
};

}  // namespace ui
