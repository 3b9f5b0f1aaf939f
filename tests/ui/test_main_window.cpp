// The editor's main window with real widgets and real key events, under a virtual X server: it
// opens on the springs example and draws it, F4 plays and pauses, F5 resets, the parameters dock
// edits the running simulation (and refuses what is out of range), the arrow keys steer the pool's
// ball (drawn as an arrow at it while it is pushed), T kicks from a seed (Simulation › Kick
// Particles, the handout's tilt), A switches collisions, F2 saves a screenshot, F1 lists the keys,
// and closing while running ends the worker thread. The integrator box reaches the worker; the status
// bar shows the local error and the energy drift; F7's accuracy dialog plans on the worker and
// applies its pick as one undoable edit. Waits are on frames, never fixed sleeps.

#include "ui/dialogs/accuracy_dialog.h"
#include "ui/simulation/frame_pacer.h"
#include "ui/dialogs/help_dialog.h"
#include "ui/panels/inspector_field.h"
#include "ui/panels/inspector_panel.h"
#include "ui/viewport/edit_tools.h"
#include "ui/document/document_files.h"
#include "ui/window/main_window.h"
#include "ui/window/window_size.h"
#include "ui/panels/parameter_row.h"
#include "ui/panels/parameters_panel.h"
#include "ui/document/scene_document.h"
#include "ui/simulation/simulation_controller.h"
#include "session/simulation_runner.h"
#include "ui/panels/value_spin_box.h"
#include "ui/viewport/viewport.h"

#include <QCheckBox>
#include <QLabel>
#include <QComboBox>
#include <QDockWidget>
#include <QStatusBar>
#include <QTableWidget>
#include <QScreen>
#include <QSettings>
#include <QSignalSpy>
#include <QSlider>
#include <QThread>
#include <QTimer>
#include <QUndoStack>
#include <QLineEdit>
#include <QRegularExpression>
#include <QScopeGuard>
#include <QScrollArea>
#include <QScrollBar>
#include <numeric>
#include <QtTest>

#include "editor_fixture.h"
#include "help_entries.h"

namespace {

using namespace Qt::StringLiterals;
using test::frameAfter;
using test::settledFrame;

// how far apart two colours are, per channel
int colourDistance(QRgb a, QRgb b)
{
    return std::max({std::abs(qRed(a) - qRed(b)), std::abs(qGreen(a) - qGreen(b)), std::abs(qBlue(a) - qBlue(b))});
}

}  // namespace

class TestMainWindow : public test::EditorTest {
    Q_OBJECT

private slots:
    void init();
    void cleanup();

    void opensOnTheSpringsExampleAndDrawsIt();
    void f4PlaysAndPauses();
    void f5RestoresTheInitialState();
    void speedMenuKeysAndBoxAgree();
    void toolbarsShowEveryFieldAtAnyWidth();
    void inspectorIsNeverCut();
    void statusBarShowsTheRun();
    void statusBarShowsFramesBesideSteps();
    void inspectorShowsTheCurrentStateBesideTheInitial();
    void sliderChangesTheStiffnessTheWorkerUses();
    void outOfRangeValueNeverReachesTheWorker();
    void undoReachesTheWorkerToo();
    void undoKeysWorkWhileAFieldHasTheFocus();
    void selectAllSaysWhatItSelected();
    void openingAnotherSceneClearsTheSelection();
    void framePacingStartsOverWithEachSceneAndPlay();
    void undoAndRedoSayWhatTheyDid();
    void warningsGoWhenStale();
    void blowupPausesAndShowsInTheStatusBar();
    void arrowKeysSteerThePoolBall();
    void cueStrikesThePoolBallWithSpin();
    void kickIsTheSameForTheSameSeed();
    void aSwitchesCollisions();
    void f2SavesAScreenshot();
    void f1ListsEveryShortcut();
    void integratorChoiceReachesTheWorker();
    void statusBarShowsTheLocalErrorAndTheDrift();
    void f7PlansAndAppliesTheCheapestIntegrator();
    void saveWritesTheEditedScene();
    void badFileLeavesTheSceneOpen();
    void examplesAreAllListed();
    void closingWhileRunningEndsTheWorker();
    void geometryIsRemembered();
    void clothLayersAreToggledAndRemembered();
    void firstSizeFitsTheScreen();

private:
    void press(Qt::Key key, Qt::KeyboardModifiers modifiers = Qt::NoModifier)
    {
        QTest::keyClick(m_window, key, modifiers);
    }
    // how many pixels of the view are in the steering arrow's colour
    int steeringPixels() const
    {
        const QImage image = m_window->viewport()->grabFramebuffer();
        const QColor arrow = QColor::fromRgbF(ui::kSteeringColour[0], ui::kSteeringColour[1], ui::kSteeringColour[2]);
        int count = 0;
        for (int y = 0; y < image.height(); ++y)
            for (int x = 0; x < image.width(); ++x) {
                const QColor c = image.pixelColor(x, y);
                count += std::abs(c.red() - arrow.red()) <= 8 && std::abs(c.green() - arrow.green()) <= 8 &&
                         std::abs(c.blue() - arrow.blue()) <= 8;
            }
        return count;
    }
};

void TestMainWindow::init()
{
    // shortcuts need an active window
    QVERIFY2(openEditor(), qPrintable(editorFailure()));
}

void TestMainWindow::cleanup()
{
    closeEditor();
}

void TestMainWindow::opensOnTheSpringsExampleAndDrawsIt()
{
    QVERIFY(m_window->windowTitle().startsWith(QStringLiteral("springs")));
    QVERIFY(!m_window->isWindowModified());
    const auto frame = settledFrame(controller());
    QCOMPARE(frame->snapshot->particleCount(), int(m_window->document()->scene().particles.size()));
    QVERIFY(frame->snapshot->particleCount() > 0);

    // the viewport has the frame, and draws something other than background where a free
    // particle projects
    ui::Viewport *viewport = m_window->viewport();
    QTRY_VERIFY(viewport->snapshot() == frame->snapshot);
    const QImage image = viewport->grabFramebuffer();
    QVERIFY(!image.isNull());
    const double scale = double(image.width()) / viewport->width();
    const core::SceneDesc &scene = m_window->document()->scene();
    const std::size_t middle = scene.particles.size() / 2;
    QVERIFY(!scene.particles[middle].pinned);
    const Eigen::Vector3d at = scene.particles[middle].position;
    const std::optional<QPointF> pixel = viewport->camera().project(QVector3D(float(at.x()), float(at.y()), float(at.z())));
    QVERIFY(pixel.has_value());
    const QPoint centre = (*pixel * scale).toPoint();
    QVERIFY(image.rect().contains(centre));
    const QRgb background = image.pixel(2, 2);
    int differing = 0;
    for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx)
            differing += colourDistance(image.pixel(centre + QPoint(dx, dy)), background) > 24 ? 1 : 0;
    QVERIFY2(differing >= 5, qPrintable(QStringLiteral("particle at (%1, %2) looks like background")
                                            .arg(centre.x())
                                            .arg(centre.y())));
}

