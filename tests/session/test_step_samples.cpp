// The plots' samples of every step, taken by the runner on the worker's side: one per step kept,
// however many steps an advance takes, each the core's energies, momentum and followed particle to
// the bit; an edit at the same step replaces its sample; a reset starts over, a blow-up and a
// resume from a scrubbed step drop the steps taken back; what a frame delivered goes, the rest
// waits within a bound; and a runner that does not sample (springlab-sim's) takes nothing.

#include "session/simulation_runner.h"
#include "session/step_samples.h"

#include "core/model/diagnostics.h"
#include "core/step.h"

#include <QtTest>

namespace {

// a pinned anchor and a free 1 kg particle on a spring, under gravity, released stretched
std::shared_ptr<const core::SceneDesc> pendulum(double stiffness = 100.0, double timeStep = 0.01)
{
    auto scene = std::make_shared<core::SceneDesc>();
    scene->name = "pendulum";
    scene->settings.timeStep = timeStep;
    core::ParticleDesc anchor;
    anchor.pinned = true;
    core::ParticleDesc bob;
    bob.position = {1.0, 0.0, 0.0};
    bob.velocity = {0.0, 0.5, 0.2};
    scene->particles = {anchor, bob};
    scene->springs = {core::SpringDesc{0, 1, stiffness, 0.1, 0.5}};
    return scene;
}

// a runner on the scene that samples every step, following particle 1
ui::SimulationRunner samplingRunner(std::shared_ptr<const core::SceneDesc> scene)
{
    ui::SimulationRunner runner;
    runner.samples().setEnabled(true);
    runner.samples().setParticle(1);
    runner.apply(ui::SetSceneEdit{std::move(scene), ui::SceneChange::Replace});
    return runner;
}

std::vector<std::uint64_t> stepsOf(const ui::StepSampleBatch &samples)
{
    std::vector<std::uint64_t> steps;
    for (const ui::StepSample &sample : samples)
        steps.push_back(sample.step);
    return steps;
}

std::vector<std::uint64_t> range(std::uint64_t first, std::uint64_t last)
{
    std::vector<std::uint64_t> steps;
    for (std::uint64_t s = first; s <= last; ++s)
        steps.push_back(s);
    return steps;
}

constexpr double kNoBudgetLimit = 1e9;  // s

}  // namespace

class TestStepSamples : public QObject {
    Q_OBJECT

private slots:
    void everyStepKeptIsSampledAsTheCoreHasIt();
    void anEditAtTheSameStepReplacesItsSample();
    void resetStartsOverAndBlowupDropsTheStepsTakenBack();
    void resumeFromAScrubDropsTheOldFuture();
    void deliveredSamplesGoAndThePendingAreBounded();
    void aRunnerThatDoesNotSampleTakesNothing();
};

void TestStepSamples::everyStepKeptIsSampledAsTheCoreHasIt()
{
    // 25 steps in one advance, as a tick of a window that draws seldom takes them
    const auto scene = pendulum();
    ui::SimulationRunner runner = samplingRunner(scene);
    runner.apply(ui::Play{});
    QCOMPARE(runner.advance(0.255, kNoBudgetLimit).steps, 25);
    const auto samples = runner.samples().pending();
    QVERIFY(samples);
    QCOMPARE(stepsOf(*samples), range(0, 25));

    // each the core's figures of that step, stepped here independently, and numbered in order
    const auto model = core::compileModel(*scene);
    core::State state = core::makeState(*model, *scene);
    core::Workspace work;
    const double initial = core::energies(*model, state).total();
    for (std::size_t i = 0; i < samples->size(); ++i) {
        if (i > 0)
            QVERIFY(core::step(*model, state, work));
        const ui::StepSample &sample = (*samples)[i];
        QCOMPARE(sample.step, state.step);
        QCOMPARE(sample.time, state.time);
        const core::Energies energies = core::energies(*model, state);
        QCOMPARE(sample.energies.kinetic, energies.kinetic);
        QCOMPARE(sample.energies.gravitational, energies.gravitational);
        QCOMPARE(sample.energies.spring, energies.spring);
        QCOMPARE(sample.initialTotal, initial);
        QVERIFY(sample.momentum == core::momentum(*model, state));
        QCOMPARE(sample.particle, 1);
        QVERIFY(sample.position == Eigen::Vector3d(state.position.col(1)));
        QVERIFY(sample.velocity == Eigen::Vector3d(state.velocity.col(1)));
        if (i > 0)
            QVERIFY(sample.sequence > (*samples)[i - 1].sequence);
    }
}

