// The step: order of passes, sub-steps, passes the plan skips, blow-up detection, determinism.
#include "core/model/generators.h"
#include "core/integrators/integrator.h"
#include "core/step.h"
#include "scene_builder.h"

#include <QtTest>
#include <atomic>
#include <chrono>
#include <cstring>
#include <thread>

class TestStep : public QObject {
    Q_OBJECT

private slots:
    void skippedPassesNeverRun_data();
    void skippedPassesNeverRun();
    void substepsEqualSmallerSteps();
    void blowupIsCaughtAndNamed();
    void blownUpStateIsNotSteppedAgain();
    void checkSeesEveryParticle_data();
    void checkSeesEveryParticle();
    void appliedForcePushes();
    void sameSceneSameBits();
    void interruptStopsBeforeASubStep_data();
    void interruptStopsBeforeASubStep();
    void aStepCutAtAnyStopPointIsRetakenToTheBit();
    void aStepCutInsideTheSpringPassIsRetakenToTheBit();
};

namespace {

std::uint64_t calls(const core::Workspace &work, core::Stage stage)
{
    return work.profile[stage].calls;
}

}  // namespace

void TestStep::skippedPassesNeverRun_data()
{
    QTest::addColumn<bool>("gravity");
    QTest::addColumn<bool>("drag");
    QTest::addColumn<bool>("springs");
    QTest::addColumn<bool>("planes");
    QTest::addColumn<bool>("pairs");
    QTest::addColumn<bool>("handout");
    for (bool handout : {false, true}) {
        const char *solver = handout ? "handout" : "iterative";
        QTest::addRow("nothing, %s", solver) << false << false << false << false << false << handout;
        QTest::addRow("gravity only, %s", solver) << true << false << false << false << false << handout;
        QTest::addRow("drag only, %s", solver) << false << true << false << false << false << handout;
        QTest::addRow("springs only, %s", solver) << false << false << true << false << false << handout;
        QTest::addRow("planes only, %s", solver) << false << false << false << true << false << handout;
        QTest::addRow("pairs only, %s", solver) << false << false << false << false << true << handout;
        QTest::addRow("everything, %s", solver) << true << true << true << true << true << handout;
    }
}

void TestStep::skippedPassesNeverRun()
{
    QFETCH(bool, gravity);
    QFETCH(bool, drag);
    QFETCH(bool, springs);
    QFETCH(bool, planes);
    QFETCH(bool, pairs);
    QFETCH(bool, handout);

    core::SceneDesc scene = test::quietScene();
    scene.settings.contactSolver = handout ? core::ContactSolver::Handout : core::ContactSolver::Iterative;
    scene.settings.gravity = gravity ? Eigen::Vector3d(0, -9.81, 0) : Eigen::Vector3d::Zero();
    scene.settings.viscosity = drag ? 0.1 : 0.0;
    scene.settings.planeCollisions = planes;
    scene.settings.particleCollisions = pairs;
    scene.settings.substeps = 3;
    scene.particles = {test::particle({0, 1, 0}), test::particle({1, 1, 0})};
    if (springs)
        scene.springs = {{0, 1, 10, 0, 1}};
    scene.planes = {core::PlaneDesc{{0, 1, 0}, 0.0}};  // present, but only used when switched on

    test::Sim sim = test::compile(scene);
    for (int i = 0; i < 10; ++i)
        QVERIFY(sim.step());

    // a planned pass runs once per sub-step; an unplanned one never, and costs no time
    const auto expect = [&](core::Stage stage, bool planned) {
        QCOMPARE(calls(sim.work, stage), planned ? std::uint64_t(30) : std::uint64_t(0));
        if (!planned)
            QCOMPARE(sim.work.profile[stage].seconds, 0.0);
    };
    expect(core::Stage::Gravity, gravity);
    expect(core::Stage::Drag, drag);
    expect(core::Stage::Springs, springs);
    expect(core::Stage::Applied, false);
    expect(core::Stage::Integrate, true);
    expect(core::Stage::PlaneCollisions, handout && planes);
    expect(core::Stage::ParticleCollisions, handout && pairs);
    expect(core::Stage::Contacts, !handout && (planes || pairs));
    expect(core::Stage::Check, true);
}

