// Step doubling estimates the true local error of a sub-step within a factor of 3.
#include "core/integrators/error_estimate.h"
#include "core/integrators/reference.h"
#include "core/step.h"
#include "scene_builder.h"

#include <QtTest>
#include <atomic>

Q_DECLARE_METATYPE(core::Integrator)

class TestErrorEstimate : public QObject {
    Q_OBJECT

private slots:
    void withinAFactorOfThree_data();
    void withinAFactorOfThree();
    void leavesTheStateAlone();
    void stopsWhenInterrupted();
};

void TestErrorEstimate::withinAFactorOfThree_data()
{
    QTest::addColumn<core::Integrator>("integrator");
    QTest::addColumn<double>("h");
    QTest::newRow("symplectic-euler") << core::Integrator::SymplecticEuler << 1e-3;
    QTest::newRow("explicit-euler") << core::Integrator::ExplicitEuler << 1e-3;
    QTest::newRow("velocity-verlet") << core::Integrator::VelocityVerlet << 1e-3;
    QTest::newRow("rk4") << core::Integrator::Rk4 << 1e-2;
    QTest::newRow("implicit-euler") << core::Integrator::ImplicitEuler << 1e-3;
}

void TestErrorEstimate::withinAFactorOfThree()
{
    QFETCH(core::Integrator, integrator);
    QFETCH(double, h);
    // from the exact state of the damped oscillator at several times, one step of h against the
    // exact solution h later
    const core::OscillatorOptions o;
    core::SceneDesc scene = core::makeOscillator(o);
    scene.settings.integrator = integrator;
    scene.settings.timeStep = h;
    auto model = core::compileModel(scene);
    core::StepDoubling doubling;
    for (double t : {0.05, 0.31, 0.77, 1.2}) {
        core::State state = core::makeState(*model, scene);
        core::Workspace work;
        state.position(0, 1) = o.restLength + core::oscillatorStretch(o, t);
        state.velocity(0, 1) = core::oscillatorRate(o, t);
        const auto estimate = doubling.estimate(model, state);
        QVERIFY(estimate.has_value());
        QVERIFY(core::step(*model, state, work));
        const double truth = std::abs(state.position(0, 1) - o.restLength - core::oscillatorStretch(o, t + h));
        QVERIFY2(*estimate <= 3.0 * truth && *estimate >= truth / 3.0,
                 qPrintable(QString("t %1: estimate %2, true %3").arg(t).arg(*estimate).arg(truth)));
    }
}

void TestErrorEstimate::leavesTheStateAlone()
{
    core::SceneDesc scene = core::makeOscillator({});
    auto model = core::compileModel(scene);
    core::State state = core::makeState(*model, scene);
    const Eigen::Matrix3Xd before = state.position;
    core::StepDoubling doubling;
    QVERIFY(doubling.estimate(model, state).value() > 0.0);
    QVERIFY(state.position == before);
    QCOMPARE(state.step, std::uint64_t(0));
}

void TestErrorEstimate::stopsWhenInterrupted()
{
    // a raised flag: no estimate, and it says why; lowered: the same estimate as without one
    core::SceneDesc scene = core::makeOscillator({});
    auto model = core::compileModel(scene);
    const core::State state = core::makeState(*model, scene);
    std::atomic<bool> waiting{true};
    core::StepDoubling cut;
    cut.setInterrupt(&waiting);
    QVERIFY(!cut.estimate(model, state));
    QVERIFY(cut.interrupted());
    waiting = false;
    const std::optional<double> estimate = cut.estimate(model, state);
    QVERIFY(!cut.interrupted());
    core::StepDoubling plain;
    QVERIFY(estimate && *estimate == plain.estimate(model, state).value());
}

QTEST_APPLESS_MAIN(TestErrorEstimate)
#include "test_error_estimate.moc"
