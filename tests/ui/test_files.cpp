// The editor's files, through the real menus and events under a virtual X server: New gives the
// empty scene with a fresh undo history; Save As then Open gives back the same scene; the recent
// files keep order, stop at ten and forget a missing file; Revert reloads the file; a corrupt
// file leaves the document as it was; the unsaved-changes question guards New, Open, close and
// drops; autosave writes a recovery file and a later start recovers it; a dropped file and the
// command line's file open; "Use current state as initial" makes F5 return to the captured state
// and undoes back; no save writes over the scene's file or a recovery file under another name. Questions are answered by a function, never a modal dialog; waits are on
// frames or files, never fixed sleeps.

#include "tests/test_files.h"
#include "ui/document/autosave.h"
#include "ui/dialogs/help_dialog.h"
#include "ui/document/document_files.h"
#include "ui/window/main_window.h"
#include "ui/document/recent_files.h"
#include "ui/document/scene_commands.h"
#include "ui/document/scene_document.h"
#include "ui/panels/plots_widget.h"
#include "session/session_file.h"
#include "ui/simulation/simulation_controller.h"
#include "ui/viewport/viewport.h"

#include "core/io/scene_file.h"

#include <QDockWidget>
#include <QDropEvent>
#include <QMenu>
#include <QMenuBar>
#include <QMimeData>
#include <QSettings>
#include <QUndoStack>
#include <QUndoView>
#include <QUrl>
#include <QtTest>

#include "editor_fixture.h"

#include <csignal>
#include <linux/capability.h>
#include <sys/resource.h>
#include <sys/syscall.h>
#include <unistd.h>

namespace {

using test::readAll;

using test::settledFrame;

bool writeFile(const QString &path, const QByteArray &bytes)
{
    QFile file(path);
    return file.open(QIODevice::WriteOnly) && file.write(bytes) == bytes.size();
}

// a question asked of the user, as the window put it
struct Question {
    QMessageBox::Icon icon;
    QString title;
    QString text;
    QMessageBox::StandardButtons buttons;
};

// While it lives, the calling thread's effective capabilities lack the two that let root ignore
// permission bits (CI runs the tests as root), so a read-only folder binds it as it binds a user.
// Capabilities are per thread on Linux; saving happens on this (the GUI) thread.
class WithoutPermissionOverride {
public:
    WithoutPermissionOverride()
    {
        if (syscall(SYS_capget, &m_header, m_saved) != 0)
            return;
        __user_cap_data_struct reduced[2] = {m_saved[0], m_saved[1]};
        reduced[0].effective &= ~((1u << CAP_DAC_OVERRIDE) | (1u << CAP_DAC_READ_SEARCH));
        m_changed = syscall(SYS_capset, &m_header, reduced) == 0;
    }
    ~WithoutPermissionOverride()
    {
        if (m_changed)
            syscall(SYS_capset, &m_header, m_saved);
    }
    WithoutPermissionOverride(const WithoutPermissionOverride &) = delete;
    WithoutPermissionOverride &operator=(const WithoutPermissionOverride &) = delete;

private:
    __user_cap_header_struct m_header{_LINUX_CAPABILITY_VERSION_3, 0};
    __user_cap_data_struct m_saved[2]{};
    bool m_changed = false;
};

// While it lives, no file this process writes may grow past `bytes`: a write beyond fails with
// EFBIG, as one fails with ENOSPC on a full disk (making a real full disk needs a mount, which the
// tests cannot count on). SIGXFSZ, which would otherwise kill the process, is ignored meanwhile.
class FileSizeLimit {
public:
    explicit FileSizeLimit(rlim_t bytes)
    {
        m_oldHandler = std::signal(SIGXFSZ, SIG_IGN);
        m_set = getrlimit(RLIMIT_FSIZE, &m_saved) == 0;
        rlimit limit = m_saved;
        limit.rlim_cur = bytes;
        m_set = m_set && setrlimit(RLIMIT_FSIZE, &limit) == 0;
    }
    ~FileSizeLimit()
    {
        if (m_set)
            setrlimit(RLIMIT_FSIZE, &m_saved);
        std::signal(SIGXFSZ, m_oldHandler);
    }
    FileSizeLimit(const FileSizeLimit &) = delete;
    FileSizeLimit &operator=(const FileSizeLimit &) = delete;
    bool active() const { return m_set; }

private:
    rlimit m_saved{};
    bool m_set = false;
    void (*m_oldHandler)(int) = SIG_DFL;
};

}  // namespace

class TestFiles : public test::EditorTest {
    Q_OBJECT

private slots:
    void initTestCase();
    void init();
    void cleanup();

    void newGivesAnEmptySceneAndClearsTheUndoHistory();
    void saveAsThenOpenGivesTheSameScene();
    void recentFilesKeepOrderStopAtTenAndForgetMissingOnes();
    void revertReloadsTheSavedFile();
    void corruptFileShowsTheErrorAndKeepsTheDocument();
    void saveIntoAReadOnlyFolderFailsAndKeepsTheChanges();
    void saveOntoAFullDiskFailsAndKeepsTheOldFile_data();
    void saveOntoAFullDiskFailsAndKeepsTheOldFile();
    void unsavedChangesAreAskedAbout();
    void autosaveWritesARecoveryFileAndRemovesIt();
    void autosaveIsConfigured();
    void nextStartRecoversACrashedSession();
    void droppedSceneFileOpens();
    void commandLineFileOpens();
    void openStartsInTheFolderLastUsed();
    void useCurrentStateAsInitialThenResetAndUndo();
    void undoHistoryAndRedoKeys();
    void helpListsTheFileKeys();
    void recordedSessionReplaysToTheSameBits();
    void saveNeverWritesOverARecoveryFile();
    void autosaveNeverWritesOverTheScenesFile();
    void plotsAndRecordingsNeverWriteOverTheScene();

private:
    ui::SceneDocument &document() { return *m_window->document(); }
    QAction *action(const char *name) const
    {
        auto *found = m_window->findChild<QAction *>(QString::fromLatin1(name));
        if (!found)
            qWarning("no action named %s", name);
        return found;
    }
    void press(Qt::Key key, Qt::KeyboardModifiers modifiers = Qt::NoModifier)
    {
        QTest::keyClick(m_window, key, modifiers);
    }
    // a new window, left hidden, with the tests' answers: what the next start of the editor finds
    void restart() { QVERIFY2(openEditor(answered(false)), qPrintable(editorFailure())); }
    test::EditorOptions answered(bool show);
    // one step of undo: more viscosity (never merged with the one before)
    void edit()
    {
        core::Settings settings = document().scene().settings;
        settings.viscosity += 0.25;
        document().undoStack()->push(new ui::SettingsCommand(document(), QStringLiteral("viscosity"), {}, settings));
    }
    QString savedFile(const QString &name, const core::SceneDesc &scene);

