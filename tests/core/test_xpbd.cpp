// The xpbd integrator (core/integrators/xpbd.cpp): springs as compliant distance constraints. What it must do
// for a user: hold the spring's own stiffness whatever the sub-step (the statics of a hanging
// mass), run stiff springs that explicit schemes cannot at the same step, keep pins exact, give
// the same bits on any number of threads, and break springs and collide like every integrator;
// more constraint passes a sub-step hold the springs closer to their rest lengths.

#include "core/model/generators.h"
#include "core/passes.h"
#include "core/integrators/stability.h"
#include "core/threads.h"
#include "core/integrators/xpbd_layout.h"
#include "scene_builder.h"
#include "torn_sheet.h"

#include <QtTest>

#include <limits>
#include <set>

class TestXpbd : public QObject {
    Q_OBJECT
private slots:
    void hangingMassStretchesByItsWeight_data();
    void hangingMassStretchesByItsWeight();
    void stiffChainRunsWhereEulerBlowsUp();
    void withoutSpringsItIsSymplecticEuler();
    void layoutNeverMovesAParticleTwiceAtOnce();
    void sameBitsAsThePlainProjection_data();
    void sameBitsAsThePlainProjection();
    void sameBitsOnAnyThreadCount_data();
    void sameBitsOnAnyThreadCount();
    void moreIterationsStretchLess();
    void springsBreak();
    void resumedAfterABreakGoesOnToTheBit();
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

void TestXpbd::layoutNeverMovesAParticleTwiceAtOnce()
{
    // 100 × 100: five blocks, so there are seams; the pinned corners give springs with one free end
    const auto model = core::compileModel(cloth(100, 1e4, 10));
    const core::XpbdLayout &l = model->xpbdLayout;
    QCOMPARE(l.slotCount(), model->springCount());
    std::set<int> every(l.spring.begin(), l.spring.end());
    QCOMPARE(int(every.size()), model->springCount());  // each spring once
    int worstBatches = 0;
    for (int p = 0; p < l.phaseCount(); ++p) {
        std::set<int> phase;  // the particles the phase's tasks move: no two tasks share one
        for (int t = l.phaseStart[std::size_t(p)]; t < l.phaseStart[std::size_t(p) + 1]; ++t) {
            std::set<int> task;
            worstBatches = std::max(worstBatches, l.taskStart[std::size_t(t) + 1] - l.taskStart[std::size_t(t)]);
            for (int i = l.taskStart[std::size_t(t)]; i < l.taskStart[std::size_t(t) + 1]; ++i) {
                std::set<int> batch;
                for (int s = l.batchStart[std::size_t(i)]; s < l.batchStart[std::size_t(i) + 1]; ++s) {
                    const int k = l.spring[std::size_t(s)];
                    const int a = l.a[std::size_t(s)];
                    const int b = l.b[std::size_t(s)];
                    // the slot holds the model's spring, its free end first
                    QVERIFY((a == model->springA[std::size_t(k)] && b == model->springB[std::size_t(k)]) ||
                            (a == model->springB[std::size_t(k)] && b == model->springA[std::size_t(k)]));
                    QVERIFY(!model->isPinned(a));
                    QCOMPARE(l.batchMovesB[std::size_t(i)] != 0, !model->isPinned(b));
                    QCOMPARE(l.restLength[std::size_t(s)], model->restLength[k]);
                    QCOMPARE(l.wb[std::size_t(s)], model->invMass[b]);
                    for (int end : {a, b})
                        if (!model->isPinned(end)) {
                            QVERIFY2(batch.insert(end).second, qPrintable(QString("batch %1, particle %2").arg(i).arg(end)));
                            task.insert(end);
                        }
                }
            }
            for (int particle : task)
                QVERIFY2(phase.insert(particle).second, qPrintable(QString("phase %1, particle %2").arg(p).arg(particle)));
        }
    }
    qInfo("%d springs, %d tasks in %d phases, at most %d batches a task", model->springCount(), l.taskCount(),
          l.phaseCount(), worstBatches);
    // the blocks, the seams after even blocks and after odd ones; no far springs on a lattice
    QCOMPARE(l.phaseCount(), 3);
    QCOMPARE(l.phaseStart[1], 5);
    // a lattice of structural, shear and bend springs needs a few colours, not hundreds (two
    // batches a colour where some springs have a pinned end)
    QVERIFY(worstBatches <= 24);
    // another integrator has no layout
    core::SceneDesc scene = cloth(8, 1e4, 10);
    scene.settings.integrator = core::Integrator::SymplecticEuler;
    QCOMPARE(core::compileModel(scene)->xpbdLayout.slotCount(), 0);
}

namespace {

// one xpbd sub-step as docs/physics.md writes it, a spring at a time with Eigen columns, in the
// layout's order but from the model's own arrays: what the vectorised kernel must match to the bit
void plainXpbd(const core::Model &model, core::State &state, double h)
{
    const Eigen::Matrix3Xd start = [&] {
        for (int i : model.freeParticles) {
            const double w = model.invMass[i];
            Eigen::Vector3d f = Eigen::Vector3d::Zero() + model.mass[i] * model.gravity;
            if (state.appliedCount > 0)
                f += state.applied.col(i);
            state.velocity.col(i) = (state.velocity.col(i) + (h * w) * f) / (1.0 + h * model.viscosity * w);
        }
        Eigen::Matrix3Xd x0 = state.position;
        state.position += h * state.velocity;
        return x0;
    }();
    Eigen::Matrix3Xd &x = state.position;
    const core::XpbdLayout &l = model.xpbdLayout;
    std::vector<double> lambda(std::size_t(l.slotCount()), 0.0);
    for (int pass = 0; pass < model.xpbdIterations; ++pass)
        for (int s = 0; s < l.slotCount(); ++s) {
            const int k = l.spring[std::size_t(s)];
            if (state.isBroken(k))
                continue;
            const int a = model.springA[std::size_t(k)];
            const int b = model.springB[std::size_t(k)];
            const double wa = model.invMass[a];
            const double wb = model.invMass[b];
            const Eigen::Vector3d d = x.col(a) - x.col(b);
            const double length = d.norm();
            if (!(length > 0.0))
                continue;
            const Eigen::Vector3d n = d * (1.0 / length);
            const double compliance = 1.0 / (model.stiffness[k] * h * h);
            const double gamma = model.damping[k] / (model.stiffness[k] * h);
            const double denominator = (1.0 + gamma) * (wa + wb) + compliance;
            const double closing = n.dot((x.col(a) - start.col(a)) - (x.col(b) - start.col(b)));
            double &sum = lambda[std::size_t(s)];
            // with λ = 0 the middle term is exactly 0: one pass is the formula without it
            const double step =
                (-(length - model.restLength[k]) - (pass > 0 ? compliance * sum : 0.0) - gamma * closing) * (1.0 / denominator);
            sum += step;
            x.col(a) += (wa * step) * n;
            x.col(b) -= (wb * step) * n;
        }
    for (int i : model.freeParticles)
        state.velocity.col(i) = (x.col(i) - start.col(i)) * (1.0 / h);
}

}  // namespace

void TestXpbd::sameBitsAsThePlainProjection_data()
{
    QTest::addColumn<int>("iterations");
    QTest::addColumn<bool>("broken");
    QTest::addRow("one pass") << 1 << false;
    QTest::addRow("one pass, a spring broken, a force applied") << 1 << true;
    QTest::addRow("three passes, λ accumulated") << 3 << false;
}

void TestXpbd::sameBitsAsThePlainProjection()
{
    // a 60 × 60 cloth (two blocks and a seam, pinned corners) swinging: the kernel's lanes, its
    // chunks, its order and its λ give what the plain loop gives, to the bit
    QFETCH(int, iterations);
    QFETCH(bool, broken);
    core::SceneDesc scene = cloth(60, 1e6, 20);
    scene.settings.xpbdIterations = iterations;
    test::Sim sim = test::compile(scene);
    core::State plain = sim.state;
    if (broken) {
        for (core::State *state : {&sim.state, &plain}) {
            state->springBroken.assign(std::size_t(sim.model->springCount()), 0);
            state->springBroken[100] = 1;
            core::setAppliedForce(*state, 1000, Eigen::Vector3d(3.0, 20.0, -1.0));
        }
    }
    const double h = sim.model->subStep();
    for (int sub = 0; sub < 40; ++sub) {
        core::xpbd(*sim.model, sim.state, sim.work, h);
        plainXpbd(*sim.model, plain, h);
    }
    QVERIFY(sim.state.position.cwiseAbs().maxCoeff() > 0.0);
    QVERIFY(sim.state.position == plain.position);
    QVERIFY(sim.state.velocity == plain.velocity);
}

void TestXpbd::sameBitsOnAnyThreadCount_data()
{
    QTest::addColumn<int>("iterations");
    QTest::addRow("one pass") << 1;
    QTest::addRow("four passes") << 4;
}

void TestXpbd::sameBitsOnAnyThreadCount()
{
    // five blocks shared between the threads, then the seams: large enough to be split (30 000
    // springs, over core::kParallelMinimum)
    QFETCH(int, iterations);
    core::SceneDesc scene = cloth(100, 1e5, 10);
    scene.settings.xpbdIterations = iterations;
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

void TestXpbd::moreIterationsStretchLess()
{
    // a 40 × 40 cloth at 1e7 N/m draping for 0.3 s at 20 sub-steps a step: each further pass a
    // sub-step leaves its structural springs less stretched
    double last = std::numeric_limits<double>::infinity();
    for (int iterations : {1, 2, 4}) {
        core::SceneDesc scene = cloth(40, 1e7, 20);
        scene.settings.xpbdIterations = iterations;
        test::Sim sim = test::compile(scene);
        double worst = 0.0;
        for (int i = 0; i < 30; ++i) {
            QVERIFY(sim.step());
            for (int k = 0; k < sim.model->springCount(); ++k) {
                const Eigen::Vector3d d = sim.state.position.col(sim.model->springA[std::size_t(k)]) -
                                          sim.state.position.col(sim.model->springB[std::size_t(k)]);
                worst = std::max(worst, d.norm() / sim.model->restLength[k] - 1.0);
            }
        }
        qInfo("%d passes a sub-step: largest stretch %.4g", iterations, worst);
        QVERIFY2(worst < 0.8 * last, qPrintable(QString::number(worst)));
        last = worst;
    }
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

void TestXpbd::resumedAfterABreakGoesOnToTheBit()
{
    // the torn sheet: a run stored at any step from the first break on and resumed from the stored
    // scene must go on as the uninterrupted run does, to the bit
    const core::SceneDesc scene = test::tornSheet(core::Integrator::Xpbd, 10);
    test::Sim whole = test::compile(scene);
    test::checkResumeAfterBreaks(scene, whole, 90, 7);
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
