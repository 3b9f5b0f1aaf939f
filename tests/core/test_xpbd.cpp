// The xpbd integrator (core/xpbd.cpp): springs as compliant distance constraints. What it must do
// for a user: hold the spring's own stiffness whatever the sub-step (the statics of a hanging
// mass), run stiff springs that explicit schemes cannot at the same step, keep pins exact, give
// the same bits on any number of threads, and break springs and collide like every integrator.

#include "core/generators.h"
#include "core/stability.h"
#include "core/threads.h"
#include "core/xpbd.h"
#include "scene_builder.h"

#include <QtTest>

#include <set>

class TestXpbd : public QObject {
    Q_OBJECT
private slots:
    void hangingMassStretchesByItsWeight_data();
    void hangingMassStretchesByItsWeight();
    void stiffChainRunsWhereEulerBlowsUp();
    void withoutSpringsItIsSymplecticEuler();
    void coloursNeverShareAParticle();
    void sameBitsOnAnyThreadCount();
    void springsBreak();
    void dragIsStableAtAnyViscosity();
    void noStabilityLimit();
};

namespace {

// one particle of 1 kg hanging from a pinned one by a damped spring of rest length 1 m
core::SceneDesc hangingMass(double stiffness, int substeps)
{
    core::SceneDesc scene = test::quietScene();
    scene.settings.gravity = Eigen::Vector3d(0.0, -9.81, 0.0);
    scene.settings.integrator = core::Integrator::Xpbd;
    scene.settings.substeps = substeps;
    scene.particles = {test::particle({0.0, 0.0, 0.0}, Eigen::Vector3d::Zero(), 1.0, 0.05, true), test::particle({0.0, -1.0, 0.0})};
    core::addSpring(scene, 0, 1, stiffness, 2.0 * std::sqrt(stiffness));  // critically damped
    scene.springs[0].restLength = 1.0;
    return scene;
}

core::SceneDesc cloth(int size, double stiffness, int substeps)
{
    core::ClothOptions options;
    options.rows = size;
    options.cols = size;
    options.structuralStiffness = stiffness;
    options.shearStiffness = 0.2 * stiffness;
    options.bendStiffness = 0.03 * stiffness;
    options.substeps = substeps;
    core::SceneDesc scene = core::makeCloth(options);
    scene.settings.integrator = core::Integrator::Xpbd;
    return scene;
}

}  // namespace

void TestXpbd::hangingMassStretchesByItsWeight_data()
{
    QTest::addColumn<double>("stiffness");
    QTest::addColumn<int>("substeps");
    // the compliance keeps the stiffness whatever the sub-step: the same stretch at 1 and 100
    for (double k : {1e3, 1e6})
        for (int substeps : {1, 10, 100})
            QTest::addRow("k %g, %d sub-steps", k, substeps) << k << substeps;
}

void TestXpbd::hangingMassStretchesByItsWeight()
{
    QFETCH(double, stiffness);
    QFETCH(int, substeps);
    test::Sim sim = test::compile(hangingMass(stiffness, substeps));
    for (int i = 0; i < 500; ++i)
        QVERIFY(sim.step());
    const double stretch = -sim.state.position(1, 1) - 1.0;
    const double expected = 9.81 / stiffness;
    qInfo("stretch %.9g m, m g / k %.9g m", stretch, expected);
    QVERIFY2(std::abs(stretch / expected - 1.0) < 1e-6, qPrintable(QString::number(stretch / expected - 1.0)));
    QCOMPARE(sim.state.position.col(0), Eigen::Vector3d::Zero().eval());  // the pin stays exactly
}

void TestXpbd::stiffChainRunsWhereEulerBlowsUp()
{
    // a chain of 100 links at k = 1e8 N/m swinging from horizontal, 100 sub-steps of 0.1 ms:
    // symplectic Euler's limit is below that (ω = √(2k/m) ≈ 4.5e4 /s, ω h ≈ 4.5 > 2), xpbd stays
    // within 1% of each link (0.14%; at 10 sub-steps 9%: one constraint pass a sub-step carries the
    // pin's pull down the chain a colour at a time, so a long chain needs small steps)
    core::ChainOptions options;
    options.links = 100;
    options.stiffness = 1e8;
    options.damping = 10.0;
    core::SceneDesc scene = core::makeChain(options);
    scene.settings.substeps = 100;
    scene.settings.planeCollisions = false;
    scene.settings.particleCollisions = false;

    scene.settings.integrator = core::Integrator::SymplecticEuler;
    test::Sim euler = test::compile(scene);
    bool eulerLasted = true;
    for (int i = 0; i < 100 && eulerLasted; ++i)
        eulerLasted = euler.step();
    QVERIFY(!eulerLasted);

    scene.settings.integrator = core::Integrator::Xpbd;
    test::Sim sim = test::compile(scene);
    double worst = 0.0;
    for (int i = 0; i < 200; ++i) {
        QVERIFY(sim.step());
        for (int k = 0; k < sim.model->springCount(); ++k) {
            const double length = (sim.state.position.col(k) - sim.state.position.col(k + 1)).norm();
            worst = std::max(worst, std::abs(length / sim.model->restLength[k] - 1.0));
        }
    }
    qInfo("worst link strain over 2 s: %.3g", worst);
    QVERIFY2(worst < 0.01, qPrintable(QString::number(worst)));
    // it swung: the free end went below the pin
    QVERIFY(sim.state.position(1, 100) < sim.state.position(1, 0) - 1.0);
}

