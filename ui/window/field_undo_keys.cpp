#include "field_undo_keys.h"

#include <QAbstractSpinBox>
#include <QAction>
#include <QApplication>
#include <QKeyEvent>
#include <QLineEdit>

namespace ui {

namespace {

// the line edit that holds a field's typing: the field itself, or a spin box's own
QLineEdit *typingOf(QObject *watched)
{
    if (auto *edit = qobject_cast<QLineEdit *>(watched))
        return edit;
    if (auto *spinBox = qobject_cast<QAbstractSpinBox *>(watched))
        return spinBox->findChild<QLineEdit *>();
    return nullptr;
}

bool matches(const QAction *action, const QKeyEvent *key)
{
    const QKeySequence pressed(key->keyCombination());
    for (const QKeySequence &shortcut : action->shortcuts())
        if (shortcut == pressed)
            return true;
    return false;
}

}  // namespace

FieldUndoKeys::FieldUndoKeys(QWidget *window, QAction *undo, QAction *redo)
    : QObject(window), m_window(window), m_undo(undo), m_redo(redo)
{
    qApp->installEventFilter(this);
}

bool FieldUndoKeys::eventFilter(QObject *watched, QEvent *event)
{
    if (event->type() != QEvent::ShortcutOverride)
        return false;
    auto *widget = qobject_cast<QWidget *>(watched);
    QLineEdit *typing = typingOf(watched);
    if (!widget || !typing || widget->window() != m_window)
        return false;
    const auto *key = static_cast<QKeyEvent *>(event);
    // not accepted and not delivered: the shortcut goes to the window's action
    if (matches(m_undo, key) && !typing->isUndoAvailable())
        return true;
    if (matches(m_redo, key) && !typing->isRedoAvailable())
        return true;
    return false;
}

}  // namespace ui
