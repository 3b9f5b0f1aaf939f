// Autosave and recovery end to end: an editor in a process of its own (autosaving_editor) changes
// its scene, autosaves, and is killed with SIGKILL, as a crash or a power cut would end it. A new
// editor in this process then starts on the same settings: recovery is offered, the recovery file
// is still there while the question is open and after Cancel, and Yes restores exactly the scene
// the killed editor had, after which the old files are gone.

#include "ui/document/autosave.h"
#include "ui/document/document_files.h"
#include "ui/window/main_window.h"
#include "ui/document/scene_document.h"
#include "ui/viewport/viewport.h"

#include "core/io/scene_file.h"

#include <QUndoStack>
#include <QDir>
#include <QProcess>
#include <QtTest>

#include "editor_fixture.h"

class TestCrashRecovery : public test::EditorTest {
    Q_OBJECT

private slots:
    void initTestCase();
    void killedEditorIsRecoveredOnTheNextStart();
    void cleanup() { closeEditor(); }
};

void TestCrashRecovery::initTestCase()
{
    // this process and the child share throwaway settings: the recovery folder, autosave every second
    QVERIFY(foldersReady());
    setAutosave(m_files.filePath(QStringLiteral("recovery")), 1);
}

void TestCrashRecovery::killedEditorIsRecoveredOnTheNextStart()
{
    // the user's file, as last saved
    const QString scenePath = m_files.filePath(QStringLiteral("work.json"));
    const io::LoadResult example = io::loadScene(QStringLiteral(SPRINGLAB_SOURCE_DIR "/resources/scenes/cloth.json"));
    QVERIFY2(example.ok(), qPrintable(example.error));
    QVERIFY(io::saveScene(scenePath, *example.scene).ok());
    const QString expectedPath = m_files.filePath(QStringLiteral("expected.json"));

    // an editor changes it, autosaves and is killed
    QProcess editor;
    editor.setProcessChannelMode(QProcess::ForwardedErrorChannel);
    editor.start(QStringLiteral(SPRINGLAB_AUTOSAVING_EDITOR), {settingsPath(), scenePath, expectedPath});
    QVERIFY2(editor.waitForStarted(10000), qPrintable(editor.errorString()));
    QElapsedTimer clock;
    clock.start();
    QByteArray said;
    while (!said.contains('\n') && editor.state() == QProcess::Running && clock.elapsed() < 60000) {
        editor.waitForReadyRead(100);
        said += editor.readAllStandardOutput();
    }
    QVERIFY2(said.startsWith("autosaved "), said.constData());
    const QString recovery = QString::fromLocal8Bit(said.mid(10).trimmed());
    QVERIFY(QFileInfo::exists(recovery));
    editor.kill();  // SIGKILL: no destructor, no clean-up, the lock file stays behind
    QVERIFY(editor.waitForFinished(10000));
    QCOMPARE(editor.exitStatus(), QProcess::CrashExit);
    QVERIFY2(QFileInfo::exists(recovery), "the killed editor's recovery file must survive it");

    const io::LoadResult expected = io::loadScene(expectedPath);
    QVERIFY2(expected.ok(), qPrintable(expected.error));
    QVERIFY(!(*expected.scene == *example.scene));  // the killed editor's changes are real changes

    // the next start asks; Cancel keeps the files for another start
    int asked = 0;
    bool recoveryThereWhenAsked = false;
    QMessageBox::StandardButton answer = QMessageBox::Cancel;
    // a window that has not started yet, left hidden as the start under test shows it
    const auto answerHere = [&](ui::MainWindow &window) {
        window.setMessageBoxFunction([&](QMessageBox::Icon icon, const QString &, const QString &text,
                                         QMessageBox::StandardButtons buttons, QMessageBox::StandardButton) {
            if (icon == QMessageBox::Question && text.contains(QStringLiteral("did not close properly"))) {
                ++asked;
                recoveryThereWhenAsked = QFileInfo::exists(recovery);
            }
            return buttons.testFlag(answer) ? answer : QMessageBox::Ok;
        });
    };
    QVERIFY2(openEditor({.setup = answerHere, .show = false}), qPrintable(editorFailure()));
    QVERIFY(m_window->files()->start());
    QCOMPARE(asked, 1);
    QVERIFY(recoveryThereWhenAsked);
    QVERIFY(QFileInfo::exists(recovery));
    QVERIFY(!m_window->document()->isModified());

    // Yes: the killed editor's scene, as its file with unsaved changes; the old files go
    answer = QMessageBox::Yes;
    QVERIFY2(openEditor({.setup = answerHere, .show = false}), qPrintable(editorFailure()));
    QVERIFY(m_window->files()->start());
    QCOMPARE(asked, 2);
    QVERIFY(recoveryThereWhenAsked);
    QVERIFY(m_window->document()->scene() == *expected.scene);
    QCOMPARE(m_window->document()->filePath(), QFileInfo(scenePath).absoluteFilePath());
    QVERIFY(m_window->document()->isModified());
    QVERIFY(!QFileInfo::exists(recovery));
    QCOMPARE(ui::Autosave::findRecoveries(m_window->files()->autosave()->directory()).size(), 0);

    // a file opened afterwards is as saved: not modified, nothing to undo
    QString error;
    QVERIFY2(m_window->files()->openScene(QStringLiteral(SPRINGLAB_SOURCE_DIR "/resources/scenes/collisions.json"), &error),
             qPrintable(error));
    QVERIFY(!m_window->document()->isModified());
    QCOMPARE(m_window->document()->undoStack()->count(), 0);
}

QTEST_MAIN(TestCrashRecovery)
#include "test_crash_recovery.moc"