void TestStep::substepsEqualSmallerSteps()
{
    // one step of h in 4 sub-steps equals 4 steps of h/4, bit for bit
    core::SceneDesc scene = core::makeChain({});
    scene.settings.timeStep = 0.004;
    scene.settings.substeps = 4;
    test::Sim sub = test::compile(scene);
    scene.settings.timeStep = 0.001;
    scene.settings.substeps = 1;
    test::Sim fine = test::compile(scene);
    for (int i = 0; i < 50; ++i) {
        QVERIFY(sub.step());
        for (int k = 0; k < 4; ++k)
            QVERIFY(fine.step());
    }
    QVERIFY(sub.state.position == fine.state.position);
    QVERIFY(sub.state.velocity == fine.state.velocity);
    QCOMPARE(sub.state.step, std::uint64_t(50));
}

void TestStep::blowupIsCaughtAndNamed()
{
    // a stiff spring with a time step far beyond the stability limit: the run diverges
    core::SceneDesc scene = test::quietScene();
    scene.settings.timeStep = 0.1;
    scene.particles = {test::particle({0, 0, 0}, {0, 0, 0}, 1.0, 0.1, true), test::particle({1.5, 0, 0})};
    scene.springs = {{0, 1, 1e6, 0, 1}};
    test::Sim sim = test::compile(scene);
    int steps = 0;
    while (sim.step())
        QVERIFY(++steps < 1000);
    QVERIFY(sim.work.blowup.has_value());
    const core::Blowup &b = *sim.work.blowup;
    QCOMPARE(b.particle, 1);
    QCOMPARE(b.quantity, core::Blowup::Quantity::Velocity);
    QCOMPARE(b.step, std::uint64_t(steps + 1));
    QVERIFY(std::abs(b.time - 0.1 * steps) < 1e-9);
    QVERIFY(!(std::abs(b.value) <= core::kBlowupBound));
}

void TestStep::blownUpStateIsNotSteppedAgain()
{
    core::SceneDesc scene = test::quietScene();
    scene.particles = {test::particle({0, 0, 0}, {2e10, 0, 0})};
    test::Sim sim = test::compile(scene);
    QVERIFY(!sim.step());
    const Eigen::Matrix3Xd frozen = sim.state.position;
    QVERIFY(!sim.step());
    QVERIFY(sim.state.position == frozen);
    QCOMPARE(sim.state.step, std::uint64_t(0));
}

void TestStep::checkSeesEveryParticle_data()
{
    QTest::addColumn<int>("particle");
    QTest::addColumn<bool>("contacts");
    // free particles 1-2, 4-6 and 8 in stretches between the pinned 0, 3 and 7
    for (int i = 0; i < 9; ++i) {
        QTest::addRow("particle %d", i) << i << false;
        QTest::addRow("particle %d, with contacts", i) << i << true;
    }
}

// The symplectic Euler update checks what it writes, so the finite check reads only the pinned
// particles after it (or everything after a contact pass): a bad value anywhere, free or pinned,
// in any stretch, must still stop the run and be named.
void TestStep::checkSeesEveryParticle()
{
    QFETCH(int, particle);
    QFETCH(bool, contacts);
    core::SceneDesc scene = test::quietScene();
    scene.settings.planeCollisions = contacts;
    scene.planes = {core::PlaneDesc{{0.0, 1.0, 0.0}, -100.0}};
    for (int i = 0; i < 9; ++i)
        scene.particles.push_back(test::particle({double(i), 0, 0}, {0, 0, 0}, 1.0, 0.1, i == 0 || i == 3 || i == 7));
    test::Sim sim = test::compile(scene);
    QVERIFY(sim.step());
    // as an edit could leave it, or as a force could make it: past the bound
    sim.state.position(1, particle) = 2 * core::kBlowupBound;
    QVERIFY(!sim.step());
    QVERIFY(sim.work.blowup.has_value());
    QCOMPARE(sim.work.blowup->particle, particle);
    QCOMPARE(sim.work.blowup->quantity, core::Blowup::Quantity::Position);
}

