// The accuracy planner on the damped oscillator: what it picks meets the tolerance when run (within
// a factor of 3, measured by step doubling over the run, from any phase), a tighter tolerance never
// needs fewer substeps, the pick is the cheapest row, explicit schemes stay below their stability
// limit, and the counts of force evaluations are those of each scheme.
#include "core/integrators/accuracy_planner.h"
#include "core/integrators/error_estimate.h"
#include "core/integrators/reference.h"
#include "core/integrators/stability.h"
#include "core/step.h"
#include "scene_builder.h"

#include <QtTest>

namespace {

constexpr double kSecondsPerEvaluation = 1e-7;  // s, fixed so that the costs are reproducible

// the oscillator's model and its exact state at time t
test::Sim oscillatorAt(const core::OscillatorOptions &o, double t)
{
    test::Sim sim = test::compile(core::makeOscillator(o));
    sim.state.position(0, 1) = o.restLength + core::oscillatorStretch(o, t);
    sim.state.velocity(0, 1) = core::oscillatorRate(o, t);
    return sim;
}

// the same scene run with a row's integrator and substeps
std::shared_ptr<const core::Model> withRow(const core::OscillatorOptions &o, const core::PlanCandidate &row)
{
    core::SceneDesc scene = core::makeOscillator(o);
    scene.settings.integrator = row.integrator;
    scene.settings.substeps = row.substeps;
    return core::compileModel(scene);
}

QString nameOf(core::Integrator integrator)
{
    const std::string_view name = core::integratorName(integrator);
    return QString::fromLatin1(name.data(), qsizetype(name.size()));
}

}  // namespace

class TestAccuracyPlanner : public QObject {
    Q_OBJECT

private slots:
    void meetsTheToleranceWhenRun_data();
    void meetsTheToleranceWhenRun();
    void picksTheFewestSubstepsThatMeet();
    void tighterToleranceNeverFewerSubsteps();
    void picksTheCheapestRow();
    void staysBelowTheStabilityLimit();
    void countsTheForceEvaluations();
    void measuresTheCostOfAnEvaluation();
    void aRaisedStopEndsThePlan();
};

void TestAccuracyPlanner::meetsTheToleranceWhenRun_data()
{
    QTest::addColumn<double>("tolerance");
    QTest::addColumn<double>("phase");  // s, when along the exact motion the plan is made
    for (double tolerance : {1e-3, 1e-5, 1e-7, 1e-9})
        for (double phase : {0.0, 0.08, 0.157})
            QTest::addRow("tol %g at t = %g s", tolerance, phase) << tolerance << phase;
}

void TestAccuracyPlanner::meetsTheToleranceWhenRun()
{
    QFETCH(double, tolerance);
    QFETCH(double, phase);
    const core::OscillatorOptions o;
    const test::Sim sim = oscillatorAt(o, phase);
    const core::AccuracyPlan plan = core::planAccuracy(*sim.model, sim.state, tolerance, kSecondsPerEvaluation);
    QVERIFY(plan.pick() != nullptr);

    // every feasible row, the pick among them: one second of the run (more than a period), the
    // step-doubling estimate after every step
    for (const core::PlanCandidate &row : plan.candidates) {
        if (!row.feasible)
            continue;
        QVERIFY2(row.localError <= tolerance, qPrintable(nameOf(row.integrator)));
        const auto model = withRow(o, row);
        core::State state = sim.state;
        core::Workspace work;
        core::StepDoubling doubling;
        double largest = 0.0;
        for (int n = 0; n < 100; ++n) {
            const std::optional<double> error = doubling.estimate(model, state);
            QVERIFY(error.has_value());
            largest = std::max(largest, *error);
            QVERIFY(core::step(*model, state, work));
        }
        QVERIFY2(largest <= 3.0 * tolerance, qPrintable(QStringLiteral("%1 with %2 substeps: %3 m against %4 m")
                                                            .arg(nameOf(row.integrator))
                                                            .arg(row.substeps)
                                                            .arg(largest)
                                                            .arg(tolerance)));
    }
}