void TestMainWindow::f4PlaysAndPauses()
{
    press(Qt::Key_F4);
    QVERIFY(controller().isRunning());
    QTRY_VERIFY(controller().frame()->snapshot->time > 0.05);

    // F4 again: the time stays where it stopped across two later ticks
    press(Qt::Key_F4);
    QVERIFY(!controller().isRunning());
    const auto paused = settledFrame(controller());
    QVERIFY(!paused->running);
    const auto later = settledFrame(controller());
    const auto evenLater = settledFrame(controller());
    QCOMPARE(later->snapshot->time, paused->snapshot->time);
    QCOMPARE(evenLater->snapshot->time, paused->snapshot->time);
    QVERIFY(paused->snapshot->time > 0.05);
}

void TestMainWindow::speedMenuKeysAndBoxAgree()
{
    // Simulation › Speed, the toolbar's box and [ ] set one speed, which the worker plays at
    auto *box = m_window->findChild<QComboBox *>(QStringLiteral("speedBox"));
    QVERIFY(box);
    QCOMPARE(controller().speed(), 1.0);
    QCOMPARE(box->currentText(), QStringLiteral("×1"));
    m_window->findChild<QAction *>(QStringLiteral("actionSpeedFourTimes"))->trigger();
    QCOMPARE(controller().speed(), 4.0);
    QCOMPARE(box->currentText(), QStringLiteral("×4"));
    press(Qt::Key_BracketRight);
    QCOMPARE(controller().speed(), 8.0);
    press(Qt::Key_BracketRight);
    QCOMPARE(controller().speed(), ui::SimulationRunner::kAsFastAsItGoes);
    QCOMPARE(box->currentText(), QStringLiteral("Fastest"));
    QVERIFY(m_window->findChild<QAction *>(QStringLiteral("actionSpeedAsFast"))->isChecked());
    press(Qt::Key_BracketRight);  // the end of the list
    QCOMPARE(controller().speed(), ui::SimulationRunner::kAsFastAsItGoes);

    // as fast as it goes: the run steps and its frames and status bar say so
    press(Qt::Key_F4);
    QTRY_VERIFY(controller().frame()->running && controller().frame()->snapshot->time > 0.05);
    QCOMPARE(controller().frame()->speed, ui::SimulationRunner::kAsFastAsItGoes);
    auto *rate = m_window->findChild<QLabel *>(QStringLiteral("statusRate"));
    QVERIFY(rate);
    QTRY_VERIFY_WITH_TIMEOUT(rate->text().endsWith(QStringLiteral("as fast as it goes")), 20000);
    press(Qt::Key_F4);

    // the box picks ×¼, and the menu follows; [ from the start of the list stays there
    emit box->activated(0);
    QCOMPARE(controller().speed(), 0.25);
    QVERIFY(m_window->findChild<QAction *>(QStringLiteral("actionSpeedQuarter"))->isChecked());
    QVERIFY(!m_window->findChild<QAction *>(QStringLiteral("actionSpeedAsFast"))->isChecked());
    press(Qt::Key_BracketLeft);
    QCOMPARE(controller().speed(), 0.25);
    QCOMPARE(box->currentText(), QStringLiteral("×¼"));
}

void TestMainWindow::toolbarsShowEveryFieldAtAnyWidth()
{
    // wide, as tested, and narrow: the tools, the new items' fields, Snap and its grid step and the
    // speed box all show, none behind the toolbar's "»"
    const QStringList names{u"speedBox"_s, u"defaultMass"_s, u"defaultRadius"_s, u"defaultStiffness"_s,
                            u"defaultDamping"_s, u"defaultSnap"_s, u"gridStep"_s};
    for (const int width : {1600, m_window->width(), 900}) {
        m_window->resize(width, m_window->height());
        for (const QString &name : names) {
            auto *widget = m_window->findChild<QWidget *>(name);
            QVERIFY2(widget, qPrintable(name));
            QTRY_VERIFY2(widget->isVisible() && !widget->visibleRegion().isEmpty(),
                         qPrintable(QStringLiteral("%1 hidden at %2 px").arg(name).arg(width)));
        }
    }
}

void TestMainWindow::inspectorIsNeverCut()
{
    // the inspector's dock as the window opens: two particles far apart, then 40 springs
    auto *dock = m_window->findChild<QDockWidget *>(u"inspectorDock"_s);
    QVERIFY(dock);
    auto *scroll = qobject_cast<QScrollArea *>(dock->widget());
    QVERIFY(scroll);
    const auto fitsWhole = [&](const QString &name) {
        auto *label = dock->findChild<QLabel *>(name);
        if (!label)
            return name + u" missing"_s;
        const QRect inViewport(label->mapTo(scroll->viewport(), QPoint(0, 0)), label->size());
        if (label->width() < label->sizeHint().width() || label->height() < label->sizeHint().height())
            return u"%1 is %2 x %3, its text needs %4 x %5"_s.arg(name).arg(label->width()).arg(label->height())
                .arg(label->sizeHint().width()).arg(label->sizeHint().height());
        if (inViewport.right() >= scroll->viewport()->width())
            return u"%1 ends at %2, behind the scroll bar from %3"_s.arg(name).arg(inViewport.right())
                .arg(scroll->viewport()->width());
        return QString();
    };
    m_window->document()->modify([](core::SceneDesc &scene) { scene.particles[0].position = {-1.2345678, 0.5, 2.25}; },
                                 ui::SceneChange::InitialConditions);
    m_window->editTools()->setSelection(ui::Selection{{0, 57}, {}});
    QCoreApplication::processEvents();
    QTRY_COMPARE(fitsWhole(u"inspector-distance-initial"_s), QString());
    QTRY_COMPARE(fitsWhole(u"inspector-distance-current"_s), QString());
    QVERIFY(!scroll->horizontalScrollBar()->isVisible());
    // a coordinate shows its 8 digits, in a field wide enough for them
    m_window->editTools()->setSelection(ui::Selection{{0}, {}});
    auto *x = dock->findChild<QAbstractSpinBox *>(u"inspector-position.x"_s);
    QVERIFY(x);
    QTRY_COMPARE(x->text(), u"-1.2345678"_s);
    QVERIFY(x->width() >= x->fontMetrics().horizontalAdvance(x->text()));

    std::vector<int> forty(40);
    std::iota(forty.begin(), forty.end(), 0);
    m_window->editTools()->setSelection(ui::Selection{{}, forty});
    QTRY_COMPARE(fitsWhole(u"inspector-springEnds"_s), QString());
    auto *ends = dock->findChild<QLabel *>(u"inspector-springEnds"_s);
    auto *stiffness = dock->findChild<QWidget *>(u"inspector-stiffness"_s);
    QVERIFY(ends && stiffness);
    QVERIFY(ends->mapTo(dock, QPoint(0, ends->height())).y() <= stiffness->mapTo(dock, QPoint(0, 0)).y());
    QVERIFY2(ends->text().endsWith(u" and 37 more"_s), qPrintable(ends->text()));
}

