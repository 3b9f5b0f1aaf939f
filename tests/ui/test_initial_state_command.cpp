// Simulation › Use Current State as Initial on a run whose springs have torn: the scene's initial
// conditions become the run's state through core::storeState (the path of springlab-sim
// --output), so the torn springs leave the scene, Reset returns to the state as it was, and the
// run itself goes on with the same bits through the edit, its undo and its redo.

#include "ui/document/initial_state_command.h"
#include "ui/document/scene_document.h"
#include "session/simulation_runner.h"

#include "core/io/scene_file.h"
#include "core/model/state_hash.h"

#include <QUndoStack>
#include <QtTest>

namespace {

constexpr double kNoBudgetLimit = 1e9;  // s

// the tearable cloth, run until some of its springs have broken, then paused
bool runPastABreak(ui::SimulationRunner &runner, std::shared_ptr<const core::SceneDesc> &scene)
{
    const io::LoadResult loaded = io::loadScene(QStringLiteral(SPRINGLAB_SOURCE_DIR "/resources/scenes/tearable-cloth.json"));
    if (!loaded.ok())
        return false;
    scene = std::make_shared<const core::SceneDesc>(*loaded.scene);
    runner.apply(ui::SetSceneEdit{scene, ui::SceneChange::Replace});
    runner.apply(ui::Play{});
    for (int tick = 0; tick < 2000 && runner.state().breaks.size() < 3; ++tick)
        runner.advance(scene->settings.timeStep, kNoBudgetLimit);
    runner.apply(ui::Pause{});
    return runner.state().breaks.size() >= 3;
}

// steps a runner on, paused one step at a time
std::uint64_t hashAfter(ui::SimulationRunner &runner, int steps)
{
    for (int i = 0; i < steps; ++i)
        runner.apply(ui::StepOnce{});
    return core::stateHash(runner.state());
}

}  // namespace

class TestInitialStateCommand : public QObject {
    Q_OBJECT

private slots:
    void tornSpringsLeaveTheScene();
    void theRunGoesOnThroughEditUndoAndRedo();
};

void TestInitialStateCommand::tornSpringsLeaveTheScene()
{
    ui::SimulationRunner runner;
    std::shared_ptr<const core::SceneDesc> scene;
    QVERIFY(runPastABreak(runner, scene));
    runner.apply(ui::CaptureState{1});
    const std::optional<ui::CapturedStateReply> reply = ui::findReply<ui::CapturedStateReply>(runner.takeReplies());
    QVERIFY(reply && reply->captured);
    const core::State captured = reply->captured->state;
    QCOMPARE(captured.step, runner.state().step);

    ui::SceneDocument document;
    document.setScene(scene, ui::SceneChange::Replace);
    document.undoStack()->push(new ui::InitialStateCommand(document, QStringLiteral("initial"), captured));
    const core::SceneDesc &after = document.scene();
    QCOMPARE(after.springs.size(), scene->springs.size() - captured.breaks.size());
    for (std::size_t i = 0; i < after.particles.size(); ++i) {
        QCOMPARE(after.particles[i].position, Eigen::Vector3d(captured.position.col(Eigen::Index(i))));
        QCOMPARE(after.particles[i].velocity, Eigen::Vector3d(captured.velocity.col(Eigen::Index(i))));
    }
    // the same scene springlab-sim --output writes
    core::SceneDesc stored = *scene;
    core::storeState(captured, stored);
    QVERIFY(after == stored);

    // Reset (F5) starts from the state as it was, no torn spring whole again
    ui::SimulationRunner fresh;
    fresh.apply(ui::SetSceneEdit{document.sharedScene(), ui::SceneChange::Replace});
    QVERIFY(fresh.state().position == captured.position);
    QVERIFY(fresh.state().velocity == captured.velocity);
    QVERIFY(std::count(fresh.state().springBroken.begin(), fresh.state().springBroken.end(), 1) == 0);
    // and runs on as the torn run does, to the bit
    ui::SimulationRunner twin;
    std::shared_ptr<const core::SceneDesc> again;
    QVERIFY(runPastABreak(twin, again));
    QCOMPARE(twin.state().step, captured.step);
    const std::uint64_t expected = hashAfter(twin, 20);
    if (twin.state().breaks.size() == captured.breaks.size())  // no new break to tell the runs apart
        QCOMPARE(hashAfter(fresh, 20), expected);

    // undo gives the scene back as it was
    document.undoStack()->undo();
    QVERIFY(document.scene() == *scene);
}

// the worker's run is untouched by the edit (SceneChange::InitialConditions): the springs it
// broke stay broken whether the list leaves them out (redo) or has them again (undo)
void TestInitialStateCommand::theRunGoesOnThroughEditUndoAndRedo()
{
    ui::SimulationRunner runner;
    ui::SimulationRunner control;
    std::shared_ptr<const core::SceneDesc> scene;
    QVERIFY(runPastABreak(runner, scene));
    QVERIFY(runPastABreak(control, scene));
    QCOMPARE(core::stateHash(runner.state()), core::stateHash(control.state()));
    runner.apply(ui::CaptureState{1});
    const std::optional<ui::CapturedStateReply> reply = ui::findReply<ui::CapturedStateReply>(runner.takeReplies());
    QVERIFY(reply && reply->captured);
    ui::SceneDocument document;
    document.setScene(scene, ui::SceneChange::Replace);
    QObject::connect(&document, &ui::SceneDocument::sceneChanged, [&](ui::SceneChange change) {
        runner.apply(ui::SetSceneEdit{document.sharedScene(), change});
    });
    document.undoStack()->push(new ui::InitialStateCommand(document, QStringLiteral("initial"), reply->captured->state));
    QCOMPARE(runner.state().position, control.state().position);
    QCOMPARE(std::count(runner.state().springBroken.begin(), runner.state().springBroken.end(), 1), 0L);
    QCOMPARE(hashAfter(runner, 15), hashAfter(control, 15));
    document.undoStack()->undo();
    QCOMPARE(runner.state().springBroken.size(), scene->springs.size());
    QCOMPARE(std::count(runner.state().springBroken.begin(), runner.state().springBroken.end(), 1),
             std::count(control.state().springBroken.begin(), control.state().springBroken.end(), 1));
    QCOMPARE(hashAfter(runner, 15), hashAfter(control, 15));
    document.undoStack()->redo();
    QCOMPARE(hashAfter(runner, 15), hashAfter(control, 15));
}

QTEST_GUILESS_MAIN(TestInitialStateCommand)
#include "test_initial_state_command.moc"
