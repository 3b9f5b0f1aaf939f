// The monkey: seeded random user input on every example, 2500 events each (10 000 in
// tools/long_tests.sh): clicks and drags on the viewport with any button and modifier, wheel
// turns, the editor's keys, slider keys, typed values (numbers, garbage, NaN, huge) in the docks'
// fields, and every menu action, with every question and file dialog answered at random and any
// other modal dialog closed. Afterwards (an export it started cancelled, as a user would) the
// editor must still be alive (the worker publishes a frame for the latest edit) and the document
// must hold a valid scene. The events come from the seed alone (std::mt19937 with a fixed
// seed per example); a failure names the seed and the event, and SPRINGLAB_MONKEY_SEED and
// SPRINGLAB_MONKEY_EVENTS rerun one case. With the simulation paused, the window's layout settled
// before the first event, and after each event its dialog closed, the window active again and the
// worker caught up, two runs of one seed end in the same scene (reproducibleFromTheSeed); when
// they do not, the failure names the first event after which they differed.

#include "ui/document/document_files.h"
#include "ui/window/main_window.h"
#include "ui/document/scene_document.h"
#include "ui/viewport/viewport.h"

#include "core/integrators/integrator.h"
#include "core/contacts/solver_names.h"
#include "core/model/validate.h"
#include "ui/export/exporter.h"

#include <QAbstractSlider>
#include <QAbstractSpinBox>
#include <QDialog>
#include <QLineEdit>
#include <QMenu>
#include <QMenuBar>
#include <QScopeGuard>
#include <QSettings>
#include <QTimer>
#include <QUndoStack>
#include <QWheelEvent>
#include <QtTest>

#include "editor_fixture.h"

#include <random>

namespace {

// 2500 events an example in the suite; tools/long_tests.sh runs 10 000 under AddressSanitizer
constexpr int kEvents = 2500;
// how long the editor may take to answer after the events: the verdict must not depend on the
// machine's speed, so the wait is far longer than any machine needs (a passing run does not wait)
constexpr int kPatienceMs = 300000;
constexpr int kEventsPerFrame = 20;

// what the monkey may press: the editor's keys, with and without modifiers
struct KeyPress {
    Qt::Key key;
    Qt::KeyboardModifiers modifiers;
};
const KeyPress kKeys[] = {
    {Qt::Key_1, {}}, {Qt::Key_2, {}}, {Qt::Key_3, {}}, {Qt::Key_4, {}}, {Qt::Key_5, {}}, {Qt::Key_6, {}},
    {Qt::Key_F4, {}}, {Qt::Key_F5, {}}, {Qt::Key_T, {}}, {Qt::Key_A, {}}, {Qt::Key_P, {}}, {Qt::Key_F, {}},
    {Qt::Key_Home, {}}, {Qt::Key_Escape, {}}, {Qt::Key_Delete, {}}, {Qt::Key_Backspace, {}},
    {Qt::Key_Left, {}}, {Qt::Key_Right, {}}, {Qt::Key_Up, {}}, {Qt::Key_Down, {}},
    {Qt::Key_A, Qt::ControlModifier}, {Qt::Key_D, Qt::ControlModifier}, {Qt::Key_C, Qt::ControlModifier},
    {Qt::Key_V, Qt::ControlModifier}, {Qt::Key_Z, Qt::ControlModifier},
    {Qt::Key_Z, Qt::ControlModifier | Qt::ShiftModifier}, {Qt::Key_S, Qt::ControlModifier},
    {Qt::Key_N, Qt::ControlModifier}, {Qt::Key_O, Qt::ControlModifier},
};
// what the monkey may type into a field
const char *const kTyped[] = {"0", "1", "-1", "0.5", "1e3", "1e300", "-1e300", "nan", "inf", "-0", "abc", "", "2.5e-7",
                              "99999999999999999999", "1,5", " 3 "};

// one line of a paused run's trace: after which event, and what the window was then
QString describe(int event, const QString &what, const ui::MainWindow &window, int edits)
{
    const auto name = [](const QObject *object) {
        return object ? QString::fromLatin1(object->metaObject()->className()) : QStringLiteral("none");
    };
    return QStringLiteral("event %1 (%2): undo steps %3, edits %4, viewport %5x%6, active %7, focus %8")
        .arg(event).arg(what).arg(window.document()->undoStack()->count()).arg(edits)
        .arg(window.viewport()->width()).arg(window.viewport()->height())
        .arg(name(QApplication::activeWindow()), name(QApplication::focusWidget()));
}

// the first event after which two traces differ, and the two lines there
QString whereTheyPart(const QStringList &first, const QStringList &second)
{
    for (qsizetype e = 0; e < std::min(first.size(), second.size()); ++e)
        if (first[e] != second[e])
            return QStringLiteral("they part after\n  %1\n  %2").arg(first[e], second[e]);
    return QStringLiteral("their traces are the same");
}

QString text(std::string_view name)
{
    return QString::fromUtf8(name.data(), qsizetype(name.size()));
}

// what the editor held and did when the worker stopped answering, for the failure message
QString whatItWasDoing(const ui::MainWindow &window)
{
    const core::SceneDesc &scene = window.document()->scene();
    const auto last = window.controller()->frame();
    return QStringLiteral("%1 particles, %2 springs, %3 planes; time step %4 s, %5 sub-steps, %6, contacts %7; "
                          "running %8, exporting %9; last frame: step %10, message %11 of %12 sent")
        .arg(scene.particles.size()).arg(scene.springs.size()).arg(scene.planes.size())
        .arg(scene.settings.timeStep).arg(scene.settings.substeps)
        .arg(text(core::integratorName(scene.settings.integrator)))
        .arg(text(core::contactSolverName(scene.settings.contactSolver)))
        .arg(window.controller()->isRunning()).arg(window.exporter()->isExporting())
        .arg(last && last->snapshot ? qlonglong(last->snapshot->step) : -1)
        .arg(last ? qlonglong(last->appliedMessage) : -1).arg(qlonglong(window.controller()->sync() - 1));
}

// F4 and Step run the simulation: the reproducible run leaves them out
bool runsTheSimulation(const KeyPress &press)
{
    return press.key == Qt::Key_F4 && press.modifiers == Qt::NoModifier;
}

}  // namespace

