// The integrators: measured convergence order, energy behaviour, stiff stability, the adaptive
// scheme's tolerance.
#include "core/model/diagnostics.h"
#include "core/model/generators.h"
#include "core/integrators/reference.h"
#include "core/step.h"
#include "scene_builder.h"

#include <QtTest>

Q_DECLARE_METATYPE(core::Integrator)

class TestIntegrators : public QObject {
    Q_OBJECT

private slots:
    void convergenceOrder_data();
    void convergenceOrder();
    void energyOverALongRun_data();
    void energyOverALongRun();
    void implicitEulerStableFarBeyondTheExplicitLimit();
    void implicitEulerHoldsPinnedParticles();
    void adaptiveMeetsItsTolerance_data();
    void adaptiveMeetsItsTolerance();
    void everyIntegratorHasAName();
};

namespace {

// position error at time T of reference problem 1 (damped oscillator) with step h
double oscillatorError(core::Integrator integrator, double h, double duration)
{
    const core::OscillatorOptions options;
    core::SceneDesc scene = core::makeOscillator(options);
    scene.settings.integrator = integrator;
    scene.settings.timeStep = h;
    test::Sim sim = test::compile(scene);
    const int steps = static_cast<int>(std::lround(duration / h));
    for (int i = 0; i < steps; ++i)
        if (!sim.step())
            return std::numeric_limits<double>::infinity();
    const double exact = options.restLength + core::oscillatorStretch(options, steps * h);
    return std::abs(sim.state.position(0, 1) - exact);
}

}  // namespace

void TestIntegrators::convergenceOrder_data()
{
    QTest::addColumn<core::Integrator>("integrator");
    QTest::addColumn<double>("coarse");  // s, a step well inside the asymptotic range
    QTest::addColumn<double>("order");
    QTest::newRow("symplectic-euler") << core::Integrator::SymplecticEuler << 1e-3 << 1.0;
    QTest::newRow("explicit-euler") << core::Integrator::ExplicitEuler << 1e-3 << 1.0;
    QTest::newRow("velocity-verlet") << core::Integrator::VelocityVerlet << 2e-3 << 2.0;
    QTest::newRow("rk4") << core::Integrator::Rk4 << 1e-2 << 4.0;
    QTest::newRow("implicit-euler") << core::Integrator::ImplicitEuler << 1e-3 << 1.0;
}

void TestIntegrators::convergenceOrder()
{
    QFETCH(core::Integrator, integrator);
    QFETCH(double, coarse);
    QFETCH(double, order);
    // halving the step divides the error by 2^order
    const double e1 = oscillatorError(integrator, coarse, 2.0);
    const double e2 = oscillatorError(integrator, coarse / 2, 2.0);
    const double e3 = oscillatorError(integrator, coarse / 4, 2.0);
    const double measured = std::log2(e1 / e2);
    const double measuredFiner = std::log2(e2 / e3);
    QVERIFY2(std::abs(measured - order) <= 0.2 && std::abs(measuredFiner - order) <= 0.2,
             qPrintable(QString("errors %1 %2 %3, orders %4 %5").arg(e1).arg(e2).arg(e3).arg(measured).arg(measuredFiner)));
}

void TestIntegrators::energyOverALongRun_data()
{
    QTest::addColumn<core::Integrator>("integrator");
    QTest::addColumn<int>("expected");  // 0 bounded, 1 growing, -1 decaying
    QTest::newRow("symplectic-euler") << core::Integrator::SymplecticEuler << 0;
    QTest::newRow("velocity-verlet") << core::Integrator::VelocityVerlet << 0;
    QTest::newRow("explicit-euler") << core::Integrator::ExplicitEuler << 1;
    QTest::newRow("implicit-euler") << core::Integrator::ImplicitEuler << -1;
}

void TestIntegrators::energyOverALongRun()
{
    QFETCH(core::Integrator, integrator);
    QFETCH(int, expected);
    // an undamped oscillator, ω = 10 rad/s, h = 0.01 s (ω h = 0.1), about 32 periods
    core::OscillatorOptions options;
    options.damping = 0.0;
    core::SceneDesc scene = core::makeOscillator(options);
    scene.settings.integrator = integrator;
    test::Sim sim = test::compile(scene);
    const double e0 = core::energies(*sim.model, sim.state).total();
    double lowest = e0, highest = e0;
    for (int i = 0; i < 2000; ++i) {
        QVERIFY(sim.step());
        const double e = core::energies(*sim.model, sim.state).total();
        lowest = std::min(lowest, e);
        highest = std::max(highest, e);
    }
    const double last = core::energies(*sim.model, sim.state).total();
    const QString seen = QString("start %1, lowest %2, highest %3, end %4").arg(e0).arg(lowest).arg(highest).arg(last);
    if (expected == 0)
        QVERIFY2(lowest > 0.9 * e0 && highest < 1.1 * e0, qPrintable(seen));
    else if (expected > 0)
        QVERIFY2(last > 100.0 * e0, qPrintable(seen));
    else
        QVERIFY2(last < 0.01 * e0 && highest <= e0 * (1 + 1e-12), qPrintable(seen));
}

