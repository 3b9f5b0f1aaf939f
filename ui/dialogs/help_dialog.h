#pragma once
// HelpDialog (F1): every keyboard shortcut and mouse gesture. The shortcuts are read from the
// menus' actions when the dialog opens, so the list cannot fall out of date with the menus; the
// mouse gestures of the 3D view are listed here, next to the viewport's own keys.

#include <QDialog>

class QMenuBar;
class QTableWidget;

namespace ui {

class HelpDialog : public QDialog {
    Q_OBJECT

public:
    HelpDialog(const QMenuBar &menus, QWidget *parent = nullptr);

    // the table's rows as "keys\twhat they do", for the tests
    QStringList entries() const;

private:
    void addSection(const QString &title);
    void addEntry(const QString &keys, const QString &description);
    void addMenu(const QMenu &menu, const QString &path);

    QTableWidget *m_table = nullptr;
};

}  // namespace ui