class TestMonkey : public test::EditorTest {
    Q_OBJECT

private slots:
    void initTestCase();
    void survivesRandomInput_data();
    void survivesRandomInput();
    void reproducibleFromTheSeed();

private:
    struct Outcome {
        core::SceneDesc scene;
        int undoSteps = 0;
        int edits = 0;  // changes the document announced
        QString failure;  // empty when the editor survived with a valid scene
        QStringList trace;  // paused runs: what each event did, to find where two runs part
    };
    static Outcome failed(const QString &why)
    {
        Outcome outcome;
        outcome.failure = why;
        return outcome;
    }
    // `events` seeded events on a fresh window opened on `example`; `paused`: the simulation
    // never runs and each event waits for the worker, so that nothing depends on timing
    Outcome run(const QString &example, std::uint32_t seed, int events, bool paused);
};

void TestMonkey::initTestCase()
{
    QVERIFY(foldersReady());
    setAutosave(m_files.filePath(QStringLiteral("recovery")), 0);
    QSettings().setValue(QStringLiteral("screenshots/directory"), m_files.filePath(QStringLiteral("shots")));
}

TestMonkey::Outcome TestMonkey::run(const QString &example, std::uint32_t seed, int events, bool paused)
{
    std::mt19937 random(seed);
    const auto below = [&random](int n) { return static_cast<int>(random() % static_cast<std::uint32_t>(n)); };

    const QStringList examples = ui::DocumentFiles::exampleNames();
    // questions: any of the offered buttons; file dialogs: an example, a file of our own, or Cancel
    const auto answerAtRandom = [&](ui::MainWindow &window) {
        window.setMessageBoxFunction([&](QMessageBox::Icon, const QString &, const QString &,
                                         QMessageBox::StandardButtons buttons, QMessageBox::StandardButton) {
            QList<QMessageBox::StandardButton> offered;
            for (int bit = 0; bit < 32; ++bit)
                if (buttons.testFlag(static_cast<QMessageBox::StandardButton>(1u << bit)))
                    offered << static_cast<QMessageBox::StandardButton>(1u << bit);
            return offered.isEmpty() ? QMessageBox::Ok : offered[below(int(offered.size()))];
        });
        window.setFileDialogFunction([&](ui::MainWindow::FileDialogMode mode, const QString &, const QString &) {
            switch (below(3)) {
            case 0: return QString();
            case 1:
                return mode == ui::MainWindow::FileDialogMode::Open
                           ? m_files.filePath(examples[below(int(examples.size()))] + QStringLiteral(".json"))
                           : m_files.filePath(QStringLiteral("monkey.json"));
            default: return m_files.filePath(QStringLiteral("monkey.json"));
            }
        });
    };
    // every run starts from the same settings: the View menu's toggles the last run left (an
    // orthographic view picks other particles than a perspective one), the recent files it opened
    // (File › Open Recent offers other actions) and the timeline's budget are kept in them
    for (const char *kept : {"view", "files/recent", "timeline"})
        QSettings().remove(QString::fromLatin1(kept));
    // and the same files: fresh copies of the examples to open (a Save after Open writes into the
    // copy, never the source tree, and the last run's must not open here), and no monkey.json of
    // the last run's
    QFile::remove(m_files.filePath(QStringLiteral("monkey.json")));
    for (const QString &name : examples) {
        const QString copy = m_files.filePath(name + QStringLiteral(".json"));
        QFile::remove(copy);
        if (!QFile::copy(QStringLiteral(SPRINGLAB_SOURCE_DIR "/resources/scenes/%1.json").arg(name), copy))
            return failed(QStringLiteral("cannot copy the example %1").arg(name));
    }
    // small: software GL draws every pixel
    if (!openEditor({.setup = answerAtRandom, .size = QSize(800, 600), .settle = false}))
        return failed(editorFailure());
    // the window and its answers (which hold this run's locals) end with the run
    const auto closeAtEnd = qScopeGuard([this] { closeEditor(); });
    ui::MainWindow *window = m_window;
    QString error;
    if (!window->files()->openExample(example, &error))
        return failed(error);
    int edits = 0;
    QObject::connect(window->document(), &ui::SceneDocument::sceneChanged, window, [&edits] { ++edits; });
    if (paused && window->controller()->isRunning())
        QTest::keyClick(window, Qt::Key_F4);

    // any modal dialog the window opens itself (help, about, a folder chooser) is closed at once
    const auto closeModal = [] {
        if (QWidget *modal = QApplication::activeModalWidget()) {
            if (auto *dialog = qobject_cast<QDialog *>(modal))
                dialog->reject();
            else
                modal->close();
        }
    };
    QTimer closer;
    QObject::connect(&closer, &QTimer::timeout, closeModal);
    closer.start(5);
    // The paused run's events must meet the same window each time. Its docks settle their widths
    // through the X server after it is shown (a scroll bar comes or goes), which moves every click;
    // so it starts once the viewport's size has held for a while.
    if (paused && !test::sizeHeld(*window->viewport()))
        return failed(QStringLiteral("the viewport's size never settled"));

    // the menu actions, except Quit (which would end the test, not test the editor)
    QList<QAction *> actions;
    for (QMenu *menu : window->menuBar()->findChildren<QMenu *>())
        for (QAction *action : menu->actions())
            if (!action->isSeparator() && !action->menu() && action->objectName() != QStringLiteral("actionQuit"))
                actions << action;
    const auto isPlay = [](const QAction *action) {
        return action->objectName() == QStringLiteral("actionPlay") || action->objectName() == QStringLiteral("actionStep");
    };

    QStringList trace;
    ui::Viewport *viewport = window->viewport();
    const auto somewhere = [&] { return QPoint(below(viewport->width()), below(viewport->height())); };
    for (int e = 0; e < events; ++e) {
        const int kind = below(100);
        QString what = QString::number(kind);  // the kind of event, or the menu action's name
        if (kind < 30) {
            // click or drag on the viewport
            const Qt::MouseButton buttons[] = {Qt::LeftButton, Qt::LeftButton, Qt::LeftButton, Qt::RightButton,
                                               Qt::MiddleButton};
            const Qt::KeyboardModifiers modifiers[] = {Qt::NoModifier, Qt::NoModifier, Qt::ShiftModifier,
                                                       Qt::ControlModifier};
            const Qt::MouseButton button = buttons[below(5)];
            const Qt::KeyboardModifiers modifier = modifiers[below(4)];
            const QPoint from = somewhere();
            QTest::mousePress(viewport, button, modifier, from);
            for (int m = below(4); m > 0; --m)
                QTest::mouseMove(viewport, somewhere());
            QTest::mouseRelease(viewport, button, modifier, somewhere());
        } else if (kind < 38) {
            const QPoint at = somewhere();
            QWheelEvent wheel(at, viewport->mapToGlobal(at), QPoint(), QPoint(0, below(2) ? 120 : -120), Qt::NoButton,
                              Qt::NoModifier, Qt::NoScrollPhase, false);
            QCoreApplication::sendEvent(viewport, &wheel);
        } else if (kind < 63) {
            const KeyPress &press = kKeys[below(int(std::size(kKeys)))];
            if (!(paused && runsTheSimulation(press)))
                QTest::keyClick(window, press.key, press.modifiers);
        } else if (kind < 75) {
            // a slider, moved by its own keys
            const QList<QAbstractSlider *> sliders = window->findChildren<QAbstractSlider *>();
            QList<QAbstractSlider *> usable;
            for (QAbstractSlider *slider : sliders)
                if (slider->isVisible() && slider->isEnabled())
                    usable << slider;
            if (!usable.isEmpty()) {
                const Qt::Key keys[] = {Qt::Key_PageUp, Qt::Key_PageDown, Qt::Key_Home, Qt::Key_End, Qt::Key_Left,
                                        Qt::Key_Right};
                QTest::keyClick(usable[below(int(usable.size()))], keys[below(6)]);
            }
        } else if (kind < 87) {
            // a value typed into a field of a dock, then Enter
            QList<QWidget *> fields;
            for (QAbstractSpinBox *box : window->findChildren<QAbstractSpinBox *>())
                if (box->isVisible() && box->isEnabled())
                    fields << box;
            for (QLineEdit *line : window->findChildren<QLineEdit *>())
                if (line->isVisible() && line->isEnabled() && !qobject_cast<QAbstractSpinBox *>(line->parentWidget()))
                    fields << line;
            if (!fields.isEmpty()) {
                QWidget *field = fields[below(int(fields.size()))];
                field->setFocus();
                QTest::keyClick(field, Qt::Key_A, Qt::ControlModifier);
                QTest::keyClicks(field, QString::fromLatin1(kTyped[below(int(std::size(kTyped)))]));
                QTest::keyClick(field, Qt::Key_Return);
            }
        } else {
            QAction *action = actions[below(int(actions.size()))];
            if (action->isEnabled() && !(paused && isPlay(action))) {
                what = action->objectName();
                action->trigger();
            }
        }
        if (paused) {
            // A dialog closed by the timer above hands the activation back through the X server,
            // later under load; a key sent before then misses the window's shortcuts. So the
            // window's modal dialog is closed here and the window active again before the next.
            closeModal();
            // and a tool window left open (Edit › Transform Selection is not modal), which Xvfb,
            // having no window manager, may or may not leave active: the next key would then go to
            // it in one run and to the window in the other
            for (QWidget *top : QApplication::topLevelWidgets())
                if (auto *dialog = qobject_cast<QDialog *>(top); dialog && dialog->isVisible() && !dialog->isModal())
                    dialog->close();
            if (QApplication::activeWindow() != window && !test::showActive(*window))
                return failed(QStringLiteral("seed %1, event %2: the window never became active again").arg(seed).arg(e));
            if (!test::settledFrame(*window->controller()))
                return failed(QStringLiteral("seed %1, event %2: the worker stopped answering").arg(seed).arg(e));
            // A dock's content that grew wider (a longer number) asks for a wider window through a
            // posted layout request, and the X server widens it later, under load after the next
            // event: that click would then meet another viewport. So the window takes the size
            // its layout asks for before the next event.
            if (!QTest::qWaitFor([window] { return window->size().expandedTo(window->minimumSizeHint()) == window->size(); },
                                 kPatienceMs))
                return failed(QStringLiteral("seed %1, event %2: the window never took the size its docks need").arg(seed).arg(e));
        } else if (e % kEventsPerFrame == 0) {
            // let the window catch up (draw, take the worker's frame) every few events, as a
            // user's events arrive between frames; drawing after every one would only be slow
            QCoreApplication::processEvents();
        }
        if (window->isHidden())
            return failed(QStringLiteral("seed %1, event %2: the window closed").arg(seed).arg(e));
        if (paused)
            trace << describe(e, what, *window, edits);
    }
    closer.stop();

    // alive: the worker answers with a frame of the latest scene; valid: the validator accepts it
    Outcome outcome;
    outcome.trace = std::move(trace);
    outcome.scene = window->document()->scene();
    outcome.undoSteps = window->document()->undoStack()->count();
    outcome.edits = edits;
    // an export the monkey started (File › Export) steps the run on after the events, for as long as
    // the machine needs: a user waits for it or presses its Cancel, and so does the monkey; the
    // export must then end
    if (window->exporter()->isExporting()) {
        window->exporter()->cancel();
        if (!QTest::qWaitFor([window] { return !window->exporter()->isExporting(); }, kPatienceMs)) {
            outcome.failure = QStringLiteral("seed %1: the export never ended after Cancel (%2)")
                                  .arg(seed).arg(whatItWasDoing(*window));
            return outcome;
        }
    }
    const auto frame = test::settledFrame(*window->controller(), kPatienceMs);
    if (!frame)
        outcome.failure = QStringLiteral("seed %1: no frame from the worker after the events (%2)")
                              .arg(seed).arg(whatItWasDoing(*window));
    else if (const auto problem = core::findProblem(outcome.scene))
        outcome.failure = QStringLiteral("seed %1: the scene is not valid: %2").arg(seed).arg(QString::fromStdString(problem->message));
    return outcome;
}