    QString m_recoveryDirectory;

    // the answers the tests give, and what was asked
    QMessageBox::StandardButton m_answer = QMessageBox::Cancel;
    QList<Question> m_questions;
    QString m_chosenPath;
    QList<ui::MainWindow::FileDialogMode> m_dialogs;
    QStringList m_dialogStarts;  // the path each file dialog started at
};

void TestFiles::initTestCase()
{
    // settings and recovery files go to throwaway folders, never the user's
    QVERIFY(foldersReady());
    m_recoveryDirectory = m_files.filePath(QStringLiteral("recovery"));
}

test::EditorOptions TestFiles::answered(bool show)
{
    const auto answerHere = [this](ui::MainWindow &window) {
        window.setMessageBoxFunction([this](QMessageBox::Icon icon, const QString &title, const QString &text,
                                            QMessageBox::StandardButtons buttons, QMessageBox::StandardButton) {
            m_questions << Question{icon, title, text, buttons};
            return buttons.testFlag(m_answer) ? m_answer : QMessageBox::Ok;
        });
        window.setFileDialogFunction([this](ui::MainWindow::FileDialogMode mode, const QString &, const QString &start) {
            m_dialogs << mode;
            m_dialogStarts << start;
            return m_chosenPath;
        });
    };
    return {.setup = answerHere, .show = show};
}

void TestFiles::init()
{
    // every test starts from no settings: no recent files, no saved docks, autosave off
    QSettings().clear();
    setAutosave(m_recoveryDirectory, 0);
    QDir(m_recoveryDirectory).removeRecursively();
    m_answer = QMessageBox::Cancel;
    m_questions.clear();
    m_chosenPath.clear();
    m_dialogs.clear();
    m_dialogStarts.clear();

    // shortcuts need an active window
    QVERIFY2(openEditor(answered(true)), qPrintable(editorFailure()));
}

void TestFiles::cleanup()
{
    closeEditor();
}

QString TestFiles::savedFile(const QString &name, const core::SceneDesc &scene)
{
    const QString path = m_files.filePath(name);
    const io::SaveResult saved = io::saveScene(path, scene);
    if (!saved.ok())
        qWarning("%s", qPrintable(saved.error));
    return path;
}

void TestFiles::newGivesAnEmptySceneAndClearsTheUndoHistory()
{
    edit();
    QCOMPARE(document().undoStack()->count(), 1);
    QVERIFY(m_window->isWindowModified());

    // Ctrl+N asks about the change; Discard lets the new scene in
    m_answer = QMessageBox::Discard;
    press(Qt::Key_N, Qt::ControlModifier);
    QCOMPARE(m_questions.size(), 1);
    QVERIFY(m_questions.front().text.contains(QStringLiteral("springs")));

    // no particles, the default settings, the ground plane, no file, nothing to undo
    const core::SceneDesc &scene = document().scene();
    QVERIFY(scene.particles.empty());
    QVERIFY(scene.springs.empty());
    QVERIFY(scene.settings == core::Settings{});
    QCOMPARE(scene.planes.size(), std::size_t(1));
    QVERIFY(scene.planes.front().normal == Eigen::Vector3d(0.0, 1.0, 0.0));
    QCOMPARE(scene.planes.front().offset, 0.0);
    QVERIFY(scene == ui::DocumentFiles::newScene());
    QCOMPARE(document().undoStack()->count(), 0);
    QVERIFY(!m_window->isWindowModified());
    QVERIFY(document().filePath().isEmpty());
    QVERIFY(m_window->windowTitle().startsWith(QStringLiteral("untitled")));
    QVERIFY(!action("actionRevert")->isEnabled());

    // the worker runs the empty scene
    const auto frame = settledFrame(controller());
    QCOMPARE(frame->snapshot->particleCount(), 0);
    QVERIFY(frame->scene == document().sharedScene());
}

void TestFiles::saveAsThenOpenGivesTheSameScene()
{
    QString error;
    QVERIFY2(m_window->files()->openExample(QStringLiteral("particles"), &error), qPrintable(error));
    edit();
    const core::SceneDesc edited = document().scene();

    // Save As, given a name without a suffix: ".json" is added, and the window is clean
    m_chosenPath = m_files.filePath(QStringLiteral("round-trip"));
    action("actionSaveAs")->trigger();
    QCOMPARE(m_dialogs, QList<ui::MainWindow::FileDialogMode>{ui::MainWindow::FileDialogMode::Save});
    const QString path = m_chosenPath + QStringLiteral(".json");
    QVERIFY(QFileInfo::exists(path));
    QCOMPARE(document().filePath(), QFileInfo(path).absoluteFilePath());
    QVERIFY(!m_window->isWindowModified());

    // New, then Open through the menu: the same scene, bit for bit
    action("actionNew")->trigger();
    QVERIFY(document().scene().particles.empty());
    m_chosenPath = path;
    action("actionOpen")->trigger();
    QVERIFY(m_questions.isEmpty());
    QVERIFY(document().scene() == edited);
    QCOMPARE(document().scene().settings.viscosity, 0.25);
    QCOMPARE(document().filePath(), QFileInfo(path).absoluteFilePath());
    QVERIFY(!m_window->isWindowModified());

    // Ctrl+S after another edit writes that file again
    edit();
    press(Qt::Key_S, Qt::ControlModifier);
    QVERIFY(!m_window->isWindowModified());
    const io::LoadResult reloaded = io::loadScene(path);
    QVERIFY2(reloaded.ok(), qPrintable(reloaded.error));
    QCOMPARE(reloaded.scene->settings.viscosity, 0.5);
}