void TestIntegrators::implicitEulerStableFarBeyondTheExplicitLimit()
{
    // ω = 1000 rad/s: the explicit limit is h = 2/ω = 2 ms; implicit Euler at 100 × that
    core::OscillatorOptions options;
    options.stiffness = 1e6;
    options.damping = 0.0;
    core::SceneDesc scene = core::makeOscillator(options);
    scene.settings.integrator = core::Integrator::ImplicitEuler;
    scene.settings.timeStep = 0.2;
    test::Sim sim = test::compile(scene);
    const double e0 = core::energies(*sim.model, sim.state).total();
    for (int i = 0; i < 100; ++i)
        QVERIFY(sim.step());
    QVERIFY(core::energies(*sim.model, sim.state).total() < e0);
    QVERIFY(std::abs(sim.state.position(0, 1) - options.restLength) < options.displacement);

    // while symplectic Euler at the same step blows up, and is caught
    scene.settings.integrator = core::Integrator::SymplecticEuler;
    test::Sim explicitSim = test::compile(scene);
    bool ok = true;
    for (int i = 0; i < 100 && ok; ++i)
        ok = explicitSim.step();
    QVERIFY(!ok);
}

void TestIntegrators::implicitEulerHoldsPinnedParticles()
{
    // a stiff cloth hanging from two pinned corners with a large step: pins stay, nothing explodes
    core::ClothOptions options;
    options.rows = options.cols = 8;
    options.substeps = 1;
    core::SceneDesc scene = core::makeCloth(options);
    scene.settings.integrator = core::Integrator::ImplicitEuler;
    scene.settings.timeStep = 0.01;
    test::Sim sim = test::compile(scene);
    const Eigen::Vector3d corner = sim.state.position.col(0);
    for (int i = 0; i < 200; ++i)
        QVERIFY(sim.step());
    QCOMPARE(Eigen::Vector3d(sim.state.position.col(0)), corner);
    QVERIFY(sim.state.position(1, 63) < options.height - 0.1);  // the far corner fell
    // conjugate gradients converge on it: no cap hit, no factorisation
    QVERIFY(sim.work.profile.solverIterations > 0);
    QVERIFY(sim.work.profile.worstSolverResidual <= 1e-10);
    QCOMPARE(sim.work.profile.solverCapHits, std::uint64_t(0));
    QCOMPARE(sim.work.profile.factorisations, std::uint64_t(0));
}

void TestIntegrators::adaptiveMeetsItsTolerance_data()
{
    QTest::addColumn<QString>("problem");
    QTest::addColumn<double>("tolerance");
    QTest::newRow("oscillator 1e-6") << "oscillator" << 1e-6;
    QTest::newRow("oscillator 1e-9") << "oscillator" << 1e-9;
    QTest::newRow("chain 1e-6") << "chain" << 1e-6;
}

void TestIntegrators::adaptiveMeetsItsTolerance()
{
    QFETCH(QString, problem);
    QFETCH(double, tolerance);
    const double duration = 1.0;
    double error = 0.0;
    std::uint64_t rejected = 0;
    if (problem == "oscillator") {
        const core::OscillatorOptions options;
        core::SceneDesc scene = core::makeOscillator(options);
        scene.settings.integrator = core::Integrator::AdaptiveRk45;
        scene.settings.tolerance = tolerance;
        scene.settings.timeStep = 0.1;
        test::Sim sim = test::compile(scene);
        for (int i = 0; i < 10; ++i)
            QVERIFY(sim.step());
        error = std::abs(sim.state.position(0, 1) - options.restLength - core::oscillatorStretch(options, duration));
        rejected = sim.work.profile.rejectedSteps;
    } else {
        // reference problem 4: the 10-link chain released horizontally, against RK4 at 1e-5 s
        core::SceneDesc scene = core::makeChain({});
        scene.settings.planeCollisions = scene.settings.particleCollisions = false;
        scene.settings.timeStep = 1e-5;
        scene.settings.integrator = core::Integrator::Rk4;
        test::Sim reference = test::compile(scene);
        for (int i = 0; i < 100000; ++i)
            QVERIFY(reference.step());
        scene.settings.integrator = core::Integrator::AdaptiveRk45;
        scene.settings.tolerance = tolerance;
        scene.settings.timeStep = 0.01;
        test::Sim sim = test::compile(scene);
        for (int i = 0; i < 100; ++i)
            QVERIFY(sim.step());
        error = (sim.state.position - reference.state.position).cwiseAbs().maxCoeff();
        rejected = sim.work.profile.rejectedSteps;
    }
    QVERIFY2(error <= 10.0 * tolerance, qPrintable(QString("error %1 at tolerance %2").arg(error).arg(tolerance)));
    QVERIFY2(error > 0.0, "an error of exactly zero means nothing was measured");
    Q_UNUSED(rejected);
}

void TestIntegrators::everyIntegratorHasAName()
{
    for (core::Integrator integrator : core::kIntegrators) {
        const std::string_view name = core::integratorName(integrator);
        QVERIFY(name != "unknown");
        QCOMPARE(core::integratorFromName(name), std::optional<core::Integrator>(integrator));
    }
    QVERIFY(!core::integratorFromName("leapfrog"));
}

QTEST_APPLESS_MAIN(TestIntegrators)
#include "test_integrators.moc"
