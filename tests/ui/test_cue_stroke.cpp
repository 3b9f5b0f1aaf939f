// The cue's stroke (Steering::stroke) and the blow that applies it (StrikeEdit, in the runner): the
// spin a stroke above or below the centre gives, and a ball struck on felt, which ends rolling at
// the closed form's speed for every height of the cue: (5/7) s (1 + h/r).

#include "ui/simulation/steering.h"
#include "tests/session/runner_with.h"

#include "core/model/diagnostics.h"
#include "core/model/generators.h"
#include "session/simulation_runner.h"

#include <Eigen/Geometry>
#include <QtTest>

#include <cmath>

namespace {

using Vec = Eigen::Vector3d;

constexpr double kG = 9.81;  // m/s²
constexpr double kR = 0.0286;  // m, a pool ball's radius

// a pool ball at rest on felt (μ 0.2, no rolling resistance, so that the closed form is exact)
std::shared_ptr<const core::SceneDesc> ballOnFelt(double friction = 0.2)
{
    auto scene = std::make_shared<core::SceneDesc>();
    scene->name = "felt";
    scene->settings.gravity = Vec(0.0, -kG, 0.0);
    scene->settings.friction = friction;
    scene->settings.restitution = 0.0;
    scene->settings.substeps = 4;
    scene->settings.particleCollisions = false;
    scene->planes = {core::floorPlane()};
    core::ParticleDesc ball;
    ball.position = Vec(0.0, kR, 0.0);
    ball.mass = 0.17;
    ball.radius = kR;
    scene->particles = {ball};
    scene->steerable = 0;
    return scene;
}

using test::runnerWith;

}  // namespace

class TestCueStroke : public QObject {
    Q_OBJECT

private slots:
    void strokeSpinsAboutTheAxisAcrossIt();
    void atTwoFifthsOfTheRadiusItLeavesRolling();
    void speedsAndHeightsAreClamped();
    void struckOnFeltItRollsAtTheClosedForm_data();
    void struckOnFeltItRollsAtTheClosedForm();
    void struckLowItDrawsBackFromTheBallItHits();
    void aPinnedBallTakesTheSpinButDoesNotMove();
    void withoutFrictionTheSpinIsNotKept();
};

void TestCueStroke::strokeSpinsAboutTheAxisAcrossIt()
{
    // at every aim and height: the velocity along the aim at the cue's speed, and the spin
    // 5 s h / (2 r²) about up × aim (topspin above the centre, backspin below, none at it)
    for (int turns : {0, 3, 6, 17}) {
        for (int height = -ui::Steering::kMaxCueHeight; height <= ui::Steering::kMaxCueHeight; ++height) {
            ui::Steering steering;
            steering.turn(turns);
            steering.changeCue(4);  // 12 levels: 6 m/s
            steering.raiseCue(height);
            QCOMPARE(steering.strikeSpeed(), 6.0);
            const ui::Steering::Stroke stroke = steering.stroke(kR);
            const Vec aim = steering.direction();
            QVERIFY(stroke.velocityChange.isApprox(6.0 * aim));
            const double h = height / 10.0 * kR;
            const Vec expected = 5.0 * 6.0 * h / (2.0 * kR * kR) * Vec::UnitY().cross(aim);
            QVERIFY2((stroke.spinChange - expected).norm() <= 1e-12 * (1.0 + expected.norm()),
                     qPrintable(QStringLiteral("turns %1, height %2").arg(turns).arg(height)));
            // the spin lies across the stroke, horizontal
            QVERIFY(std::abs(stroke.spinChange.dot(aim)) < 1e-12 && std::abs(stroke.spinChange.y()) < 1e-12);
        }
    }
}

void TestCueStroke::atTwoFifthsOfTheRadiusItLeavesRolling()
{
    // the textbook's natural roll: struck at h = 2r/5 the point touching the table is still,
    // v + ω × (−r up) = 0; below it the point slides forward, above it backward
    ui::Steering steering;
    steering.turn(5);
    steering.raiseCue(4);
    const auto contactVelocity = [](const ui::Steering::Stroke &s) {
        return Vec(s.velocityChange + s.spinChange.cross(-kR * Vec::UnitY()));
    };
    QVERIFY(contactVelocity(steering.stroke(kR)).norm() < 1e-12 * steering.strikeSpeed());
    steering.raiseCue(-1);
    QVERIFY(contactVelocity(steering.stroke(kR)).dot(steering.direction()) > 0.0);
    steering.raiseCue(2);
    QVERIFY(contactVelocity(steering.stroke(kR)).dot(steering.direction()) < 0.0);
    // a particle without a radius (a point) takes no spin
    QVERIFY(steering.stroke(0.0).spinChange.isZero(0.0));
}