void TestFiles::recentFilesKeepOrderStopAtTenAndForgetMissingOnes()
{
    ui::RecentFiles *recent = m_window->files()->recentFiles();
    QVERIFY(recent->paths().isEmpty());
    QVERIFY(!m_window->findChild<QMenu *>(QStringLiteral("recentMenu"))->isEnabled());

    // twelve files saved: the last ten, newest first
    QStringList paths;
    for (int i = 0; i < 12; ++i) {
        paths << QFileInfo(m_files.filePath(QStringLiteral("recent-%1.json").arg(i))).absoluteFilePath();
        QString error;
        QVERIFY2(m_window->files()->saveTo(paths.back(), &error), qPrintable(error));
    }
    QStringList expected;
    for (int i = 11; i >= 2; --i)
        expected << paths[i];
    QCOMPARE(recent->paths(), expected);

    // the menu lists them in that order; opening one moves it to the top
    QMenu *menu = m_window->findChild<QMenu *>(QStringLiteral("recentMenu"));
    QVERIFY(menu->isEnabled());
    QCOMPARE(action("actionRecent1")->data().toString(), paths[11]);
    QCOMPARE(action("actionRecent10")->data().toString(), paths[2]);
    QVERIFY(!m_window->findChild<QAction *>(QStringLiteral("actionRecent11")));
    action("actionRecent4")->trigger();
    QCOMPARE(document().filePath(), paths[8]);
    QCOMPARE(recent->paths().front(), paths[8]);
    QCOMPARE(recent->paths().size(), 10);

    // a file deleted since: a message names it, and it is gone from the list; the document stays
    QVERIFY(QFile::remove(paths[5]));
    const auto before = document().sharedScene();
    QAction *missing = nullptr;
    for (QAction *entry : menu->actions())
        if (entry->data().toString() == paths[5])
            missing = entry;
    QVERIFY(missing);
    missing->trigger();
    QCOMPARE(m_questions.size(), 1);
    QVERIFY2(m_questions.front().text.contains(QStringLiteral("recent-5.json")), qPrintable(m_questions.front().text));
    QVERIFY(m_questions.front().text.contains(QStringLiteral("no longer exists")));
    QVERIFY(!recent->paths().contains(paths[5]));
    QCOMPARE(recent->paths().size(), 9);
    QVERIFY(document().sharedScene() == before);

    // the list outlives the window, through the settings
    restart();
    QCOMPARE(m_window->files()->recentFiles()->paths().size(), 9);
    QCOMPARE(m_window->files()->recentFiles()->paths().front(), paths[8]);

    // Clear empties it
    action("actionClearRecent")->trigger();
    QVERIFY(m_window->files()->recentFiles()->paths().isEmpty());
    QVERIFY(!m_window->findChild<QMenu *>(QStringLiteral("recentMenu"))->isEnabled());
}

void TestFiles::revertReloadsTheSavedFile()
{
    // an example has no file: nothing to revert to
    QVERIFY(!action("actionRevert")->isEnabled());
    QVERIFY(!m_window->files()->revert());

    const QString path = m_files.filePath(QStringLiteral("revert.json"));
    QString error;
    QVERIFY2(m_window->files()->saveTo(path, &error), qPrintable(error));
    QVERIFY(action("actionRevert")->isEnabled());
    const core::SceneDesc saved = document().scene();
    edit();
    edit();
    edit();
    QVERIFY(!(document().scene() == saved));

    // Cancel keeps the changes
    m_answer = QMessageBox::Cancel;
    action("actionRevert")->trigger();
    QCOMPARE(m_questions.size(), 1);
    QCOMPARE(m_questions.front().icon, QMessageBox::Question);
    QVERIFY(m_window->isWindowModified());
    QCOMPARE(document().undoStack()->count(), 3);

    // Discard reloads the file: its scene, clean, with nothing to undo, in the worker too
    m_answer = QMessageBox::Discard;
    action("actionRevert")->trigger();
    QVERIFY(document().scene() == saved);
    QVERIFY(!m_window->isWindowModified());
    QCOMPARE(document().undoStack()->count(), 0);
    QVERIFY(settledFrame(controller())->scene == document().sharedScene());
}

void TestFiles::corruptFileShowsTheErrorAndKeepsTheDocument()
{
    edit();
    const auto before = document().sharedScene();
    const QString path = m_files.filePath(QStringLiteral("corrupt.json"));
    QVERIFY(writeFile(path, "{ \"format\": \"springlab-scene\", \"version\": 1, \"particles\": [ {"));

    // Open: Discard the changes, then the load fails with the loader's message
    m_answer = QMessageBox::Discard;
    m_chosenPath = path;
    action("actionOpen")->trigger();
    QCOMPARE(m_questions.size(), 2);
    QCOMPARE(m_questions.back().icon, QMessageBox::Warning);
    QVERIFY2(m_questions.back().text.contains(QStringLiteral("corrupt.json")), qPrintable(m_questions.back().text));

    // exactly as it was: the same scene, still modified, the same undo history
    QVERIFY(document().sharedScene() == before);
    QVERIFY(m_window->isWindowModified());
    QCOMPARE(document().undoStack()->count(), 1);
    QVERIFY(document().filePath().isEmpty());
    QVERIFY(!m_window->files()->recentFiles()->paths().contains(QFileInfo(path).absoluteFilePath()));
}

