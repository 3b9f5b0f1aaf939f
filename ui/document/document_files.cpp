#include "document_files.h"

#include "autosave.h"
#include "recent_files.h"
#include "scene_document.h"

#include "ui/dialogs/prompts.h"

#include "core/io/file_identity.h"
#include "core/io/scene_file.h"

#include <QAction>
#include <QActionGroup>
#include <QDir>
#include <QFileInfo>
#include <QLocale>
#include <QMenu>
#include <QMimeData>
#include <QSettings>
#include <QUndoStack>
#include <QUrl>

namespace ui {

namespace {

// how long the status bar shows what a file action did, ms
constexpr int kFileMessageMs = 5000;

// the choices of File › Autosave, s (0: off)
constexpr int kAutosaveChoices[] = {0, 30, 60, 120, 300, 600};

// the examples in the handout's order; any others found in the resources follow
constexpr const char *kExampleOrder[] = {"particles", "springs", "collisions", "pool", "pool-break", "cloth",
                                         "tearable-cloth", "stack", "heap",     "cloth-on-table", "stiff-cloth",
                                         "stiff-chain", "cloth-crumple", "cloth-over-post", "mesh-flag",
                                         "mesh-tablecloth", "mesh-soft-ball"};

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
        return DocumentFiles::tr("&Off");
    if (seconds % 60 == 0)
        return DocumentFiles::tr("Every %n minute(s)", nullptr, seconds / 60);
    return DocumentFiles::tr("Every %n second(s)", nullptr, seconds);
}

}  // namespace

DocumentFiles::DocumentFiles(SceneDocument &document, const Prompts &prompts, QObject *parent)
    : QObject(parent), m_document(document), m_prompts(prompts), m_recentFiles(new RecentFiles(this)),
      m_autosave(new Autosave(document, this))
{
    connect(m_autosave, &Autosave::failed, this, &DocumentFiles::warning);
}

void DocumentFiles::addRecentMenu(QMenu *file)
{
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
    connect(m_recentFiles, &RecentFiles::changed, this, &DocumentFiles::updateRecentMenu);
    connect(m_recentMenu, &QMenu::aboutToShow, this, &DocumentFiles::updateRecentMenu);
    updateRecentMenu();
}

void DocumentFiles::addExamplesMenu(QMenu *file)
{
    QMenu *examples = file->addMenu(tr("&Examples"));
    for (const QString &name : exampleNames()) {
        examples->addAction(name, this, [this, name] {
            QString error;
            if (maybeSave() && !openExample(name, &error))
                m_prompts.ask(QMessageBox::Warning, tr("Open example"), error);
        });
    }
}

void DocumentFiles::addAutosaveMenu(QMenu *file)
{
    // how often unsaved work goes to the recovery file
    m_autosaveMenu = file->addMenu(tr("A&utosave"));
    m_autosaveMenu->setObjectName(QStringLiteral("autosaveMenu"));
    m_autosaveGroup = new QActionGroup(this);
    for (int seconds : kAutosaveChoices) {
        QAction *choice = m_autosaveMenu->addAction(intervalText(seconds));
        choice->setObjectName(QStringLiteral("actionAutosave%1").arg(seconds));
        choice->setCheckable(true);
        choice->setData(seconds);
        choice->setStatusTip(tr("How often unsaved changes are written to a recovery file, offered back after a "
                                "crash"));
        m_autosaveGroup->addAction(choice);
        connect(choice, &QAction::triggered, this, [this, seconds] { setAutosaveInterval(seconds); });
    }
    // the interval the settings give is the one checked
    setAutosaveInterval(m_autosave->intervalSeconds());
}

core::SceneDesc DocumentFiles::newScene()
{
    // the default settings (gravity, a 10 ms step, symplectic Euler, collisions on) and the floor
    core::SceneDesc scene;
    scene.planes.push_back(core::PlaneDesc{});
    return scene;
}

bool DocumentFiles::newDocument()
{
    if (!maybeSave())
        return false;
    m_document.replace(newScene(), QString());
    emit statusMessage(tr("New scene"), kFileMessageMs);
    return true;
}

bool DocumentFiles::openScene(const QString &path, QString *error)
{
    io::LoadResult loaded = io::loadScene(path);
    if (!loaded.ok()) {
        if (error)
            *error = loaded.error;
        return false;
    }
    m_document.replace(std::move(*loaded.scene), QFileInfo(path).absoluteFilePath());
    m_recentFiles->add(path);
    if (!loaded.warnings.isEmpty())
        emit warning(loaded.warnings.join(QStringLiteral("; ")));
    return true;
}

