// The timeline, through the runner that owns it: a scrub to any recorded step gives the very bits
// the run had there, edits (a slider, the mouse spring, a tilt, the steering) included; stepping
// back and forth moves inside the recording, and back from the end replays nothing; a replay cut short by waiting messages shows the
// steps it got to and goes on after them; play or an edit goes on from the step shown and drops
// the recorded future; a long run stays within the memory budget; breaks are marked.

#include "session/simulation_runner.h"

#include "core/model/generators.h"
#include "core/model/state_hash.h"

#include <QtTest>
#include <atomic>
#include <map>
#include <random>

namespace {

// a small cloth falling onto a floor, its corners pinned: springs, gravity, plane and pair
// contacts, all in play
std::shared_ptr<const core::SceneDesc> clothScene(double breakStrain = 0.0)
{
    core::ClothOptions options;
    options.rows = options.cols = 6;
    options.spacing = 0.1;
    options.radius = 0.04;
    options.height = 0.5;
    core::SceneDesc scene = core::makeCloth(options);
    scene.planes = {core::PlaneDesc{{0.0, 1.0, 0.0}, 0.0}};
    for (core::SpringDesc &spring : scene.springs)
        spring.breakStrain = breakStrain;
    return std::make_shared<core::SceneDesc>(std::move(scene));
}

// the state hash of every step taken, keyed by step
using Hashes = std::map<std::uint64_t, std::uint64_t>;

void stepAndRecord(ui::SimulationRunner &runner, int steps, Hashes &hashes)
{
    for (int i = 0; i < steps; ++i) {
        runner.apply(ui::StepOnce{});
        hashes[runner.state().step] = core::stateHash(runner.state());
    }
}

}  // namespace

class TestTimeline : public QObject {
    Q_OBJECT

private slots:
    void scrubGivesTheRecordedBits();
    void stepsBackAndForthInsideTheRecording();
    void stepsBackFromTheEndReplayNothing();
    void scrubYieldsToMessages();
    void slowScrubShowsEachStep();
    void playGoesOnFromTheStepShown();
    void editWhileScrubbedDropsTheFuture();
    void scrubbedStepShowsItsOwnScene();
    void longRunStaysWithinTheBudget();
    void aKeyframeOverTheBudgetIsReported();
    void breaksAreMarked();
    void noScrubbingWhileASessionIsRecorded();
};

void TestTimeline::scrubGivesTheRecordedBits()
{
    ui::SimulationRunner runner;
    auto scene = clothScene();
    runner.apply(ui::SetSceneEdit{scene, ui::SceneChange::Replace});
    Hashes hashes;
    hashes[0] = core::stateHash(runner.state());
    stepAndRecord(runner, 25, hashes);
    // a slider: stiffer springs from step 25
    auto stiffer = std::make_shared<core::SceneDesc>(*scene);
    for (core::SpringDesc &spring : stiffer->springs)
        spring.stiffness *= 2.0;
    runner.apply(ui::SetSceneEdit{stiffer, ui::SceneChange::Parameters});
    hashes[runner.state().step] = core::stateHash(runner.state());
    stepAndRecord(runner, 13, hashes);
    // the mouse spring on a free particle, moved twice, then let go
    runner.apply(ui::GrabEdit{8, Eigen::Vector3d(0.3, 0.9, 0.2)});
    stepAndRecord(runner, 7, hashes);
    runner.apply(ui::GrabEdit{8, Eigen::Vector3d(0.1, 1.0, 0.4)});
    stepAndRecord(runner, 11, hashes);
    runner.apply(ui::GrabEdit{-1, Eigen::Vector3d::Zero()});
    stepAndRecord(runner, 4, hashes);
    // a tilt and the steering force
    runner.apply(ui::TiltEdit{42, 1.0});
    hashes[runner.state().step] = core::stateHash(runner.state());
    stepAndRecord(runner, 9, hashes);
    runner.apply(ui::SteerEdit{14, Eigen::Vector3d(0.0, 0.0, 0.05)});
    stepAndRecord(runner, 17, hashes);
    const std::uint64_t last = runner.state().step;
    QCOMPARE(last, std::uint64_t(86));
    QCOMPARE(runner.scrubber().timeline().firstStep(), std::uint64_t(0));
    QCOMPARE(runner.scrubber().timeline().lastStep(), last);

    // every recorded step, in a shuffled order, gives the bits the run had there
    std::vector<std::uint64_t> order;
    for (const auto &[step, hash] : hashes)
        order.push_back(step);
    std::shuffle(order.begin(), order.end(), std::mt19937(5));
    for (std::uint64_t step : order) {
        runner.apply(ui::Scrub{step});
        QVERIFY(runner.scrubber().isScrubbing());
        QCOMPARE(*runner.scrubber().scrubStep(), step);
        QCOMPARE(runner.shownState().step, step);
        QVERIFY2(core::stateHash(runner.shownState()) == hashes[step], qPrintable(QString("step %1").arg(step)));
        // the snapshot drawn is of the step shown
        QCOMPARE(runner.snapshot()->step, step);
    }
    // and the run itself is where it was
    QCOMPARE(runner.state().step, last);
    QCOMPARE(core::stateHash(runner.state()), hashes[last]);
}