void TestFiles::saveIntoAReadOnlyFolderFailsAndKeepsTheChanges()
{
    // a scene saved in a folder that then becomes read-only, and changed
    const QString folder = m_files.filePath(QStringLiteral("read-only"));
    QVERIFY(QDir().mkpath(folder));
    const QString path = QDir(folder).filePath(QStringLiteral("scene.json"));
    QString error;
    QVERIFY2(m_window->files()->saveTo(path, &error), qPrintable(error));
    const QByteArray before = readAll(path);
    edit();
    QVERIFY(QFile::setPermissions(folder, QFileDevice::ReadOwner | QFileDevice::ExeOwner));
    {
        const WithoutPermissionOverride asAUser;
        // the folder really is closed to this thread now, root or not
        QFile probe(QDir(folder).filePath(QStringLiteral("probe")));
        QVERIFY2(!probe.open(QIODevice::WriteOnly), "the read-only folder still takes new files");

        // Ctrl+S: the error is shown, naming the file and why; the changes stay unsaved
        m_questions.clear();
        press(Qt::Key_S, Qt::ControlModifier);
    }
    QVERIFY(QFile::setPermissions(folder, QFileDevice::ReadOwner | QFileDevice::WriteOwner | QFileDevice::ExeOwner));
    QCOMPARE(m_questions.size(), 1);
    QCOMPARE(m_questions.front().icon, QMessageBox::Warning);
    const QString &message = m_questions.front().text;
    QVERIFY2(message.contains(QDir::toNativeSeparators(path)) && message.contains(QStringLiteral("cannot save")) &&
                 message.contains(QStringLiteral("ermission denied")),
             qPrintable(message));
    QVERIFY(document().isModified());
    QVERIFY(m_window->isWindowModified());
    QCOMPARE(readAll(path), before);
    QCOMPARE(QDir(folder).entryList(QDir::Files), QStringList{QStringLiteral("scene.json")});

    // with the folder writable again, the same Ctrl+S saves
    press(Qt::Key_S, Qt::ControlModifier);
    QCOMPARE(m_questions.size(), 1);
    QVERIFY(!document().isModified());
    QVERIFY(readAll(path) != before);
}

void TestFiles::saveOntoAFullDiskFailsAndKeepsTheOldFile_data()
{
    QTest::addColumn<QString>("example");
    QTest::addColumn<int>("limit");  // bytes no file may grow past
    // a scene over Qt's 16 KiB write buffer fails as it is written; one under it fails only when
    // the buffer is flushed, which QSaveFile::commit() of Qt 6.4 did not report
    QTest::newRow("large scene") << QStringLiteral("cloth") << 4096;
    QTest::newRow("small scene") << QStringLiteral("pool") << 512;
}

void TestFiles::saveOntoAFullDiskFailsAndKeepsTheOldFile()
{
    QFETCH(QString, example);
    QFETCH(int, limit);

    // a scene saved, then changed; the disk then fills: no file may grow past the limit
    QString error;
    QVERIFY2(m_window->files()->openExample(example, &error), qPrintable(error));
    const QString path = m_files.filePath(QStringLiteral("full.json"));
    QVERIFY2(m_window->files()->saveTo(path, &error), qPrintable(error));
    const QByteArray before = readAll(path);
    QVERIFY(before.size() > limit);
    edit();
    m_questions.clear();
    {
        const FileSizeLimit full(static_cast<rlim_t>(limit));
        QVERIFY(full.active());
        press(Qt::Key_S, Qt::ControlModifier);
    }
    QCOMPARE(m_questions.size(), 1);
    QCOMPARE(m_questions.front().icon, QMessageBox::Warning);
    const QString &message = m_questions.front().text;
    QVERIFY2(message.contains(QDir::toNativeSeparators(path)) && message.contains(QStringLiteral("cannot save")),
             qPrintable(message));
    QVERIFY(document().isModified());
    QCOMPARE(readAll(path), before);  // the old file, whole
    const QStringList left = QDir(m_files.path()).entryList({QStringLiteral("full.json*")}, QDir::Files);
    QCOMPARE(left, QStringList{QStringLiteral("full.json")});  // and no half-written temporary beside it
}

void TestFiles::unsavedChangesAreAskedAbout()
{
    // a clean document is never asked about
    QVERIFY(m_window->files()->newDocument());
    QVERIFY(m_questions.isEmpty());
    edit();
    QVERIFY(m_window->isWindowModified());

    // close: Cancel keeps the window and the changes
    m_answer = QMessageBox::Cancel;
    QVERIFY(!m_window->close());
    QVERIFY(m_window->isVisible());
    QCOMPARE(m_questions.size(), 1);
    QCOMPARE(m_questions.front().buttons, QMessageBox::Save | QMessageBox::Discard | QMessageBox::Cancel);
    QVERIFY(!controller().isShutDown());

    // New: Save on an untitled scene asks where; cancelling that cancels the New
    m_answer = QMessageBox::Save;
    m_chosenPath.clear();
    QVERIFY(!m_window->files()->newDocument());
    QCOMPARE(m_dialogs.size(), 1);
    QVERIFY(m_window->isWindowModified());
    QCOMPARE(document().undoStack()->count(), 1);

    // Save with a place to save to: written, then the new scene
    const core::SceneDesc edited = document().scene();
    m_chosenPath = m_files.filePath(QStringLiteral("asked.json"));
    QVERIFY(m_window->files()->newDocument());
    const io::LoadResult written = io::loadScene(m_chosenPath);
    QVERIFY2(written.ok(), qPrintable(written.error));
    QVERIFY(*written.scene == edited);
    QVERIFY(document().scene().particles.empty());

    // close: Discard lets it close and ends the worker
    edit();
    m_answer = QMessageBox::Discard;
    QVERIFY(m_window->close());
    QVERIFY(controller().isShutDown());
}