void TestMainWindow::f5RestoresTheInitialState()
{
    press(Qt::Key_F4);
    QTRY_VERIFY(controller().frame()->snapshot->time > 0.05);
    press(Qt::Key_F4);
    press(Qt::Key_F5);

    // every position as the scene file gives it, bit for bit as a float
    const auto frame = settledFrame(controller());
    QCOMPARE(frame->snapshot->time, 0.0);
    QCOMPARE(frame->snapshot->step, 0u);
    const core::SceneDesc &scene = m_window->document()->scene();
    for (std::size_t i = 0; i < scene.particles.size(); ++i)
        for (std::size_t axis = 0; axis < 3; ++axis)
            QCOMPARE(frame->snapshot->positions[3 * i + axis], float(scene.particles[i].position[Eigen::Index(axis)]));
}

void TestMainWindow::statusBarShowsTheRun()
{
    QCOMPARE(m_window->statusRate(), QStringLiteral("paused"));
    press(Qt::Key_F4);
    QTRY_VERIFY(m_window->statusRate().startsWith(QStringLiteral("×")) && m_window->statusRate().size() > 2);
    QTRY_VERIFY(m_window->statusTime() != QStringLiteral("t = 0.000 s"));
    QVERIFY(m_window->statusTime().endsWith(QStringLiteral(" s")));
}

void TestMainWindow::statusBarShowsFramesBesideSteps()
{
    // while running: the steps and the frames per second, side by side, each measured (never 0);
    // paused: neither
    QCOMPARE(m_window->statusSteps(), QString());
    QCOMPARE(m_window->statusFrames(), QString());
    QStringList seen;
    const QMetaObject::Connection watch =
        connect(&controller(), &ui::SimulationController::frameChanged, this, [&] { seen += m_window->statusSteps(); });
    const auto unwatch = qScopeGuard([&] { disconnect(watch); });
    press(Qt::Key_F4);
    const QRegularExpression measured(QStringLiteral("^[0-9.]+ (steps|frames)/s$"));
    QTRY_VERIFY2(measured.match(m_window->statusFrames()).hasMatch(), qPrintable(m_window->statusFrames()));
    QTRY_VERIFY2(measured.match(m_window->statusSteps()).hasMatch(), qPrintable(m_window->statusSteps()));
    QVERIFY(!m_window->statusFrames().startsWith(QStringLiteral("0 ")));
    for (const QString &steps : seen)
        QVERIFY2(steps != QStringLiteral("0 steps/s"), qPrintable(seen.join(QStringLiteral(", "))));

    // the frames' figure sits right after the steps'
    const QList<QLabel *> figures = m_window->statusBar()->findChildren<QLabel *>(Qt::FindDirectChildrenOnly);
    const auto at = [&](const char *name) {
        for (qsizetype i = 0; i < figures.size(); ++i)
            if (figures[i]->objectName() == QLatin1String(name))
                return i;
        return qsizetype(-1);
    };
    QVERIFY(at("statusSteps") >= 0);
    QCOMPARE(at("statusFrames"), at("statusSteps") + 1);

    press(Qt::Key_F4);
    QTRY_COMPARE(m_window->statusFrames(), QString());
    QTRY_COMPARE(m_window->statusSteps(), QString());
}

void TestMainWindow::inspectorShowsTheCurrentStateBesideTheInitial()
{
    // one particle falling from 2 m, selected
    core::SceneDesc scene;
    scene.name = "falling";
    scene.particles.push_back(core::ParticleDesc{});
    scene.particles[0].position = {0.0, 2.0, 0.0};
    m_window->document()->replace(scene, QString());
    QVERIFY(settledFrame(controller()));
    m_window->editTools()->setSelection({{0}, {}});
    ui::InspectorPanel *inspector = m_window->inspector();
    QLabel *currentY = inspector->currentField(QStringLiteral("position.y"));
    QLabel *currentVy = inspector->currentField(QStringLiteral("velocity.y"));
    QVERIFY(currentY && currentVy);
    QTRY_COMPARE(currentY->text(), QStringLiteral("2"));

    // a few steps: the current values are the snapshot's, the initial ones stay the scene's
    for (int i = 0; i < 5; ++i)
        press(Qt::Key_F6);
    QTRY_VERIFY(controller().frame()->snapshot->step >= 5 && !controller().isRunning());
    const std::shared_ptr<const core::Snapshot> snapshot = controller().frame()->snapshot;
    QTRY_COMPARE(currentY->text(), QString::number(double(snapshot->positions[1]), 'g', 6));
    QCOMPARE(currentVy->text(), QString::number(double(snapshot->velocities[1]), 'g', 6));
    QVERIFY(currentY->text().toDouble() < 2.0);
    QVERIFY(currentVy->text().toDouble() < 0.0);
    ui::InspectorSpinBox *initialY = inspector->particleField(QStringLiteral("position.y"));
    QCOMPARE(initialY->value(), 2.0);

    // the initial y is still typed, and undone
    initialY->setFocus();
    initialY->selectAll();
    QTest::keyClicks(initialY, QStringLiteral("3"));
    QTest::keyClick(initialY, Qt::Key_Return);
    QCOMPARE(m_window->document()->scene().particles[0].position.y(), 3.0);
    m_window->document()->undoStack()->undo();
    QCOMPARE(m_window->document()->scene().particles[0].position.y(), 2.0);
    QCOMPARE(initialY->value(), 2.0);
}

void TestMainWindow::sliderChangesTheStiffnessTheWorkerUses()
{
    // while running, a move of the real slider reaches the worker's model
    press(Qt::Key_F4);
    QTRY_VERIFY(controller().frame()->snapshot->step > 0);
    ui::ParameterRow *row = m_window->parametersPanel()->row(QStringLiteral("stiffness"));
    const ui::SliderScale scale = ui::sliderScale(core::parameterInfo(core::Parameter::Stiffness));
    row->slider()->setValue(scale.positionOf(500.0));
    const double expected = scale.valueAt(row->slider()->value());
    QVERIFY(expected != 4000.0);

    const auto frame = settledFrame(controller());
    QVERIFY(frame->running);
    for (Eigen::Index k = 0; k < frame->model->stiffness.size(); ++k)
        QCOMPARE(frame->model->stiffness[k], expected);
    QVERIFY(m_window->isWindowModified());
}