void TestStep::appliedForcePushes()
{
    core::SceneDesc scene = test::quietScene();
    scene.settings.timeStep = 0.5;
    scene.particles = {test::particle({0, 0, 0}, {0, 0, 0}, 2.0), test::particle({5, 0, 0})};
    test::Sim sim = test::compile(scene);
    core::setAppliedForce(sim.state, 0, {4, 0, 0});
    QCOMPARE(sim.state.appliedCount, 1);
    QVERIFY(sim.step());
    QCOMPARE(sim.state.velocity(0, 0), 1.0);  // a = F/m = 2, v = a h
    QCOMPARE(sim.state.velocity(0, 1), 0.0);
    core::setAppliedForce(sim.state, 0, Eigen::Vector3d::Zero());
    QCOMPARE(sim.state.appliedCount, 0);
    QVERIFY(sim.step());
    QCOMPARE(sim.state.velocity(0, 0), 1.0);
    QCOMPARE(sim.work.profile[core::Stage::Applied].calls, std::uint64_t(1));
}

void TestStep::sameSceneSameBits()
{
    // two runs of the same scene give the same bits (no hidden state, no uninitialised memory)
    core::ClothOptions options;
    options.rows = options.cols = 8;
    core::SceneDesc scene = core::makeCloth(options);
    scene.planes = {core::PlaneDesc{{0, 1, 0}, 0.5}};
    test::Sim a = test::compile(scene);
    test::Sim b = test::compile(scene);
    for (int i = 0; i < 300; ++i) {
        QVERIFY(a.step());
        QVERIFY(b.step());
    }
    QVERIFY(std::memcmp(a.state.position.data(), b.state.position.data(), sizeof(double) * 3 * 64) == 0);
    QVERIFY(std::memcmp(a.state.velocity.data(), b.state.velocity.data(), sizeof(double) * 3 * 64) == 0);
    QVERIFY(a.state.position(1, 20) < 1.0);  // and it moved
}

void TestStep::interruptStopsBeforeASubStep_data()
{
    QTest::addColumn<QString>("integrator");
    for (const char *name : {"symplectic-euler", "rk4", "implicit-euler", "adaptive-rk45"})
        QTest::newRow(name) << QString::fromLatin1(name);
}

void TestStep::interruptStopsBeforeASubStep()
{
    // a raised flag: the step stops before its first sub-step, says so, and is not a blow-up;
    // a lowered one changes nothing, to the bit
    QFETCH(QString, integrator);
    core::ClothOptions options;
    options.rows = options.cols = 6;
    core::SceneDesc scene = core::makeCloth(options);
    scene.settings.integrator = *core::integratorFromName(integrator.toStdString());
    QVERIFY(scene.settings.substeps > 1);  // a stop between sub-steps is possible
    scene.planes = {core::PlaneDesc{{0, 1, 0}, 0.5}};
    test::Sim cut = test::compile(scene);
    test::Sim plain = test::compile(scene);
    std::atomic<bool> waiting{true};
    cut.work.interrupt = &waiting;
    const core::State before = cut.state;
    QVERIFY(!cut.step());
    QVERIFY(cut.work.interrupted);
    QVERIFY(!cut.work.blowup);
    QVERIFY(cut.state.position == before.position && cut.state.step == 0);

    waiting = false;
    for (int i = 0; i < 20; ++i) {
        QVERIFY(cut.step());
        QVERIFY(!cut.work.interrupted);
        QVERIFY(plain.step());
    }
    QVERIFY(cut.state.position == plain.state.position && cut.state.velocity == plain.state.velocity);
    QCOMPARE(cut.state.step, 20u);
}

