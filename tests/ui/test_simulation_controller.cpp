// SimulationController with its real worker thread: play advances time, pause stops it, reset
// restores the initial state bit for bit, edits reach the worker between steps, a followed
// document's scene reaches it as it changes, a blow-up pauses and is reported, shutting down
// while running ends the thread, and frames that bring nothing but steps keep the window's pace.
// Waits are on frames (QTRY_*), never fixed sleeps.

#include "ui/simulation/simulation_controller.h"

#include "ui/document/scene_document.h"

#include "core/model/generators.h"

#include <QSignalSpy>
#include <QThread>
#include <QtTest>

#include "frame_wait.h"

namespace {

using test::frameAfter;
using test::settledFrame;

// the handout's springs net, small enough to step fast
std::shared_ptr<const core::SceneDesc> netScene(double stiffness = 4e3)
{
    core::NetOptions options;
    options.rows = 5;
    options.cols = 5;
    options.stiffness = stiffness;
    return std::make_shared<const core::SceneDesc>(core::makeNet(options));
}

// a net far too stiff for its time step
std::shared_ptr<const core::SceneDesc> explodingScene()
{
    auto scene = std::make_shared<core::SceneDesc>(*netScene(1e9));
    scene->settings.timeStep = 0.1;
    return scene;
}

}  // namespace

class TestSimulationController : public QObject {
    Q_OBJECT

private slots:
    void publishesTheSceneItIsGiven();
    void playAdvancesTimeAndPauseStopsIt();
    void stepOnceTakesOneStep();
    void resetRestoresTheInitialPositionsBitForBit();
    void parameterEditReachesTheWorker();
    void tiltWithTheSameSeedGivesTheSameKick();
    void followedDocumentReachesTheWorker();
    void blowupPausesAndIsReported();
    void shutDownWhileRunningEndsTheThread();
    void pauseCutsALongStepShort();
    void stepsAloneKeepTheFramePace();
    void framesOfTheSameStateShareTheSnapshot();
};

void TestSimulationController::publishesTheSceneItIsGiven()
{
    ui::SimulationController controller;
    const auto scene = netScene();
    const auto frame = frameAfter(controller, controller.setScene(scene, ui::SceneChange::Replace));
    QVERIFY(frame);
    QCOMPARE(frame->snapshot->particleCount(), 25);
    QCOMPARE(frame->snapshot->time, 0.0);
    QVERIFY(frame->scene == scene);
    QVERIFY(!frame->running);
}

void TestSimulationController::playAdvancesTimeAndPauseStopsIt()
{
    ui::SimulationController controller;
    QSignalSpy running(&controller, &ui::SimulationController::runningChanged);
    controller.setScene(netScene(), ui::SceneChange::Replace);
    controller.play();
    QVERIFY(controller.isRunning());
    QCOMPARE(running.count(), 1);
    QTRY_VERIFY(controller.frame() && controller.frame()->snapshot->time > 0.05);
    QTRY_VERIFY(controller.frame()->realTimeFactor > 0.0);

    // paused: two later ticks see the same time
    const auto paused = frameAfter(controller, controller.pause());
    QVERIFY(paused);
    QVERIFY(!paused->running);
    const auto later = frameAfter(controller, controller.sync());
    const auto evenLater = frameAfter(controller, controller.sync());
    QVERIFY(later && evenLater);
    QCOMPARE(later->snapshot->time, paused->snapshot->time);
    QCOMPARE(evenLater->snapshot->step, paused->snapshot->step);
}

void TestSimulationController::stepOnceTakesOneStep()
{
    ui::SimulationController controller;
    controller.setScene(netScene(), ui::SceneChange::Replace);
    const auto first = frameAfter(controller, controller.stepOnce());
    QVERIFY(first);
    QCOMPARE(first->snapshot->step, 1u);
    const auto second = frameAfter(controller, controller.stepOnce());
    QCOMPARE(second->snapshot->step, 2u);
    QCOMPARE(second->snapshot->time, 2 * netScene()->settings.timeStep);
}

void TestSimulationController::resetRestoresTheInitialPositionsBitForBit()
{
    ui::SimulationController controller;
    const auto scene = netScene();
    controller.setScene(scene, ui::SceneChange::Replace);
    controller.play();
    QTRY_VERIFY(controller.frame() && controller.frame()->snapshot->time > 0.05);
    controller.pause();
    const auto reset = frameAfter(controller, controller.reset());
    QVERIFY(reset);
    QCOMPARE(reset->snapshot->time, 0.0);
    QCOMPARE(reset->snapshot->step, 0u);
    const std::vector<float> &positions = reset->snapshot->positions;
    for (std::size_t i = 0; i < scene->particles.size(); ++i)
        for (std::size_t axis = 0; axis < 3; ++axis)
            QCOMPARE(positions[3 * i + axis], float(scene->particles[i].position[Eigen::Index(axis)]));
}

