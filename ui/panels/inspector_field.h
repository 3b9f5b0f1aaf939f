#pragma once
// InspectorSpinBox: one value in the inspector. It is the parameters panel's ValueSpinBox (any
// number can be typed so that a bad one is refused with a message rather than clamped; arrows step
// along the parameter's scale) with what the inspector adds: it can show "mixed" when the selected
// items differ, and it tells a typed value (one undo step each) from an arrow or wheel step (steps
// on one field merge into one undo step). It never edits anything itself; the inspector listens.

#include "value_spin_box.h"

#include "core/model/parameters.h"

namespace ui {

class InspectorSpinBox : public ValueSpinBox {
    Q_OBJECT

public:
    explicit InspectorSpinBox(core::Parameter parameter, QWidget *parent = nullptr);

    core::Parameter parameter() const { return m_parameter; }

    // shows a value without emitting anything
    void showValue(double value);
    // shows an empty field with the placeholder "mixed"; arrow steps start from `start`
    void showMixed(double start);
    bool isMixed() const { return m_mixed; }

    QString textFromValue(double value) const override;
    void stepBy(int steps) override;

signals:
    // the user typed a number and pressed Enter or left the field (the number may be out of
    // range or NaN: checking it is the inspector's job)
    void typed(double value);
    // an arrow key, arrow button or wheel step changed the value
    void stepped(double value);

private:
    void finishTyping();

    core::Parameter m_parameter;
    bool m_mixed = false;
    bool m_stepping = false;
    bool m_typing = false;  // the user edited the text since the field last showed a value
    QString m_typedText;
};

}  // namespace ui
