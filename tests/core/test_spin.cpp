// Spin and rolling (core/contacts/contact_spin.h and the solvers that use it): balls that slide
// turn to rolling, roll down slopes, roll to a stop against rolling resistance, come back with
// backspin and follow through in a pool shot, each against its closed form; energy with the
// turning part never rises in random scenes; a scene without friction never turns; files and
// resumes keep the spin to the bit.

#include "core/io/scene_file.h"
#include "core/model/diagnostics.h"
#include "core/model/generators.h"
#include "core/model/state_hash.h"
#include "scene_builder.h"

#include <QtTest>

#include <cmath>

namespace {

using Vec = Eigen::Vector3d;

constexpr double kG = 9.81;  // m/s²
constexpr double kR = 0.05;  // m, the balls' radius

// a ball of radius kR resting on the floor y = 0 at x, moving at v along x with spin w (rad/s)
core::SceneDesc ballOnFloor(double v, const Vec &spin, double friction, core::Integrator integrator)
{
    core::SceneDesc scene;
    scene.name = "spin";
    scene.settings.integrator = integrator;
    scene.settings.friction = friction;
    scene.settings.restitution = 0.0;
    scene.settings.substeps = 4;
    scene.settings.particleCollisions = false;
    scene.planes = {core::floorPlane()};
    core::ParticleDesc ball = test::particle(Vec(0.0, kR, 0.0), Vec(v, 0.0, 0.0), 0.17, kR);
    ball.angularVelocity = spin;
    scene.particles = {ball};
    return scene;
}

// the speed of the ball's point of contact with the floor along x: v_x + r ω_z (zero when rolling)
double contactSlip(const test::Sim &sim)
{
    return sim.state.velocity(0, 0) + kR * sim.state.angularVelocity(2, 0);
}

}  // namespace

class TestSpin : public QObject {
    Q_OBJECT

private slots:
    void slidingTurnsToRolling_data();
    void slidingTurnsToRolling();
    void rollsDownASlope_data();
    void rollsDownASlope();
    void rollingResistanceStopsIt();
    void backspinBringsItBack();
    void poolShotFollowsThrough();
    void spinningFrictionStopsATop();
    void energyNeverRisesWithSpin();
    void nothingTurnsWithoutFriction();
    void fileAndResumeKeepTheSpin();
};

void TestSpin::slidingTurnsToRolling_data()
{
    QTest::addColumn<int>("integrator");
    for (const core::Integrator integrator : core::kIntegrators)
        QTest::newRow(std::string(core::integratorName(integrator)).c_str()) << int(integrator);
}

void TestSpin::slidingTurnsToRolling()
{
    // struck at v0 = 2 m/s without spin on μ = 0.2: friction μ g slows it and turns it until its
    // point of contact stops, at t = 2 v0 / (7 μ g) = 0.291 s, rolling at 5 v0 / 7 = 1.429 m/s after
    // 12 v0² / (49 μ g) = 0.499 m; then it rolls on at that speed (no rolling resistance)
    QFETCH(int, integrator);
    const double v0 = 2.0, mu = 0.2;
    test::Sim sim = test::compile(ballOnFloor(v0, Vec::Zero(), mu, core::Integrator(integrator)));
    QVERIFY(sim.model->plan.spin);
    const double rollsAt = 2.0 * v0 / (7.0 * mu * kG);
    double rolledAt = -1.0, rolledFrom = 0.0;
    for (int step = 0; step < 100; ++step) {
        QVERIFY(sim.step());
        if (rolledAt < 0.0 && std::abs(contactSlip(sim)) < 1e-6 * v0) {
            rolledAt = sim.state.time;
            rolledFrom = sim.state.position(0, 0);
        }
    }
    QVERIFY2(rolledAt > 0.0, "it never rolled");
    QVERIFY2(std::abs(rolledAt - rollsAt) <= 0.011, qPrintable(QString::number(rolledAt)));  // to the step
    // (to the step: read at the end of the step it began rolling in, up to v0 h further on)
    QVERIFY2(std::abs(rolledFrom - 12.0 * v0 * v0 / (49.0 * mu * kG)) < v0 * 0.01, qPrintable(QString::number(rolledFrom)));
    QVERIFY2(std::abs(sim.state.velocity(0, 0) - 5.0 * v0 / 7.0) < 1e-3 * v0,
             qPrintable(QString::number(sim.state.velocity(0, 0))));
    QVERIFY(std::abs(contactSlip(sim)) < 1e-6 * v0);
    QVERIFY(std::abs(sim.state.position(1, 0) - kR) < 1e-6);  // on the floor all along
}

