// Start, run, load another scene and close while running, over and over: each cycle opens an
// editor on one example, lets the worker step it, loads the next example while it runs and
// closes the window while the worker is still stepping. Every cycle must get a frame of each scene
// from the worker. Under AddressSanitizer with leak checking (tools/long_tests.sh runs 1000 cycles)
// this is the test for crashes and leaks on the way in and out; SPRINGLAB_LIFECYCLE_CYCLES sets
// the count (CI's plain build runs 20).

#include "ui/document/document_files.h"
#include "ui/window/main_window.h"
#include "ui/document/scene_document.h"
#include "ui/simulation/simulation_controller.h"
#include "ui/viewport/viewport.h"

#include <QtTest>

#include "editor_fixture.h"

namespace {

// under the sanitizers a scene loads and steps many times slower than in a release build
constexpr int kFrameWaitMs = 60000;

}  // namespace

class TestLifecycle : public test::EditorTest {
    Q_OBJECT

private slots:
    void initTestCase();
    void startRunLoadAndCloseWhileRunning();
};

void TestLifecycle::initTestCase()
{
    QVERIFY(foldersReady());
    setAutosave(settingsPath() + QStringLiteral("/recovery"), 0);
}

void TestLifecycle::startRunLoadAndCloseWhileRunning()
{
    const int cycles = qEnvironmentVariableIsSet("SPRINGLAB_LIFECYCLE_CYCLES")
                           ? qEnvironmentVariableIntValue("SPRINGLAB_LIFECYCLE_CYCLES")
                           : 20;
    const QStringList examples = ui::DocumentFiles::exampleNames();
    QVERIFY(examples.size() >= 2);
    for (int cycle = 0; cycle < cycles; ++cycle) {
        const QString first = examples[cycle % examples.size()];
        const QString second = examples[(cycle + 1) % examples.size()];
        // shown, and the example opened before the worker's first frame is waited for
        QVERIFY2(openEditor({.size = QSize(640, 480), .activate = false, .settle = false}), qPrintable(editorFailure()));
        ui::MainWindow *window = m_window;
        QString error;
        QVERIFY2(window->files()->openExample(first, &error), qPrintable(error));
        ui::SimulationController &controller = *window->controller();
        controller.play();

        // the first scene steps: a frame of it with time past zero
        auto frame = test::settledFrame(controller, kFrameWaitMs);
        QVERIFY2(frame && frame->scene == window->document()->sharedScene(), qPrintable(first));
        QTRY_VERIFY_WITH_TIMEOUT(controller.frame()->snapshot && controller.frame()->snapshot->time > 0.0, kFrameWaitMs);
        QVERIFY(controller.isRunning());

        // another scene while it runs, then close while that one runs
        QVERIFY2(window->files()->openExample(second, &error), qPrintable(error));
        controller.play();
        frame = test::settledFrame(controller, kFrameWaitMs);
        QVERIFY2(frame && frame->scene == window->document()->sharedScene(), qPrintable(second));
        QVERIFY(controller.isRunning());
        window->close();
        closeEditor();
        // the long runs report how far they got, so a stop names its cycle
        if ((cycle + 1) % 50 == 0)
            qInfo("cycle %d of %d done", cycle + 1, cycles);
    }
}

QTEST_MAIN(TestLifecycle)
#include "test_lifecycle.moc"