void TestFiles::autosaveWritesARecoveryFileAndRemovesIt()
{
    ui::Autosave *autosave = m_window->files()->autosave();
    QCOMPARE(autosave->directory(), m_recoveryDirectory);
    autosave->setIntervalSeconds(1);
    const QString recovery = autosave->recoveryPath();
    QVERIFY(recovery.startsWith(m_recoveryDirectory));

    // a clean document is not autosaved
    const QString path = m_files.filePath(QStringLiteral("autosaved.json"));
    QString error;
    QVERIFY2(m_window->files()->saveTo(path, &error), qPrintable(error));
    QVERIFY(!QFileInfo::exists(recovery));

    // a change is, within the interval, to the recovery file and not the user's
    const QByteArray onDisk = [&] {
        QFile file(path);
        return file.open(QIODevice::ReadOnly) ? file.readAll() : QByteArray();
    }();
    edit();
    QTRY_VERIFY_WITH_TIMEOUT(QFileInfo::exists(recovery), 10000);
    const io::LoadResult recovered = io::loadScene(recovery);
    QVERIFY2(recovered.ok(), qPrintable(recovered.error));
    QVERIFY(*recovered.scene == document().scene());
    QFile user(path);
    QVERIFY(user.open(QIODevice::ReadOnly));
    QCOMPARE(user.readAll(), onDisk);
    QCOMPARE(ui::Autosave::findRecoveries(m_recoveryDirectory).size(), 0);  // this session is alive

    // saving removes it
    QVERIFY2(m_window->files()->saveTo(path, &error), qPrintable(error));
    QVERIFY(!QFileInfo::exists(recovery));

    // so does undoing back to the saved state, and a clean end
    edit();
    QTRY_VERIFY_WITH_TIMEOUT(QFileInfo::exists(recovery), 10000);
    press(Qt::Key_Z, Qt::ControlModifier);
    QVERIFY(!m_window->isWindowModified());
    QVERIFY(!QFileInfo::exists(recovery));
    edit();
    QTRY_VERIFY_WITH_TIMEOUT(QFileInfo::exists(recovery), 10000);
    m_answer = QMessageBox::Discard;
    QVERIFY(m_window->close());
    QVERIFY(!QFileInfo::exists(recovery));
    QVERIFY(QDir(m_recoveryDirectory).entryList(QDir::Files).isEmpty());
}

void TestFiles::autosaveIsConfigured()
{
    // from the settings, at start
    closeEditor();
    QSettings().setValue(QStringLiteral("autosave/intervalSeconds"), 45);
    restart();
    QCOMPARE(m_window->files()->autosave()->intervalSeconds(), 45);
    auto *custom = m_window->findChild<QMenu *>(QStringLiteral("autosaveMenu"))->actions().back();
    QVERIFY(custom->isChecked());
    QCOMPARE(custom->data().toInt(), 45);

    // and from File › Autosave, which remembers the choice; Off writes nothing
    action("actionAutosave120")->trigger();
    QCOMPARE(m_window->files()->autosave()->intervalSeconds(), 120);
    QCOMPARE(QSettings().value(QStringLiteral("autosave/intervalSeconds")).toInt(), 120);
    action("actionAutosave0")->trigger();
    QCOMPARE(m_window->files()->autosave()->intervalSeconds(), 0);
    QCOMPARE(QSettings().value(QStringLiteral("autosave/intervalSeconds")).toInt(), 0);
    QString error;
    QVERIFY(m_window->files()->autosave()->saveNow(&error));  // clean: nothing to write
    QVERIFY(!QFileInfo::exists(m_window->files()->autosave()->recoveryPath()));
}

void TestFiles::nextStartRecoversACrashedSession()
{
    // a session edits its file and autosaves
    const QString path = m_files.filePath(QStringLiteral("crashed.json"));
    QString error;
    QVERIFY2(m_window->files()->saveTo(path, &error), qPrintable(error));
    edit();
    edit();
    const core::SceneDesc unsaved = document().scene();
    QVERIFY2(m_window->files()->autosave()->saveNow(&error), qPrintable(error));
    const QString recovery = m_window->files()->autosave()->recoveryPath();
    QVERIFY(QFileInfo::exists(recovery));

    // its files as a crash leaves them: no live process holds their lock
    const QDir folder(m_recoveryDirectory);
    QString source = recovery;
    source.replace(QStringLiteral(".recovery.json"), QStringLiteral(".recovery.source"));
    QVERIFY(QFile::copy(recovery, folder.filePath(QStringLiteral("crashed.recovery.json"))));
    QVERIFY(QFile::copy(source, folder.filePath(QStringLiteral("crashed.recovery.source"))));
    m_answer = QMessageBox::Discard;
    closeEditor();
    QCOMPARE(folder.entryList(QDir::Files),
             (QStringList{QStringLiteral("crashed.recovery.json"), QStringLiteral("crashed.recovery.source")}));

    // Cancel: kept for another start
    restart();
    m_answer = QMessageBox::Cancel;
    QVERIFY(m_window->files()->start());
    QCOMPARE(m_questions.size(), 1);
    QCOMPARE(m_questions.front().icon, QMessageBox::Question);
    QVERIFY2(m_questions.front().text.contains(QStringLiteral("crashed.json")), qPrintable(m_questions.front().text));
    QCOMPARE(document().displayName(), QStringLiteral("springs"));
    QVERIFY(folder.exists(QStringLiteral("crashed.recovery.json")));

    // Yes: the autosaved scene, as the user's file with unsaved changes; the old files go
    restart();
    m_answer = QMessageBox::Yes;
    QVERIFY(m_window->files()->start(path));
    QVERIFY(document().scene() == unsaved);
    QCOMPARE(document().filePath(), QFileInfo(path).absoluteFilePath());
    QVERIFY(document().isModified());
    QVERIFY(!folder.exists(QStringLiteral("crashed.recovery.json")));
    QVERIFY(QFileInfo::exists(m_window->files()->autosave()->recoveryPath()));
    QVERIFY(settledFrame(controller())->scene == document().sharedScene());

    // No: thrown away
    m_window->files()->autosave()->saveNow();
    QVERIFY(QFile::copy(m_window->files()->autosave()->recoveryPath(),
                        folder.filePath(QStringLiteral("again.recovery.json"))));
    restart();
    m_answer = QMessageBox::No;
    QVERIFY(m_window->files()->start());
    QCOMPARE(document().displayName(), QStringLiteral("springs"));
    QVERIFY(!document().isModified());
    QVERIFY(ui::Autosave::findRecoveries(m_recoveryDirectory).isEmpty());
}

