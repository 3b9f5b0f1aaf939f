// Breakable springs: a spring breaks the step its strain passes its breaking strain, never when
// compressed, and once broken exerts no force, stores no energy and is skipped by every scheme;
// the pass costs nothing in a scene where nothing can break.
#include "core/model/diagnostics.h"
#include "core/model/generators.h"
#include "core/passes.h"
#include "core/step.h"
#include "scene_builder.h"

#include <QtTest>
#include <random>

class TestSpringBreaks : public QObject {
    Q_OBJECT

private slots:
    void breaksTheStepItsStrainIsPassed();
    void compressionNeverBreaks();
    void brokenSpringPullsNothing_data();
    void brokenSpringPullsNothing();
    void gatherEqualsThePlainLoopWithBrokenSprings();
    void passRunsOnlyWhenSomethingCanBreak();
    void parameterChangeKeepsTheBreaks();
};

namespace {

// particle 0 pinned at the origin, particle 1 moving away along x at `speed`, joined at rest
core::SceneDesc separatingPair(double speed, double breakStrain)
{
    core::SceneDesc scene = test::quietScene();
    scene.particles = {test::particle({0, 0, 0}, {0, 0, 0}, 1.0, 0.1, true), test::particle({1, 0, 0}, {speed, 0, 0})};
    scene.springs = {core::SpringDesc{0, 1, 10.0, 0.0, 1.0, breakStrain}};
    return scene;
}

double strain(const core::Model &model, const core::State &state, int k)
{
    const int a = model.springA[static_cast<std::size_t>(k)];
    const int b = model.springB[static_cast<std::size_t>(k)];
    const double rest = model.restLength[k];
    return ((state.position.col(a) - state.position.col(b)).norm() - rest) / rest;
}

}  // namespace

void TestSpringBreaks::breaksTheStepItsStrainIsPassed()
{
    test::Sim sim = test::compile(separatingPair(5.0, 0.3));
    QVERIFY(sim.model->plan.springBreaks);
    int brokeAt = 0;
    for (int step = 1; step <= 200 && brokeAt == 0; ++step) {
        const bool wasBroken = sim.state.isBroken(0);
        QVERIFY(sim.step());
        const double s = strain(*sim.model, sim.state, 0);
        // broken exactly when the strain at the end of the step is past 0.3, and never before
        QCOMPARE(sim.state.isBroken(0), wasBroken || s > 0.3);
        if (sim.state.isBroken(0))
            brokeAt = step;
    }
    QVERIFY2(brokeAt > 1, "the spring must hold for a while, then break");
    QCOMPARE(sim.state.breaks.size(), std::size_t(1));
    QCOMPARE(sim.state.breaks.front().spring, 0);
    QCOMPARE(sim.state.breaks.front().step, std::uint64_t(brokeAt));

    // from then on the particle coasts: its speed stays what it was at the break
    const double speed = sim.state.velocity(0, 1);
    for (int step = 0; step < 20; ++step)
        QVERIFY(sim.step());
    QCOMPARE(sim.state.velocity(0, 1), speed);
    QCOMPARE(sim.state.breaks.size(), std::size_t(1));
}

void TestSpringBreaks::compressionNeverBreaks()
{
    // moving in, the spring is squeezed to well past 30 % compression and bounces back out
    test::Sim sim = test::compile(separatingPair(-3.0, 0.3));
    double least = 0.0;
    for (int step = 0; step < 300; ++step) {
        QVERIFY(sim.step());
        least = std::min(least, strain(*sim.model, sim.state, 0));
        if (strain(*sim.model, sim.state, 0) > 0.3)
            break;  // out past the limit on the rebound: that may break it, by design
        QVERIFY(!sim.state.isBroken(0));
    }
    QVERIFY2(least < -0.3, qPrintable(QString("compressed only to %1").arg(least)));
}

void TestSpringBreaks::brokenSpringPullsNothing_data()
{
    QTest::addColumn<int>("integrator");
    for (core::Integrator integrator : core::kIntegrators) {
        const std::string_view name = core::integratorName(integrator);
        QTest::addRow("%.*s", int(name.size()), name.data()) << int(integrator);
    }
}

