// Steering: the arrow keys' force turns in the horizontal plane and grows in levels of a fixed
// acceleration.

#include "ui/simulation/steering.h"

#include <QtTest>

class TestSteering : public QObject {
    Q_OBJECT

private slots:
    void startsWithNoForce();
    void turnsCounterClockwiseSeenFromAbove();
    void strengthIsClampedToItsLevels();
    void forceScalesWithMass();
};

void TestSteering::startsWithNoForce()
{
    const ui::Steering steering;
    QVERIFY(steering.force(3.0).isZero(0.0));
    QVERIFY(steering.direction().isApprox(Eigen::Vector3d::UnitX()));
}

void TestSteering::turnsCounterClockwiseSeenFromAbove()
{
    // six presses left is a quarter turn from +x to -z; the direction stays horizontal and unit
    ui::Steering steering;
    steering.turn(6);
    QCOMPARE(steering.angle, 90.0);
    QVERIFY(steering.direction().isApprox(-Eigen::Vector3d::UnitZ()));
    steering.turn(-12);
    QCOMPARE(steering.angle, 270.0);
    QVERIFY(steering.direction().isApprox(Eigen::Vector3d::UnitZ()));
    steering.turn(7);
    QCOMPARE(steering.direction().y(), 0.0);
    QVERIFY(std::abs(steering.direction().norm() - 1.0) < 1e-15);
}

void TestSteering::strengthIsClampedToItsLevels()
{
    ui::Steering steering;
    steering.change(-3);
    QCOMPARE(steering.level, 0);
    steering.change(ui::Steering::kMaxLevel + 5);
    QCOMPARE(steering.level, ui::Steering::kMaxLevel);
}

void TestSteering::forceScalesWithMass()
{
    ui::Steering steering;
    steering.change(3);
    QCOMPARE(steering.strength(2.0), 3 * ui::Steering::kAccelerationPerLevel * 2.0);
    QVERIFY(steering.force(2.0).isApprox(steering.strength(2.0) * Eigen::Vector3d::UnitX()));
}

QTEST_APPLESS_MAIN(TestSteering)
#include "test_steering.moc"
