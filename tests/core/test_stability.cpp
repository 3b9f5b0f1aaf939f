// The stability limit: exact on a single oscillator, matched by experiment on chains, the same
// bits when analysed a slice at a time, and the blow-up message names what failed, where, why and
// the fix.
#include "core/diagnostics.h"
#include "core/generators.h"
#include "core/reference.h"
#include "core/stability.h"
#include "core/step.h"
#include "scene_builder.h"

#include <QtTest>

class TestStability : public QObject {
    Q_OBJECT

private slots:
    void singleOscillatorIsExact();
    void dampingNarrowsTheLimit();
    void measuredLimitMatchesTheory_data();
    void measuredLimitMatchesTheory();
    void implicitAndAdaptiveHaveNoLimit();
    void analysisInSlicesIsTheWhole();
    void blowupMessage();
    void blowupAdviceIsPossible_data();
    void blowupAdviceIsPossible();
    void adaptiveStopsOnAHopelesslyStiffScene();
    void autoSubstepsKeepTheChainStable();
    void pairSpeedLimit();
};

namespace {

// a straight chain of `nodes` particles along x, pinned at the first, at rest length, with small
// seeded random velocities to excite every mode; no gravity, no contacts
core::SceneDesc chain(int nodes)
{
    core::ChainOptions options;
    options.links = nodes - 1;
    core::SceneDesc scene = core::makeChain(options);
    scene.settings.gravity = Eigen::Vector3d::Zero();
    scene.settings.planeCollisions = scene.settings.particleCollisions = false;
    for (auto &spring : scene.springs)
        spring.damping = 0.0;
    std::uint32_t seed = 7u;
    for (std::size_t i = 1; i < scene.particles.size(); ++i)
        for (int axis = 0; axis < 3; ++axis) {
            seed = seed * 1664525u + 1013904223u;
            scene.particles[i].velocity[axis] = 1e-3 * (static_cast<double>(seed >> 8) / double(1u << 24) - 0.5);
        }
    return scene;
}

// stable: the energy stays under 10× its start for `steps` steps
bool stableAt(core::SceneDesc scene, double h, int steps)
{
    scene.settings.timeStep = h;
    test::Sim sim = test::compile(scene);
    const double start = core::energies(*sim.model, sim.state).total();
    for (int i = 0; i < steps; ++i)
        if (!sim.step() || core::energies(*sim.model, sim.state).total() > 10.0 * start)
            return false;
    return true;
}

}  // namespace

void TestStability::singleOscillatorIsExact()
{
    core::OscillatorOptions options;
    options.damping = 0.0;
    options.displacement = 0.0;  // at rest length: the linearisation is the spring itself
    const core::SceneDesc scene = core::makeOscillator(options);
    test::Sim sim = test::compile(scene);
    const core::StabilityLimit limit = core::stabilityLimit(*sim.model, sim.state);
    QVERIFY(limit.converged);
    QVERIFY(std::abs(limit.omegaMax - 10.0) < 1e-9);
    QVERIFY(limit.gershgorinOmega >= limit.omegaMax);
    QVERIFY(std::abs(limit.maxSubStep(core::Integrator::SymplecticEuler) - 0.2) < 1e-10);
    QVERIFY(std::abs(limit.maxSubStep(core::Integrator::Rk4) - 0.2 * std::sqrt(2.0)) < 1e-10);
}

void TestStability::dampingNarrowsTheLimit()
{
    core::OscillatorOptions options;
    options.damping = 4.0;  // γ = kc/m = 4 1/s
    options.displacement = 0.0;
    test::Sim sim = test::compile(core::makeOscillator(options));
    const core::StabilityLimit limit = core::stabilityLimit(*sim.model, sim.state);
    QVERIFY(std::abs(limit.dampingRate - 4.0) < 1e-9);
    // (√(γ² + 4ω²) - γ)/ω² = (√(16 + 400) - 4)/100
    const double expected = (std::sqrt(416.0) - 4.0) / 100.0;
    QVERIFY(std::abs(limit.maxSubStep(core::Integrator::SymplecticEuler) - expected) < 1e-10);
    QVERIFY(expected < 0.2);
    // explicit Euler: stable only while damping wins, h < γ/ω² = 0.04 s
    QVERIFY(std::abs(limit.maxSubStep(core::Integrator::ExplicitEuler) - 0.04) < 1e-10);
}

void TestStability::measuredLimitMatchesTheory_data()
{
    QTest::addColumn<int>("nodes");
    QTest::newRow("2 nodes") << 2;
    QTest::newRow("10 nodes") << 10;
    QTest::newRow("100 nodes") << 100;
}