void TestMainWindow::outOfRangeValueNeverReachesTheWorker()
{
    ui::ParameterRow *row = m_window->parametersPanel()->row(QStringLiteral("stiffness"));
    const double before = row->value();
    row->spinBox()->setFocus();
    row->spinBox()->selectAll();
    QTest::keyClicks(row->spinBox(), QStringLiteral("5e9"));
    QTest::keyClick(row->spinBox(), Qt::Key_Return);

    // refused with a message, in the panel and the status bar; the worker keeps the old value
    QVERIFY(m_window->parametersPanel()->message().contains(QStringLiteral("at most")));
    QCOMPARE(m_window->statusWarning(), m_window->parametersPanel()->message());
    const auto frame = settledFrame(controller());
    QCOMPARE(frame->model->stiffness[0], before);
    QCOMPARE(m_window->document()->scene().springs.front().stiffness, before);
    QVERIFY(!m_window->isWindowModified());
}

void TestMainWindow::undoReachesTheWorkerToo()
{
    ui::ParameterRow *row = m_window->parametersPanel()->row(QStringLiteral("gravity.y"));
    row->slider()->setValue(0);
    QCOMPARE(settledFrame(controller())->model->gravity.y(), -20.0);
    press(Qt::Key_Z, Qt::ControlModifier);
    QCOMPARE(settledFrame(controller())->model->gravity.y(), -9.81);
    QCOMPARE(row->value(), -9.81);
    QVERIFY(!m_window->isWindowModified());
}

void TestMainWindow::undoKeysWorkWhileAFieldHasTheFocus()
{
    // a value typed into the dock and entered: the field keeps the focus, and Ctrl+Z there undoes
    // the scene's edit, Ctrl+Y and Ctrl+Shift+Z redo it
    ui::ParameterRow *row = m_window->parametersPanel()->row(QStringLiteral("viscosity"));
    QAbstractSpinBox *field = row->spinBox();
    field->setFocus();
    QTRY_VERIFY(field->hasFocus());
    field->selectAll();
    QTest::keyClicks(field, QStringLiteral("0.75"));
    QTest::keyClick(field, Qt::Key_Return);
    QCOMPARE(m_window->document()->scene().settings.viscosity, 0.75);
    QVERIFY(field->hasFocus());
    QTest::keyClick(field, Qt::Key_Z, Qt::ControlModifier);
    QCOMPARE(m_window->document()->scene().settings.viscosity, 0.0);
    QCOMPARE(row->value(), 0.0);
    QTest::keyClick(field, Qt::Key_Y, Qt::ControlModifier);
    QCOMPARE(m_window->document()->scene().settings.viscosity, 0.75);
    QTest::keyClick(field, Qt::Key_Z, Qt::ControlModifier);
    QTest::keyClick(field, Qt::Key_Z, Qt::ControlModifier | Qt::ShiftModifier);
    QCOMPARE(m_window->document()->scene().settings.viscosity, 0.75);

    // while a value is being typed, Ctrl+Z undoes the typing, as in any text field
    field->selectAll();
    QTest::keyClicks(field, QStringLiteral("3"));
    QTest::keyClick(field, Qt::Key_Z, Qt::ControlModifier);
    QCOMPARE(m_window->document()->scene().settings.viscosity, 0.75);
    QVERIFY(field->findChild<QLineEdit *>()->text() != QStringLiteral("3"));
}

void TestMainWindow::selectAllSaysWhatItSelected()
{
    // the status bar says what Ctrl+A selected, not what an earlier rubber band did
    const core::SceneDesc &scene = m_window->document()->scene();
    QVERIFY(scene.particles.size() > 1 && !scene.springs.empty());
    m_window->viewport()->setFocus();
    press(Qt::Key_A, Qt::ControlModifier);
    QCOMPARE(m_window->statusBar()->currentMessage(),
             QStringLiteral("%1 particles and %2 springs selected").arg(scene.particles.size()).arg(scene.springs.size()));
    press(Qt::Key_Escape);
    QCOMPARE(m_window->statusBar()->currentMessage(), QStringLiteral("Nothing selected"));
}

void TestMainWindow::openingAnotherSceneClearsTheSelection()
{
    // Examples › springs, Ctrl+A, Examples › collisions: nothing of the new scene is selected, and
    // Delete leaves it whole (it used to keep the old selection by index and empty the new scene)
    QString error;
    QVERIFY2(m_window->files()->openExample(QStringLiteral("springs"), &error), qPrintable(error));
    m_window->viewport()->setFocus();
    press(Qt::Key_A, Qt::ControlModifier);
    QVERIFY(!m_window->editTools()->selection().particles.empty());
    QVERIFY2(m_window->files()->openExample(QStringLiteral("collisions"), &error), qPrintable(error));
    const std::size_t count = m_window->document()->scene().particles.size();
    QVERIFY(count > 0);
    QVERIFY(m_window->editTools()->selection().particles.empty());
    QVERIFY(m_window->editTools()->selection().springs.empty());
    QVERIFY(!m_window->editTools()->measurement());
    m_window->viewport()->setFocus();
    press(Qt::Key_Delete);
    QCOMPARE(m_window->document()->scene().particles.size(), count);
}

void TestMainWindow::framePacingStartsOverWithEachSceneAndPlay()
{
    // a frame interval left by costly frames (30 s: a scene of 10⁶ particles drawn in software)
    // is not the next scene's, nor the next Play's: both start at the most frames again
    const double most = 1.0 / ui::FramePacer::kMostFramesPerSecond;
    controller().setFrameInterval(30.0);
    QCOMPARE(controller().frameInterval(), 30.0);
    QString error;
    QVERIFY2(m_window->files()->openExample(QStringLiteral("collisions"), &error), qPrintable(error));
    QVERIFY(std::abs(controller().frameInterval() - most) < 1e-9);
    controller().setFrameInterval(30.0);
    press(Qt::Key_F4);
    QTRY_VERIFY(controller().frame()->running);
    QVERIFY2(controller().frameInterval() <= ui::FramePacer::kMostSecondsBetweenFrames,
             qPrintable(QString::number(controller().frameInterval())));
    press(Qt::Key_F4);
}

void TestMainWindow::undoAndRedoSayWhatTheyDid()
{
    // an edit (A: collisions off), then Undo and Redo: the status bar names the edit each time
    press(Qt::Key_A);
    QTRY_VERIFY(!m_window->document()->scene().settings.planeCollisions);
    press(Qt::Key_Z, Qt::ControlModifier);
    QTRY_VERIFY(m_window->document()->scene().settings.planeCollisions);
    QCOMPARE(m_window->statusBar()->currentMessage(), QStringLiteral("Undid “Collisions off”"));
    press(Qt::Key_Z, Qt::ControlModifier | Qt::ShiftModifier);
    QTRY_VERIFY(!m_window->document()->scene().settings.planeCollisions);
    QCOMPARE(m_window->statusBar()->currentMessage(), QStringLiteral("Redid “Collisions off”"));
    // two at once, from the history (a click in View › Undo History): both counted, the
    // earliest named; and back again
    QUndoStack *stack = m_window->document()->undoStack();
    stack->push(new QUndoCommand(QStringLiteral("Second")));
    const int top = stack->index();
    stack->setIndex(top - 2);
    QCOMPARE(m_window->statusBar()->currentMessage(), QStringLiteral("Undid 2 edits, back to before “Collisions off”"));
    stack->setIndex(top);
    QCOMPARE(m_window->statusBar()->currentMessage(), QStringLiteral("Redid 2 edits, up to “Second”"));
}