void TestStep::aStepCutAtAnyStopPointIsRetakenToTheBit()
{
    // a pile resting on the floor, with the iterative contact solver's every stage at work: a step
    // may stop between the stages of a sub-step, not only between sub-steps (a sub-step of 10⁶
    // particles took 0.2 s, too long for a Pause to wait). Cut at each stop point in turn and put
    // back as the runner does, the step taken again has the bits of a step never cut
    core::SceneDesc scene;
    scene.name = "pile";
    scene.settings.substeps = 3;
    scene.planes = {core::PlaneDesc{{0, 1, 0}, 0.0}};
    for (int x = 0; x < 3; ++x)
        for (int z = 0; z < 3; ++z)
            scene.particles.push_back(test::particle({0.2 * x, 0.1, 0.2 * z}, {0.05 * x, -0.2, 0.0}));
    scene.particles.push_back(test::particle({0.1, 0.3, 0.1}, {0.0, -1.0, 0.0}));  // on top, still falling
    scene.springs.push_back(core::SpringDesc{0, 1, 100.0, 0.5, 0.2});
    test::Sim plain = test::compile(scene);
    QVERIFY(plain.step());
    QVERIFY(plain.model->plan.contactSolver);
    QVERIFY(!plain.work.contactSolver.contacts.empty());  // resting contacts: every stage ran
    const std::uint64_t points = plain.work.stopPoints;
    // in each sub-step: at its top, after its integration; before the impacts' broad phase, after
    // it and after the impacts; before the resting contacts' broad phase, after it, after gathering
    // them, after sorting them and after their velocities
    QCOMPARE(points, 10u * 3u);

    for (std::uint64_t at = 1; at <= points; ++at) {
        test::Sim cut = test::compile(scene);
        const core::State before = cut.state;
        cut.work.stopAtPoint = at;
        QVERIFY(!cut.step());
        QVERIFY(cut.work.interrupted);
        QVERIFY(!cut.work.blowup);
        QCOMPARE(cut.work.stopPoints, at);
        cut.state = before;
        cut.work.stopAtPoint = 0;
        QVERIFY(cut.step());
        QVERIFY2(cut.state.position == plain.state.position && cut.state.velocity == plain.state.velocity &&
                     cut.state.contactImpulses == plain.state.contactImpulses,
                 qPrintable(QStringLiteral("cut at stop point %1").arg(at)));
        QCOMPARE(cut.state.step, 1u);
    }
}

void TestStep::aStepCutInsideTheSpringPassIsRetakenToTheBit()
{
    // a 160 × 160 cloth on the fused lattice path without contacts: the spring pass is nearly all
    // of a step, and it stops between two blocks of particles once the flag is up (at 10⁶
    // particles the pass is 66 ms long, too long for a Pause). A second thread raises the flag at
    // 12 points of a step; each step it cut, put back and taken again, has the bits of a step
    // never cut, and some of the cuts fell inside the pass
    core::ClothOptions options;
    options.rows = options.cols = 160;
    options.substeps = 4;
    core::SceneDesc scene = core::makeCloth(options);
    scene.settings.planeCollisions = false;
    scene.settings.particleCollisions = false;
    test::Sim plain = test::compile(scene);
    QCOMPARE(plain.model->plan.subStep, core::SubStepPath::FusedLattice);
    const auto began = std::chrono::steady_clock::now();
    QVERIFY(plain.step());
    const std::chrono::duration<double> stepLength = std::chrono::steady_clock::now() - began;

    // the flag goes up at 12 points of a step in turn, round after round until a cut has fallen
    // inside the pass: on a busy machine a thread may wake late, so how many rounds that takes
    // depends on the load, what a cut must give does not
    constexpr int kTries = 12;
    constexpr int kMostRounds = 20;
    int cuts = 0;
    std::uint64_t inPass = 0;
    for (int attempt = 0; attempt < kTries * kMostRounds && (cuts == 0 || inPass == 0); ++attempt) {
        const int r = attempt % kTries;
        test::Sim cut = test::compile(scene);
        const core::State before = cut.state;
        std::atomic<bool> flag{false};
        cut.work.interrupt = &flag;
        std::thread raiser([&] {
            std::this_thread::sleep_for(stepLength * ((r + 0.5) / kTries));
            flag.store(true, std::memory_order_relaxed);
        });
        const bool whole = cut.step();
        raiser.join();
        if (whole)
            continue;  // the step ended before the flag
        ++cuts;
        QVERIFY(cut.work.interrupted);
        QVERIFY(!cut.work.blowup);
        inPass += cut.work.springPassesCut;
        cut.state = before;
        flag.store(false, std::memory_order_relaxed);
        QVERIFY(cut.step());
        QVERIFY2(cut.state.position == plain.state.position && cut.state.velocity == plain.state.velocity,
                 qPrintable(QStringLiteral("cut at %1 of the step").arg((r + 0.5) / kTries)));
    }
    QCOMPARE_GT(cuts, 0);
    QCOMPARE_GT(inPass, std::uint64_t(0));
}

QTEST_APPLESS_MAIN(TestStep)
#include "test_step.moc"