void TestSpin::rollsDownASlope_data()
{
    QTest::addColumn<double>("degrees");
    QTest::addColumn<double>("mu");
    // rolls while tan θ ≤ (7/2) μ: 20° needs μ ≥ 0.104
    QTest::newRow("20 degrees, mu 0.5: rolls") << 20.0 << 0.5;
    QTest::newRow("35 degrees, mu 0.3: rolls") << 35.0 << 0.3;
    QTest::newRow("20 degrees, mu 0.05: slides") << 20.0 << 0.05;
    QTest::newRow("45 degrees, mu 0.2: slides") << 45.0 << 0.2;
}

void TestSpin::rollsDownASlope()
{
    // from rest on the slope: rolling at (5/7) g sin θ where it can, else sliding at
    // g (sin θ − μ cos θ) with its spin rising at (5/2) μ g cos θ / r
    QFETCH(double, degrees);
    QFETCH(double, mu);
    const double angle = degrees * M_PI / 180.0;
    core::SceneDesc scene = ballOnFloor(0.0, Vec::Zero(), mu, core::Integrator::SymplecticEuler);
    const Vec normal(-std::sin(angle), std::cos(angle), 0.0);
    scene.planes = {core::PlaneDesc{normal, 0.0}};
    scene.particles[0].position = kR * normal;
    test::Sim sim = test::compile(scene);
    for (int step = 0; step < 100; ++step)
        QVERIFY(sim.step());
    const Vec down(std::cos(angle), std::sin(angle), 0.0);
    const double speed = -sim.state.velocity.col(0).dot(down);
    const bool rolls = std::tan(angle) <= 3.5 * mu;
    const double expected = rolls ? 5.0 / 7.0 * kG * std::sin(angle) : kG * (std::sin(angle) - mu * std::cos(angle));
    QVERIFY2(std::abs(speed - expected * 1.0) < 5e-3 * expected,
             qPrintable(QStringLiteral("%1 m/s after 1 s, expected %2").arg(speed).arg(expected)));
    const double spin = std::abs(sim.state.angularVelocity(2, 0));
    const double expectedSpin = rolls ? expected / kR : 2.5 * mu * kG * std::cos(angle) / kR;
    QVERIFY2(std::abs(spin - expectedSpin) < 5e-3 * expectedSpin,
             qPrintable(QStringLiteral("%1 rad/s, expected %2").arg(spin).arg(expectedSpin)));
    QVERIFY(std::abs(sim.state.position.col(0).dot(normal) - kR) < 1e-6);  // on the slope
}

void TestSpin::rollingResistanceStopsIt()
{
    // rolling at 1 m/s with μr = 0.01: it carries (7/10) m v² and the resistance takes μr m g a
    // metre, so it stops after (7/10) v² / (μr g) = 7.14 m, in (7/5) v / (μr g) = 14.3 s
    const double v = 1.0, muR = 0.01;
    core::SceneDesc scene = ballOnFloor(v, Vec(0.0, 0.0, -v / kR), 0.5, core::Integrator::SymplecticEuler);
    scene.settings.rollingFriction = muR;
    test::Sim sim = test::compile(scene);
    double stoppedAt = -1.0;
    for (int step = 0; step < 2000 && stoppedAt < 0.0; ++step) {
        QVERIFY(sim.step());
        if (sim.state.velocity(0, 0) <= 1e-9)
            stoppedAt = sim.state.time;
    }
    const double distance = 0.7 * v * v / (muR * kG);
    QVERIFY2(stoppedAt > 0.0, "it never stopped");
    QVERIFY2(std::abs(sim.state.position(0, 0) - distance) < 0.01 * distance,
             qPrintable(QStringLiteral("stopped after %1 m, expected %2").arg(sim.state.position(0, 0)).arg(distance)));
    QVERIFY2(std::abs(stoppedAt - 1.4 * v / (muR * kG)) < 0.02, qPrintable(QString::number(stoppedAt)));
    // and stays stopped, not turning
    for (int step = 0; step < 100; ++step)
        QVERIFY(sim.step());
    QVERIFY(sim.state.velocity.col(0).norm() < 1e-9 && sim.state.angularVelocity.col(0).norm() < 1e-6);
}

