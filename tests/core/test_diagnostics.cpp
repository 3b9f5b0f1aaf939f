// Energies and momentum against values worked out by hand; energy behaviour over a run.
#include "core/model/diagnostics.h"
#include "core/model/generators.h"
#include "core/step.h"
#include "scene_builder.h"

#include <QtTest>

class TestDiagnostics : public QObject {
    Q_OBJECT

private slots:
    void byHand();
    void undampedOscillatorKeepsItsEnergy();
    void dampingOnlyLosesEnergy();
};

void TestDiagnostics::byHand()
{
    core::SceneDesc scene = test::quietScene();
    scene.settings.gravity = {0, -10, 0};
    scene.particles = {test::particle({0, 2, 0}, {3, 4, 0}, 2.0), test::particle({0, 0, 1}, {1, 1, 1}, 5.0, 0.1, true)};
    scene.springs = {{0, 1, 8, 0, 2}};  // length √5
    test::Sim sim = test::compile(scene);
    const core::Energies e = core::energies(*sim.model, sim.state);
    QCOMPARE(e.kinetic, 25.0);                 // ½ 2 · 25; the pinned one is at rest
    QCOMPARE(e.gravitational, 40.0);           // 2 · 10 · 2 + 5 · 10 · 0
    const double stretch = std::sqrt(5.0) - 2.0;
    QVERIFY(std::abs(e.spring - 4.0 * stretch * stretch) < 1e-14);
    QCOMPARE(e.total(), e.kinetic + e.gravitational + e.spring);
    QCOMPARE(core::momentum(*sim.model, sim.state), Eigen::Vector3d(6, 8, 0));
}

void TestDiagnostics::undampedOscillatorKeepsItsEnergy()
{
    // symplectic Euler keeps the energy of a harmonic oscillator bounded (no drift) at ωh = 0.1
    core::SceneDesc scene = test::quietScene();
    scene.settings.timeStep = 0.001;
    scene.particles = {test::particle({0, 0, 0}, {0, 0, 0}, 1.0, 0.1, true), test::particle({1.1, 0, 0})};
    scene.springs = {{0, 1, 10000, 0, 1}};
    test::Sim sim = test::compile(scene);
    const double e0 = core::energies(*sim.model, sim.state).total();
    double worst = 0.0;
    for (int i = 0; i < 20000; ++i) {
        QVERIFY(sim.step());
        worst = std::max(worst, std::abs(core::energies(*sim.model, sim.state).total() - e0) / e0);
    }
    QVERIFY2(worst < 0.06, qPrintable(QString::number(worst)));
    // and the explicit Euler baseline gains energy on the same problem
    scene.settings.integrator = core::Integrator::ExplicitEuler;
    test::Sim forward = test::compile(scene);
    for (int i = 0; i < 2000; ++i)
        QVERIFY(forward.step());
    QVERIFY(core::energies(*forward.model, forward.state).total() > 2.0 * e0);
}

void TestDiagnostics::dampingOnlyLosesEnergy()
{
    core::ChainOptions options;
    options.damping = 0.5;
    core::SceneDesc scene = core::makeChain(options);
    scene.settings.viscosity = 0.05;
    scene.settings.timeStep = 0.001;
    test::Sim sim = test::compile(scene);
    double previous = core::energies(*sim.model, sim.state).total();
    const double first = previous;
    for (int i = 0; i < 3000; ++i) {
        QVERIFY(sim.step());
        if (i % 100 == 99) {
            const double now = core::energies(*sim.model, sim.state).total();
            QVERIFY2(now <= previous + 1e-3, qPrintable(QString("%1 > %2 at step %3").arg(now).arg(previous).arg(i)));
            previous = now;
        }
    }
    QVERIFY(previous < first - 0.1);  // it did lose energy: the chain swung down and slowed
}

QTEST_APPLESS_MAIN(TestDiagnostics)
#include "test_diagnostics.moc"
