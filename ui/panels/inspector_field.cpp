#include "inspector_field.h"

#include <QLineEdit>
#include <QSignalBlocker>
#include <limits>
#include <optional>

namespace ui {

namespace {

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

InspectorSpinBox::InspectorSpinBox(core::Parameter parameter, QWidget *parent)
    : ValueSpinBox(sliderScale(core::parameterInfo(parameter)), parent), m_parameter(parameter)
{
    setMinimumWidth(70);
    lineEdit()->setPlaceholderText(tr("mixed"));

    // remember what the user typed: on Enter the spin box would replace an empty or unfinished
    // text by the value it held, and for a mixed field that value means nothing
    connect(lineEdit(), &QLineEdit::textEdited, this, [this](const QString &text) {
        m_typing = true;
        m_typedText = text;
    });
    connect(this, &QAbstractSpinBox::editingFinished, this, &InspectorSpinBox::finishTyping);
    connect(this, &QDoubleSpinBox::valueChanged, this, [this](double value) {
        if (m_stepping)
            emit stepped(value);
    });
}

void InspectorSpinBox::showValue(double value)
{
    const QSignalBlocker block(this);
    m_mixed = false;
    m_typing = false;
    setValue(value);
}

void InspectorSpinBox::showMixed(double start)
{
    const QSignalBlocker block(this);
    m_mixed = true;
    m_typing = false;
    setValue(start);
    lineEdit()->clear();
}

QString InspectorSpinBox::textFromValue(double value) const
{
    // a mixed field stays empty so that its placeholder shows
    return m_mixed ? QString() : ValueSpinBox::textFromValue(value);
}

QValidator::State InspectorSpinBox::validate(QString &input, int &pos) const
{
    const QString word = input.trimmed().toLower();
    if (nonFinite(word))
        return QValidator::Acceptable;
    for (const char *full : kNonFinite)
        if (!word.isEmpty() && QLatin1String(full).startsWith(word))
            return QValidator::Intermediate;
    return ValueSpinBox::validate(input, pos);
}

double InspectorSpinBox::valueFromText(const QString &text) const
{
    if (const std::optional<double> value = nonFinite(text))
        return *value;
    return ValueSpinBox::valueFromText(text);
}

void InspectorSpinBox::stepBy(int steps)
{
    // a step replaces whatever was being typed
    m_typing = false;
    m_mixed = false;
    m_stepping = true;
    ValueSpinBox::stepBy(steps);
    m_stepping = false;
}

void InspectorSpinBox::finishTyping()
{
    if (!m_typing)
        return;
    m_typing = false;
    // an empty or unfinished number is no value: the field shows the scene's value again
    QString text = m_typedText.trimmed();
    int position = 0;
    if (text.isEmpty() || validate(text, position) != QValidator::Acceptable)
        return;
    emit typed(valueFromText(text));
}

}  // namespace ui