void TestFiles::droppedSceneFileOpens()
{
    QString error;
    QVERIFY2(m_window->files()->openExample(QStringLiteral("particles"), &error), qPrintable(error));
    const core::SceneDesc particles = document().scene();
    QVERIFY2(m_window->files()->openExample(QStringLiteral("collisions"), &error), qPrintable(error));
    const QString path = savedFile(QStringLiteral("dropped.json"), particles);

    auto drop = [this](const QString &file) {
        QMimeData mime;
        mime.setUrls({QUrl::fromLocalFile(file)});
        const QPoint centre = m_window->rect().center();
        QDragEnterEvent enter(centre, Qt::CopyAction, &mime, Qt::LeftButton, Qt::NoModifier);
        QApplication::sendEvent(m_window, &enter);
        if (!enter.isAccepted())
            return false;
        QDropEvent event(QPointF(centre), Qt::CopyAction, &mime, Qt::LeftButton, Qt::NoModifier);
        QApplication::sendEvent(m_window, &event);
        return event.isAccepted();
    };

    // anything but a .json file is refused
    const QString text = m_files.filePath(QStringLiteral("notes.txt"));
    QVERIFY(writeFile(text, "hello"));
    QVERIFY(!drop(text));

    // a changed scene is asked about first; Cancel keeps it
    edit();
    m_answer = QMessageBox::Cancel;
    QVERIFY(drop(path));
    QTRY_COMPARE(m_questions.size(), 1);
    QCOMPARE(document().displayName(), QStringLiteral("collisions"));

    // Discard: the dropped file is open
    m_answer = QMessageBox::Discard;
    QVERIFY(drop(path));
    QTRY_COMPARE(document().filePath(), QFileInfo(path).absoluteFilePath());
    QVERIFY(document().scene() == particles);
    QVERIFY(!m_window->isWindowModified());
    QCOMPARE(m_window->files()->recentFiles()->paths().front(), QFileInfo(path).canonicalFilePath());
}

void TestFiles::openStartsInTheFolderLastUsed()
{
    // a scene opened from a folder of its own, then an example: Ctrl+O and Save As start in that
    // folder, not the home folder (an example has no folder)
    const QString folder = m_files.filePath(QStringLiteral("projects"));
    QVERIFY(QDir().mkpath(folder));
    QString error;
    QVERIFY2(m_window->files()->openExample(QStringLiteral("particles"), &error), qPrintable(error));
    const QString path = QDir(folder).filePath(QStringLiteral("mine.json"));
    QVERIFY(io::saveScene(path, document().scene()).ok());
    QVERIFY2(m_window->files()->openScene(path, &error), qPrintable(error));
    QVERIFY2(m_window->files()->openExample(QStringLiteral("springs"), &error), qPrintable(error));
    QVERIFY(document().filePath().isEmpty());
    m_window->files()->openFromDialog();  // answered with no path: cancelled
    QCOMPARE(m_dialogs, (QList<ui::MainWindow::FileDialogMode>{ui::MainWindow::FileDialogMode::Open}));
    QCOMPARE(QDir(m_dialogStarts.front()).canonicalPath(), QDir(folder).canonicalPath());
    m_window->files()->saveAs();
    QCOMPARE(QFileInfo(m_dialogStarts.back()).dir().canonicalPath(), QDir(folder).canonicalPath());
}

void TestFiles::commandLineFileOpens()
{
    // a good file opens
    QString error;
    QVERIFY2(m_window->files()->openExample(QStringLiteral("particles"), &error), qPrintable(error));
    const QString path = savedFile(QStringLiteral("command-line.json"), document().scene());
    restart();
    QVERIFY(m_window->files()->start(path, &error));
    QCOMPARE(document().filePath(), QFileInfo(path).absoluteFilePath());
    QCOMPARE(document().displayName(), QStringLiteral("particles"));
    QVERIFY(m_questions.isEmpty());

    // a bad one shows the loader's message, and the default example is open instead
    const QString bad = m_files.filePath(QStringLiteral("bad-argument.json"));
    QVERIFY(writeFile(bad, "{\"format\": \"springlab-scene\", \"version\": 1, \"particles\": 3}"));
    restart();
    QVERIFY(!m_window->files()->start(bad, &error));
    QVERIFY2(error.contains(QStringLiteral("bad-argument.json")), qPrintable(error));
    QCOMPARE(m_questions.size(), 1);
    QVERIFY(m_questions.front().text.contains(error));
    QCOMPARE(document().displayName(), QString::fromLatin1(ui::DocumentFiles::kDefaultExample));
    QVERIFY(document().filePath().isEmpty());
}

