// The damped spring force against values worked out by hand, and Newton's third law; both
// threaded passes (gathered, and by runs of lattice-like springs) against the plain scatter loop.
#include "core/model/generators.h"
#include "core/passes.h"
#include "core/step.h"
#include "core/threads.h"
#include "scene_builder.h"

#include <QtTest>

class TestSprings : public QObject {
    Q_OBJECT

private slots:
    void hookeAndDamperByHand_data();
    void hookeAndDamperByHand();
    void equalAndOpposite();
    void zeroLengthGivesNoNaN();
    void pinnedEndIsStillPulled();
    void gatherEqualsThePlainLoopToTheBit();
    void clothIsCutIntoRuns();
    void runsEqualThePlainLoopToTheBit_data();
    void runsEqualThePlainLoopToTheBit();
    void sameBitsOnOneAndTwoThreads();
};

void TestSprings::hookeAndDamperByHand_data()
{
    QTest::addColumn<double>("length");
    QTest::addColumn<double>("restLength");
    QTest::addColumn<double>("stiffness");
    QTest::addColumn<double>("damping");
    QTest::addColumn<double>("relativeSpeed");  // (va - vb)·u, u from b to a
    QTest::addColumn<double>("expectedForce");  // on a, along u

    // stretched by 0.5 m at 100 N/m: pulled back by 50 N
    QTest::newRow("stretched") << 1.5 << 1.0 << 100.0 << 0.0 << 0.0 << -50.0;
    // compressed by 0.25 m at 40 N/m: pushed out by 10 N
    QTest::newRow("compressed") << 0.75 << 1.0 << 40.0 << 0.0 << 0.0 << 10.0;
    // at rest length, separating at 2 m/s with kc = 3: damper pulls back 6 N
    QTest::newRow("damper only") << 1.0 << 1.0 << 100.0 << 3.0 << 2.0 << -6.0;
    // both: -k (l - l0) - kc s = -10 * 0.2 - 0.5 * (-4) = -2 + 2 = 0
    QTest::newRow("cancel") << 1.2 << 1.0 << 10.0 << 0.5 << -4.0 << 0.0;
}

void TestSprings::hookeAndDamperByHand()
{
    QFETCH(double, length);
    QFETCH(double, restLength);
    QFETCH(double, stiffness);
    QFETCH(double, damping);
    QFETCH(double, relativeSpeed);
    QFETCH(double, expectedForce);

    // a along a skew axis so that every component is exercised
    const Eigen::Vector3d u = Eigen::Vector3d(1.0, 2.0, -2.0) / 3.0;
    core::SceneDesc scene = test::quietScene();
    scene.particles = {test::particle(length * u, relativeSpeed * u), test::particle(Eigen::Vector3d::Zero())};
    scene.springs = {core::SpringDesc{0, 1, stiffness, damping, restLength}};
    test::Sim sim = test::compile(scene);

    sim.work.force.setZero();
    core::addSprings(*sim.model, sim.state, sim.work);
    const Eigen::Vector3d expected = expectedForce * u;
    QVERIFY2((sim.work.force.col(0) - expected).norm() < 1e-12,
             qPrintable(QString("force on a %1 %2 %3").arg(sim.work.force(0, 0)).arg(sim.work.force(1, 0)).arg(sim.work.force(2, 0))));
}

void TestSprings::equalAndOpposite()
{
    // three particles in a triangle with moving ends: the forces sum to zero, pair by pair
    core::SceneDesc scene = test::quietScene();
    scene.particles = {test::particle({0, 0, 0}, {1, 0, 0}), test::particle({1, 0.2, 0}, {0, -1, 0.5}),
                       test::particle({0.3, 1, 0.4}, {0, 0, 0})};
    scene.springs = {{0, 1, 50, 0.7, 0.8}, {1, 2, 20, 0.1, 1.3}, {2, 0, 5, 2.0, 0.2}};
    test::Sim sim = test::compile(scene);
    sim.work.force.setZero();
    core::addSprings(*sim.model, sim.state, sim.work);
    const Eigen::Vector3d total = sim.work.force.rowwise().sum();
    QVERIFY(total.norm() < 1e-12);
    QVERIFY(sim.work.force.col(0).norm() > 1.0);  // and the forces are not trivially zero
}

