#include "prompts.h"

#include <QCoreApplication>
#include <QFileDialog>

namespace ui {

QMessageBox::StandardButton Prompts::ask(QMessageBox::Icon icon, const QString &title, const QString &text,
                                         QMessageBox::StandardButtons buttons,
                                         QMessageBox::StandardButton defaultButton) const
{
    if (m_messageBox)
        return m_messageBox(icon, title, text, buttons, defaultButton);
    QMessageBox box(icon, title, text, buttons, m_parent);
    box.setDefaultButton(defaultButton);
    return static_cast<QMessageBox::StandardButton>(box.exec());
}

QString Prompts::chooseFile(FileDialogMode mode, const QString &title, const QString &suggestedPath,
                            const QString &filter) const
{
    if (m_fileDialog)
        return m_fileDialog(mode, title, suggestedPath);
    const QString files =
        filter.isEmpty() ? QCoreApplication::translate("ui::MainWindow", "Springlab scenes (*.json)") : filter;
    switch (mode) {
    case FileDialogMode::Open:
        return QFileDialog::getOpenFileName(m_parent, title, suggestedPath, files);
    case FileDialogMode::Save:
        return QFileDialog::getSaveFileName(m_parent, title, suggestedPath, files);
    case FileDialogMode::Folder:
        return QFileDialog::getExistingDirectory(m_parent, title, suggestedPath);
    }
    return {};
}

}  // namespace ui