void TestMainWindow::warningsGoWhenStale()
{
    // a refused value is said until the next edit, undo or reset, not for ever
    ui::ParameterRow *row = m_window->parametersPanel()->row(QStringLiteral("substeps"));
    const auto typeInto = [&](const QString &text) {
        row->spinBox()->setFocus();
        row->spinBox()->selectAll();
        QTest::keyClicks(row->spinBox(), text);
        QTest::keyClick(row->spinBox(), Qt::Key_Return);
    };
    typeInto(QStringLiteral("0.5"));
    QVERIFY2(m_window->statusWarning().contains(QStringLiteral("Substeps")), qPrintable(m_window->statusWarning()));
    typeInto(QStringLiteral("2"));
    QCOMPARE(m_window->document()->scene().settings.substeps, 2);
    QCOMPARE(m_window->statusWarning(), QString());

    typeInto(QStringLiteral("0.5"));
    QVERIFY(!m_window->statusWarning().isEmpty());
    m_window->viewport()->setFocus();
    press(Qt::Key_Z, Qt::ControlModifier);
    QCOMPARE(m_window->document()->scene().settings.substeps, 1);
    QCOMPARE(m_window->statusWarning(), QString());

    typeInto(QStringLiteral("0.5"));
    QVERIFY(!m_window->statusWarning().isEmpty());
    m_window->viewport()->setFocus();
    press(Qt::Key_F5);
    QCOMPARE(m_window->statusWarning(), QString());
}

void TestMainWindow::blowupPausesAndShowsInTheStatusBar()
{
    // springs far too stiff for the time step
    core::SceneDesc scene = m_window->document()->scene();
    scene.settings.timeStep = 0.1;
    for (core::SpringDesc &spring : scene.springs)
        spring.stiffness = 1e9;
    m_window->document()->replace(scene, QString());
    QSignalSpy blewUp(&controller(), &ui::SimulationController::blewUp);
    press(Qt::Key_F4);
    QVERIFY(blewUp.wait(10000));

    // paused at the last good state, and the status bar says what failed, when, why and the fix
    QVERIFY(!controller().isRunning());
    const QString warning = m_window->statusWarning();
    QVERIFY2((warning.startsWith(QStringLiteral("Particle ")) || warning.startsWith(QStringLiteral("The total energy grew "))) &&
                 warning.contains(QStringLiteral("(step ")) &&
                 warning.contains(QStringLiteral("the stability limit")) &&
                 warning.contains(QStringLiteral("for stiffness 1e+09 N/m with symplectic-euler: use ≥ ")) &&
                 warning.endsWith(QStringLiteral("Paused at the last good state.")),
             qPrintable(warning));
    const auto frame = settledFrame(controller());
    QVERIFY(!frame->running);
    QCOMPARE(m_window->statusRate(), QStringLiteral("paused"));
    for (float x : frame->snapshot->positions)
        QVERIFY(std::isfinite(x));

    // the parameters panel said so before the run: the sub-step is past the limit, in red
    ui::ParametersPanel *panel = m_window->parametersPanel();
    QLabel *note = panel->stabilityLabel();
    QVERIFY2(note->text().contains(QStringLiteral("× over: use ≥ ")), qPrintable(note->text()));
    QVERIFY(note->styleSheet().contains(QStringLiteral("#b00020")));

    // auto substeps, by a click: the worker takes as many as the limit asks, and the run holds
    QTest::mouseClick(panel->autoSubstepsBox(), Qt::LeftButton, {},
                      QPoint(8, panel->autoSubstepsBox()->height() / 2));
    QVERIFY(m_window->document()->scene().settings.autoSubsteps);
    const auto automatic = settledFrame(controller());
    QVERIFY(automatic->model->substeps > 100);
    QVERIFY(automatic->model->subStep() <= core::kStableShare * automatic->stability->maxSubStep(core::Integrator::SymplecticEuler));
    QTRY_VERIFY2(!note->styleSheet().contains(QStringLiteral("#b00020")) && note->text().contains(QStringLiteral("auto: ")),
                 qPrintable(note->text()));
    press(Qt::Key_F5);
    blewUp.clear();
    press(Qt::Key_F4);
    const std::uint64_t start = settledFrame(controller())->snapshot->step;
    QTRY_VERIFY_WITH_TIMEOUT(controller().frame()->snapshot->step >= start + 5, 20000);
    press(Qt::Key_F4);
    QCOMPARE(blewUp.count(), 0);
    for (float x : settledFrame(controller())->snapshot->positions)
        QVERIFY(std::isfinite(x));
    // and undo switches it off again
    m_window->document()->undoStack()->undo();
    QVERIFY(!m_window->document()->scene().settings.autoSubsteps);
    QVERIFY(!panel->autoSubstepsBox()->isChecked());
}

void TestMainWindow::arrowKeysSteerThePoolBall()
{
    QString error;
    QVERIFY2(m_window->files()->openExample(QStringLiteral("pool"), &error), qPrintable(error));
    const core::SceneDesc &scene = m_window->document()->scene();
    QVERIFY2(scene.steerable >= 0, "the pool example names no steerable particle");
    const auto ball = std::size_t(scene.steerable);
    const double mass = scene.particles[ball].mass;
    QVERIFY(settledFrame(controller())->scene == m_window->document()->sharedScene());

    // at rest without a push: no arrow, and two steps (F6) change no horizontal momentum
    QCOMPARE(steeringPixels(), 0);
    press(Qt::Key_F6);
    press(Qt::Key_F6);
    const auto still = settledFrame(controller());
    QCOMPARE(still->snapshot->step, 2u);
    QCOMPARE(still->snapshot->momentum.x(), 0.0);

    // three presses of Up push along +x: the ball gains speed in x
    press(Qt::Key_Up);
    press(Qt::Key_Up);
    press(Qt::Key_Up);
    QCOMPARE(m_window->steering().level, 3);
    // the arrow in the view shows the push at the ball
    QCOMPARE(m_window->viewport()->steeringArrow().particle, int(ball));
    QCOMPARE_GT(steeringPixels(), 20);
    for (int i = 0; i < 5; ++i)
        press(Qt::Key_F6);
    const auto pushed = settledFrame(controller());
    QCOMPARE(pushed->snapshot->step, 7u);
    const double speedX = pushed->snapshot->momentum.x() / mass;
    QVERIFY2(speedX > 0.05, qPrintable(QString::number(speedX)));
    QVERIFY(pushed->snapshot->positions[3 * ball] > still->snapshot->positions[3 * ball]);

    // six presses of Left turn the push a quarter turn, to -z
    for (int i = 0; i < 6; ++i)
        press(Qt::Key_Left);
    QCOMPARE(m_window->steering().angle, 90.0);
    for (int i = 0; i < 5; ++i)
        press(Qt::Key_F6);
    const auto turned = settledFrame(controller());
    QVERIFY(turned->snapshot->momentum.z() < pushed->snapshot->momentum.z() - 0.05 * mass);

    // Down to zero: no more push
    for (int i = 0; i < 3; ++i)
        press(Qt::Key_Down);
    QCOMPARE(m_window->steering().level, 0);
    QCOMPARE(steeringPixels(), 0);
}