void TestFiles::useCurrentStateAsInitialThenResetAndUndo()
{
    // two free particles in flight, no contacts: run, pause, capture
    QString error;
    QVERIFY2(m_window->files()->openExample(QStringLiteral("particles"), &error), qPrintable(error));
    const core::SceneDesc original = document().scene();
    press(Qt::Key_F4);
    QTRY_VERIFY(controller().frame()->snapshot->time > 0.05);
    press(Qt::Key_F4);
    const auto paused = settledFrame(controller());
    QVERIFY(!paused->running);
    auto reply = std::make_shared<ui::CapturedStateReply>();
    const QObject receiver;
    connect(&controller(), &ui::SimulationController::stateCaptured, &receiver,
            [reply](const ui::CapturedStateReply &r) { *reply = r; });
    action("actionUseCurrentState")->trigger();
    QTRY_COMPARE(document().undoStack()->count(), 1);
    QVERIFY(m_window->isWindowModified());

    // the scene's initial conditions are the paused state: positions as drawn, velocities the run's
    const core::SceneDesc &captured = document().scene();
    QVERIFY(settledFrame(controller()));
    QVERIFY(reply->captured);
    QCOMPARE(reply->captured->state.step, paused->snapshot->step);
    for (std::size_t i = 0; i < captured.particles.size(); ++i) {
        const auto column = Eigen::Index(i);
        QVERIFY(captured.particles[i].position == reply->captured->state.position.col(column));
        QVERIFY(captured.particles[i].velocity == reply->captured->state.velocity.col(column));
        for (Eigen::Index axis = 0; axis < 3; ++axis)
            QCOMPARE(float(captured.particles[i].position[axis]), paused->snapshot->positions[3 * i + std::size_t(axis)]);
    }
    // gravity has moved and sped them: not the old initial conditions
    QVERIFY(captured.particles[1].position.y() < original.particles[1].position.y());
    QVERIFY(captured.particles[1].velocity.y() < 0.0);
    // only the initial conditions changed
    QVERIFY(captured.settings == original.settings);
    QCOMPARE(captured.particles[0].mass, original.particles[0].mass);

    // a few steps on, F5 returns to the captured state
    const core::SceneDesc capturedCopy = captured;
    for (int i = 0; i < 3; ++i)
        press(Qt::Key_F6);
    QVERIFY(settledFrame(controller())->snapshot->step > paused->snapshot->step);
    press(Qt::Key_F5);
    const auto reset = settledFrame(controller());
    QCOMPARE(reset->snapshot->step, 0u);
    for (std::size_t i = 0; i < capturedCopy.particles.size(); ++i)
        for (std::size_t axis = 0; axis < 3; ++axis)
            QCOMPARE(reset->snapshot->positions[3 * i + axis],
                     float(capturedCopy.particles[i].position[Eigen::Index(axis)]));

    // undo gives back the old initial conditions exactly; F5 then returns to them
    press(Qt::Key_Z, Qt::ControlModifier);
    QVERIFY(document().scene() == original);
    QVERIFY(!m_window->isWindowModified());
    press(Qt::Key_F5);
    const auto undone = settledFrame(controller());
    for (std::size_t i = 0; i < original.particles.size(); ++i)
        for (std::size_t axis = 0; axis < 3; ++axis)
            QCOMPARE(undone->snapshot->positions[3 * i + axis], float(original.particles[i].position[Eigen::Index(axis)]));

    // redo, the same captured state again
    press(Qt::Key_Z, Qt::ControlModifier | Qt::ShiftModifier);
    QVERIFY(document().scene() == capturedCopy);
}

void TestFiles::undoHistoryAndRedoKeys()
{
    // the history dock is hidden until View › Undo History shows it; it lists the document's stack
    auto *dock = m_window->findChild<QDockWidget *>(QStringLiteral("undoHistoryDock"));
    QVERIFY(dock);
    QVERIFY(dock->isHidden());
    QCOMPARE(m_window->undoView()->stack(), document().undoStack());
    action("actionUndoHistory")->trigger();
    QVERIFY(dock->isVisible());
    const double viscosity = document().scene().settings.viscosity;
    edit();
    edit();
    QCOMPARE(m_window->undoView()->model()->rowCount(), 3);  // the opened state, then two edits

    // Ctrl+Z twice, Ctrl+Shift+Z once
    press(Qt::Key_Z, Qt::ControlModifier);
    press(Qt::Key_Z, Qt::ControlModifier);
    QCOMPARE(document().undoStack()->index(), 0);
    press(Qt::Key_Z, Qt::ControlModifier | Qt::ShiftModifier);
    QCOMPARE(document().undoStack()->index(), 1);
    QCOMPARE(document().scene().settings.viscosity, viscosity + 0.25);
    QVERIFY(action("actionRedo")->shortcuts().contains(QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_Z)));
    action("actionUndoHistory")->trigger();
    QVERIFY(dock->isHidden());
}

void TestFiles::helpListsTheFileKeys()
{
    const ui::HelpDialog help(*m_window->menuBar(), m_window);
    const QString all = help.entries().join(QLatin1Char('\n'));
    for (const char *entry : {"Ctrl+N\tFile › New", "Ctrl+O\tFile › Open", "Ctrl+S\tFile › Save",
                              "Ctrl+Shift+S\tFile › Save As", "Ctrl+Q\tFile › Quit", "Ctrl+Z\tEdit › Undo",
                              "Ctrl+Shift+Z", "Drop a .json file", "springlab SCENE.json", "Undo History"})
        QVERIFY2(all.contains(QString::fromUtf8(entry)), entry);
}

void TestFiles::recordedSessionReplaysToTheSameBits()
{
    // Ctrl+R records while the scene runs and is edited: a tilt, a slider's worth of viscosity
    QString error;
    QVERIFY2(m_window->files()->openExample(QStringLiteral("cloth"), &error), qPrintable(error));
    QVERIFY(settledFrame(controller()));
    if (!controller().isRunning())
        press(Qt::Key_F4);
    QVERIFY(action("actionRecordSession"));
    press(Qt::Key_R, Qt::ControlModifier);
    QVERIFY(action("actionRecordSession")->isChecked());
    QTRY_VERIFY_WITH_TIMEOUT(controller().frame()->snapshot->time > 0.05, 10000);
    press(Qt::Key_T);
    edit();
    const double timeAtEdit = controller().frame()->snapshot->time;
    QTRY_VERIFY_WITH_TIMEOUT(controller().frame()->snapshot->time > timeAtEdit + 0.05, 10000);

    // Ctrl+R again: the recording comes back from the worker and is saved where the user says
    const QString path = m_files.filePath(QStringLiteral("cloth.replay.json"));
    m_chosenPath = path;
    m_dialogs.clear();
    press(Qt::Key_R, Qt::ControlModifier);
    QVERIFY(!action("actionRecordSession")->isChecked());
    QTRY_VERIFY_WITH_TIMEOUT(QFileInfo::exists(path), 10000);
    QCOMPARE(m_dialogs, QList<ui::MainWindow::FileDialogMode>{ui::MainWindow::FileDialogMode::Save});

    // replayed on its own, it ends with the bits the editor's run ended with
    const ui::RecordingLoad loaded = ui::loadRecording(path);
    QVERIFY2(loaded.recording, qPrintable(loaded.error));
    QVERIFY(loaded.recording->steps > 0);
    QVERIFY(loaded.recording->entries.size() >= 2);  // the tilt and the viscosity
    const ui::ReplayResult replayed = ui::replay(*loaded.recording);
    QVERIFY2(replayed.error.empty(), replayed.error.c_str());
    QCOMPARE(replayed.hash, loaded.recording->finalHash);
}