void TestCueStroke::speedsAndHeightsAreClamped()
{
    ui::Steering steering;
    QCOMPARE(steering.cueLevel, 8);
    QCOMPARE(steering.strikeSpeed(), 4.0);
    steering.changeCue(-100);
    QCOMPARE(steering.cueLevel, 1);  // never a stroke of no speed
    steering.changeCue(100);
    QCOMPARE(steering.cueLevel, ui::Steering::kMaxCueLevel);
    steering.raiseCue(100);
    QCOMPARE(steering.cueHeight, ui::Steering::kMaxCueHeight);
    steering.raiseCue(-100);
    QCOMPARE(steering.cueHeight, -ui::Steering::kMaxCueHeight);
    // the push is a separate thing: a stroke leaves it alone
    QCOMPARE(steering.level, 0);
    steering.apply({.turn = 1, .push = 2, .cue = -3, .height = 4});
    QCOMPARE(steering.angle, ui::Steering::kTurnDegrees);
    QCOMPARE(steering.level, 2);
    QCOMPARE(steering.cueLevel, ui::Steering::kMaxCueLevel - 3);
    QCOMPARE(steering.cueHeight, -ui::Steering::kMaxCueHeight + 4);
}

void TestCueStroke::struckOnFeltItRollsAtTheClosedForm_data()
{
    QTest::addColumn<int>("height");
    for (int height = -ui::Steering::kMaxCueHeight; height <= ui::Steering::kMaxCueHeight; ++height)
        QTest::newRow(qPrintable(QStringLiteral("%1 r").arg(height / 10.0))) << height;
}

void TestCueStroke::struckOnFeltItRollsAtTheClosedForm()
{
    // struck at s from height h: it slides while its point of contact moves, friction μ m g
    // trading speed for spin, and rolls on at (5/7) s (1 + h/r) (at h = 2r/5, at once at s); its
    // point of contact starts at s (1 − 5h / (2r)) and slows at (7/2) μ g, so it slides for at most
    // 1.31 s (at h = −r/2 and s = 4 m/s)
    QFETCH(int, height);
    ui::SimulationRunner runner = runnerWith(ballOnFelt());
    QVERIFY(runner.state().angularVelocity.cols() == 1);
    ui::Steering steering;
    steering.turn(3);  // 45°: the stroke need not be along an axis
    steering.raiseCue(height);
    const ui::Steering::Stroke stroke = steering.stroke(kR);
    const double before = core::energies(*runner.model(), runner.state()).total();
    runner.apply(ui::StrikeEdit{0, stroke.velocityChange, stroke.spinChange});
    QVERIFY(runner.state().velocity.col(0).isApprox(stroke.velocityChange));
    QVERIFY(runner.state().angularVelocity.col(0) == stroke.spinChange);
    // the blow is the work of the cue: ½ m s² + ½ I ω²
    const double work = 0.5 * 0.17 * stroke.velocityChange.squaredNorm() +
                        0.5 * 0.4 * 0.17 * kR * kR * stroke.spinChange.squaredNorm();
    QVERIFY(std::abs(core::energies(*runner.model(), runner.state()).total() - before - work) < 1e-9 * work);

    for (int step = 0; step < 150; ++step)
        runner.apply(ui::StepOnce{});
    QCOMPARE(runner.state().step, std::uint64_t(150));  // not stopped as a runaway
    const double s = steering.strikeSpeed();
    const double expected = 5.0 / 7.0 * s * (1.0 + height / 10.0);
    const Vec velocity = runner.state().velocity.col(0);
    QVERIFY2(std::abs(velocity.dot(steering.direction()) - expected) < 2e-3 * s,
             qPrintable(QStringLiteral("%1 m/s, expected %2").arg(velocity.dot(steering.direction())).arg(expected)));
    QVERIFY(std::abs(velocity.cross(steering.direction()).norm()) < 1e-9);  // straight on
    // rolling: the point of contact is still
    const Vec contact = velocity + Vec(runner.state().angularVelocity.col(0)).cross(-kR * Vec::UnitY());
    QVERIFY2(contact.norm() < 1e-6 * s, qPrintable(QString::number(contact.norm())));
}