void TestMainWindow::cueStrikesThePoolBallWithSpin()
{
    QString error;
    QVERIFY2(m_window->files()->openExample(QStringLiteral("pool"), &error), qPrintable(error));
    const core::SceneDesc &scene = m_window->document()->scene();
    const auto ball = std::size_t(scene.steerable);
    const double mass = scene.particles[ball].mass, radius = scene.particles[ball].radius;
    QVERIFY(settledFrame(controller())->model->plan.spin);  // the felt has friction

    // S strikes; Shift+Up makes the stroke faster, Page Down moves the cue below the centre
    auto *strike = m_window->findChild<QAction *>(QStringLiteral("actionStrikeCueBall"));
    QVERIFY(strike && strike->isEnabled());
    QCOMPARE(strike->shortcut(), QKeySequence(Qt::Key_S));
    press(Qt::Key_Up, Qt::ShiftModifier);
    press(Qt::Key_Up, Qt::ShiftModifier);
    for (int i = 0; i < 3; ++i)
        press(Qt::Key_PageDown);
    QCOMPARE(m_window->steering().strikeSpeed(), 5.0);
    QCOMPARE(m_window->steering().cueHeight, -3);
    QCOMPARE(m_window->steering().level, 0);  // the push is left alone
    auto *figure = m_window->statusBar()->findChild<QLabel *>(QStringLiteral("statusSteer"));
    QVERIFY(figure);
    QCOMPARE(figure->text(), QStringLiteral("push 0 N 0°; cue 5 m/s −0.3r"));

    // struck paused, then a step: along +x at 5 m/s with backspin 5 s h / (2 r²) = 7.5 rad/s about
    // up × x = -z, which friction has barely touched in one step
    press(Qt::Key_S);
    QVERIFY2(m_window->statusBar()->currentMessage().startsWith(
                 QStringLiteral("Particle %1 struck at 5 m/s, 0.3 r below the centre: spin 7.5 rad/s").arg(ball)),
             qPrintable(m_window->statusBar()->currentMessage()));
    press(Qt::Key_F6);
    const auto struck = settledFrame(controller());
    QCOMPARE(struck->snapshot->step, 1u);
    const double speed = struck->snapshot->momentum.x() / mass;
    const double spinZ = struck->snapshot->angularVelocities[3 * ball + 2];
    const double expectedSpin = 5.0 * 5.0 * 0.3 * radius / (2.0 * radius * radius);
    QVERIFY2(std::abs(speed - 5.0) < 0.05, qPrintable(QString::number(speed)));
    QVERIFY2(std::abs(spinZ - expectedSpin) < 0.05 * expectedSpin, qPrintable(QString::number(spinZ)));
    // backspin: the point touching the felt slides forward faster than the ball
    QVERIFY(speed + radius * spinZ > speed);
    // a Reset takes the stroke back, as it does every edit of the run
    press(Qt::Key_F5);
    QCOMPARE(settledFrame(controller())->snapshot->momentum.x(), 0.0);
}

void TestMainWindow::kickIsTheSameForTheSameSeed()
{
    // the menu names T for what it does, and says it is the handout's tilt; so does F1's table
    auto *kick = m_window->findChild<QAction *>(QStringLiteral("actionKickParticles"));
    QVERIFY(kick);
    QCOMPARE(kick->shortcut(), QKeySequence(Qt::Key_T));
    QCOMPARE(kick->text(), QStringLiteral("&Kick Particles"));
    QVERIFY2(kick->statusTip().contains(QStringLiteral("random velocity")) &&
                 kick->statusTip().contains(QStringLiteral("\"tilt\"")),
             qPrintable(kick->statusTip()));
    const std::optional<QStringList> entries = test::helpEntries(m_window);
    QVERIFY(entries);
    QVERIFY2(entries->contains(QStringLiteral("T\tSimulation › Kick Particles: ") + kick->statusTip()),
             qPrintable(entries->filter(QStringLiteral("Simulation ›")).join(QLatin1Char('\n'))));

    // T, then one step: the positions show the kick
    auto tiltAndStep = [this](std::uint64_t seed) {
        press(Qt::Key_F5);
        controller().setTiltSeed(seed);
        press(Qt::Key_T);
        press(Qt::Key_F6);
        return settledFrame(controller())->snapshot->positions;
    };
    const std::vector<float> first = tiltAndStep(11);
    const std::vector<float> again = tiltAndStep(11);
    const std::vector<float> other = tiltAndStep(12);
    press(Qt::Key_F5);
    press(Qt::Key_F6);
    const std::vector<float> untilted = settledFrame(controller())->snapshot->positions;
    QVERIFY(first == again);
    QVERIFY(first != other);
    QVERIFY(first != untilted);
}

void TestMainWindow::aSwitchesCollisions()
{
    QVERIFY(m_window->document()->scene().settings.planeCollisions);
    press(Qt::Key_A);
    auto frame = settledFrame(controller());
    QVERIFY(!frame->scene->settings.planeCollisions);
    QVERIFY(!frame->scene->settings.particleCollisions);
    QVERIFY(!frame->model->plan.particleCollisions);
    QVERIFY(!m_window->parametersPanel()->planeCollisionsBox()->isChecked());

    press(Qt::Key_A);
    frame = settledFrame(controller());
    QVERIFY(frame->scene->settings.planeCollisions);
    QVERIFY(frame->scene->settings.particleCollisions);
}

void TestMainWindow::f2SavesAScreenshot()
{
    const QString folder = m_files.filePath(QStringLiteral("shots"));
    m_window->setScreenshotDirectory(folder);
    QTRY_VERIFY(m_window->viewport()->snapshot() != nullptr);
    press(Qt::Key_F2);
    const QStringList shots = QDir(folder).entryList({QStringLiteral("*.png")});
    QCOMPARE(shots.size(), 1);
    QVERIFY(shots.front().startsWith(QStringLiteral("springlab-springs-")));
    const QImage image(QDir(folder).filePath(shots.front()));
    QVERIFY(!image.isNull());
    QCOMPARE(image.size(), m_window->viewport()->grabFramebuffer().size());

    // a second one in the same second gets its own name
    press(Qt::Key_F2);
    QCOMPARE(QDir(folder).entryList({QStringLiteral("*.png")}).size(), 2);
}