void TestSimulationController::parameterEditReachesTheWorker()
{
    ui::SimulationController controller;
    controller.setScene(netScene(4e3), ui::SceneChange::Replace);
    controller.play();
    QTRY_VERIFY(controller.frame() && controller.frame()->snapshot->step > 2);

    // while running: the next frame's model has the new stiffness, and time went on
    const auto frame = frameAfter(controller, controller.setScene(netScene(250.0), ui::SceneChange::Parameters));
    QVERIFY(frame);
    QCOMPARE(frame->model->stiffness[0], 250.0);
    QVERIFY(frame->snapshot->step > 2);
    QVERIFY(controller.isRunning());
}

void TestSimulationController::tiltWithTheSameSeedGivesTheSameKick()
{
    // tilt, then one step: the positions show the kick
    auto kicked = [](std::uint64_t seed) {
        ui::SimulationController controller;
        controller.setScene(netScene(), ui::SceneChange::Replace);
        controller.setTiltSeed(seed);
        controller.tilt();
        return frameAfter(controller, controller.stepOnce())->snapshot->positions;
    };
    auto unkicked = [] {
        ui::SimulationController controller;
        controller.setScene(netScene(), ui::SceneChange::Replace);
        return frameAfter(controller, controller.stepOnce())->snapshot->positions;
    };
    QVERIFY(kicked(7) == kicked(7));
    QVERIFY(kicked(7) != kicked(8));
    QVERIFY(kicked(7) != unkicked());
}

void TestSimulationController::followedDocumentReachesTheWorker()
{
    ui::SceneDocument document;
    ui::SimulationController controller;
    controller.follow(document);
    QSignalSpy replaced(&controller, &ui::SimulationController::sceneReplaced);

    // a whole new scene: announced with its message's number, and the frame after it shows it
    document.replace(*netScene(4e3), QString());
    QCOMPARE(replaced.count(), 1);
    const auto sequence = replaced.takeFirst().front().value<std::uint64_t>();
    const auto opened = frameAfter(controller, sequence);
    QVERIFY(opened);
    QVERIFY(opened->scene == document.sharedScene());

    // an edit reaches the worker too, and is no new scene
    document.modify(
        [](core::SceneDesc &scene) {
            for (core::SpringDesc &spring : scene.springs)
                spring.stiffness = 250.0;
        },
        ui::SceneChange::Parameters);
    QCOMPARE(replaced.count(), 0);
    const auto edited = frameAfter(controller, controller.sync());
    QVERIFY(edited);
    QVERIFY(edited->scene == document.sharedScene());
    QCOMPARE(edited->model->stiffness[0], 250.0);
}

void TestSimulationController::blowupPausesAndIsReported()
{
    ui::SimulationController controller;
    QSignalSpy blewUp(&controller, &ui::SimulationController::blewUp);
    controller.setScene(explodingScene(), ui::SceneChange::Replace);
    controller.play();
    QVERIFY(blewUp.wait(10000));
    QVERIFY(!controller.isRunning());
    const QString message = blewUp.front().front().toString();
    // the energy's runaway is seen after the first tick, before any value is out of bounds
    QVERIFY2((message.startsWith("Particle ") || message.startsWith("The total energy grew from ")) &&
                 message.contains("stability limit"),
             qPrintable(message));
    const auto frame = frameAfter(controller, controller.sync());
    QVERIFY(!frame->running);
    QVERIFY(!frame->snapshot->blowup.has_value());  // back at the last good state
    // the limit the message names is the one the frame carries for the panel
    QVERIFY(frame->stability.has_value());
    QVERIFY(frame->model->subStep() > frame->stability->maxSubStep(frame->model->integrator));
}

void TestSimulationController::shutDownWhileRunningEndsTheThread()
{
    ui::SimulationController controller;
    controller.setScene(netScene(), ui::SceneChange::Replace);
    controller.play();
    QTRY_VERIFY(controller.frame() && controller.frame()->snapshot->time > 0.0);
    QVERIFY(controller.workerThread()->isRunning());
    controller.shutDown();
    QVERIFY(controller.workerThread()->isFinished());
    QVERIFY(controller.isShutDown());
    QVERIFY(!controller.isRunning());
    controller.shutDown();  // twice is harmless
}

