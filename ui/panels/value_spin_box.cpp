#include "value_spin_box.h"

#include <QWheelEvent>

#include <QRegularExpression>
#include <limits>

namespace ui {

namespace {

// the slider positions one arrow press moves
constexpr int kPositionsPerStep = 10;

}  // namespace

ValueSpinBox::ValueSpinBox(const SliderScale &scale, QWidget *parent) : QDoubleSpinBox(parent), m_scale(scale)
{
    // every double can be typed; the row checks the range and says what is wrong
    setDecimals(std::numeric_limits<double>::max_exponent10 + std::numeric_limits<double>::digits10);
    setRange(-std::numeric_limits<double>::max(), std::numeric_limits<double>::max());
    setKeyboardTracking(false);
    setAccelerated(true);
    setFocusPolicy(Qt::StrongFocus);  // not Qt::WheelFocus: a wheel turned over it does not take focus
}

void ValueSpinBox::wheelEvent(QWheelEvent *event)
{
    if (!hasFocus()) {
        event->ignore();  // to the scroll area around it
        return;
    }
    QDoubleSpinBox::wheelEvent(event);
}

QLocale ValueSpinBox::numberLocale() const
{
    QLocale numbers = locale();
    numbers.setNumberOptions(QLocale::OmitGroupSeparator);
    return numbers;
}

QString ValueSpinBox::textFromValue(double value) const
{
    return numberLocale().toString(value, 'g', 6);
}

double ValueSpinBox::valueFromText(const QString &text) const
{
    bool ok = false;
    const double value = numberLocale().toDouble(text.trimmed(), &ok);
    return ok ? value : this->value();
}

QValidator::State ValueSpinBox::validate(QString &input, int &) const
{
    const QString text = input.trimmed();
    bool ok = false;
    numberLocale().toDouble(text, &ok);
    if (ok)
        return QValidator::Acceptable;
    // a number on its way: "", "-", "1e", "1e-", "0."
    const QLocale numbers = numberLocale();
    const QString pattern = QStringLiteral("^[-+]?[0-9%1]*([eE][-+]?[0-9]*)?$")
                                .arg(QRegularExpression::escape(numbers.decimalPoint()));
    if (QRegularExpression(pattern).match(text).hasMatch())
        return QValidator::Intermediate;
    return QValidator::Invalid;
}

void ValueSpinBox::fixup(QString &input) const
{
    // an unfinished number goes back to the value shown before
    input = textFromValue(value());
}

void ValueSpinBox::stepBy(int steps)
{
    setValue(m_scale.valueAt(m_scale.positionOf(value()) + steps * kPositionsPerStep));
    selectAll();
}

}  // namespace ui