bool DocumentFiles::openFile(const QString &path)
{
    if (!maybeSave())
        return false;
    QString error;
    if (!openScene(path, &error)) {
        m_prompts.ask(QMessageBox::Warning, tr("Open scene"), error);
        return false;
    }
    emit statusMessage(tr("Opened %1").arg(nativePath(path)), kFileMessageMs);
    return true;
}

bool DocumentFiles::openExample(const QString &name, QString *error)
{
    io::LoadResult loaded = io::loadScene(examplePath(name));
    if (!loaded.ok()) {
        if (error)
            *error = loaded.error.isEmpty() ? tr("no example named \"%1\"").arg(name) : loaded.error;
        return false;
    }
    // an example is not a file of the user's: saving asks where
    m_document.replace(std::move(*loaded.scene), QString());
    return true;
}

QStringList DocumentFiles::exampleNames()
{
    QStringList found = QDir(QStringLiteral(":/scenes")).entryList({QStringLiteral("*.json")}, QDir::Files, QDir::Name);
    for (QString &name : found)
        name.chop(5);  // ".json"
    QStringList ordered;
    for (const char *name : kExampleOrder)
        if (found.removeOne(QString::fromLatin1(name)))
            ordered << QString::fromLatin1(name);
    return ordered + found;
}

QString DocumentFiles::dialogFolder() const
{
    // the scene's own folder; for an example or a new scene, the folder of the file last opened
    // or saved (File › Open Recent's first), not the home folder every time
    if (!m_document.filePath().isEmpty())
        return m_document.folder();
    const QStringList recent = m_recentFiles->paths();
    if (!recent.isEmpty() && QFileInfo(QFileInfo(recent.first()).absolutePath()).isDir())
        return QFileInfo(recent.first()).absolutePath();
    return m_document.folder();
}

void DocumentFiles::openFromDialog()
{
    if (!maybeSave())
        return;
    const QString path = m_prompts.chooseFile(Prompts::FileDialogMode::Open, tr("Open scene"), dialogFolder());
    if (path.isEmpty())
        return;
    // the question about changes was asked already
    QString error;
    if (!openScene(path, &error))
        m_prompts.ask(QMessageBox::Warning, tr("Open scene"), error);
}

bool DocumentFiles::revert()
{
    const QString path = m_document.filePath();
    if (path.isEmpty())
        return false;
    if (m_document.isModified()) {
        const QMessageBox::StandardButton answer =
            m_prompts.ask(QMessageBox::Question, tr("Revert"),
                          tr("Throw away the changes to \"%1\" and reload %2 from disk? This cannot be undone.")
                              .arg(m_document.displayName(), nativePath(path)),
                          QMessageBox::Discard | QMessageBox::Cancel, QMessageBox::Cancel);
        if (answer != QMessageBox::Discard)
            return false;
    }
    // a file that no longer loads leaves the document as it is
    QString error;
    if (!openScene(path, &error)) {
        m_prompts.ask(QMessageBox::Warning, tr("Revert"), error);
        return false;
    }
    emit statusMessage(tr("Reverted to %1").arg(nativePath(path)), kFileMessageMs);
    return true;
}

bool DocumentFiles::save()
{
    if (m_document.filePath().isEmpty())
        return saveAs();
    QString error;
    if (!saveTo(m_document.filePath(), &error)) {
        m_prompts.ask(QMessageBox::Warning, tr("Save scene"), error);
        return false;
    }
    return true;
}

bool DocumentFiles::saveAs()
{
    const QString suggested = m_document.filePath().isEmpty()
                                  ? QDir(dialogFolder()).filePath(m_document.displayName() + QStringLiteral(".json"))
                                  : m_document.filePath();
    QString path = m_prompts.chooseFile(Prompts::FileDialogMode::Save, tr("Save scene"), suggested);
    if (path.isEmpty())
        return false;
    if (QFileInfo(path).suffix().isEmpty())
        path += QStringLiteral(".json");
    QString error;
    if (!saveTo(path, &error)) {
        m_prompts.ask(QMessageBox::Warning, tr("Save scene"), error);
        return false;
    }
    return true;
}