void TestSprings::zeroLengthGivesNoNaN()
{
    // two particles at the same point, rest length 0.5: a finite push along a fixed axis
    core::SceneDesc scene = test::quietScene();
    scene.particles = {test::particle({1, 1, 1}), test::particle({1, 1, 1})};
    scene.springs = {{0, 1, 10, 1, 0.5}};
    test::Sim sim = test::compile(scene);
    sim.work.force.setZero();
    core::addSprings(*sim.model, sim.state, sim.work);
    QVERIFY(sim.work.force.allFinite());
    QCOMPARE(sim.work.force.col(0).norm(), 5.0);
    QCOMPARE(Eigen::Vector3d(sim.work.force.col(0)), Eigen::Vector3d(-sim.work.force.col(1)));
}

void TestSprings::pinnedEndIsStillPulled()
{
    // the free end of a spring from a pinned anchor falls back toward it
    core::SceneDesc scene = test::quietScene();
    scene.particles = {test::particle({0, 0, 0}, {0, 0, 0}, 1.0, 0.1, true), test::particle({2, 0, 0})};
    scene.springs = {{0, 1, 10, 0, 1}};
    test::Sim sim = test::compile(scene);
    sim.work.force.setZero();
    core::addSprings(*sim.model, sim.state, sim.work);
    QCOMPARE(Eigen::Vector3d(sim.work.force.col(1)), Eigen::Vector3d(-10, 0, 0));
    QCOMPARE(Eigen::Vector3d(sim.work.force.col(0)), Eigen::Vector3d(10, 0, 0));
}

namespace {

// a cloth of n × n with every spring kind, shuffled a little and moving: each spring stretched,
// compressed or turning, so that every term of the force is exercised
core::SceneDesc movingCloth(int n, std::uint32_t seed)
{
    core::ClothOptions options;
    options.cols = options.rows = n;
    core::SceneDesc scene = core::makeCloth(options);
    scene.settings.particleCollisions = false;  // the springs are what is tested
    scene.settings.substeps = 2;
    for (core::ParticleDesc &p : scene.particles)
        for (int axis = 0; axis < 3; ++axis) {
            seed = seed * 1664525u + 1013904223u;
            const double r = static_cast<double>(seed >> 8) / double(1u << 24) - 0.5;
            p.position[axis] += 0.01 * r;
            if (!p.pinned)
                p.velocity[axis] = r;
        }
    return scene;
}

}  // namespace

void TestSprings::gatherEqualsThePlainLoopToTheBit()
{
    // small (one thread) and large enough to be split across threads
    for (int n : {7, 80}) {
        test::Sim sim = test::compile(movingCloth(n, 11u));
        // some springs with coincident ends, which take the vectorised kernel's other branch
        for (int k = 0; k < sim.model->springCount(); k += 37)
            sim.state.position.col(sim.model->springB[std::size_t(k)]) =
                sim.state.position.col(sim.model->springA[std::size_t(k)]);
        sim.work.force.setRandom();  // on top of what is there, as in a step
        const Eigen::Matrix3Xd start = sim.work.force;
        core::addSpringsGathered(*sim.model, sim.state, sim.work);
        const Eigen::Matrix3Xd gathered = sim.work.force;
        sim.work.force = start;
        core::addSpringsReference(*sim.model, sim.state, sim.work);
        QVERIFY(gathered.cwiseNotEqual(start).any());
        QVERIFY2(gathered.cwiseEqual(sim.work.force).all(), qPrintable(QString("n = %1").arg(n)));
    }
}

void TestSprings::clothIsCutIntoRuns()
{
    // row by row, each kind of spring is a run per row (structural and bend along a row, the two
    // shears) or one run for the whole cloth (structural and bend down the columns): 4 n runs
    const int n = 30;
    const test::Sim cloth = test::compile(movingCloth(n, 3u));
    QCOMPARE(int(cloth.model->springLayout.runs.size()), 4 * n);
    QCOMPARE(cloth.model->springLayout.pass, core::SpringPass::Runs);
    int covered = 0;
    for (const core::SpringRun &run : cloth.model->springLayout.runs) {
        QCOMPARE(run.first, covered);
        for (int j = 0; j < run.count; ++j) {
            QCOMPARE(cloth.model->springA[std::size_t(run.first + j)], run.a + j);
            QCOMPARE(cloth.model->springB[std::size_t(run.first + j)], run.b + j);
        }
        covered += run.count;
    }
    QCOMPARE(covered, cloth.model->springCount());

    // springs in no order at all: runs of one, and the pass gathers instead
    core::SceneDesc scattered = test::quietScene();
    for (int i = 0; i < 50; ++i)
        scattered.particles.push_back(test::particle(Eigen::Vector3d(i, 0, 0)));
    for (int k = 0; k < 49; ++k)
        scattered.springs.push_back(core::SpringDesc{(k * 7) % 50, (k * 7 + 13) % 50, 10.0, 0.1, 1.0});
    QCOMPARE(test::compile(scattered).model->springLayout.pass, core::SpringPass::Gathered);
}