void TestSpin::backspinBringsItBack()
{
    // struck at v0 = 1 m/s with backspin ω0 = 3 v0 / r: while it slides, v falls at μ g and the
    // backspin at (5/2) μ g / r; it rolls once v + r ω = 0, at (5 v0 − 2 r ω0) / 7 = −(1/7) v0: back
    const double v0 = 1.0, w0 = 3.0 * v0 / kR, mu = 0.3;
    test::Sim sim = test::compile(ballOnFloor(v0, Vec(0.0, 0.0, w0), mu, core::Integrator::SymplecticEuler));
    for (int step = 0; step < 200; ++step)
        QVERIFY(sim.step());
    const double expected = (5.0 * v0 - 2.0 * kR * w0) / 7.0;
    QVERIFY2(std::abs(sim.state.velocity(0, 0) - expected) < 2e-3, qPrintable(QString::number(sim.state.velocity(0, 0))));
    QVERIFY(std::abs(contactSlip(sim)) < 1e-6);
    // the farthest it went: v0² / (2 μ g) less what the step rounds, before it came back
    QVERIFY(sim.state.velocity(0, 0) < 0.0);
}

void TestSpin::poolShotFollowsThrough()
{
    // a cue ball rolling at v0 into a resting object ball, e = 1, no friction between the balls:
    // the cue ball stops, then its spin drives it on to (2/7) v0 ("follow"); the object ball
    // leaves sliding at v0 and rolls at (5/7) v0
    const double v0 = 2.0;
    core::SceneDesc scene = ballOnFloor(v0, Vec(0.0, 0.0, -v0 / kR), 0.2, core::Integrator::SymplecticEuler);
    scene.settings.restitution = 1.0;
    scene.settings.particleCollisions = true;
    scene.planes[0].friction = 0.2;
    scene.settings.friction = 0.0;  // between the balls
    scene.particles.push_back(test::particle(Vec(0.5, kR, 0.0), Vec::Zero(), 0.17, kR));
    test::Sim sim = test::compile(scene);
    QVERIFY(sim.model->plan.spin);
    for (int step = 0; step < 200; ++step)
        QVERIFY(sim.step());
    QVERIFY2(std::abs(sim.state.velocity(0, 0) - 2.0 / 7.0 * v0) < 0.01 * v0,
             qPrintable(QStringLiteral("cue %1 m/s").arg(sim.state.velocity(0, 0))));
    QVERIFY2(std::abs(sim.state.velocity(0, 1) - 5.0 / 7.0 * v0) < 0.01 * v0,
             qPrintable(QStringLiteral("object %1 m/s").arg(sim.state.velocity(0, 1))));
}

void TestSpin::spinningFrictionStopsATop()
{
    // a ball spinning at 20 rad/s about the vertical, μ_spin = 0.1: the torque μ_spin m g r against
    // I = (2/5) m r² stops it in ω r (2/5) / (μ_spin g) = 0.408 s
    const double w = 20.0, muSpin = 0.1;
    core::SceneDesc scene = ballOnFloor(0.0, Vec(0.0, w, 0.0), 0.0, core::Integrator::SymplecticEuler);
    scene.settings.spinningFriction = muSpin;
    test::Sim sim = test::compile(scene);
    double stoppedAt = -1.0;
    for (int step = 0; step < 100 && stoppedAt < 0.0; ++step) {
        QVERIFY(sim.step());
        if (std::abs(sim.state.angularVelocity(1, 0)) < 1e-9)
            stoppedAt = sim.state.time;
    }
    const double expected = 0.4 * w * kR / (muSpin * kG);
    QVERIFY2(std::abs(stoppedAt - expected) <= 0.011, qPrintable(QString::number(stoppedAt)));
    QVERIFY(sim.state.velocity.col(0).norm() < 1e-9);  // it spins in place
}

void TestSpin::energyNeverRisesWithSpin()
{
    // seeded random balls with random spins in a box, friction, rolling resistance and e < 1:
    // the energy, its turning part included, never rises from one step to the next
    for (std::uint32_t seed : {1u, 2u, 3u, 4u, 5u}) {
        test::Lcg next{seed};
        core::SceneDesc scene;
        scene.name = "spin box";
        scene.settings.friction = 0.1 + 0.1 * next(5);
        scene.settings.rollingFriction = 0.01 * next(3);
        scene.settings.restitution = 0.2 * next(5);
        scene.settings.substeps = 4;
        for (int side = 0; side < 3; ++side) {
            Vec n = Vec::Zero();
            n[side] = 1.0;
            scene.planes.push_back(core::PlaneDesc{n, -0.5});
            scene.planes.push_back(core::PlaneDesc{-n, -0.5});
        }
        for (int i = 0; i < 40; ++i) {
            core::ParticleDesc p = test::particle(Vec(0.02 * next(40) - 0.4, 0.02 * next(40) - 0.4, 0.02 * next(40) - 0.4),
                                                  Vec(next(9) - 4.0, next(9) - 4.0, next(9) - 4.0), 0.1 + 0.1 * next(5),
                                                  0.03 + 0.01 * next(3));
            p.angularVelocity = Vec(next(41) - 20.0, next(41) - 20.0, next(41) - 20.0);
            scene.particles.push_back(p);
        }
        test::Sim sim = test::compile(scene);
        double before = core::energies(*sim.model, sim.state).total();
        for (int step = 0; step < 300; ++step) {
            QVERIFY(sim.step());
            const double after = core::energies(*sim.model, sim.state).total();
            QVERIFY2(after <= before + 1e-9 * std::max(1.0, std::abs(before)),
                     qPrintable(QStringLiteral("seed %1, step %2: %3 J after %4 J").arg(seed).arg(step).arg(after).arg(before)));
            before = after;
        }
    }
}