bool DocumentFiles::saveTo(const QString &path, QString *error)
{
    // autosave writes over its recovery files and removes them: a scene saved as one would be lost
    if (m_autosave->isRecoveryFile(path)) {
        if (error)
            *error = tr("%1: cannot save: it is an autosave recovery file, which Springlab writes over and removes; "
                        "choose another name")
                         .arg(nativePath(path));
        return false;
    }
    // atomic: io::saveScene writes through QSaveFile, so a failure leaves the old file whole
    const io::SaveResult saved = io::saveScene(path, m_document.scene());
    if (!saved.ok()) {
        if (error)
            *error = saved.error;
        return false;
    }
    m_document.markSaved(QFileInfo(path).absoluteFilePath());
    m_recentFiles->add(path);
    emit statusMessage(tr("Saved %1").arg(nativePath(path)), kFileMessageMs);
    return true;
}

bool DocumentFiles::maybeSave()
{
    if (!m_document.isModified())
        return true;
    const QMessageBox::StandardButton answer =
        m_prompts.ask(QMessageBox::Warning, tr("Unsaved changes"),
                      tr("The scene \"%1\" has changes that are not saved.").arg(m_document.displayName()),
                      QMessageBox::Save | QMessageBox::Discard | QMessageBox::Cancel, QMessageBox::Save);
    if (answer == QMessageBox::Save)
        return save();
    return answer == QMessageBox::Discard;
}

QString DocumentFiles::protectedFileAt(const QString &path) const
{
    if (io::sameFile(path, m_document.filePath()))
        return tr("it is the open scene's file, %1").arg(nativePath(m_document.filePath()));
    if (m_autosave->isRecoveryFile(path))
        return tr("it is an autosave recovery file, which Springlab writes over and removes");
    return QString();
}

void DocumentFiles::openRecent(const QString &path)
{
    // a file moved or deleted since: say so, and forget it
    if (!QFileInfo::exists(path)) {
        m_recentFiles->remove(path);
        m_prompts.ask(QMessageBox::Warning, tr("Open recent"),
                      tr("%1 no longer exists; it was removed from the recent files.").arg(nativePath(path)));
        return;
    }
    openFile(path);
}

void DocumentFiles::updateRecentMenu()
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

void DocumentFiles::setAutosaveInterval(int seconds)
{
    // a value set by hand in the settings that the menu does not list gets an entry of its own
    QAction *match = nullptr;
    for (QAction *choice : m_autosaveGroup->actions())
        if (choice->data().toInt() == seconds)
            match = choice;
    if (!match) {
        match = m_autosaveMenu->addAction(intervalText(seconds));
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

bool DocumentFiles::start(const QString &path, QString *error)
{
    // work a crash left behind comes first; the command line's file then waits for another time
    if (offerRecovery()) {
        if (!path.isEmpty())
            emit warning(tr("Recovered unsaved work; %1 was not opened").arg(nativePath(path)));
        return true;
    }
    if (path.isEmpty())
        return true;
    QString reason;
    if (openScene(path, &reason))
        return true;
    if (error)
        *error = reason;
    m_prompts.ask(QMessageBox::Warning, tr("Open scene"),
                  tr("Could not open the scene:\n%1\n\nThe %2 example is open instead.")
                      .arg(reason, QString::fromLatin1(kDefaultExample)));
    return false;
}

bool DocumentFiles::offerRecovery()
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
        m_prompts.ask(QMessageBox::Question, tr("Recover unsaved work"),
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
        m_prompts.ask(QMessageBox::Warning, tr("Recover unsaved work"),
                      tr("The recovery file cannot be read; it is kept at %1.\n\n%2")
                          .arg(nativePath(recovery.scenePath), loaded.error));
        return false;
    }
    // the recovered scene belongs to the user's file, and differs from it: modified until saved
    m_document.replace(std::move(*loaded.scene), recovery.sourcePath);
    m_document.undoStack()->resetClean();
    // this session's recovery file takes over before the old one goes
    QString error;
    if (!m_autosave->saveNow(&error))
        emit warning(error);
    else
        Autosave::removeRecovery(recovery);
    emit statusMessage(tr("Recovered unsaved changes to %1").arg(m_document.displayName()), kFileMessageMs);
    return true;
}

QString DocumentFiles::droppedScenePath(const QMimeData *mime)
{
    // exactly one local .json file
    if (!mime || !mime->hasUrls() || mime->urls().size() != 1)
        return QString();
    const QUrl url = mime->urls().front();
    if (!url.isLocalFile() || !url.toLocalFile().endsWith(QStringLiteral(".json"), Qt::CaseInsensitive))
        return QString();
    return url.toLocalFile();
}

}  // namespace ui
