// The closed-form reference solutions agree with what they describe (and with the simulation at
// a fine step), so that the accuracy benchmark measures against the truth.
#include "core/integrators/reference.h"
#include "core/step.h"
#include "scene_builder.h"

#include <QtTest>

class TestReference : public QObject {
    Q_OBJECT

private slots:
    void oscillatorSatisfiesItsEquation();
    void bounceTimesAndHeights();
    void headOnVelocities();
};

void TestReference::oscillatorSatisfiesItsEquation()
{
    // u(0), u'(0) as given, and m u'' + kc u' + k u = 0 by finite differences
    const core::OscillatorOptions o;
    QVERIFY(std::abs(core::oscillatorStretch(o, 0.0) - o.displacement) < 1e-15);
    QVERIFY(std::abs(core::oscillatorRate(o, 0.0) - o.speed) < 1e-14);
    for (double t : {0.1, 0.7, 1.3}) {
        const double d = 1e-4;
        const double u = core::oscillatorStretch(o, t);
        const double rate = (core::oscillatorStretch(o, t + d) - core::oscillatorStretch(o, t - d)) / (2 * d);
        const double accel =
            (core::oscillatorStretch(o, t + d) - 2 * u + core::oscillatorStretch(o, t - d)) / (d * d);
        QVERIFY(std::abs(rate - core::oscillatorRate(o, t)) < 1e-5);
        QVERIFY(std::abs(o.mass * accel + o.damping * rate + o.stiffness * u) < 1e-4);
    }
}

void TestReference::bounceTimesAndHeights()
{
    // simulate the bounce at a fine step and find the first two impacts and the first apex
    const core::BounceOptions o;
    core::SceneDesc scene = core::makeBounce(o);
    scene.settings.timeStep = 1e-5;
    test::Sim sim = test::compile(scene);
    std::vector<double> impacts;
    double apex = 0.0;
    double previousVy = 0.0;
    while (impacts.size() < 2) {
        QVERIFY(sim.step());
        const double vy = sim.state.velocity(1, 0);
        if (previousVy < 0.0 && vy > 0.0)
            impacts.push_back(sim.state.time);
        if (impacts.size() == 1)
            apex = std::max(apex, sim.state.position(1, 0));
        previousVy = vy;
    }
    QVERIFY2(std::abs(impacts[0] - core::bounceImpactTime(o, 0)) < 1e-4, qPrintable(QString::number(impacts[0])));
    QVERIFY2(std::abs(impacts[1] - core::bounceImpactTime(o, 1)) < 1e-3, qPrintable(QString::number(impacts[1])));
    QVERIFY2(std::abs(apex - core::bounceApexHeight(o, 0)) < 1e-3, qPrintable(QString::number(apex)));
}

void TestReference::headOnVelocities()
{
    for (double e : {1.0, 0.5, 0.0}) {
        core::HeadOnOptions o;
        o.restitution = e;
        core::SceneDesc scene = core::makeHeadOn(o);
        scene.settings.timeStep = 1e-3;
        test::Sim sim = test::compile(scene);
        for (int i = 0; i < 500; ++i)
            QVERIFY(sim.step());
        QVERIFY(std::abs(sim.state.velocity(0, 0) - core::headOnSpeedAfter(o, 0)) < 1e-12);
        QVERIFY(std::abs(sim.state.velocity(0, 1) - core::headOnSpeedAfter(o, 1)) < 1e-12);
    }
}

QTEST_APPLESS_MAIN(TestReference)
#include "test_reference.moc"