void TestStability::measuredLimitMatchesTheory()
{
    QFETCH(int, nodes);
    const core::SceneDesc scene = chain(nodes);
    test::Sim sim = test::compile(scene);
    const double theory = core::stabilityLimit(*sim.model, sim.state).maxSubStep(core::Integrator::SymplecticEuler);

    // bisection between a stable and an unstable step
    double stable = 0.5 * theory, unstable = 2.0 * theory;
    QVERIFY(stableAt(scene, stable, 4000));
    QVERIFY(!stableAt(scene, unstable, 4000));
    for (int i = 0; i < 14; ++i) {
        const double middle = 0.5 * (stable + unstable);
        (stableAt(scene, middle, 4000) ? stable : unstable) = middle;
    }
    const double ratio = stable / theory;
    QVERIFY2(ratio >= 0.95 && ratio <= 1.0, qPrintable(QString("measured %1 s, theory %2 s, ratio %3")
                                                            .arg(stable).arg(theory).arg(ratio)));
}

void TestStability::implicitAndAdaptiveHaveNoLimit()
{
    test::Sim sim = test::compile(chain(5));
    const core::StabilityLimit limit = core::stabilityLimit(*sim.model, sim.state);
    QVERIFY(std::isinf(limit.maxSubStep(core::Integrator::ImplicitEuler)));
    QVERIFY(std::isinf(limit.maxSubStep(core::Integrator::AdaptiveRk45)));
    QCOMPARE(limit.maxSubStep(core::Integrator::ExplicitEuler), 0.0);  // undamped
    // and a scene without springs has nothing to limit
    test::Sim empty = test::compile(test::quietScene());
    QVERIFY(std::isinf(core::stabilityLimit(*empty.model, empty.state).maxSubStep(core::Integrator::SymplecticEuler)));
}

void TestStability::analysisInSlicesIsTheWhole()
{
    // a cloth (many modes near the top: the power iteration takes many products), analysed one
    // product at a time as the editor does between steps, ends with the bits of the whole analysis
    core::ClothOptions options;
    options.rows = options.cols = 12;
    test::Sim sim = test::compile(core::makeCloth(options));
    const core::StabilityLimit whole = core::stabilityLimit(*sim.model, sim.state);

    core::StabilityAnalysis analysis(*sim.model, sim.state);
    int slices = 1;
    while (!analysis.run(1))
        ++slices;
    QVERIFY2(slices > 10, qPrintable(QString::number(slices)));  // it was spread out
    QVERIFY(analysis.done());
    const core::StabilityLimit &sliced = analysis.limit();
    QCOMPARE(sliced.omegaMax, whole.omegaMax);
    QCOMPARE(sliced.dampingRate, whole.dampingRate);
    QCOMPARE(sliced.gershgorinOmega, whole.gershgorinOmega);
    QCOMPARE(sliced.converged, whole.converged);
    QVERIFY(whole.omegaMax > 0.0);

    // the state it linearises at is its own copy: the run may go on meanwhile
    core::StabilityAnalysis early(*sim.model, sim.state);
    early.run(3);
    sim.step();
    early.run(1000);
    QCOMPARE(early.limit().omegaMax, whole.omegaMax);

    // nothing to analyse: done at once
    test::Sim empty = test::compile(core::SceneDesc{});
    QVERIFY(core::StabilityAnalysis(*empty.model, empty.state).done());
}

void TestStability::blowupMessage()
{
    // k = 1e5 N/m, m = 1 kg: ω = 316 rad/s, limit 2/ω = 6.3 ms; h = 0.02 s is 3.2× that
    core::OscillatorOptions options;
    options.stiffness = 1e5;
    options.damping = 0.0;
    core::SceneDesc scene = core::makeOscillator(options);
    scene.settings.timeStep = 0.02;
    test::Sim sim = test::compile(scene);
    const core::State start = sim.state;
    while (sim.step()) {
    }
    QVERIFY(sim.work.blowup.has_value());
    const std::string message =
        core::explainBlowup(*sim.model, *sim.work.blowup, core::stabilityLimit(*sim.model, start));
    const QString text = QString::fromStdString(message);
    QVERIFY2(text.startsWith("Particle 1's velocity became"), message.c_str());
    QVERIFY2(text.contains(QString("(step %1)").arg(sim.work.blowup->step)), message.c_str());
    QVERIFY2(text.contains("The time step 0.02 s is 3.2× the stability limit 0.0063 s"), message.c_str());
    QVERIFY2(text.contains("stiffness 1e+05 N/m with symplectic-euler"), message.c_str());
    QVERIFY2(text.contains("use ≥ 4 substeps or the implicit-euler integrator"), message.c_str());
}