void TestMainWindow::f1ListsEveryShortcut()
{
    const std::optional<QStringList> entries = test::helpEntries(m_window);
    QVERIFY(entries);

    // every key of the handout, and the mouse
    const QString all = entries->join(QLatin1Char('\n'));
    for (const char *key : {"F1\t", "F2\t", "F4\t", "F5\t", "F6\t", "F7\t", "T\t", "A\t", "Left\t", "Right\t", "Up\t",
                            "Down\t", "F, Home\t", "Ctrl+Z\t"})
        QVERIFY2(all.contains(QLatin1String(key)) || all.contains(QLatin1Char('\n') + QLatin1String(key)), key);
    QVERIFY(all.contains(QStringLiteral("Orbit")));
    QVERIFY(all.contains(QStringLiteral("Pan")));
    QVERIFY(all.contains(QStringLiteral("Zoom")));

    // and what tells how accurate the run is
    QVERIFY(all.contains(QStringLiteral("Accuracy")));
    QVERIFY(all.contains(QStringLiteral("Integrator")));
    QVERIFY(all.contains(QStringLiteral("local error")));
    QVERIFY(all.contains(QStringLiteral("ΔE")));

    // and the plots, with what their lost energy is
    QVERIFY(all.contains(QStringLiteral("F8\tView › Plots")));
    QVERIFY(all.contains(QStringLiteral("lost since reset")));
    QVERIFY(all.contains(QStringLiteral("Export CSV")));
}

void TestMainWindow::integratorChoiceReachesTheWorker()
{
    // three presses of Down in the box, while running: rk4 from symplectic-euler
    press(Qt::Key_F4);
    QComboBox *box = m_window->parametersPanel()->integratorBox();
    QCOMPARE(box->currentText(), QStringLiteral("symplectic-euler"));
    box->setFocus();
    for (int i = 0; i < 3; ++i)
        QTest::keyClick(box, Qt::Key_Down);
    QCOMPARE(box->currentText(), QStringLiteral("rk4"));
    auto frame = settledFrame(controller());
    QVERIFY(frame->running);
    QCOMPARE(frame->model->integrator, core::Integrator::Rk4);
    ui::ParameterRow *tolerance = m_window->parametersPanel()->row(QStringLiteral("tolerance"));
    QVERIFY(!tolerance->isEnabled());

    // the adaptive one (two below rk4), and its tolerance typed in
    QTest::keyClick(box, Qt::Key_Down);
    QTest::keyClick(box, Qt::Key_Down);
    QVERIFY(tolerance->isEnabled());
    tolerance->spinBox()->setFocus();
    tolerance->spinBox()->selectAll();
    QTest::keyClicks(tolerance->spinBox(), QStringLiteral("1e-8"));
    QTest::keyClick(tolerance->spinBox(), Qt::Key_Return);
    frame = settledFrame(controller());
    QCOMPARE(frame->model->integrator, core::Integrator::AdaptiveRk45);
    QCOMPARE(frame->model->tolerance, 1e-8);

    // undo, step by step, reaches the worker too
    m_window->viewport()->setFocus();
    press(Qt::Key_Z, Qt::ControlModifier);
    QCOMPARE(settledFrame(controller())->model->tolerance, 1e-6);
    press(Qt::Key_Z, Qt::ControlModifier);
    QCOMPARE(settledFrame(controller())->model->integrator, core::Integrator::ImplicitEuler);
    press(Qt::Key_Z, Qt::ControlModifier);
    QCOMPARE(settledFrame(controller())->model->integrator, core::Integrator::Rk4);
    QCOMPARE(box->currentText(), QStringLiteral("rk4"));
}

void TestMainWindow::statusBarShowsTheLocalErrorAndTheDrift()
{
    // running: an estimate of the local error, and the drift since the scene was loaded
    press(Qt::Key_F4);
    QTRY_VERIFY(m_window->statusError().startsWith(QStringLiteral("local error ≈ ")) &&
                m_window->statusError().endsWith(QStringLiteral(" m/step")));
    QTRY_VERIFY(controller().frame()->snapshot->step > 20);
    QVERIFY(m_window->statusDrift().startsWith(QStringLiteral("ΔE = ")));
    const auto frame = settledFrame(controller());
    QVERIFY(frame->localError.has_value() && *frame->localError > 0.0);

    // paused and reset: no drift
    press(Qt::Key_F4);
    press(Qt::Key_F5);
    const auto reset = settledFrame(controller());
    QCOMPARE(reset->snapshot->energies.total(), reset->initialEnergies.total());
    QTRY_VERIFY2(m_window->statusDrift() == QStringLiteral("ΔE = 0 %") ||
                     m_window->statusDrift() == QStringLiteral("ΔE = 0 J"),
                 qPrintable(m_window->statusDrift()));
}

void TestMainWindow::f7PlansAndAppliesTheCheapestIntegrator()
{
    // F7 while running opens the dialog
    press(Qt::Key_F4);
    QTRY_VERIFY(controller().frame()->snapshot->step > 0);
    press(Qt::Key_F7);
    ui::AccuracyDialog *dialog = m_window->accuracyDialog();
    QVERIFY(dialog != nullptr);
    QVERIFY(QTest::qWaitForWindowExposed(dialog));

    // a tolerance out of range is refused there
    QUndoStack *undo = m_window->document()->undoStack();
    dialog->toleranceBox()->setFocus();
    dialog->toleranceBox()->selectAll();
    QTest::keyClicks(dialog->toleranceBox(), QStringLiteral("5"));
    QTest::keyClick(dialog->toleranceBox(), Qt::Key_Return);
    QVERIFY2(dialog->summary().contains(QStringLiteral("must be at most")), qPrintable(dialog->summary()));
    QCOMPARE(undo->count(), 0);

    // 1e-7 m per step, typed and Return: the worker plans, the pick is applied as one edit
    auto planned = std::make_shared<std::shared_ptr<const core::AccuracyPlan>>();
    const QObject receiver;
    connect(&controller(), &ui::SimulationController::accuracyPlanned, &receiver,
            [planned](const ui::AccuracyPlanReply &reply) { *planned = reply.plan; });
    dialog->toleranceBox()->selectAll();
    QTest::keyClicks(dialog->toleranceBox(), QStringLiteral("1e-7"));
    QTest::keyClick(dialog->toleranceBox(), Qt::Key_Return);
    QTRY_COMPARE_WITH_TIMEOUT(undo->count(), 1, 20000);
    const auto frame = settledFrame(controller());
    QVERIFY(*planned != nullptr);
    const core::PlanCandidate *pick = (*planned)->pick();
    QVERIFY(pick != nullptr);
    QCOMPARE((*planned)->tolerance, 1e-7);
    QVERIFY(pick->localError <= 1e-7);
    QCOMPARE(frame->model->integrator, pick->integrator);
    QCOMPARE(frame->model->substeps, pick->substeps);
    QVERIFY(frame->running);

    // it says what it picked and why, in the dialog and the status bar, above the whole table
    const std::string_view name = core::integratorName(pick->integrator);
    QVERIFY2(dialog->summary().startsWith(QString::fromLatin1(name.data(), qsizetype(name.size()))),
             qPrintable(dialog->summary()));
    QVERIFY(dialog->summary().contains(QStringLiteral("per simulated second")));
    QVERIFY(dialog->summary().contains(QStringLiteral("meet")));
    QCOMPARE(m_window->statusBar()->currentMessage(), dialog->summary());
    QCOMPARE(dialog->table()->rowCount(), int(std::size(core::kIntegrators)));

    // closed, the dialog hands the keyboard back: one undo gives back the scene's integrator and
    // substeps, in the worker too
    dialog->close();
    QVERIFY(test::showActive(*m_window));
    press(Qt::Key_Z, Qt::ControlModifier);
    QTRY_COMPARE(undo->index(), 0);
    const auto undone = settledFrame(controller());
    QCOMPARE(undone->model->integrator, core::Integrator::SymplecticEuler);
    QCOMPARE(undone->model->substeps, 1);
}