void TestStepSamples::anEditAtTheSameStepReplacesItsSample()
{
    // paused at step 3, a stiffer spring: step 3 again, with the new spring energy
    ui::SimulationRunner runner = samplingRunner(pendulum());
    for (int i = 0; i < 3; ++i)
        runner.apply(ui::StepOnce{});
    const double before = runner.samples().pending()->back().energies.spring;
    runner.apply(ui::SetSceneEdit{pendulum(400.0), ui::SceneChange::Parameters});
    const auto samples = runner.samples().pending();
    QCOMPARE(stepsOf(*samples), range(0, 3));
    QCOMPARE(samples->back().energies.spring, 4.0 * before);
}

void TestStepSamples::resetStartsOverAndBlowupDropsTheStepsTakenBack()
{
    ui::SimulationRunner runner = samplingRunner(pendulum());
    for (int i = 0; i < 4; ++i)
        runner.apply(ui::StepOnce{});
    runner.apply(ui::Reset{});
    QCOMPARE(stepsOf(*runner.samples().pending()), range(0, 0));

    // far too stiff for its step (amplified ~h²k/m = 10³ times a step): the run goes back to where
    // the advance began, and the samples of the steps it took before blowing up go too
    ui::SimulationRunner stiff = samplingRunner(pendulum(1e5, 0.1));
    stiff.apply(ui::Play{});
    const int steps = stiff.advance(5.0, kNoBudgetLimit).steps;
    QVERIFY(!stiff.isRunning());
    QCOMPARE(stiff.state().step, 0u);
    QCOMPARE_GT(steps, 0);  // some were taken, and sampled, before the one that blew up
    QCOMPARE(stepsOf(*stiff.samples().pending()), range(0, 0));
}

void TestStepSamples::resumeFromAScrubDropsTheOldFuture()
{
    // 20 steps, back to step 12, then on: the samples after 12 are of the new run alone
    ui::SimulationRunner runner = samplingRunner(pendulum());
    runner.apply(ui::Play{});
    runner.advance(0.205, kNoBudgetLimit);
    QCOMPARE(runner.state().step, 20u);
    runner.apply(ui::Scrub{12});
    QCOMPARE(runner.samples().pending()->back().step, 20u);  // scrubbing samples nothing
    runner.apply(ui::Play{});
    QCOMPARE(runner.advance(0.015, kNoBudgetLimit).steps, 1);
    const auto samples = runner.samples().pending();
    QCOMPARE(stepsOf(*samples), range(0, 13));
}

void TestStepSamples::deliveredSamplesGoAndThePendingAreBounded()
{
    ui::SimulationRunner runner = samplingRunner(pendulum());
    for (int i = 0; i < 5; ++i)
        runner.apply(ui::StepOnce{});
    const auto first = runner.samples().pending();
    runner.samples().delivered((*first)[3].sequence);
    QCOMPARE(stepsOf(*runner.samples().pending()), range(4, 5));
    runner.samples().delivered(first->back().sequence);
    QVERIFY(!runner.samples().pending());
    runner.apply(ui::StepOnce{});
    QCOMPARE(stepsOf(*runner.samples().pending()), range(6, 6));

    // a window that takes nothing: the oldest go past the bound
    ui::SimulationRunner unread = samplingRunner(pendulum());
    unread.apply(ui::Play{});
    const double h = unread.model()->timeStep;
    unread.advance((double(ui::StepSampler::kMaxPending) + 10.5) * h, kNoBudgetLimit);
    QCOMPARE(unread.samples().pendingCount(), ui::StepSampler::kMaxPending);
    QCOMPARE(unread.samples().pending()->back().step, unread.state().step);
}

void TestStepSamples::aRunnerThatDoesNotSampleTakesNothing()
{
    ui::SimulationRunner runner;
    runner.apply(ui::SetSceneEdit{pendulum(), ui::SceneChange::Replace});
    runner.apply(ui::StepOnce{});
    QVERIFY(!runner.samples().enabled());
    QVERIFY(!runner.samples().pending());
}

QTEST_APPLESS_MAIN(TestStepSamples)
#include "test_step_samples.moc"