void TestStability::blowupAdviceIsPossible_data()
{
    // the scene's oscillator (one free particle of `mass` on a spring of `stiffness`), and what
    // the message must say, and must not
    QTest::addColumn<double>("mass");
    QTest::addColumn<double>("stiffness");
    QTest::addColumn<double>("viscosity");
    QTest::addColumn<double>("timeStep");
    QTest::addColumn<QString>("says");
    QTest::addColumn<QString>("neverSays");
    // ω = 3e14 rad/s: 1.8e12 substeps would be needed, past the int range and the 10 000 allowed
    QTest::newRow("far too many substeps") << 1e-20 << 1e9 << 0.0 << 0.01
                                           << "it would take 1.8e+12 substeps, more than the 1e+04 allowed: use the "
                                              "implicit-euler integrator, softer springs or heavier particles"
                                           << "use ≥ -";
    QTest::newRow("more than allowed") << 1e-5 << 1e9 << 0.0 << 0.01 << "more than the 1e+04 allowed" << "use ≥ ";
    // drag 1e6 kg/s on 1e-9 kg: a time constant of 1e-15 s, named as the cause
    QTest::newRow("drag") << 1e-9 << 1.0 << 1e6 << 0.01
                          << "The drag (viscosity 1e+06 kg/s on a particle of 1e-09 kg) is too strong for the sub-step"
                          << "within the springs' stability limit";
    // ω = 10 rad/s, limit 0.2 s; a step of 0.201 s reads as such, not as "1× the limit 0.2 s"
    QTest::newRow("just past the limit") << 1.0 << 100.0 << 0.0 << 0.201
                                         << "The time step 0.201 s is 1.005× the stability limit 0.2 s" << "1× the";
}

void TestStability::blowupAdviceIsPossible()
{
    QFETCH(double, mass);
    QFETCH(double, stiffness);
    QFETCH(double, viscosity);
    QFETCH(double, timeStep);
    QFETCH(QString, says);
    QFETCH(QString, neverSays);
    core::OscillatorOptions options;
    options.stiffness = stiffness;
    options.damping = 0.0;
    core::SceneDesc scene = core::makeOscillator(options);
    for (core::ParticleDesc &p : scene.particles)
        p.mass = mass;
    scene.settings.viscosity = viscosity;
    scene.settings.timeStep = timeStep;
    test::Sim sim = test::compile(scene);
    const core::Blowup blowup{1, core::Blowup::Quantity::Velocity, 1e12, 3, 2.0 * timeStep};
    const QString text = QString::fromStdString(
        core::explainBlowup(*sim.model, blowup, core::stabilityLimit(*sim.model, sim.state)));
    QVERIFY2(text.contains(says), qPrintable(text));
    QVERIFY2(!text.contains(neverSays), qPrintable(text));
}

void TestStability::adaptiveStopsOnAHopelesslyStiffScene()
{
    // found by fuzzing the loader: drag 1e6 kg/s on a 1e-9 kg particle is a time constant of
    // 1e-15 s; adaptive-rk45 shrank its step for ever inside one 1 s step. It now stops, says why
    core::SceneDesc scene;
    scene.settings.integrator = core::Integrator::AdaptiveRk45;
    scene.settings.timeStep = 1.0;
    scene.settings.viscosity = 1e6;
    scene.settings.gravity = Eigen::Vector3d::Zero();
    core::ParticleDesc p;
    p.position = {0.0, 1.0, 0.0};
    p.velocity = {1.0, 0.0, 0.0};
    p.mass = 1e-9;
    p.radius = 0.1;
    scene.particles = {p};
    test::Sim sim = test::compile(scene);
    const core::State start = sim.state;
    QVERIFY(!sim.step());
    QVERIFY(sim.work.blowup.has_value());
    QCOMPARE(sim.work.blowup->quantity, core::Blowup::Quantity::StepSize);
    QCOMPARE(sim.work.blowup->step, std::uint64_t(1));
    QVERIFY(sim.work.blowup->value > 0.0 && sim.work.blowup->value < 1e-9);
    const std::string message =
        core::explainBlowup(*sim.model, *sim.work.blowup, core::stabilityLimit(*sim.model, start));
    const QString text = QString::fromStdString(message);
    QVERIFY2(text.startsWith("adaptive-rk45 could not meet its tolerance 1e-06 within a sub-step at t = 0 s (step 1)"),
             message.c_str());
    QVERIFY2(text.contains("use the implicit-euler integrator"), message.c_str());
    // the step refuses to go on, as after any blow-up
    QVERIFY(!sim.step());
}