void TestTimeline::stepsBackAndForthInsideTheRecording()
{
    ui::SimulationRunner runner;
    runner.apply(ui::SetSceneEdit{clothScene(), ui::SceneChange::Replace});
    Hashes hashes;
    stepAndRecord(runner, 40, hashes);

    // back from the run's end, twice: steps 39 and 38
    runner.apply(ui::StepBack{});
    runner.apply(ui::StepBack{});
    QCOMPARE(*runner.scrubber().scrubStep(), std::uint64_t(38));
    QCOMPARE(core::stateHash(runner.shownState()), hashes[38]);
    // forward through the recording: nothing is dropped on the way
    for (std::uint64_t step = 39; step <= 40; ++step) {
        runner.apply(ui::StepOnce{});
        QCOMPARE(*runner.scrubber().scrubStep(), step);
        QCOMPARE(core::stateHash(runner.shownState()), hashes[step]);
        QCOMPARE(runner.scrubber().timeline().lastStep(), std::uint64_t(40));
    }
    // a step at the recording's end is a new step of the run
    runner.apply(ui::StepOnce{});
    QVERIFY(!runner.scrubber().isScrubbing());
    QCOMPARE(runner.state().step, std::uint64_t(41));
    QCOMPARE(runner.scrubber().timeline().lastStep(), std::uint64_t(41));
}

void TestTimeline::stepsBackFromTheEndReplayNothing()
{
    ui::SimulationRunner runner;
    runner.apply(ui::SetSceneEdit{clothScene(), ui::SceneChange::Replace});
    Hashes hashes;
    stepAndRecord(runner, 47, hashes);
    const ui::Timeline &timeline = runner.scrubber().timeline();
    constexpr int kTail = ui::Timeline::kTailSteps;
    // each of the latest kTailSteps steps is a keyframe of its own; before them, one in
    // kKeyInterval (the tail keyframes that aged went, memory and all)
    for (std::uint64_t step = 47 - kTail; step <= 47; ++step)
        QCOMPARE(timeline.keyAtOrBefore(step)->state.step, step);
    QCOMPARE(timeline.keyAtOrBefore(47 - kTail - 1)->state.step, std::uint64_t(30));
    QCOMPARE(timeline.keyAtOrBefore(29)->state.step, std::uint64_t(20));

    // so stepping back from the end replays no step: each is shown from its own keyframe, exact,
    // by a scrubber of that recording allowed to replay no step at all
    ui::Scrubber scrubber;
    scrubber.timeline() = timeline;
    core::Workspace work;
    for (std::uint64_t step = 46; step >= 47 - kTail; --step) {
        QVERIFY(scrubber.show(step, work, nullptr, 0));
        QVERIFY(!scrubber.pendingStep());
        QCOMPARE(*scrubber.scrubStep(), step);
        QCOMPARE(core::stateHash(scrubber.shown()->state), hashes[step]);
    }
    // further back, the replay from the keyframe before is still needed
    QVERIFY(scrubber.show(33, work, nullptr, 0));
    QCOMPARE(scrubber.pendingStep(), std::optional<std::uint64_t>(33));
    QCOMPARE(*scrubber.scrubStep(), std::uint64_t(30));
}

