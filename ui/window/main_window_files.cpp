// MainWindow's File menu and drops of scene files. What they do with the document's files (New,
// Open, Save, Revert, recent files, autosave and recovery) is DocumentFiles's
// (ui/document/document_files.h); File › Export is the Exporter's (ui/export/exporter.h).

#include "main_window.h"

#include "ui/document/document_files.h"
#include "ui/document/scene_document.h"
#include "ui/export/exporter.h"

#include <QAction>
#include <QDragEnterEvent>
#include <QDropEvent>
#include <QMenuBar>
#include <QTimer>

namespace ui {

namespace {

// the platform's keys for a standard action, or the common one where the platform has none (a
// bare X11 session has no Save As key, for one)
QList<QKeySequence> standardKeys(QKeySequence::StandardKey key, const QKeySequence &fallback)
{
    const QList<QKeySequence> keys = QKeySequence::keyBindings(key);
    return keys.isEmpty() ? QList<QKeySequence>{fallback} : keys;
}

}  // namespace

void MainWindow::createFileMenu()
{
    QMenu *file = m_fileMenu = menuBar()->addMenu(tr("&File"));
    QAction *newAction = file->addAction(tr("&New"), m_files, &DocumentFiles::newDocument);
    newAction->setObjectName(QStringLiteral("actionNew"));
    newAction->setShortcuts(standardKeys(QKeySequence::New, QKeySequence(Qt::CTRL | Qt::Key_N)));
    newAction->setStatusTip(tr("Start an empty scene: default settings and a ground plane at y = 0"));
    QAction *open = file->addAction(tr("&Open..."), m_files, &DocumentFiles::openFromDialog);
    open->setObjectName(QStringLiteral("actionOpen"));
    open->setShortcuts(standardKeys(QKeySequence::Open, QKeySequence(Qt::CTRL | Qt::Key_O)));
    open->setStatusTip(tr("Open a scene file (a .json file can also be dropped on the window)"));
    QAction *importMesh = file->addAction(tr("&Import Mesh..."), this, &MainWindow::showImportMesh);
    importMesh->setObjectName(QStringLiteral("actionImportMesh"));
    importMesh->setShortcut(QKeySequence(Qt::CTRL | Qt::Key_I));
    importMesh->setStatusTip(tr("Bring in a model (OBJ, PLY, STL, glTF, FBX, ...) as a cloth, a soft body or a collider"));
    m_files->addRecentMenu(file);
    m_files->addExamplesMenu(file);
    file->addSeparator();
    QAction *saveAction = file->addAction(tr("&Save"), m_files, &DocumentFiles::save);
    saveAction->setObjectName(QStringLiteral("actionSave"));
    saveAction->setShortcuts(standardKeys(QKeySequence::Save, QKeySequence(Qt::CTRL | Qt::Key_S)));
    QAction *saveAsAction = file->addAction(tr("Save &As..."), m_files, &DocumentFiles::saveAs);
    saveAsAction->setObjectName(QStringLiteral("actionSaveAs"));
    saveAsAction->setShortcuts(standardKeys(QKeySequence::SaveAs, QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_S)));
    m_revertAction = file->addAction(tr("Re&vert"), m_files, &DocumentFiles::revert);
    m_revertAction->setObjectName(QStringLiteral("actionRevert"));
    m_revertAction->setStatusTip(tr("Throw away the changes and reload the scene's file from disk"));
    m_files->addAutosaveMenu(file);
    file->addSeparator();
    QAction *screenshot = file->addAction(tr("Save Screensho&t"), this, [this] {
        QString error;
        if (saveScreenshot(&error).isEmpty())
            showWarning(error);
    });
    screenshot->setObjectName(QStringLiteral("actionScreenshot"));
    screenshot->setShortcut(Qt::Key_F2);
    screenshot->setStatusTip(tr("Save the 3D view as a PNG in the screenshot folder"));
    file->addAction(tr("Screenshot &Folder..."), this, &MainWindow::chooseScreenshotDirectory);
    m_exporter->addMenu(file);
    file->addSeparator();
    QAction *quit = file->addAction(tr("&Quit"), this, &QWidget::close);
    quit->setObjectName(QStringLiteral("actionQuit"));
    quit->setShortcuts(standardKeys(QKeySequence::Quit, QKeySequence(Qt::CTRL | Qt::Key_Q)));
    updateFileActions();
}

void MainWindow::updateFileActions()
{
    // only a document with a file of its own can go back to it
    m_revertAction->setEnabled(!m_document->filePath().isEmpty());
}

void MainWindow::dragEnterEvent(QDragEnterEvent *event)
{
    if (!DocumentFiles::droppedScenePath(event->mimeData()).isEmpty())
        event->acceptProposedAction();
}

void MainWindow::dragMoveEvent(QDragMoveEvent *event)
{
    if (!DocumentFiles::droppedScenePath(event->mimeData()).isEmpty())
        event->acceptProposedAction();
}

void MainWindow::dropEvent(QDropEvent *event)
{
    const QString path = DocumentFiles::droppedScenePath(event->mimeData());
    if (path.isEmpty())
        return;
    event->acceptProposedAction();
    // opened once the drop has finished: the unsaved-changes question must not run inside it
    QTimer::singleShot(0, m_files, [files = m_files, path] { files->openFile(path); });
}

}  // namespace ui