void TestAccuracyPlanner::picksTheFewestSubstepsThatMeet()
{
    // one substep fewer than a row says would miss the tolerance (unless stability holds it there)
    const core::OscillatorOptions o;
    const test::Sim sim = oscillatorAt(o, 0.0);
    const double tolerance = 1e-6;
    const core::AccuracyPlan plan = core::planAccuracy(*sim.model, sim.state, tolerance, kSecondsPerEvaluation);
    const double omega = core::stabilityLimit(*sim.model, sim.state).omegaMax;
    QVERIFY(std::abs(omega - std::sqrt(o.stiffness / o.mass)) < 1e-6 * omega);
    for (const core::PlanCandidate &row : plan.candidates) {
        if (!row.feasible || row.substeps == 1 || row.stabilityLimited)
            continue;
        core::PlanCandidate fewer = row;
        fewer.substeps -= 1;
        core::StepDoubling doubling;
        const auto error = doubling.estimateLocalError(withRow(o, fewer), sim.state);
        QVERIFY(error.has_value());
        QVERIFY2(std::max(error->position, error->velocity / omega) > tolerance, qPrintable(nameOf(row.integrator)));
    }
}

void TestAccuracyPlanner::tighterToleranceNeverFewerSubsteps()
{
    const test::Sim sim = oscillatorAt({}, 0.05);
    std::vector<int> previous;
    for (double tolerance = 1e-1; tolerance >= 1e-11; tolerance /= 3.0) {
        const core::AccuracyPlan plan = core::planAccuracy(*sim.model, sim.state, tolerance, kSecondsPerEvaluation);
        QCOMPARE(plan.candidates.size(), std::size(core::kIntegrators) - 1);
        for (std::size_t i = 0; i < plan.candidates.size(); ++i) {
            const core::PlanCandidate &row = plan.candidates[i];
            if (!previous.empty())
                QVERIFY2(row.substeps >= previous[i], qPrintable(QStringLiteral("%1 at %2: %3 < %4")
                                                                     .arg(nameOf(row.integrator))
                                                                     .arg(tolerance)
                                                                     .arg(row.substeps)
                                                                     .arg(previous[i])));
        }
        previous.clear();
        for (const core::PlanCandidate &row : plan.candidates)
            previous.push_back(row.substeps);
    }
}

void TestAccuracyPlanner::picksTheCheapestRow()
{
    const test::Sim sim = oscillatorAt({}, 0.0);
    for (double tolerance : {1e-2, 1e-4, 1e-6, 1e-8, 1e-10}) {
        const core::AccuracyPlan plan = core::planAccuracy(*sim.model, sim.state, tolerance, kSecondsPerEvaluation);
        const core::PlanCandidate *pick = plan.pick();
        QVERIFY(pick != nullptr);
        QVERIFY(pick->feasible);
        for (const core::PlanCandidate &row : plan.candidates) {
            // the cost is substeps × evaluations × seconds per evaluation, per simulated second
            QCOMPARE(row.secondsPerSimulatedSecond,
                     row.feasible ? row.substeps * row.evaluationsPerSubstep * kSecondsPerEvaluation / plan.timeStep
                                  : 0.0);
            if (row.feasible)
                QVERIFY(pick->secondsPerSimulatedSecond <= row.secondsPerSimulatedSecond);
        }
    }
    // the adaptive scheme chooses its own steps: it is not a row
    const core::AccuracyPlan plan = core::planAccuracy(*sim.model, sim.state, 1e-6, kSecondsPerEvaluation);
    for (const core::PlanCandidate &row : plan.candidates)
        QVERIFY(row.integrator != core::Integrator::AdaptiveRk45);
}

