#include "inspector_field.h"

#include <QLineEdit>
#include <QSignalBlocker>

namespace ui {

InspectorSpinBox::InspectorSpinBox(core::Parameter parameter, QWidget *parent)
    : ValueSpinBox(sliderScale(core::parameterInfo(parameter)), parent), m_parameter(parameter)
{
    setMinimumWidth(70);
    lineEdit()->setPlaceholderText(tr("mixed"));
    // "nan", "inf" and "-inf" can be typed too, so that they are refused with a message rather
    // than swallowed by the validator without a word
    setNonFiniteTypable(true);

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