void TestXpbd::withoutSpringsItIsSymplecticEuler()
{
    // with no springs the sub-step is symplectic Euler's kick and drift, to rounding (its velocity
    // is the move divided by h) and with the drag taken implicitly, v / (1 + h c / m)
    core::SceneDesc scene = test::quietScene();
    scene.settings.gravity = Eigen::Vector3d(0.0, -9.81, 0.0);
    scene.particles = {test::particle({0.0, 0.0, 0.0}, {3.0, 4.0, 0.0})};
    scene.settings.integrator = core::Integrator::SymplecticEuler;
    test::Sim euler = test::compile(scene);
    scene.settings.integrator = core::Integrator::Xpbd;
    test::Sim sim = test::compile(scene);
    for (int i = 0; i < 100; ++i) {
        QVERIFY(euler.step());
        QVERIFY(sim.step());
    }
    QVERIFY((sim.state.position - euler.state.position).norm() < 1e-12);
    QVERIFY((sim.state.velocity - euler.state.velocity).norm() < 1e-11);
}

void TestXpbd::coloursNeverShareAParticle()
{
    const auto model = core::compileModel(cloth(24, 1e4, 10));
    QCOMPARE(int(model->xpbdOrder.size()), model->springCount());
    std::set<int> every(model->xpbdOrder.begin(), model->xpbdOrder.end());
    QCOMPARE(int(every.size()), model->springCount());  // each spring once
    for (std::size_t c = 0; c + 1 < model->xpbdColourStart.size(); ++c) {
        std::set<int> moved;
        for (int s = model->xpbdColourStart[c]; s < model->xpbdColourStart[c + 1]; ++s) {
            const int k = model->xpbdOrder[std::size_t(s)];
            for (int end : {model->springA[std::size_t(k)], model->springB[std::size_t(k)]})
                if (!model->isPinned(end))
                    QVERIFY2(moved.insert(end).second, qPrintable(QString("colour %1, particle %2").arg(c).arg(end)));
        }
    }
    qInfo("%d springs in %d colours", model->springCount(), int(model->xpbdColourStart.size()) - 1);
    // a lattice of structural, shear and bend springs needs a few colours, not hundreds
    QVERIFY(model->xpbdColourStart.size() - 1 <= 24);
    // another integrator has no colours
    core::SceneDesc scene = cloth(8, 1e4, 10);
    scene.settings.integrator = core::Integrator::SymplecticEuler;
    QVERIFY(core::compileModel(scene)->xpbdOrder.empty());
}

void TestXpbd::sameBitsOnAnyThreadCount()
{
    // a colour is solved on all threads at once; large enough that the colours are split (some
    // 4900 springs a colour, over core::kParallelMinimum)
    const core::SceneDesc scene = cloth(100, 1e5, 10);
    Eigen::Matrix3Xd ends[2];
    for (int threads : {1, 2}) {
        core::setThreadCount(threads);
        test::Sim sim = test::compile(scene);
        for (int i = 0; i < 5; ++i)
            QVERIFY(sim.step());
        ends[threads - 1] = sim.state.position;
    }
    core::setThreadCount(0);
    QVERIFY(ends[0] == ends[1]);
}

void TestXpbd::springsBreak()
{
    // pulled apart at 10 m/s, a spring that breaks at 50% strain breaks, and its ends fly on
    core::SceneDesc scene = test::quietScene();
    scene.settings.integrator = core::Integrator::Xpbd;
    scene.particles = {test::particle({0.0, 0.0, 0.0}, {-10.0, 0.0, 0.0}), test::particle({1.0, 0.0, 0.0}, {10.0, 0.0, 0.0})};
    core::addSpring(scene, 0, 1, 100.0, 0.0);
    scene.springs[0].breakStrain = 0.5;
    test::Sim sim = test::compile(scene);
    for (int i = 0; i < 50; ++i)
        QVERIFY(sim.step());
    QVERIFY(sim.state.isBroken(0));
    QVERIFY(sim.state.position(0, 1) - sim.state.position(0, 0) > 5.0);
}

void TestXpbd::dragIsStableAtAnyViscosity()
{
    // viscosity 1e6 kg/s on 1 g: an explicit kick would blow up (h c / m = 1e7); the implicit one
    // brings the particle to rest
    core::SceneDesc scene = test::quietScene();
    scene.settings.integrator = core::Integrator::Xpbd;
    scene.settings.viscosity = 1e6;
    scene.particles = {test::particle({0.0, 0.0, 0.0}, {1.0, 0.0, 0.0}, 1e-3)};
    test::Sim sim = test::compile(scene);
    for (int i = 0; i < 10; ++i)
        QVERIFY(sim.step());
    QVERIFY(sim.state.velocity.col(0).norm() < 1e-6);
    QVERIFY(sim.state.position(0, 0) > 0.0 && sim.state.position(0, 0) < 1e-6);
}

void TestXpbd::noStabilityLimit()
{
    const core::SceneDesc scene = cloth(8, 1e8, 1);
    const auto model = core::compileModel(scene);
    const core::State state = core::makeState(*model, scene);
    const core::StabilityLimit limit = core::stabilityLimit(*model, state);
    QVERIFY(limit.omegaMax > 0.0);
    QVERIFY(std::isinf(limit.maxSubStep(core::Integrator::Xpbd)));
    QVERIFY(std::isfinite(limit.maxSubStep(core::Integrator::SymplecticEuler)));
}

QTEST_MAIN(TestXpbd)
#include "test_xpbd.moc"