void TestMainWindow::saveWritesTheEditedScene()
{
    // an edit marks the window modified; saving clears the mark and the file has the edit
    m_window->parametersPanel()->row(QStringLiteral("viscosity"))->slider()->setValue(100);
    QVERIFY(m_window->isWindowModified());
    const QString path = m_files.filePath(QStringLiteral("saved.json"));
    QString error;
    QVERIFY2(m_window->files()->saveTo(path, &error), qPrintable(error));
    QVERIFY(!m_window->isWindowModified());
    QCOMPARE(m_window->document()->filePath(), QFileInfo(path).absoluteFilePath());

    // opening it again gives the same scene, bit for bit
    const core::SceneDesc saved = m_window->document()->scene();
    QVERIFY(m_window->files()->openScene(path, &error));
    QVERIFY(m_window->document()->scene() == saved);
    QVERIFY(m_window->document()->scene().settings.viscosity > 0.0);
}

void TestMainWindow::badFileLeavesTheSceneOpen()
{
    // a file that is not JSON: the message names the file, and springs stays open
    const QString path = m_files.filePath(QStringLiteral("broken.json"));
    QFile file(path);
    QVERIFY(file.open(QIODevice::WriteOnly));
    file.write("{ \"format\": \"springlab-scene\", ");
    file.close();
    QString error;
    QVERIFY(!m_window->files()->openScene(path, &error));
    QVERIFY2(error.contains(QStringLiteral("broken.json")), qPrintable(error));
    QCOMPARE(m_window->document()->displayName(), QStringLiteral("springs"));

    QVERIFY(!m_window->files()->openScene(m_files.filePath(QStringLiteral("missing.json")), &error));
    QVERIFY2(error.contains(QStringLiteral("missing.json")), qPrintable(error));
}

void TestMainWindow::examplesAreAllListed()
{
    const QStringList names = ui::DocumentFiles::exampleNames();
    QCOMPARE(names.mid(0, 6), (QStringList{"particles", "springs", "collisions", "pool", "pool-break", "cloth"}));
    for (const QString &name : names) {
        QString error;
        QVERIFY2(m_window->files()->openExample(name, &error), qPrintable(error));
        QVERIFY(m_window->windowTitle().startsWith(m_window->document()->displayName()));
        QCOMPARE(settledFrame(controller())->snapshot->particleCount(),
                 int(m_window->document()->scene().particles.size()));
    }
}

void TestMainWindow::closingWhileRunningEndsTheWorker()
{
    press(Qt::Key_F4);
    QTRY_VERIFY(controller().frame()->snapshot->time > 0.0);
    QThread *thread = controller().workerThread();
    QVERIFY(thread->isRunning());
    QVERIFY(m_window->close());
    QVERIFY(thread->isFinished());
    QVERIFY(controller().isShutDown());
}

void TestMainWindow::geometryIsRemembered()
{
    // closing saves the size and the docks; the next window comes back the same
    m_window->resize(900, 640);
    QTRY_COMPARE(m_window->size(), QSize(900, 640));
    auto *dock = m_window->findChild<QDockWidget *>(QStringLiteral("parametersDock"));
    QVERIFY(dock);
    dock->hide();
    QVERIFY(m_window->close());

    QVERIFY2(openEditor({.activate = false, .settle = false}), qPrintable(editorFailure()));
    QCOMPARE(m_window->size(), QSize(900, 640));
    QVERIFY(m_window->findChild<QDockWidget *>(QStringLiteral("parametersDock"))->isHidden());

    // and nothing was written outside the test's own folder
    QSettings settings;
    QVERIFY(settings.fileName().startsWith(settingsPath()));
}

void TestMainWindow::clothLayersAreToggledAndRemembered()
{
    // View › Surface, Spheres on Surface, Springs on Surface: the sheet alone at first
    auto action = [this](const char *name) { return m_window->findChild<QAction *>(QString::fromLatin1(name)); };
    QAction *surface = action("actionShowSurface");
    QAction *spheres = action("actionSurfaceSpheres");
    QAction *springs = action("actionSurfaceSprings");
    QVERIFY(surface && spheres && springs);
    QVERIFY(surface->isChecked() && !spheres->isChecked() && !springs->isChecked());
    QCOMPARE(m_window->viewport()->layers(), ui::ViewLayers{});

    // each reaches the view; the sheet's options wait while it is off
    springs->trigger();
    QVERIFY(m_window->viewport()->layers().surfaceSprings);
    surface->trigger();
    QVERIFY(!m_window->viewport()->layers().surface);
    QVERIFY(!spheres->isEnabled() && !springs->isEnabled());

    // and the next window draws the same way
    QVERIFY(m_window->close());
    QVERIFY2(openEditor({.activate = false, .settle = false}), qPrintable(editorFailure()));
    QCOMPARE(m_window->viewport()->layers(), (ui::ViewLayers{false, false, true}));
    QVERIFY(!action("actionShowSurface")->isChecked() && action("actionSurfaceSprings")->isChecked());
}

void TestMainWindow::firstSizeFitsTheScreen()
{
    // 1200 × 800 where it fits (this test's screen, 1280 × 1024); inside a smaller screen with
    // 64 px to spare, such as 1600 × 1000 at a scale factor of 1.5 (1066 × 666 logical pixels)
    QCOMPARE(ui::defaultWindowSize(QSize(1280, 1024)), QSize(1200, 800));
    QCOMPARE(ui::defaultWindowSize(QSize(1066, 666)), QSize(1002, 602));
    QCOMPARE(ui::defaultWindowSize(QSize()), QSize(1200, 800));
    // and the window that opens without remembered settings has it
    QVERIFY(m_window->close());  // (which saves its geometry: removed after)
    QSettings().remove(QStringLiteral("mainWindow"));
    QVERIFY2(openEditor({.activate = false, .settle = false}), qPrintable(editorFailure()));
    QCOMPARE(m_window->size(), ui::defaultWindowSize(m_window->screen()->availableGeometry().size()));
}

QTEST_MAIN(TestMainWindow)
#include "test_main_window.moc"