void TestMonkey::survivesRandomInput_data()
{
    QTest::addColumn<QString>("example");
    QTest::addColumn<std::uint32_t>("seed");
    const QByteArray only = qgetenv("SPRINGLAB_MONKEY_SEED");
    const QStringList examples = ui::DocumentFiles::exampleNames();
    // SPRINGLAB_MONKEY_PART=k/n: every n-th example from the k-th (1-based), so that CTest runs the
    // examples as n tests side by side (tests/ui/CMakeLists.txt); each keeps its own seed
    int part = 0, parts = 1;
    const QList<QByteArray> split = qgetenv("SPRINGLAB_MONKEY_PART").split('/');
    if (split.size() == 2 && split[1].toInt() > 0) {
        parts = split[1].toInt();
        part = split[0].toInt() - 1;
    }
    for (int i = 0; i < examples.size(); ++i) {
        if (i % parts != part)
            continue;
        const std::uint32_t seed = only.isEmpty() ? 1000u + static_cast<std::uint32_t>(i) : only.toUInt();
        QTest::newRow(qPrintable(examples[i])) << examples[i] << seed;
    }
}

void TestMonkey::survivesRandomInput()
{
    QFETCH(QString, example);
    QFETCH(std::uint32_t, seed);
    const int events = qEnvironmentVariableIsSet("SPRINGLAB_MONKEY_EVENTS")
                           ? qEnvironmentVariableIntValue("SPRINGLAB_MONKEY_EVENTS")
                           : kEvents;
    const Outcome outcome = run(example, seed, events, false);
    QVERIFY2(outcome.failure.isEmpty(), qPrintable(outcome.failure));
    QVERIFY(outcome.edits > 0);  // the monkey did edit
}

void TestMonkey::reproducibleFromTheSeed()
{
    const Outcome first = run(QStringLiteral("springs"), 77u, 400, true);
    QVERIFY2(first.failure.isEmpty(), qPrintable(first.failure));
    const Outcome second = run(QStringLiteral("springs"), 77u, 400, true);
    QVERIFY2(second.failure.isEmpty(), qPrintable(second.failure));
    const bool same = second.undoSteps == first.undoSteps && second.edits == first.edits && second.scene == first.scene;
    QVERIFY2(same, qPrintable(QStringLiteral("two runs of seed 77 ended apart (undo steps %1 and %2, edits %3 and %4); %5")
                                  .arg(first.undoSteps).arg(second.undoSteps).arg(first.edits).arg(second.edits)
                                  .arg(whereTheyPart(first.trace, second.trace))));
    QVERIFY(first.edits > 0);
}

QTEST_MAIN(TestMonkey)
#include "test_monkey.moc"