void TestSpringBreaks::brokenSpringPullsNothing()
{
    QFETCH(int, integrator);
    // stretched to twice its rest length at once: broken in the first step
    core::SceneDesc scene = separatingPair(0.0, 0.5);
    scene.particles[1].position = {2.0, 0.0, 0.0};
    scene.settings.integrator = static_cast<core::Integrator>(integrator);
    test::Sim sim = test::compile(scene);
    QVERIFY(core::energies(*sim.model, sim.state).spring > 1.0);
    QVERIFY(sim.step());
    // the first step still felt the pull; it broke at its end
    QVERIFY(sim.state.isBroken(0));
    QVERIFY(sim.state.velocity(0, 1) < 0.0);

    QCOMPARE(core::energies(*sim.model, sim.state).spring, 0.0);
    sim.work.force.setZero();
    core::addSprings(*sim.model, sim.state, sim.work);
    QCOMPARE(sim.work.force.norm(), 0.0);
    // every scheme moves the freed particle on in a straight line at its speed
    const Eigen::Vector3d velocity = sim.state.velocity.col(1);
    const Eigen::Vector3d position = sim.state.position.col(1);
    QVERIFY(sim.step());
    QVERIFY((sim.state.velocity.col(1) - velocity).norm() < 1e-12);
    QVERIFY((sim.state.position.col(1) - (position + sim.model->timeStep * velocity)).norm() < 1e-12);
}

void TestSpringBreaks::gatherEqualsThePlainLoopWithBrokenSprings()
{
    // a moving cloth with every third spring broken at random
    core::ClothOptions options;
    options.rows = options.cols = 20;
    core::SceneDesc scene = core::makeCloth(options);
    for (core::SpringDesc &spring : scene.springs)
        spring.breakStrain = 10.0;
    test::Sim sim = test::compile(scene);
    std::mt19937 random(7);
    std::uniform_real_distribution<double> jitter(-0.01, 0.01);
    for (Eigen::Index i = 0; i < sim.state.position.size(); ++i) {
        sim.state.position.data()[i] += jitter(random);
        sim.state.velocity.data()[i] = 100.0 * jitter(random);
    }
    int broken = 0;
    for (std::size_t k = 0; k < sim.state.springBroken.size(); ++k)
        if (random() % 3 == 0) {
            sim.state.springBroken[k] = 1;
            ++broken;
        }
    QVERIFY(broken > 100);

    core::State reference = sim.state;
    core::Workspace referenceWork = sim.work;
    sim.work.force.setZero();
    referenceWork.force.setZero();
    core::addSprings(*sim.model, sim.state, sim.work);
    core::addSpringsReference(*sim.model, reference, referenceWork);
    QVERIFY(sim.work.force.norm() > 1.0);
    QCOMPARE(sim.work.force, referenceWork.force);
}

void TestSpringBreaks::passRunsOnlyWhenSomethingCanBreak()
{
    for (const double breakStrain : {0.0, 0.3}) {
        test::Sim sim = test::compile(separatingPair(1.0, breakStrain));
        QCOMPARE(sim.model->plan.springBreaks, breakStrain > 0.0);
        QCOMPARE(sim.state.springBroken.empty(), breakStrain == 0.0);
        for (int step = 0; step < 10; ++step)
            QVERIFY(sim.step());
        QCOMPARE(sim.work.profile[core::Stage::Breaks].calls, breakStrain > 0.0 ? std::uint64_t(10) : 0);
        if (breakStrain == 0.0)
            QCOMPARE(sim.work.profile[core::Stage::Breaks].seconds, 0.0);
    }
}

void TestSpringBreaks::parameterChangeKeepsTheBreaks()
{
    core::SceneDesc scene = separatingPair(5.0, 0.3);
    test::Sim sim = test::compile(scene);
    for (int step = 0; step < 200 && !sim.state.isBroken(0); ++step)
        QVERIFY(sim.step());
    QVERIFY(sim.state.isBroken(0));

    // a new stiffness: the same springs, so the break stands
    scene.springs[0].stiffness = 20.0;
    auto stiffer = core::compileModel(scene);
    core::fitSpringBreaks(*stiffer, sim.state);
    QVERIFY(sim.state.isBroken(0));
    QCOMPARE(sim.state.breaks.size(), std::size_t(1));

    // a second spring: the list changed, every spring is whole again
    scene.particles.push_back(test::particle({0, 1, 0}));
    scene.springs.push_back(core::SpringDesc{0, 2, 10.0, 0.0, 1.0, 0.3});
    auto more = core::compileModel(scene);
    core::State grown = core::makeState(*more, scene);
    QCOMPARE(grown.springBroken.size(), std::size_t(2));
    QVERIFY(!grown.isBroken(0));
    QVERIFY(grown.breaks.capacity() >= 2);
}

QTEST_APPLESS_MAIN(TestSpringBreaks)
#include "test_spring_breaks.moc"
