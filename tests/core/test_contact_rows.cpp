// Rows of touching balls, as a user builds them (a Newton's cradle, a rack, a ball against a wall
// on a floor): the impulse passes through the row as the closed form of sequential elastic impacts
// says, no contact adds energy, and nothing passes through the row at any speed. The scenes and
// their numbers are those a review of the contact solver measured, not ones tuned to the code.

#include "core/integrators/integrator.h"
#include "core/model/diagnostics.h"
#include "core/model/generators.h"
#include "scene_builder.h"

#include <QtTest>

#include <cmath>
#include <vector>

namespace {

constexpr double kRadius = 0.05;  // m, the balls of every scene here

// `strikers` balls in contact moving at `speed` along +x into `resting` touching balls at rest,
// 5 cm balls of 1 kg, a gap of 10 cm before the row; no gravity, no floor, no friction
core::SceneDesc cradle(int strikers, int resting, double speed, double restitution)
{
    core::SceneDesc scene;
    scene.name = "cradle";
    scene.settings.gravity = Eigen::Vector3d::Zero();
    scene.settings.restitution = restitution;
    scene.settings.planeCollisions = false;
    double x = 0.0;
    for (int k = 0; k < strikers; ++k, x += 2.0 * kRadius)
        scene.particles.push_back(test::particle({x, 0.0, 0.0}, {speed, 0.0, 0.0}, 1.0, kRadius));
    x += 0.1;  // the gap before the row
    for (int k = 0; k < resting; ++k, x += 2.0 * kRadius)
        scene.particles.push_back(test::particle({x, 0.0, 0.0}, Eigen::Vector3d::Zero(), 1.0, kRadius));
    return scene;
}

// a floor, and `balls` touching 5 cm balls resting on it in a row along x, the last touching a
// wall when `wall`; a striker 10 cm before the row at `speed` towards it. Gravity on, no friction
core::SceneDesc rowOnAFloor(int balls, bool wall, double speed, double restitution)
{
    core::SceneDesc scene;
    scene.name = "row on a floor";
    scene.settings.restitution = restitution;
    scene.planes = {core::floorPlane()};
    scene.particles.push_back(test::particle({0.0, kRadius, 0.0}, {speed, 0.0, 0.0}, 1.0, kRadius));
    double x = 2.0 * kRadius + 0.1;
    for (int k = 0; k < balls; ++k, x += 2.0 * kRadius)
        scene.particles.push_back(test::particle({x, kRadius, 0.0}, Eigen::Vector3d::Zero(), 1.0, kRadius));
    if (wall)
        scene.planes.push_back(core::PlaneDesc{Eigen::Vector3d(-1.0, 0.0, 0.0), -(x - kRadius)});
    return scene;
}

double kinetic(const test::Sim &sim)
{
    return core::energies(*sim.model, sim.state).kinetic;
}

double total(const test::Sim &sim)
{
    const core::Energies e = core::energies(*sim.model, sim.state);
    return e.kinetic + e.gravitational + e.spring;
}

// steps `seconds` of the scene, failing if it blows up, and checks at every step that the order
// along x is kept (no ball passed through another) and the total energy never rose by more than
// `rise` J above its start
bool runKeepingOrder(test::Sim &sim, double seconds, double rise, QString &why)
{
    const double start = total(sim);
    const int steps = static_cast<int>(std::lround(seconds / sim.model->timeStep));
    for (int s = 0; s < steps; ++s) {
        if (!sim.step()) {
            why = QStringLiteral("blew up at step %1").arg(s);
            return false;
        }
        for (int i = 0; i + 1 < sim.model->particleCount(); ++i)
            if (sim.state.position(0, i) > sim.state.position(0, i + 1)) {
                why = QStringLiteral("ball %1 passed ball %2 at step %3").arg(i).arg(i + 1).arg(s);
                return false;
            }
        if (total(sim) > start + rise) {
            why = QStringLiteral("energy rose from %1 J to %2 J at step %3").arg(start).arg(total(sim)).arg(s);
            return false;
        }
    }
    return true;
}

}  // namespace