void TestSprings::runsEqualThePlainLoopToTheBit_data()
{
    QTest::addColumn<int>("particles");
    QTest::addColumn<bool>("breakable");
    QTest::newRow("small, one thread's share") << 600 << false;
    QTest::newRow("split across threads") << 20000 << false;
    QTest::newRow("split, some springs broken") << 20000 << true;
}

// Runs of every shape: ends in order and reversed (b above a, b below a), one apart and far apart
// (farther than a thread's share, so the two ends' springs lie in separate stretches), long and of
// one spring, with coincident ends; the result must be the plain loop's to the bit on 1, 2 and 3
// threads, whichever thread each particle falls to.
void TestSprings::runsEqualThePlainLoopToTheBit()
{
    QFETCH(int, particles);
    QFETCH(bool, breakable);
    core::SceneDesc scene = test::quietScene();
    test::Lcg next{17u};
    for (int i = 0; i < particles; ++i)
        scene.particles.push_back(test::particle(Eigen::Vector3d(next(1000) * 1e-3, next(1000) * 1e-3, next(1000) * 1e-3),
                                                 Eigen::Vector3d(next(100) * 1e-2, next(100) * 1e-2, 0.0)));
    test::addRandomRuns(scene, {1, -1, 2, -3, particles / 2 + 1, -(particles / 2 + 7), 37}, 400, next);
    const core::Model probe = *core::compileModel(scene);
    QVERIFY2(probe.springLayout.pass == core::SpringPass::Runs, "the scene should be cut into long runs");

    const int before = core::threadCount();
    const Eigen::Matrix3Xd start = Eigen::Matrix3Xd::Random(3, particles);  // on top, as in a step
    Eigen::Matrix3Xd reference;
    for (int threads : {1, 2, 3}) {
        if (threads > 1 && core::maxThreadCount() < 2)
            break;
        core::setThreadCount(threads);
        test::Sim sim = test::compile(scene);
        test::coincideAndBreak(sim, breakable);
        sim.work.force = start;
        core::addSpringRuns(*sim.model, sim.state, sim.work);
        const Eigen::Matrix3Xd byRuns = sim.work.force;
        if (threads == 1) {
            sim.work.force = start;
            core::addSpringsReference(*sim.model, sim.state, sim.work);
            reference = sim.work.force;
            QVERIFY(reference.cwiseNotEqual(start).any());
        }
        const Eigen::Index differing = (byRuns.array() != reference.array()).count();
        QVERIFY2(differing == 0, qPrintable(QString("%1 threads: %2 values differ").arg(threads).arg(differing)));
    }
    core::setThreadCount(before);
}

void TestSprings::sameBitsOnOneAndTwoThreads()
{
    if (core::maxThreadCount() < 2)
        QSKIP("one hardware thread: nothing to compare");
    const core::SceneDesc scene = movingCloth(80, 5u);  // 6400 particles, ~38k springs: split
    const int before = core::threadCount();
    const auto run = [&](int threads) {
        core::setThreadCount(threads);
        test::Sim sim = test::compile(scene);
        for (int i = 0; i < 20; ++i)
            sim.step();
        return sim.state;
    };
    const core::State one = run(1);
    const core::State two = run(2);
    core::setThreadCount(before);
    QCOMPARE(core::threadCount(), before);
    QVERIFY(one.position.cwiseEqual(two.position).all());
    QVERIFY(one.velocity.cwiseEqual(two.velocity).all());
}

QTEST_APPLESS_MAIN(TestSprings)
#include "test_springs.moc"