void TestSpin::nothingTurnsWithoutFriction()
{
    // no friction anywhere and nothing spinning: the plan leaves the spin out, and the state has none
    core::SceneDesc scene = ballOnFloor(2.0, Vec::Zero(), 0.0, core::Integrator::SymplecticEuler);
    test::Sim still = test::compile(scene);
    QVERIFY(!still.model->plan.spin);
    QVERIFY(still.step());
    QCOMPARE(still.state.angularVelocity.cols(), Eigen::Index(0));
    QCOMPARE(still.state.orientation.cols(), Eigen::Index(0));
    // a spin given, or rolling resistance alone, brings it in
    scene.particles[0].angularVelocity = Vec(0.0, 1.0, 0.0);
    QVERIFY(test::compile(scene).model->plan.spin);
    scene.particles[0].angularVelocity.setZero();
    scene.planes[0].rollingFriction = 0.01;
    QVERIFY(test::compile(scene).model->plan.spin);
    // a frictionless contact leaves a spin as it was, and the orientation turns at it exactly
    scene.planes[0].rollingFriction.reset();
    scene.particles[0].angularVelocity = Vec(0.0, 0.0, 3.0);
    test::Sim spinning = test::compile(scene);
    for (int step = 0; step < 50; ++step)
        QVERIFY(spinning.step());
    QCOMPARE(spinning.state.angularVelocity(2, 0), 3.0);
    const double angle = 3.0 * spinning.state.time;  // about z
    const Eigen::Vector4d q = spinning.state.orientation.col(0);
    QVERIFY(std::abs(q[0] - std::cos(0.5 * angle)) < 1e-12 && std::abs(q[3] - std::sin(0.5 * angle)) < 1e-12);
}

void TestSpin::fileAndResumeKeepTheSpin()
{
    // a rolling pool shot saved half way (spins, orientations, rolling resistance in the file) and
    // run on from the file ends with the same bits as the run straight through
    core::SceneDesc scene = ballOnFloor(2.0, Vec(1.0, 0.0, 5.0), 0.2, core::Integrator::SymplecticEuler);
    scene.settings.rollingFriction = 0.01;
    scene.settings.spinningFriction = 0.02;
    scene.settings.particleCollisions = true;
    scene.settings.restitution = 0.9;
    scene.planes[0].rollingFriction = 0.015;
    scene.particles.push_back(test::particle(Vec(0.5, kR, 0.01), Vec::Zero(), 0.17, kR));
    test::Sim straight = test::compile(scene);
    test::Sim first = test::compile(scene);
    for (int step = 0; step < 60; ++step) {
        QVERIFY(straight.step());
        QVERIFY(first.step());
    }
    core::SceneDesc saved = scene;
    core::storeState(first.state, saved);
    QVERIFY(!saved.particles[0].orientation.isApprox(Eigen::Vector4d(1, 0, 0, 0)));
    const QByteArray text = io::sceneToJson(saved);
    QVERIFY(text.contains("\"angularVelocity\"") && text.contains("\"orientation\"") &&
            text.contains("\"rollingFriction\"") && text.contains("\"spinningFriction\""));
    const io::LoadResult loaded = io::parseScene(text, QStringLiteral("spin.json"));
    QVERIFY2(loaded.scene.has_value(), qPrintable(loaded.error));
    QCOMPARE(loaded.scene->particles[0].angularVelocity, saved.particles[0].angularVelocity);
    QCOMPARE(loaded.scene->particles[0].orientation, saved.particles[0].orientation);
    QCOMPARE(loaded.scene->planes[0].rollingFriction, std::optional<double>(0.015));
    core::SceneDesc resumedScene = *loaded.scene;
    test::Sim resumed = test::compile(resumedScene);
    resumed.state.time = first.state.time;
    resumed.state.step = first.state.step;
    for (int step = 0; step < 60; ++step) {
        QVERIFY(straight.step());
        QVERIFY(resumed.step());
    }
    QCOMPARE(core::stateHash(resumed.state), core::stateHash(straight.state));
}

QTEST_GUILESS_MAIN(TestSpin)
#include "test_spin.moc"