class TestContactRows : public QObject {
    Q_OBJECT
private slots:
    void cradlePassesTheImpulseThrough_data();
    void cradlePassesTheImpulseThrough();
    void fastCradleAddsNoEnergyAndKeepsItsOrder_data();
    void fastCradleAddsNoEnergyAndKeepsItsOrder();
    void strikeAgainstABallAtAWallAddsNoEnergy_data();
    void strikeAgainstABallAtAWallAddsNoEnergy();
    void strikeIntoARowOnAFloorAddsNoEnergy_data();
    void strikeIntoARowOnAFloorAddsNoEnergy();
    void heavyStrikerDoesNotPressTheRowIntoItself_data();
    void heavyStrikerDoesNotPressTheRowIntoItself();
    void aBallSentOnMeetsTheBallAhead_data();
    void aBallSentOnMeetsTheBallAhead();
    void aHeavyStrikerIntoASpacedRowOfMixedMasses_data();
    void aHeavyStrikerIntoASpacedRowOfMixedMasses();
};

void TestContactRows::cradlePassesTheImpulseThrough_data()
{
    QTest::addColumn<int>("strikers");
    QTest::addColumn<int>("integrator");
    for (int strikers : {1, 2, 3})
        for (core::Integrator integrator : {core::Integrator::SymplecticEuler, core::Integrator::VelocityVerlet,
                                            core::Integrator::Rk4, core::Integrator::Xpbd})
            QTest::addRow("%d striker(s), %s", strikers, integratorName(integrator).data())
                << strikers << static_cast<int>(integrator);
}

void TestContactRows::cradlePassesTheImpulseThrough()
{
    // n balls at 1 m/s into a row, e = 1, equal masses: the closed form of elastic impacts taken
    // in order is that the last n balls leave at 1 m/s and every other ball stops
    QFETCH(int, strikers);
    QFETCH(int, integrator);
    constexpr int kRow = 5;
    core::SceneDesc scene = cradle(strikers, kRow, 1.0, 1.0);
    scene.settings.integrator = static_cast<core::Integrator>(integrator);
    test::Sim sim = test::compile(scene);
    const double before = kinetic(sim);
    QString why;
    QVERIFY2(runKeepingOrder(sim, 1.0, 1e-9 * before, why), qPrintable(why));
    const int n = strikers + kRow;
    for (int i = 0; i < n; ++i) {
        const double expected = i >= n - strikers ? 1.0 : 0.0;
        QVERIFY2(std::abs(sim.state.velocity(0, i) - expected) < 1e-9,
                 qPrintable(QStringLiteral("ball %1 moves at %2 m/s, not %3").arg(i).arg(sim.state.velocity(0, i)).arg(expected)));
    }
    QVERIFY(std::abs(kinetic(sim) - before) <= 1e-9 * before);
}

void TestContactRows::fastCradleAddsNoEnergyAndKeepsItsOrder_data()
{
    QTest::addColumn<double>("speed");
    for (double speed : {20.0, 30.0, 50.0, 200.0})
        QTest::addRow("%g m/s", speed) << speed;
}

void TestContactRows::fastCradleAddsNoEnergyAndKeepsItsOrder()
{
    // the same cradle struck at 20 to 200 m/s: the striker crosses a ball's width within a
    // sub-step, yet it meets the row, the impulse still comes out of the last ball, and the
    // kinetic energy does not rise
    QFETCH(double, speed);
    test::Sim sim = test::compile(cradle(1, 5, speed, 1.0));
    const double before = kinetic(sim);
    QString why;
    QVERIFY2(runKeepingOrder(sim, 0.2, 1e-9 * before, why), qPrintable(why));
    QVERIFY2(std::abs(sim.state.velocity(0, 5) - speed) < 1e-6 * speed,
             qPrintable(QStringLiteral("the last ball moves at %1 m/s").arg(sim.state.velocity(0, 5))));
    QVERIFY(kinetic(sim) <= before * (1.0 + 1e-9));
}

