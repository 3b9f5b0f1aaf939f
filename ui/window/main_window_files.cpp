// MainWindow's files: the File menu (New, Open, Open Recent, Examples, Save, Save As, Revert,
// Autosave), drops of scene files, the unsaved-changes question, and autosave with recovery after
// a crash. Every message and file dialog goes through ask() and chooseFile(), which tests replace.

#include "main_window.h"

#include "ui/export/exporter.h"

#include "ui/document/autosave.h"
#include "ui/document/recent_files.h"
#include "ui/document/scene_document.h"

#include "core/io/scene_file.h"

#include <QAction>
#include <QActionGroup>
#include <QDir>
#include <QDragEnterEvent>
#include <QDropEvent>
#include <QFileDialog>
#include <QFileInfo>
#include <QLocale>
#include <QMenuBar>
#include <QMimeData>
#include <QSettings>
#include <QStatusBar>
#include <QTimer>
#include <QUndoStack>
#include <QUrl>

namespace ui {

namespace {

// how long the status bar shows what a file action did, ms
constexpr int kFileMessageMs = 5000;

// the choices of File › Autosave, s (0: off)
constexpr int kAutosaveChoices[] = {0, 30, 60, 120, 300, 600};

// the platform's keys for a standard action, or the common one where the platform has none (a
// bare X11 session has no Save As key, for one)
QList<QKeySequence> standardKeys(QKeySequence::StandardKey key, const QKeySequence &fallback)
{
    const QList<QKeySequence> keys = QKeySequence::keyBindings(key);
    return keys.isEmpty() ? QList<QKeySequence>{fallback} : keys;
}

QString examplePath(const QString &name)
{
    return QStringLiteral(":/scenes/%1.json").arg(name);
}

QString nativePath(const QString &path)
{
    return QDir::toNativeSeparators(path);
}

QString intervalText(int seconds)
{
    if (seconds == 0)
        return MainWindow::tr("&Off");
    if (seconds % 60 == 0)
        return MainWindow::tr("Every %n minute(s)", nullptr, seconds / 60);
    return MainWindow::tr("Every %n second(s)", nullptr, seconds);
}

}  // namespace

void MainWindow::createFileMenu()
{
    QMenu *file = m_fileMenu = menuBar()->addMenu(tr("&File"));
    QAction *newAction = file->addAction(tr("&New"), this, &MainWindow::newDocument);
    newAction->setObjectName(QStringLiteral("actionNew"));
    newAction->setShortcuts(standardKeys(QKeySequence::New, QKeySequence(Qt::CTRL | Qt::Key_N)));
    newAction->setStatusTip(tr("Start an empty scene: default settings and a ground plane at y = 0"));
    QAction *open = file->addAction(tr("&Open..."), this, &MainWindow::openFromDialog);
    open->setObjectName(QStringLiteral("actionOpen"));
    open->setShortcuts(standardKeys(QKeySequence::Open, QKeySequence(Qt::CTRL | Qt::Key_O)));
    open->setStatusTip(tr("Open a scene file (a .json file can also be dropped on the window)"));

    // recent files, rebuilt whenever the list changes (in this window or another)
    m_recentMenu = file->addMenu(tr("Open &Recent"));
    m_recentMenu->setObjectName(QStringLiteral("recentMenu"));
    for (int i = 0; i < RecentFiles::kMaximum; ++i) {
        QAction *entry = m_recentMenu->addAction(QString());
        entry->setObjectName(QStringLiteral("actionRecent%1").arg(i + 1));
        connect(entry, &QAction::triggered, this, [this, entry] { openRecent(entry->data().toString()); });
        m_recentActions << entry;
    }
    m_recentMenu->addSeparator();
    m_clearRecentAction = m_recentMenu->addAction(tr("&Clear Recent Files"), m_recentFiles, &RecentFiles::clear);
    m_clearRecentAction->setObjectName(QStringLiteral("actionClearRecent"));
    connect(m_recentFiles, &RecentFiles::changed, this, &MainWindow::updateRecentMenu);
    connect(m_recentMenu, &QMenu::aboutToShow, this, &MainWindow::updateRecentMenu);
    updateRecentMenu();

    QMenu *examples = file->addMenu(tr("&Examples"));
    for (const QString &name : exampleNames()) {
        examples->addAction(name, this, [this, name] {
            QString error;
            if (maybeSave() && !openExample(name, &error))
                ask(QMessageBox::Warning, tr("Open example"), error);
        });
    }
    file->addSeparator();
    QAction *saveAction = file->addAction(tr("&Save"), this, &MainWindow::save);
    saveAction->setObjectName(QStringLiteral("actionSave"));
    saveAction->setShortcuts(standardKeys(QKeySequence::Save, QKeySequence(Qt::CTRL | Qt::Key_S)));
    QAction *saveAsAction = file->addAction(tr("Save &As..."), this, &MainWindow::saveAs);
    saveAsAction->setObjectName(QStringLiteral("actionSaveAs"));
    saveAsAction->setShortcuts(standardKeys(QKeySequence::SaveAs, QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_S)));
    m_revertAction = file->addAction(tr("Re&vert"), this, &MainWindow::revert);
    m_revertAction->setObjectName(QStringLiteral("actionRevert"));
    m_revertAction->setStatusTip(tr("Throw away the changes and reload the scene's file from disk"));