void TestTimeline::scrubYieldsToMessages()
{
    ui::SimulationRunner runner;
    runner.apply(ui::SetSceneEdit{clothScene(), ui::SceneChange::Replace});
    Hashes hashes;
    // (steps 30 to 40 have keyframes of their own; the replays below are before them)
    stepAndRecord(runner, 40, hashes);
    std::atomic<bool> waiting{false};
    runner.setInterrupt(&waiting);

    // step 19 is replayed from the keyframe at step 10; with messages waiting the replay does not
    // go on: the keyframe is shown, the rest pending, and the worker comes back to it
    waiting = true;
    runner.apply(ui::Scrub{19});
    QCOMPARE(runner.scrubber().scrubStep(), std::optional<std::uint64_t>(10));
    QCOMPARE(runner.scrubber().pendingStep(), std::optional<std::uint64_t>(19));
    QVERIFY(runner.hasWorkLeft());
    QVERIFY(!runner.continueScrub());  // still waiting
    QCOMPARE(runner.scrubber().scrubStep(), std::optional<std::uint64_t>(10));

    // the messages are in: on to step 19, the recorded bits
    waiting = false;
    QVERIFY(runner.continueScrub());
    QCOMPARE(runner.scrubber().scrubStep(), std::optional<std::uint64_t>(19));
    QCOMPARE(core::stateHash(runner.shownState()), hashes[19]);
    QVERIFY(!runner.scrubber().pendingStep());

    // a scrub elsewhere while one is pending replaces it
    waiting = true;
    runner.apply(ui::Scrub{8});
    QCOMPARE(runner.scrubber().pendingStep(), std::optional<std::uint64_t>(8));
    runner.apply(ui::Scrub{24});
    QCOMPARE(runner.scrubber().pendingStep(), std::optional<std::uint64_t>(24));
    waiting = false;
    QVERIFY(runner.continueScrub());
    QCOMPARE(core::stateHash(runner.shownState()), hashes[24]);

    // Step Back twice, the second while the first still replays from its keyframe: two steps back
    // from the step asked for, 22, not one back from the keyframe shown on the way (it went to 19),
    // and Step while pending goes on from the step asked for too
    waiting = true;
    runner.apply(ui::StepBack{});
    QCOMPARE(runner.scrubber().scrubStep(), std::optional<std::uint64_t>(20));
    QCOMPARE(runner.scrubber().pendingStep(), std::optional<std::uint64_t>(23));
    runner.apply(ui::StepBack{});
    QCOMPARE(runner.scrubber().pendingStep(), std::optional<std::uint64_t>(22));
    runner.apply(ui::StepOnce{});
    runner.apply(ui::StepBack{});
    QCOMPARE(runner.scrubber().pendingStep(), std::optional<std::uint64_t>(22));
    waiting = false;
    QVERIFY(runner.continueScrub());
    QCOMPARE(runner.scrubber().scrubStep(), std::optional<std::uint64_t>(22));
    QCOMPARE(core::stateHash(runner.shownState()), hashes[22]);
}

void TestTimeline::slowScrubShowsEachStep()
{
    // steps slower than kInterruptibleStepSeconds (a 16 × 16 cloth in 4000 sub-steps: tens of ms
    // even on a fast machine): a scrub shows the keyframe at once, then one replayed step a tick
    core::ClothOptions options;
    options.rows = options.cols = 16;
    core::SceneDesc cloth = core::makeCloth(options);
    cloth.settings.substeps = 4000;
    ui::SimulationRunner runner;
    runner.apply(ui::SetSceneEdit{std::make_shared<const core::SceneDesc>(cloth), ui::SceneChange::Replace});
    Hashes hashes;
    // (steps 15 to 25 have keyframes of their own: stepsBackFromTheEndReplayNothing)
    stepAndRecord(runner, 25, hashes);
    QVERIFY(runner.stepsAreSlow());

    runner.apply(ui::Scrub{12});
    QCOMPARE(runner.scrubber().scrubStep(), std::optional<std::uint64_t>(10));
    QCOMPARE(runner.scrubber().pendingStep(), std::optional<std::uint64_t>(12));
    QVERIFY(runner.continueScrub());
    QCOMPARE(runner.scrubber().scrubStep(), std::optional<std::uint64_t>(11));
    QCOMPARE(core::stateHash(runner.shownState()), hashes[11]);
    QVERIFY(runner.continueScrub());
    QCOMPARE(runner.scrubber().scrubStep(), std::optional<std::uint64_t>(12));
    QCOMPARE(core::stateHash(runner.shownState()), hashes[12]);
    QVERIFY(!runner.scrubber().pendingStep());
    QVERIFY(!runner.continueScrub());
}

