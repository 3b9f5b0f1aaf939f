#include "value_spin_box.h"

#include <QLineEdit>
#include <QWheelEvent>

#include <QRegularExpression>
#include <cmath>
#include <limits>
#include <optional>

namespace ui {

namespace {

// the slider positions one arrow press moves
constexpr int kPositionsPerStep = 10;

// the words for values that are not finite, as typed
constexpr const char *kNonFinite[] = {"nan", "inf", "-inf"};

std::optional<double> nonFinite(const QString &text)
{
    const QString word = text.trimmed().toLower();
    if (word == QLatin1String(kNonFinite[0]))
        return std::numeric_limits<double>::quiet_NaN();
    if (word == QLatin1String(kNonFinite[1]))
        return std::numeric_limits<double>::infinity();
    if (word == QLatin1String(kNonFinite[2]))
        return -std::numeric_limits<double>::infinity();
    return std::nullopt;
}

}  // namespace

ValueSpinBox::ValueSpinBox(const SliderScale &scale, QWidget *parent) : QDoubleSpinBox(parent), m_scale(scale)
{
    // every double can be typed; the row checks the range and says what is wrong
    setDecimals(std::numeric_limits<double>::max_exponent10 + std::numeric_limits<double>::digits10);
    setRange(-std::numeric_limits<double>::max(), std::numeric_limits<double>::max());
    setKeyboardTracking(false);
    setAccelerated(true);
    setFocusPolicy(Qt::StrongFocus);  // not Qt::WheelFocus: a wheel turned over it does not take focus

    // a NaN or infinity typed is kept beside the clamped value the spin box holds
    connect(lineEdit(), &QLineEdit::textEdited, this, [this](const QString &text) {
        m_typedText = text;
        m_typedNonFinite.reset();
    });
    connect(this, &QAbstractSpinBox::editingFinished, this, [this] {
        if (!m_nonFiniteTypable || m_typedText.isNull())
            return;
        m_typedNonFinite = nonFinite(m_typedText);
        m_typedText = QString();
        if (m_typedNonFinite)
            lineEdit()->setText(textFromValue(value()));
    });
}

double ValueSpinBox::typedValue() const
{
    return m_typedNonFinite.value_or(value());
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
    // the word typed, while the clamped value it became is held
    if (m_typedNonFinite && std::abs(value) == std::numeric_limits<double>::max())
        return locale().toString(*m_typedNonFinite).toLower();
    return numberLocale().toString(value, 'g', m_digits);
}

double ValueSpinBox::valueFromText(const QString &text) const
{
    if (m_nonFiniteTypable)
        if (const std::optional<double> value = nonFinite(text))
            return *value;
    bool ok = false;
    const double value = numberLocale().toDouble(text.trimmed(), &ok);
    return ok ? value : this->value();
}

QValidator::State ValueSpinBox::validate(QString &input, int &) const
{
    const QString text = input.trimmed();
    if (m_nonFiniteTypable) {
        const QString word = text.toLower();
        if (nonFinite(word))
            return QValidator::Acceptable;
        for (const char *full : kNonFinite)
            if (!word.isEmpty() && QLatin1String(full).startsWith(word))
                return QValidator::Intermediate;
    }
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
    m_typedNonFinite.reset();
    setValue(m_scale.valueAt(m_scale.positionOf(value()) + steps * kPositionsPerStep));
    selectAll();
}

}  // namespace ui