void TestStability::autoSubstepsKeepTheChainStable()
{
    // a step 5× the limit: auto substeps splits it into the fewest sub-steps under 90% of the limit,
    // and a run that blows up without them stays bounded with them
    core::SceneDesc scene = chain(10);
    const test::Sim probe = test::compile(scene);
    const core::StabilityLimit limit = core::stabilityLimit(*probe.model, probe.state);
    const double maxStep = limit.maxSubStep(core::Integrator::SymplecticEuler);
    const double h = 5.0 * maxStep;
    QVERIFY(!stableAt(scene, h, 4000));

    scene.settings.timeStep = h;
    scene.settings.autoSubsteps = true;
    const test::Sim sim = test::compile(scene);
    const int substeps = sim.model->substeps;
    QCOMPARE(substeps, int(std::ceil(5.0 / core::kStableShare)));
    QVERIFY(sim.model->subStep() <= core::kStableShare * maxStep);
    QVERIFY(h / (substeps - 1) > core::kStableShare * maxStep);  // the fewest that do
    QVERIFY(stableAt(scene, h, 4000));

    // the scene's substeps is the least it takes
    scene.settings.substeps = 20;
    QCOMPARE(test::compile(scene).model->substeps, 20);

    // the arithmetic at the edges: at least `least`, at most `most`, and `most` when no step is stable
    QCOMPARE(core::stableSubsteps(limit, core::Integrator::SymplecticEuler, 0.5 * maxStep, 1, 10000), 1);
    QCOMPARE(core::stableSubsteps(limit, core::Integrator::SymplecticEuler, 1e6 * maxStep, 1, 10000), 10000);
    QCOMPARE(core::stableSubsteps(limit, core::Integrator::ImplicitEuler, h, 2, 10000), 2);
    QCOMPARE(core::stableSubsteps(limit, core::Integrator::ExplicitEuler, h, 1, 10000), 10000);  // undamped
}

void TestStability::pairSpeedLimit()
{
    // two particles of radius 0.05 m head on at 10 m/s each, and a third at rest with a larger
    // radius: relative displacement 20 m/s × 0.01 s = 0.2 m per sub-step against a contact at 0.1 m
    core::SceneDesc scene;
    scene.settings.gravity.setZero();
    scene.settings.timeStep = 0.01;
    core::ParticleDesc p;
    p.radius = 0.05;
    p.position = {-1.0, 0.0, 0.0};
    p.velocity = {10.0, 0.0, 0.0};
    scene.particles.push_back(p);
    p.position = {1.0, 0.0, 0.0};
    p.velocity = {-10.0, 0.0, 0.0};
    scene.particles.push_back(p);
    p.position = {0.0, 5.0, 0.0};
    p.velocity.setZero();
    p.radius = 0.5;
    scene.particles.push_back(p);
    const test::Sim sim = test::compile(scene);
    const std::optional<core::PairSpeedExcess> excess = core::pairSpeedExcess(*sim.model, sim.state);
    QVERIFY(excess.has_value());
    QCOMPARE(excess->relativeSpeed, 20.0);
    QVERIFY(std::abs(excess->displacement - 0.2) < 1e-12);
    QCOMPARE(excess->contactDistance, 0.1);
    QCOMPARE(excess->substeps, 2);
    QVERIFY(excess->fastest == 0 || excess->fastest == 1);
    const std::string text = core::explainPairSpeed(*excess);
    QVERIFY2(text.find("Particles move up to 0.2 m apart per sub-step (up to 20 m/s") == 0 &&
                 text.find("more than the 0.1 m at which the smallest pair touches") != std::string::npos &&
                 text.find("Use ≥ 2 substeps.") != std::string::npos,
             text.c_str());

    // the substeps it names are enough; without particle contacts there is no limit
    scene.settings.substeps = excess->substeps;
    test::Sim split = test::compile(scene);
    QVERIFY(!core::pairSpeedExcess(*split.model, split.state).has_value());
    scene.settings.substeps = 1;
    scene.settings.particleCollisions = false;
    split = test::compile(scene);
    QVERIFY(!core::pairSpeedExcess(*split.model, split.state).has_value());

    // and the substeps it names do hold them: the two bounce instead of passing through
    scene.settings.particleCollisions = true;
    scene.settings.substeps = excess->substeps;
    test::Sim run = test::compile(scene);
    for (int i = 0; i < 20; ++i)
        QVERIFY(run.step());
    QVERIFY(run.state.position(0, 0) < run.state.position(0, 1));
}

QTEST_APPLESS_MAIN(TestStability)
#include "test_stability.moc"