    // how often unsaved work goes to the recovery file
    QMenu *autosave = file->addMenu(tr("A&utosave"));
    autosave->setObjectName(QStringLiteral("autosaveMenu"));
    m_autosaveGroup = new QActionGroup(this);
    for (int seconds : kAutosaveChoices) {
        QAction *choice = autosave->addAction(intervalText(seconds));
        choice->setObjectName(QStringLiteral("actionAutosave%1").arg(seconds));
        choice->setCheckable(true);
        choice->setData(seconds);
        choice->setStatusTip(tr("How often unsaved changes are written to a recovery file, offered back after a "
                                "crash"));
        m_autosaveGroup->addAction(choice);
        connect(choice, &QAction::triggered, this, [this, seconds] { setAutosaveInterval(seconds); });
    }
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
}

void MainWindow::createAutosave()
{
    m_autosave = new Autosave(*m_document, this);
    connect(m_autosave, &Autosave::failed, this, &MainWindow::showWarning);
    setAutosaveInterval(m_autosave->intervalSeconds());
    updateFileActions();
}

void MainWindow::setMessageBoxFunction(MessageBoxFunction function)
{
    m_prompts.setMessageBoxFunction(std::move(function));
}

void MainWindow::setFileDialogFunction(FileDialogFunction function)
{
    m_prompts.setFileDialogFunction(std::move(function));
}

QMessageBox::StandardButton MainWindow::ask(QMessageBox::Icon icon, const QString &title, const QString &text,
                                            QMessageBox::StandardButtons buttons,
                                            QMessageBox::StandardButton defaultButton)
{
    return m_prompts.ask(icon, title, text, buttons, defaultButton);
}

QString MainWindow::chooseFile(FileDialogMode mode, const QString &title, const QString &suggestedPath,
                               const QString &filter)
{
    return m_prompts.chooseFile(mode, title, suggestedPath, filter);
}

core::SceneDesc MainWindow::newScene()
{
    // the default settings (gravity, a 10 ms step, symplectic Euler, collisions on) and the floor
    core::SceneDesc scene;
    scene.planes.push_back(core::PlaneDesc{});
    return scene;
}

bool MainWindow::newDocument()
{
    if (!maybeSave())
        return false;
    m_document->replace(newScene(), QString());
    statusBar()->showMessage(tr("New scene"), kFileMessageMs);
    return true;
}

bool MainWindow::openScene(const QString &path, QString *error)
{
    io::LoadResult loaded = io::loadScene(path);
    if (!loaded.ok()) {
        if (error)
            *error = loaded.error;
        return false;
    }
    m_document->replace(std::move(*loaded.scene), QFileInfo(path).absoluteFilePath());
    m_recentFiles->add(path);
    if (!loaded.warnings.isEmpty())
        showWarning(loaded.warnings.join(QStringLiteral("; ")));
    return true;
}

bool MainWindow::openFile(const QString &path)
{
    if (!maybeSave())
        return false;
    QString error;
    if (!openScene(path, &error)) {
        ask(QMessageBox::Warning, tr("Open scene"), error);
        return false;
    }
    statusBar()->showMessage(tr("Opened %1").arg(nativePath(path)), kFileMessageMs);
    return true;
}

bool MainWindow::openExample(const QString &name, QString *error)
{
    io::LoadResult loaded = io::loadScene(examplePath(name));
    if (!loaded.ok()) {
        if (error)
            *error = loaded.error.isEmpty() ? tr("no example named \"%1\"").arg(name) : loaded.error;
        return false;
    }
    // an example is not a file of the user's: saving asks where
    m_document->replace(std::move(*loaded.scene), QString());
    return true;
}

void MainWindow::openFromDialog()
{
    if (!maybeSave())
        return;
    const QString directory = m_document->filePath().isEmpty() ? QDir::homePath()
                                                               : QFileInfo(m_document->filePath()).absolutePath();
    const QString path = chooseFile(FileDialogMode::Open, tr("Open scene"), directory);
    if (path.isEmpty())
        return;
    // the question about changes was asked already
    QString error;
    if (!openScene(path, &error))
        ask(QMessageBox::Warning, tr("Open scene"), error);
}