void TestContactRows::strikeAgainstABallAtAWallAddsNoEnergy_data()
{
    QTest::addColumn<double>("speed");
    QTest::addColumn<double>("timeStep");
    for (double h : {0.01, 0.001})
        for (double speed : {0.5, 1.0, 2.0, 3.0, 4.0, 5.0})
            QTest::addRow("%g m/s, h %g s", speed, h) << speed << h;
}

void TestContactRows::strikeAgainstABallAtAWallAddsNoEnergy()
{
    // two 5 cm balls on a floor, the second touching a wall, the first struck towards it; e = 1,
    // no friction, gravity on. Elastic impacts in order: the second ball takes the striker's
    // speed, the wall sends it back, it gives it back to the striker, which leaves at -v. The
    // energy never rises (beyond round-off of the gravitational energy of resting balls)
    QFETCH(double, speed);
    QFETCH(double, timeStep);
    core::SceneDesc scene = rowOnAFloor(1, true, speed, 1.0);
    scene.settings.timeStep = timeStep;
    test::Sim sim = test::compile(scene);
    const double before = kinetic(sim);
    QString why;
    QVERIFY2(runKeepingOrder(sim, 0.5, 1e-6 * before, why), qPrintable(why));
    QVERIFY2(kinetic(sim) <= before * (1.0 + 1e-6),
             qPrintable(QStringLiteral("kinetic energy %1 J from %2 J").arg(kinetic(sim)).arg(before)));
    QVERIFY2(std::abs(sim.state.velocity(0, 0) + speed) < 1e-3 * speed,
             qPrintable(QStringLiteral("the striker leaves at %1 m/s").arg(sim.state.velocity(0, 0))));
}

void TestContactRows::strikeIntoARowOnAFloorAddsNoEnergy_data()
{
    QTest::addColumn<int>("balls");
    QTest::addColumn<double>("restitution");
    for (double e : {1.0, 0.9})
        for (int balls = 2; balls <= 5; ++balls)
            QTest::addRow("%d balls, e %g", balls, e) << balls << e;
}

void TestContactRows::strikeIntoARowOnAFloorAddsNoEnergy()
{
    // a striker at 2 m/s into a row of touching balls resting on a floor, no wall: the energy never
    // rises, nothing passes through, and with e = 1 the last ball leaves at the striker's speed
    QFETCH(int, balls);
    QFETCH(double, restitution);
    test::Sim sim = test::compile(rowOnAFloor(balls, false, 2.0, restitution));
    const double before = kinetic(sim);
    QString why;
    QVERIFY2(runKeepingOrder(sim, 0.5, 1e-6 * before, why), qPrintable(why));
    QVERIFY2(kinetic(sim) <= before * (1.0 + 1e-6),
             qPrintable(QStringLiteral("kinetic energy %1 J from %2 J").arg(kinetic(sim)).arg(before)));
    if (restitution == 1.0)
        QVERIFY2(std::abs(sim.state.velocity(0, balls) - 2.0) < 2e-3,
                 qPrintable(QStringLiteral("the last ball leaves at %1 m/s").arg(sim.state.velocity(0, balls))));
}

void TestContactRows::heavyStrikerDoesNotPressTheRowIntoItself_data()
{
    QTest::addColumn<double>("speed");
    QTest::addColumn<double>("restitution");
    for (double e : {0.0, 0.5})
        for (double speed : {5.0, 20.0, 60.0, 150.0})
            QTest::addRow("%g m/s, e %g", speed, e) << speed << e;
}

