#pragma once
// Prompts: every question, message and file dialog the editor shows goes through one object, so
// that the tests can answer them without a modal dialog. By default a QMessageBox and a
// QFileDialog over the parent window; the tests set functions that answer instead.

#include <QMessageBox>
#include <QString>
#include <functional>

class QWidget;

namespace ui {

class Prompts {
public:
    using MessageBoxFunction =
        std::function<QMessageBox::StandardButton(QMessageBox::Icon icon, const QString &title, const QString &text,
                                                  QMessageBox::StandardButtons buttons,
                                                  QMessageBox::StandardButton defaultButton)>;
    enum class FileDialogMode { Open, Save, Folder };
    // returns the chosen path (a folder's for Folder), or an empty string when cancelled
    using FileDialogFunction =
        std::function<QString(FileDialogMode mode, const QString &title, const QString &suggestedPath)>;

    explicit Prompts(QWidget *parent) : m_parent(parent) {}

    void setMessageBoxFunction(MessageBoxFunction function) { m_messageBox = std::move(function); }
    void setFileDialogFunction(FileDialogFunction function) { m_fileDialog = std::move(function); }

    QMessageBox::StandardButton ask(QMessageBox::Icon icon, const QString &title, const QString &text,
                                    QMessageBox::StandardButtons buttons = QMessageBox::Ok,
                                    QMessageBox::StandardButton defaultButton = QMessageBox::NoButton) const;
    // filter: the file dialog's, by default the scene files
    QString chooseFile(FileDialogMode mode, const QString &title, const QString &suggestedPath,
                       const QString &filter = QString()) const;

private:
    QWidget *m_parent;
    MessageBoxFunction m_messageBox;
    FileDialogFunction m_fileDialog;
};

}  // namespace ui