void TestFiles::saveNeverWritesOverARecoveryFile()
{
    // a change autosaved to this session's recovery file
    ui::Autosave *autosave = m_window->files()->autosave();
    edit();
    QString error;
    QVERIFY2(autosave->saveNow(&error), qPrintable(error));
    const QString recovery = autosave->recoveryPath();
    const QByteArray autosaved = readAll(recovery);
    QVERIFY(!autosaved.isEmpty());

    // Save As onto it, by its path or a link to it: autosave would remove the saved scene with its
    // file, so the save is refused with a warning, and the changes stay unsaved
    const QString link = m_files.filePath(QStringLiteral("recovery-link.json"));
    QVERIFY(QFile::link(recovery, link));
    for (const QString &chosen : {recovery, link}) {
        m_questions.clear();
        m_chosenPath = chosen;
        action("actionSaveAs")->trigger();
        QCOMPARE(m_questions.size(), 1);
        QCOMPARE(m_questions.front().icon, QMessageBox::Warning);
        const QString &message = m_questions.front().text;
        QVERIFY2(message.contains(QDir::toNativeSeparators(chosen)) && message.contains(QStringLiteral("autosave recovery file")),
                 qPrintable(message));
        QVERIFY(document().isModified());
        QVERIFY(document().filePath().isEmpty());
        QCOMPARE(readAll(recovery), autosaved);
    }

    // another session's recovery file, known by its name in the folder, is refused too
    const QString another = QDir(m_recoveryDirectory).filePath(QStringLiteral("another.recovery.json"));
    QVERIFY(!m_window->files()->saveTo(another, &error));
    QVERIFY2(error.contains(QStringLiteral("autosave recovery file")), qPrintable(error));
    QVERIFY(!QFileInfo::exists(another));

    // and a file of the user's still saves
    const QString mine = m_files.filePath(QStringLiteral("mine.json"));
    QVERIFY2(m_window->files()->saveTo(mine, &error), qPrintable(error));
    QVERIFY(!document().isModified());
}

void TestFiles::autosaveNeverWritesOverTheScenesFile()
{
    // the recovery file's path made a link to the user's file: autosaving would change that file
    // without a Save
    QString error;
    const QString mine = m_files.filePath(QStringLiteral("mine.json"));
    QVERIFY2(m_window->files()->saveTo(mine, &error), qPrintable(error));
    const QByteArray saved = readAll(mine);
    ui::Autosave *autosave = m_window->files()->autosave();
    QVERIFY(QDir().mkpath(m_recoveryDirectory));
    QVERIFY(QFile::link(mine, autosave->recoveryPath()));
    edit();
    QVERIFY(!autosave->saveNow(&error));
    QVERIFY2(error.contains(QStringLiteral("never writes over")), qPrintable(error));
    QCOMPARE(readAll(mine), saved);
    QVERIFY(document().isModified());
}

void TestFiles::plotsAndRecordingsNeverWriteOverTheScene()
{
    // the scene saved, and reached by other names: a hard link, a symbolic link, "./"; what a
    // session recording or a plot asks before it saves calls each of them the scene's file
    QString error;
    const QString scene = m_files.filePath(QStringLiteral("guarded.json"));
    QVERIFY2(m_window->files()->saveTo(scene, &error), qPrintable(error));
    const QByteArray saved = readAll(scene);
    const QString hardLink = m_files.filePath(QStringLiteral("guarded-alias.replay.json"));
    QVERIFY(::link(QFile::encodeName(scene).constData(), QFile::encodeName(hardLink).constData()) == 0);
    const QString symbolicLink = m_files.filePath(QStringLiteral("guarded-link.csv"));
    QVERIFY(QFile::link(scene, symbolicLink));
    for (const QString &name : {scene, hardLink, symbolicLink, m_files.path() + QStringLiteral("/./guarded.json")}) {
        const QString refused = m_window->files()->protectedFileAt(name);
        QVERIFY2(refused.contains(QStringLiteral("open scene's file")), qPrintable(name + QStringLiteral(": ") + refused));
    }
    QVERIFY(m_window->files()->protectedFileAt(m_files.filePath(QStringLiteral("guarded.replay.json"))).isEmpty());

    // a plot's data exported through the link: refused with a warning, the scene as it was
    auto *plots = m_window->findChild<ui::PlotsWidget *>();
    QVERIFY(plots);
    m_questions.clear();
    m_chosenPath = symbolicLink;
    emit plots->exportRequested(ui::PlotExport::Csv);
    QCOMPARE(m_questions.size(), 1);
    QCOMPARE(m_questions.front().icon, QMessageBox::Warning);
    QVERIFY2(m_questions.front().text.contains(QStringLiteral("open scene's file")), qPrintable(m_questions.front().text));
    QCOMPARE(readAll(scene), saved);
    QVERIFY(QFileInfo(symbolicLink).isSymLink());
}

QTEST_MAIN(TestFiles)
#include "test_files.moc"
