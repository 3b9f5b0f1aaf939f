#pragma once
// ValueSpinBox: a QDoubleSpinBox for physical values from 1e-5 to 1e9. It shows six significant
// digits (with an exponent when needed) instead of fixed decimals, accepts any number typed, even
// one outside the parameter's range, so that the row can refuse it with a message instead of
// silently clamping it, and steps along the slider's scale (so arrows step by a factor on a log
// scale). It takes the mouse wheel only when focused (a click or Tab gives it focus), so that
// scrolling the dock over it scrolls the dock.

#include "slider_scale.h"

#include <QDoubleSpinBox>
#include <QString>

#include <optional>

namespace ui {

class ValueSpinBox : public QDoubleSpinBox {
    Q_OBJECT

public:
    ValueSpinBox(const SliderScale &scale, QWidget *parent = nullptr);

    // lets "nan", "inf" and "-inf" be typed too, for a field whose owner refuses them with a
    // message rather than have the validator swallow them without a word
    void setNonFiniteTypable(bool typable) { m_nonFiniteTypable = typable; }
    // significant digits shown (6 unless set): the inspector's coordinates show 8, as many as a
    // user types for a position to the tenth of a micrometre
    void setSignificantDigits(int digits) { m_digits = digits; }
    // the value as typed: value(), or the NaN or infinity typed last, which QDoubleSpinBox cannot
    // hold (it clamps them to its range); the field shows the word typed meanwhile
    double typedValue() const;

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
    bool m_nonFiniteTypable = false;
    int m_digits = 6;
    QString m_typedText;                       // typed since the field last finished editing
    std::optional<double> m_typedNonFinite;    // the value that field holds, when not finite
};

}  // namespace ui