bool MainWindow::revert()
{
    const QString path = m_document->filePath();
    if (path.isEmpty())
        return false;
    if (m_document->isModified()) {
        const QMessageBox::StandardButton answer =
            ask(QMessageBox::Question, tr("Revert"),
                tr("Throw away the changes to \"%1\" and reload %2 from disk? This cannot be undone.")
                    .arg(m_document->displayName(), nativePath(path)),
                QMessageBox::Discard | QMessageBox::Cancel, QMessageBox::Cancel);
        if (answer != QMessageBox::Discard)
            return false;
    }
    // a file that no longer loads leaves the document as it is
    QString error;
    if (!openScene(path, &error)) {
        ask(QMessageBox::Warning, tr("Revert"), error);
        return false;
    }
    statusBar()->showMessage(tr("Reverted to %1").arg(nativePath(path)), kFileMessageMs);
    return true;
}

bool MainWindow::save()
{
    if (m_document->filePath().isEmpty())
        return saveAs();
    QString error;
    if (!saveTo(m_document->filePath(), &error)) {
        ask(QMessageBox::Warning, tr("Save scene"), error);
        return false;
    }
    return true;
}

bool MainWindow::saveAs()
{
    const QString suggested = m_document->filePath().isEmpty()
                                  ? QDir::home().filePath(m_document->displayName() + QStringLiteral(".json"))
                                  : m_document->filePath();
    QString path = chooseFile(FileDialogMode::Save, tr("Save scene"), suggested);
    if (path.isEmpty())
        return false;
    if (QFileInfo(path).suffix().isEmpty())
        path += QStringLiteral(".json");
    QString error;
    if (!saveTo(path, &error)) {
        ask(QMessageBox::Warning, tr("Save scene"), error);
        return false;
    }
    return true;
}

bool MainWindow::saveTo(const QString &path, QString *error)
{
    // atomic: io::saveScene writes through QSaveFile, so a failure leaves the old file whole
    const io::SaveResult saved = io::saveScene(path, m_document->scene());
    if (!saved.ok()) {
        if (error)
            *error = saved.error;
        return false;
    }
    m_document->markSaved(QFileInfo(path).absoluteFilePath());
    m_recentFiles->add(path);
    statusBar()->showMessage(tr("Saved %1").arg(nativePath(path)), kFileMessageMs);
    return true;
}

bool MainWindow::maybeSave()
{
    if (!m_document->isModified())
        return true;
    const QMessageBox::StandardButton answer =
        ask(QMessageBox::Warning, tr("Unsaved changes"),
            tr("The scene \"%1\" has changes that are not saved.").arg(m_document->displayName()),
            QMessageBox::Save | QMessageBox::Discard | QMessageBox::Cancel, QMessageBox::Save);
    if (answer == QMessageBox::Save)
        return save();
    return answer == QMessageBox::Discard;
}

void MainWindow::openRecent(const QString &path)
{
    // a file moved or deleted since: say so, and forget it
    if (!QFileInfo::exists(path)) {
        m_recentFiles->remove(path);
        ask(QMessageBox::Warning, tr("Open recent"),
            tr("%1 no longer exists; it was removed from the recent files.").arg(nativePath(path)));
        return;
    }
    openFile(path);
}

void MainWindow::updateRecentMenu()
{
    // the entries are reused, never deleted: this may run inside one of their own triggers
    const QStringList paths = m_recentFiles->paths();
    for (int i = 0; i < m_recentActions.size(); ++i) {
        QAction *entry = m_recentActions[i];
        const QString path = paths.value(i);
        entry->setVisible(i < paths.size());
        entry->setData(path);
        // &1 .. &9, then 1&0: each has a mnemonic
        const QString number = i < 9 ? QStringLiteral("&%1").arg(i + 1) : QStringLiteral("1&0");
        entry->setText(QStringLiteral("%1  %2").arg(number, QFileInfo(path).fileName()));
        entry->setStatusTip(nativePath(path));
        entry->setToolTip(nativePath(path));
    }
    m_clearRecentAction->setEnabled(!paths.isEmpty());
    m_recentMenu->setEnabled(!paths.isEmpty());
}

void MainWindow::updateFileActions()
{
    // only a document with a file of its own can go back to it
    if (m_revertAction)
        m_revertAction->setEnabled(!m_document->filePath().isEmpty());
}