void TestSimulationController::pauseCutsALongStepShort()
{
    // a step of a second or more: a 32 × 32 cloth at a time step of 1 s in 20 000 sub-steps
    core::ClothOptions options;
    options.rows = options.cols = 32;
    auto scene = std::make_shared<core::SceneDesc>(core::makeCloth(options));
    scene->settings.timeStep = 1.0;
    scene->settings.substeps = 20000;
    ui::SimulationController controller;
    QVERIFY(frameAfter(controller, controller.setScene(scene, ui::SceneChange::Replace)));

    // Pause, sent once the worker has taken the Step and is stepping, is answered at once with
    // the step not taken (it would show step 1 had the step run to its end first)
    controller.stepOnce();
    QVERIFY(QTest::qWaitFor([&] { return !controller.messagesWaiting(); }, 10000));
    const auto paused = frameAfter(controller, controller.pause(), 60000);
    QVERIFY(paused);
    QCOMPARE(paused->snapshot->step, 0u);
    QCOMPARE(paused->stepsOwed, 0u);
    QVERIFY(!paused->running);

    // a Sync instead of a Pause: the step is owed, then taken once the messages are through
    controller.stepOnce();
    QVERIFY(QTest::qWaitFor([&] { return !controller.messagesWaiting(); }, 10000));
    const auto synced = frameAfter(controller, controller.sync(), 60000);
    QVERIFY(synced);
    QCOMPARE(synced->snapshot->step, 0u);
    QCOMPARE(synced->stepsOwed, 1u);
    QTRY_VERIFY_WITH_TIMEOUT(controller.frame()->snapshot->step == 1u, 120000);
    QCOMPARE(controller.frame()->stepsOwed, 0u);
}

void TestSimulationController::stepsAloneKeepTheFramePace()
{
    ui::SimulationController controller;
    controller.setScene(netScene(), ui::SceneChange::Replace);
    controller.play();
    QTRY_VERIFY(controller.frame() && controller.frame()->running && controller.frame()->snapshot->step > 0);

    // a window that draws a frame an hour: the run goes on, and the only frames are the answers
    // to messages (here Syncs), each at once
    controller.setFrameInterval(3600.0);
    std::shared_ptr<const ui::SimulationFrame> frame = settledFrame(controller);
    QVERIFY(frame);
    const std::uint64_t from = frame->snapshot->step;
    QSignalSpy frames(&controller, &ui::SimulationController::frameChanged);
    int syncs = 0;
    while (frame && frame->snapshot->step < from + 30) {
        // the worker's timer ticks meanwhile: it steps, and shows no frame it was not asked for
        QVERIFY(!QTest::qWaitFor([&] { return frames.count() > syncs; }, 50));
        frame = settledFrame(controller);
        ++syncs;
    }
    QVERIFY(frame);
    QVERIFY(frame->running);
    QCOMPARE_LE(frames.count(), syncs);

    // a Pause is answered at once, whatever the pace
    const auto paused = frameAfter(controller, controller.pause());
    QVERIFY(paused);
    QVERIFY(!paused->running);

    // without a pace, every tick's steps are shown again
    controller.setFrameInterval(0.0);
    const auto playing = frameAfter(controller, controller.play());
    QVERIFY(playing);
    QTRY_VERIFY(controller.frame()->appliedMessage == playing->appliedMessage &&
                controller.frame()->snapshot->step > playing->snapshot->step);
}

void TestSimulationController::framesOfTheSameStateShareTheSnapshot()
{
    // a Sync or a Pause shows the state shown before: the same snapshot, not a new copy of it
    ui::SimulationController controller;
    const auto loaded = frameAfter(controller, controller.setScene(netScene(), ui::SceneChange::Replace));
    QVERIFY(loaded);
    const auto synced = settledFrame(controller);
    QVERIFY(synced);
    QVERIFY(synced.get() != loaded.get());
    QCOMPARE(synced->snapshot.get(), loaded->snapshot.get());
    const auto paused = frameAfter(controller, controller.pause());
    QVERIFY(paused);
    QCOMPARE(paused->snapshot.get(), loaded->snapshot.get());

    // a step, a tilt or an edit changes what is shown: a new snapshot each time
    const auto stepped = frameAfter(controller, controller.stepOnce());
    QVERIFY(stepped);
    QCOMPARE(stepped->snapshot->step, 1u);
    QVERIFY(stepped->snapshot.get() != loaded->snapshot.get());
    const auto tilted = frameAfter(controller, controller.tilt());
    QVERIFY(tilted);
    QCOMPARE(tilted->snapshot->step, 1u);
    QVERIFY(tilted->snapshot.get() != stepped->snapshot.get());
    QVERIFY(tilted->snapshot->velocities != stepped->snapshot->velocities);
    const auto edited = frameAfter(controller, controller.setScene(netScene(5e3), ui::SceneChange::Parameters));
    QVERIFY(edited);
    QVERIFY(edited->snapshot.get() != tilted->snapshot.get());
}

QTEST_GUILESS_MAIN(TestSimulationController)
#include "test_simulation_controller.moc"
