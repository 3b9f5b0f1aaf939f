#pragma once
// What the editor's UI tests share: F1's help, read. The dialog is modal, so its entries are read
// from inside its own event loop, and then it is closed.

#include "ui/dialogs/help_dialog.h"

#include <QApplication>
#include <QStringList>
#include <QTimer>
#include <QtTest>
#include <optional>

namespace test {

// presses F1 on window; the help's entries, or nullopt when no help dialog opened
inline std::optional<QStringList> helpEntries(QWidget *window)
{
    std::optional<QStringList> entries;
    QTimer::singleShot(0, window, [&entries] {
        if (auto *help = qobject_cast<ui::HelpDialog *>(QApplication::activeModalWidget())) {
            entries = help->entries();
            help->reject();
        }
    });
    QTest::keyClick(window, Qt::Key_F1);
    return entries;
}

}  // namespace test