void TestContactRows::heavyStrikerDoesNotPressTheRowIntoItself()
{
    // a 50 kg striker drives a row of six 1 kg balls into a wall on a floor: the row is crushed
    // between a mass it cannot stop and a wall it cannot pass, the case where the contact
    // iterations carry too little of the push through. After every step no two balls overlap by
    // more than a fifth of their contact distance, none is inside the wall, the order is kept and
    // the energy never rises
    QFETCH(double, speed);
    QFETCH(double, restitution);
    core::SceneDesc scene = rowOnAFloor(6, true, speed, restitution);
    scene.particles[0].mass = 50.0;
    test::Sim sim = test::compile(scene);
    const double wall = -scene.planes.back().offset;
    const double start = total(sim);
    double deepest = 0.0;
    for (int s = 0; s < 50; ++s) {
        QVERIFY2(sim.step(), qPrintable(QStringLiteral("blew up at step %1").arg(s)));
        for (int i = 0; i + 1 < sim.model->particleCount(); ++i) {
            deepest = std::max(deepest, 2.0 * kRadius - (sim.state.position(0, i + 1) - sim.state.position(0, i)));
            QVERIFY2(sim.state.position(0, i) < sim.state.position(0, i + 1),
                     qPrintable(QStringLiteral("ball %1 passed ball %2 at step %3").arg(i).arg(i + 1).arg(s)));
        }
        const int last = sim.model->particleCount() - 1;
        QVERIFY2(sim.state.position(0, last) <= wall - kRadius + 0.2 * kRadius,
                 qPrintable(QStringLiteral("the last ball is %1 m into the wall at step %2")
                                .arg(sim.state.position(0, last) + kRadius - wall)
                                .arg(s)));
        QVERIFY2(total(sim) <= start * (1.0 + 1e-6),
                 qPrintable(QStringLiteral("energy rose from %1 J to %2 J at step %3").arg(start).arg(total(sim)).arg(s)));
    }
    qInfo("deepest overlap between two balls %.3g mm (contact distance %.0f mm)", 1e3 * deepest, 2e3 * kRadius);
    QVERIFY2(deepest < 0.2 * 2.0 * kRadius, qPrintable(QString::number(deepest)));
}

void TestContactRows::aBallSentOnMeetsTheBallAhead_data()
{
    QTest::addColumn<int>("integrator");
    for (core::Integrator integrator : {core::Integrator::SymplecticEuler, core::Integrator::ExplicitEuler,
                                        core::Integrator::VelocityVerlet, core::Integrator::Rk4,
                                        core::Integrator::ImplicitEuler, core::Integrator::Xpbd})
        QTest::addRow("%s", integratorName(integrator).data()) << static_cast<int>(integrator);
}

void TestContactRows::aBallSentOnMeetsTheBallAhead()
{
    // three 5 cm balls of 1 kg along x, e = 1: A flies off at -100 m/s, B at rest 5 cm behind it,
    // C 1 cm behind B at -130 m/s. C strikes B 77 µs into the sub-step and B, sent on at -130 m/s,
    // closes on A at 30 m/s and would pass right through it before the sub-step's 10 ms end. The
    // closed form of the two elastic impacts: A -130, B -100, C at rest, in their order. (Searched
    // with the sum of the two balls' speeds, 230 m/s, as the bound on how fast their gap closes,
    // 64 advancements stopped micrometres short of the touch and B came out on A's far side)
    QFETCH(int, integrator);
    core::SceneDesc scene = cradle(0, 0, 0.0, 1.0);
    scene.settings.integrator = static_cast<core::Integrator>(integrator);
    scene.settings.timeStep = 0.01;
    scene.settings.substeps = 1;
    scene.particles = {test::particle({0.0, 0.0, 0.0}, {-100.0, 0.0, 0.0}, 1.0, kRadius),
                       test::particle({0.15, 0.0, 0.0}, Eigen::Vector3d::Zero(), 1.0, kRadius),
                       test::particle({0.26, 0.0, 0.0}, {-130.0, 0.0, 0.0}, 1.0, kRadius)};
    test::Sim sim = test::compile(scene);
    const double before = kinetic(sim);
    QVERIFY(sim.step());
    const Eigen::Vector3d expected(-130.0, -100.0, 0.0);
    for (int i = 0; i < 3; ++i)
        QVERIFY2(std::abs(sim.state.velocity(0, i) - expected[i]) < 1e-9,
                 qPrintable(QStringLiteral("ball %1 moves at %2 m/s, not %3").arg(i).arg(sim.state.velocity(0, i)).arg(expected[i])));
    QVERIFY(sim.state.position(0, 0) < sim.state.position(0, 1) && sim.state.position(0, 1) < sim.state.position(0, 2));
    QVERIFY(std::abs(kinetic(sim) - before) <= 1e-9 * before);
}