void MainWindow::setAutosaveInterval(int seconds)
{
    // a value set by hand in the settings that the menu does not list gets an entry of its own
    QAction *match = nullptr;
    for (QAction *choice : m_autosaveGroup->actions())
        if (choice->data().toInt() == seconds)
            match = choice;
    if (!match) {
        auto *menu = m_fileMenu->findChild<QMenu *>(QStringLiteral("autosaveMenu"));
        match = menu->addAction(intervalText(seconds));
        match->setCheckable(true);
        match->setData(seconds);
        m_autosaveGroup->addAction(match);
        connect(match, &QAction::triggered, this, [this, seconds] { setAutosaveInterval(seconds); });
    }
    match->setChecked(true);
    if (seconds != m_autosave->intervalSeconds()) {
        m_autosave->setIntervalSeconds(seconds);
        QSettings().setValue(QStringLiteral("autosave/intervalSeconds"), seconds);
    }
}

bool MainWindow::start(const QString &path, QString *error)
{
    // work a crash left behind comes first; the command line's file then waits for another time
    if (offerRecovery()) {
        if (!path.isEmpty())
            showWarning(tr("Recovered unsaved work; %1 was not opened").arg(nativePath(path)));
        return true;
    }
    if (path.isEmpty())
        return true;
    QString reason;
    if (openScene(path, &reason))
        return true;
    if (error)
        *error = reason;
    ask(QMessageBox::Warning, tr("Open scene"),
        tr("Could not open the scene:\n%1\n\nThe %2 example is open instead.")
            .arg(reason, QString::fromLatin1(kDefaultExample)));
    return false;
}

bool MainWindow::offerRecovery()
{
    const QList<Autosave::Recovery> recoveries = Autosave::findRecoveries(m_autosave->directory());
    if (recoveries.isEmpty())
        return false;

    // the newest only; any others stay for the next start
    const Autosave::Recovery &recovery = recoveries.front();
    const QString what = recovery.sourcePath.isEmpty()
                             ? tr("an untitled scene")
                             : tr("\"%1\"").arg(nativePath(recovery.sourcePath));
    const QMessageBox::StandardButton answer =
        ask(QMessageBox::Question, tr("Recover unsaved work"),
            tr("Springlab did not close properly. Changes to %1, autosaved %2, were not saved.\n\n"
               "Recover them? No throws them away; Cancel keeps them for the next start.")
                .arg(what, QLocale().toString(recovery.saved, QLocale::ShortFormat)),
            QMessageBox::Yes | QMessageBox::No | QMessageBox::Cancel, QMessageBox::Yes);
    if (answer == QMessageBox::No)
        Autosave::removeRecovery(recovery);
    if (answer != QMessageBox::Yes)
        return false;

    io::LoadResult loaded = io::loadScene(recovery.scenePath);
    if (!loaded.ok()) {
        ask(QMessageBox::Warning, tr("Recover unsaved work"),
            tr("The recovery file cannot be read; it is kept at %1.\n\n%2")
                .arg(nativePath(recovery.scenePath), loaded.error));
        return false;
    }
    // the recovered scene belongs to the user's file, and differs from it: modified until saved
    m_document->replace(std::move(*loaded.scene), recovery.sourcePath);
    m_document->undoStack()->resetClean();
    // this session's recovery file takes over before the old one goes
    QString error;
    if (!m_autosave->saveNow(&error))
        showWarning(error);
    else
        Autosave::removeRecovery(recovery);
    statusBar()->showMessage(tr("Recovered unsaved changes to %1").arg(m_document->displayName()), kFileMessageMs);
    return true;
}

QString MainWindow::droppedScenePath(const QMimeData *mime)
{
    // exactly one local .json file
    if (!mime || !mime->hasUrls() || mime->urls().size() != 1)
        return QString();
    const QUrl url = mime->urls().front();
    if (!url.isLocalFile() || !url.toLocalFile().endsWith(QStringLiteral(".json"), Qt::CaseInsensitive))
        return QString();
    return url.toLocalFile();
}

void MainWindow::dragEnterEvent(QDragEnterEvent *event)
{
    if (!droppedScenePath(event->mimeData()).isEmpty())
        event->acceptProposedAction();
}

void MainWindow::dragMoveEvent(QDragMoveEvent *event)
{
    if (!droppedScenePath(event->mimeData()).isEmpty())
        event->acceptProposedAction();
}

void MainWindow::dropEvent(QDropEvent *event)
{
    const QString path = droppedScenePath(event->mimeData());
    if (path.isEmpty())
        return;
    event->acceptProposedAction();
    // opened once the drop has finished: the unsaved-changes question must not run inside it
    QTimer::singleShot(0, this, [this, path] { openFile(path); });
}

}  // namespace ui