void TestCueStroke::struckLowItDrawsBackFromTheBallItHits()
{
    // the draw shot: struck at s = 4 m/s half the radius below the centre, into a ball 0.3 m on (e 1,
    // no friction between the balls). Until it hits, it slides: v = s − μ g t, and its backspin
    // r ω = (5/4) s − (5/2) μ g t. The hit stops it and leaves the spin, which rolls it back at
    // −(2/7) r ω; the ball hit leaves at the cue ball's speed and rolls at 5/7 of it
    const double mu = 0.2, s = 4.0, gap = 0.3;
    auto scene = std::make_shared<core::SceneDesc>(*ballOnFelt(0.0));
    scene->planes[0].friction = mu;
    scene->settings.restitution = 1.0;
    scene->settings.particleCollisions = true;
    core::ParticleDesc object = scene->particles[0];
    object.position.x() = 2.0 * kR + gap;
    scene->particles.push_back(object);
    ui::SimulationRunner runner = runnerWith(scene);
    ui::Steering steering;
    steering.changeCue(-8 + int(s / ui::Steering::kStrikeSpeedPerLevel));
    steering.raiseCue(-5);
    QCOMPARE(steering.strikeSpeed(), s);
    const ui::Steering::Stroke stroke = steering.stroke(kR);
    runner.apply(ui::StrikeEdit{0, stroke.velocityChange, stroke.spinChange});
    for (int step = 0; step < 200; ++step)
        runner.apply(ui::StepOnce{});
    QCOMPARE(runner.state().step, std::uint64_t(200));

    const double a = mu * kG;
    const double hitAt = (s - std::sqrt(s * s - 2.0 * a * gap)) / a;  // gap = s t − ½ a t²
    const double speedAtHit = s - a * hitAt, backspinAtHit = 1.25 * s - 2.5 * a * hitAt;
    const double cue = runner.state().velocity(0, 0), hit = runner.state().velocity(0, 1);
    QVERIFY2(std::abs(cue + 2.0 / 7.0 * backspinAtHit) < 0.02,
             qPrintable(QStringLiteral("cue ball %1 m/s, expected %2").arg(cue).arg(-2.0 / 7.0 * backspinAtHit)));
    QVERIFY2(std::abs(hit - 5.0 / 7.0 * speedAtHit) < 0.02,
             qPrintable(QStringLiteral("ball hit %1 m/s, expected %2").arg(hit).arg(5.0 / 7.0 * speedAtHit)));
}

void TestCueStroke::aPinnedBallTakesTheSpinButDoesNotMove()
{
    auto scene = std::make_shared<core::SceneDesc>(*ballOnFelt());
    scene->particles[0].pinned = true;
    core::ParticleDesc free;  // so that something is free and the felt's friction turns things
    free.position = Vec(1.0, kR, 0.0);
    free.radius = kR;
    scene->particles.push_back(free);
    ui::SimulationRunner runner = runnerWith(scene);
    QVERIFY(runner.state().angularVelocity.cols() == 2);
    runner.apply(ui::StrikeEdit{0, Vec(3.0, 0.0, 0.0), Vec(0.0, 10.0, 0.0)});
    QVERIFY(runner.state().velocity.col(0).isZero(0.0));
    QCOMPARE(runner.state().angularVelocity(1, 0), 10.0);
    // out of range: nothing happens
    runner.apply(ui::StrikeEdit{2, Vec(3.0, 0.0, 0.0), Vec::Zero()});
    runner.apply(ui::StrikeEdit{-1, Vec(3.0, 0.0, 0.0), Vec::Zero()});
    QVERIFY(runner.state().velocity.isZero(0.0));
}

void TestCueStroke::withoutFrictionTheSpinIsNotKept()
{
    // nothing has friction: the plan has no spin, so the stroke moves the ball and no more
    ui::SimulationRunner runner = runnerWith(ballOnFelt(0.0));
    QCOMPARE(runner.state().angularVelocity.cols(), Eigen::Index(0));
    QVERIFY(!runner.model()->plan.spin);
    runner.apply(ui::StrikeEdit{0, Vec(2.0, 0.0, 0.0), Vec(0.0, 0.0, -50.0)});
    QCOMPARE(runner.state().velocity(0, 0), 2.0);
    QCOMPARE(runner.state().angularVelocity.cols(), Eigen::Index(0));
    for (int step = 0; step < 10; ++step)
        runner.apply(ui::StepOnce{});
    QCOMPARE(runner.state().velocity(0, 0), 2.0);  // it slides on, unslowed
}

QTEST_APPLESS_MAIN(TestCueStroke)
#include "test_cue_stroke.moc"
