#pragma once
// The scene's undo and redo keys while a text field has the focus. A field (a spin box of the
// Parameters dock or the inspector, a line edit) takes Ctrl+Z for its own typing, so the scene's
// Ctrl+Z did nothing while one had the focus, which is most of the time after an edit. This filter
// lets the field keep the keys only while it has typing of its own to undo or redo; otherwise they
// reach the window's Undo and Redo actions.

#include <QObject>

class QAction;

namespace ui {

class FieldUndoKeys : public QObject {
    Q_OBJECT
public:
    // watches the key events of the fields inside `window`; undo and redo are its actions
    FieldUndoKeys(QWidget *window, QAction *undo, QAction *redo);

protected:
    bool eventFilter(QObject *watched, QEvent *event) override;

private:
    QWidget *m_window;
    QAction *m_undo;
    QAction *m_redo;
};

}  // namespace ui