void TestTimeline::playGoesOnFromTheStepShown()
{
    ui::SimulationRunner runner;
    runner.apply(ui::SetSceneEdit{clothScene(), ui::SceneChange::Replace});
    Hashes hashes;
    stepAndRecord(runner, 60, hashes);

    runner.apply(ui::Scrub{23});
    runner.apply(ui::Play{});
    QVERIFY(!runner.scrubber().isScrubbing());
    QVERIFY(runner.isRunning());
    QCOMPARE(runner.state().step, std::uint64_t(23));
    QCOMPARE(runner.scrubber().timeline().lastStep(), std::uint64_t(23));  // the future is gone
    // nothing changed since: the run goes on exactly as it did the first time
    const ui::SimulationRunner::Advance advanced = runner.advance(5.5 * 0.01, 1e9);
    QCOMPARE(advanced.steps, 5);
    QCOMPARE(runner.state().step, std::uint64_t(28));
    QCOMPARE(core::stateHash(runner.state()), hashes[28]);
}

void TestTimeline::editWhileScrubbedDropsTheFuture()
{
    ui::SimulationRunner runner;
    auto scene = clothScene();
    runner.apply(ui::SetSceneEdit{scene, ui::SceneChange::Replace});
    Hashes hashes;
    stepAndRecord(runner, 50, hashes);

    runner.apply(ui::Scrub{17});
    auto damped = std::make_shared<core::SceneDesc>(*scene);
    damped->settings.viscosity = 0.5;
    runner.apply(ui::SetSceneEdit{damped, ui::SceneChange::Parameters});
    QVERIFY(!runner.scrubber().isScrubbing());
    QCOMPARE(runner.state().step, std::uint64_t(17));
    QCOMPARE(core::stateHash(runner.state()), hashes[17]);
    QCOMPARE(runner.scrubber().timeline().lastStep(), std::uint64_t(17));
    QCOMPARE(runner.model()->viscosity, 0.5);

    // recorded again from there, with the drag: different from the first time
    stepAndRecord(runner, 5, hashes);
    runner.apply(ui::Scrub{19});
    QCOMPARE(core::stateHash(runner.shownState()), hashes[19]);
    // a step before the edit still shows the first run's bits
    runner.apply(ui::Scrub{12});
    QCOMPARE(core::stateHash(runner.shownState()), hashes[12]);
}

// A step recorded before a particle was added is shown with the scene and model it was stepped
// with, not the editor's newer one: the worker's frame pairs them with the snapshot, and a frame
// whose scene had a particle more than its snapshot was a torn frame (found by the live-edit
// stress under ThreadSanitizer, which scrubbed with the timeline slider's keys after an add).
void TestTimeline::scrubbedStepShowsItsOwnScene()
{
    ui::SimulationRunner runner;
    auto scene = clothScene();
    runner.apply(ui::SetSceneEdit{scene, ui::SceneChange::Replace});
    Hashes hashes;
    stepAndRecord(runner, 20, hashes);
    auto grown = std::make_shared<core::SceneDesc>(*scene);
    grown->particles.push_back(core::ParticleDesc{Eigen::Vector3d(0.0, 2.0, 0.0), Eigen::Vector3d::Zero(), 1.0, 0.05, false});
    runner.apply(ui::SetSceneEdit{grown, ui::SceneChange::Structure});
    stepAndRecord(runner, 20, hashes);

    runner.apply(ui::Scrub{10});
    QVERIFY(runner.scrubber().isScrubbing());
    QVERIFY(runner.shownScene() == scene);
    QCOMPARE(runner.shownModel()->particleCount(), int(scene->particles.size()));
    QCOMPARE(runner.snapshot()->particleCount(), int(scene->particles.size()));
    QVERIFY(runner.scene() == grown);  // the editor's scene is still the newer one

    runner.apply(ui::Scrub{35});
    QVERIFY(runner.shownScene() == grown);
    QCOMPARE(runner.snapshot()->particleCount(), int(grown->particles.size()));
}