void TestContactRows::aHeavyStrikerIntoASpacedRowOfMixedMasses_data()
{
    QTest::addColumn<int>("integrator");
    QTest::addColumn<double>("restitution");
    for (core::Integrator integrator : {core::Integrator::SymplecticEuler, core::Integrator::VelocityVerlet,
                                        core::Integrator::Rk4, core::Integrator::ImplicitEuler})
        for (double restitution : {0.05, 0.35, 0.7})
            QTest::addRow("%s, e %g", integratorName(integrator).data(), restitution)
                << static_cast<int>(integrator) << restitution;
}

void TestContactRows::aHeavyStrikerIntoASpacedRowOfMixedMasses()
{
    // a 10 kg ball at 80 m/s into eight 5 cm balls 5 cm apart, of 1 kg but for an 8 kg one third
    // and a 4 kg one seventh, held 2 cm over a floor under gravity, a wall 20 cm past the row: a
    // dozen impacts a ball in one 10 ms step, ending in jams. Two-ball impact zones took turns at
    // one instant (the heavy ball's neighbour joined neither, closing on them slower than a resting
    // contact's threshold), hundreds of them, until the sub-step's impacts ran out and the row
    // ended a step with balls three quarters inside each other. After every step: no two balls
    // overlap by more than a hundredth of their contact distance, none passes another, the
    // energy never rises
    QFETCH(int, integrator);
    QFETCH(double, restitution);
    core::SceneDesc scene = cradle(0, 0, 0.0, restitution);
    scene.settings.integrator = static_cast<core::Integrator>(integrator);
    scene.settings.gravity = Eigen::Vector3d(0.0, -9.81, 0.0);
    scene.settings.timeStep = 0.01;
    scene.settings.substeps = 1;
    scene.settings.planeCollisions = true;
    const double y = kRadius + 0.02;
    scene.particles.push_back(test::particle({-0.3, y, 0.0}, {80.0, 0.0, 0.0}, 10.0, kRadius));
    for (int k = 0; k < 8; ++k)
        scene.particles.push_back(test::particle({0.15 * k, y, 0.0}, Eigen::Vector3d::Zero(),
                                                 k == 2 ? 8.0 : k == 6 ? 4.0 : 1.0, kRadius));
    scene.planes = {core::floorPlane(), core::PlaneDesc{Eigen::Vector3d(-1.0, 0.0, 0.0), -(0.15 * 7 + kRadius + 0.2)}};
    test::Sim sim = test::compile(scene);
    const double start = total(sim);
    for (int s = 0; s < 30; ++s) {
        QVERIFY2(sim.step(), qPrintable(QStringLiteral("blew up at step %1").arg(s)));
        for (int i = 0; i < sim.model->particleCount(); ++i)
            for (int j = i + 1; j < sim.model->particleCount(); ++j) {
                const double overlap = 2.0 * kRadius - (sim.state.position.col(j) - sim.state.position.col(i)).norm();
                QVERIFY2(overlap < 0.01 * 2.0 * kRadius,
                         qPrintable(QStringLiteral("balls %1 and %2 end step %3 %4 mm inside each other")
                                        .arg(i).arg(j).arg(s).arg(1e3 * overlap)));
            }
        for (int i = 0; i + 1 < sim.model->particleCount(); ++i)
            QVERIFY2(sim.state.position(0, i) < sim.state.position(0, i + 1),
                     qPrintable(QStringLiteral("ball %1 passed ball %2 at step %3").arg(i).arg(i + 1).arg(s)));
        QVERIFY2(total(sim) <= start * (1.0 + 1e-6),
                 qPrintable(QStringLiteral("energy rose from %1 J to %2 J at step %3").arg(start).arg(total(sim)).arg(s)));
    }
}

QTEST_APPLESS_MAIN(TestContactRows)
#include "test_contact_rows.moc"