void TestAccuracyPlanner::staysBelowTheStabilityLimit()
{
    // a stiff spring (ω = 1000 rad/s) barely stretched: the tolerance alone would allow one substep
    core::OscillatorOptions o;
    o.stiffness = 1e6;
    o.displacement = 1e-5;
    const test::Sim sim = oscillatorAt(o, 0.0);
    const core::StabilityLimit limit = core::stabilityLimit(*sim.model, sim.state);
    const core::AccuracyPlan plan = core::planAccuracy(*sim.model, sim.state, 1e-2, kSecondsPerEvaluation);
    for (const core::PlanCandidate &row : plan.candidates) {
        if (!row.feasible)
            continue;
        const double subStep = plan.timeStep / row.substeps;
        QVERIFY2(subStep <= limit.maxSubStep(row.integrator), qPrintable(nameOf(row.integrator)));
    }
    const core::PlanCandidate &symplectic = plan.candidates[0];
    QCOMPARE(symplectic.integrator, core::Integrator::SymplecticEuler);
    QVERIFY(symplectic.feasible);
    QVERIFY(symplectic.stabilityLimited);
    QVERIFY(symplectic.substeps > 1);
    QCOMPARE(symplectic.substeps, int(std::ceil(plan.timeStep / (core::kStabilityMargin * limit.maxSubStep(
                                                                                               symplectic.integrator)))));
    // implicit Euler has no limit: one substep is enough for it
    QCOMPARE(plan.candidates[4].integrator, core::Integrator::ImplicitEuler);
    QCOMPARE(plan.candidates[4].substeps, 1);

    // without damping explicit Euler has no stable step: never picked, and the row says why
    o.damping = 0.0;
    const test::Sim undamped = oscillatorAt(o, 0.0);
    const core::AccuracyPlan still = core::planAccuracy(*undamped.model, undamped.state, 1e-2, kSecondsPerEvaluation);
    const core::PlanCandidate &forward = still.candidates[1];
    QCOMPARE(forward.integrator, core::Integrator::ExplicitEuler);
    QVERIFY(!forward.feasible);
    QVERIFY2(QString::fromStdString(forward.reason).contains(QStringLiteral("unstable")),
             forward.reason.c_str());
    QVERIFY(still.pick() != nullptr);
    QVERIFY(still.pick()->integrator != core::Integrator::ExplicitEuler);
}

void TestAccuracyPlanner::countsTheForceEvaluations()
{
    const test::Sim sim = oscillatorAt({}, 0.0);
    const core::AccuracyPlan plan = core::planAccuracy(*sim.model, sim.state, 1e-6, kSecondsPerEvaluation);
    const double expected[] = {1.0, 1.0, 2.0, 4.0};
    for (std::size_t i = 0; i < std::size(expected); ++i)
        QCOMPARE(plan.candidates[i].evaluationsPerSubstep, expected[i]);

    // the solvers (implicit Euler, projective, vbd): their sub-step timed against an evaluation,
    // at least one
    for (std::size_t i = 4; i < plan.candidates.size(); ++i) {
        const core::PlanCandidate &candidate = plan.candidates[i];
        if (candidate.integrator == core::Integrator::AdaptiveRk45)
            continue;
        if (candidate.integrator == core::Integrator::ImplicitEuler || core::isVariational(candidate.integrator)) {
            QVERIFY2(candidate.evaluationsPerSubstep >= 1.0, core::integratorName(candidate.integrator).data());
            QVERIFY(std::isfinite(candidate.evaluationsPerSubstep));
        }
    }
}

void TestAccuracyPlanner::measuresTheCostOfAnEvaluation()
{
    test::Sim sim = oscillatorAt({}, 0.0);
    QCOMPARE(core::profiledSecondsPerEvaluation(sim.work.profile), 0.0);  // nothing measured yet
    for (int n = 0; n < 40; ++n)
        QVERIFY(sim.step());
    QVERIFY(core::profiledSecondsPerEvaluation(sim.work.profile) > 0.0);
    QVERIFY(core::timedSecondsPerEvaluation(*sim.model, sim.state) > 0.0);
}

void TestAccuracyPlanner::aRaisedStopEndsThePlan()
{
    // the editor closing raises the flag: the plan ends stopped, nothing chosen; lowered, the same
    // plan goes to its end
    const core::OscillatorOptions o;
    const test::Sim sim = oscillatorAt(o, 0.0);
    std::atomic<bool> stop{true};
    const core::AccuracyPlan stopped = core::planAccuracy(*sim.model, sim.state, 1e-7, kSecondsPerEvaluation, &stop);
    QVERIFY(stopped.stopped);
    QVERIFY(stopped.candidates.empty());
    QVERIFY(stopped.pick() == nullptr);
    stop = false;
    const core::AccuracyPlan done = core::planAccuracy(*sim.model, sim.state, 1e-7, kSecondsPerEvaluation, &stop);
    QVERIFY(!done.stopped);
    QVERIFY(done.pick() != nullptr);
}

QTEST_APPLESS_MAIN(TestAccuracyPlanner)
#include "test_accuracy_planner.moc"