void TestTimeline::longRunStaysWithinTheBudget()
{
    ui::SimulationRunner runner;
    constexpr std::size_t kBudget = 96 * 1024;  // bytes: a few dozen keyframes of this cloth
    runner.apply(ui::SetTimelineBudget{kBudget});
    runner.apply(ui::SetSceneEdit{clothScene(), ui::SceneChange::Replace});
    Hashes hashes;
    std::size_t most = 0;
    for (int i = 0; i < 3000; ++i) {
        stepAndRecord(runner, 1, hashes);
        most = std::max(most, runner.scrubber().timeline().usedBytes());
        QVERIFY(runner.scrubber().timeline().usedBytes() <= kBudget);
    }
    QVERIFY2(most > kBudget / 2, qPrintable(QString("used at most %1 bytes").arg(most)));
    // the newest part of the run is kept, the oldest dropped
    const ui::Timeline &timeline = runner.scrubber().timeline();
    QCOMPARE(timeline.lastStep(), std::uint64_t(3000));
    QVERIFY(timeline.firstStep() > 0);
    QVERIFY2(timeline.lastStep() - timeline.firstStep() >= 100,
             qPrintable(QString("only steps %1 to %2").arg(timeline.firstStep()).arg(timeline.lastStep())));
    // its first and a middle step are exact; a step before it cannot be shown
    for (std::uint64_t step : {timeline.firstStep(), (timeline.firstStep() + timeline.lastStep()) / 2 + 3}) {
        runner.apply(ui::Scrub{step});
        QCOMPARE(core::stateHash(runner.shownState()), hashes[step]);
    }
    const std::uint64_t shown = *runner.scrubber().scrubStep();
    runner.apply(ui::Scrub{timeline.firstStep() - 1});
    QCOMPARE(*runner.scrubber().scrubStep(), shown);
    // a smaller budget drops more at once
    runner.apply(ui::SetTimelineBudget{kBudget / 4});
    QVERIFY(runner.scrubber().timeline().usedBytes() <= kBudget / 4);
}

void TestTimeline::aKeyframeOverTheBudgetIsReported()
{
    // a budget smaller than one keyframe of the cloth: nothing recorded, and how much one needs
    ui::SimulationRunner runner;
    runner.apply(ui::SetTimelineBudget{1024});
    runner.apply(ui::SetSceneEdit{clothScene(), ui::SceneChange::Replace});
    Hashes hashes;
    stepAndRecord(runner, 12, hashes);
    const ui::Timeline &timeline = runner.scrubber().timeline();
    QVERIFY(timeline.empty());
    QCOMPARE_GT(timeline.keyframeOverBudget(), std::size_t(1024));
    const std::size_t needed = timeline.keyframeOverBudget();

    // a budget that holds it: recorded again from the next keyframe, and nothing reported
    runner.apply(ui::SetTimelineBudget{16 * needed});
    stepAndRecord(runner, 12, hashes);
    QVERIFY(!timeline.empty());
    QCOMPARE(timeline.keyframeOverBudget(), std::size_t(0));
}

void TestTimeline::breaksAreMarked()
{
    ui::SimulationRunner runner;
    runner.apply(ui::SetSceneEdit{clothScene(2e-3), ui::SceneChange::Replace});
    Hashes hashes;
    stepAndRecord(runner, 80, hashes);
    const std::vector<core::SpringBreak> &breaks = runner.state().breaks;
    QVERIFY2(!breaks.empty(), "the brittle cloth must tear as it falls");
    // every break of the keyed steps is marked, once, in order
    std::vector<std::uint64_t> expected;
    for (const core::SpringBreak &b : breaks)
        if (b.step <= 80 && (expected.empty() || expected.back() != b.step))
            expected.push_back(b.step);
    QCOMPARE(runner.scrubber().timeline().breakSteps(), expected);
    // scrubbed back before the first break, the cloth is whole; at the run's end, torn
    runner.apply(ui::Scrub{expected.front() - 1});
    QCOMPARE(runner.snapshot()->breakCount, std::uint64_t(0));
    runner.apply(ui::Scrub{80});
    QCOMPARE(runner.snapshot()->breakCount, std::uint64_t(breaks.size()));
    // after a scrub back and an edit, the later breaks are gone from the marks
    runner.apply(ui::Scrub{expected.front()});
    runner.apply(ui::TiltEdit{1, 0.0});
    QVERIFY(runner.scrubber().timeline().breakSteps().back() <= expected.front());
}

void TestTimeline::noScrubbingWhileASessionIsRecorded()
{
    ui::SimulationRunner runner;
    runner.apply(ui::SetSceneEdit{clothScene(), ui::SceneChange::Replace});
    Hashes hashes;
    stepAndRecord(runner, 20, hashes);
    runner.apply(ui::StartRecording{});
    runner.apply(ui::Scrub{5});
    QVERIFY(!runner.scrubber().isScrubbing());
    QCOMPARE(runner.state().step, std::uint64_t(20));
    runner.apply(ui::StopRecording{1});
    runner.apply(ui::Scrub{5});
    QVERIFY(runner.scrubber().isScrubbing());
}

QTEST_APPLESS_MAIN(TestTimeline)
#include "test_timeline.moc"
