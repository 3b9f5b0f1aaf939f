// Gravity and viscous drag against values worked out by hand.
#include "core/passes.h"
#include "scene_builder.h"

#include <QtTest>

class TestGravity : public QObject {
    Q_OBJECT

private slots:
    void weightIsMassTimesG();
    void dragOpposesVelocity();
};

void TestGravity::weightIsMassTimesG()
{
    core::SceneDesc scene = test::quietScene();
    scene.settings.gravity = {0.5, -9.81, 0};
    scene.particles = {test::particle({0, 0, 0}, {0, 0, 0}, 2.0), test::particle({1, 0, 0}, {0, 0, 0}, 0.25)};
    test::Sim sim = test::compile(scene);
    sim.work.force.setZero();
    core::addGravity(*sim.model, sim.state, sim.work);
    QCOMPARE(Eigen::Vector3d(sim.work.force.col(0)), Eigen::Vector3d(1.0, -19.62, 0));
    QCOMPARE(Eigen::Vector3d(sim.work.force.col(1)), Eigen::Vector3d(0.125, -2.4525, 0));
}

void TestGravity::dragOpposesVelocity()
{
    core::SceneDesc scene = test::quietScene();
    scene.settings.viscosity = 0.5;
    scene.particles = {test::particle({0, 0, 0}, {2, -4, 6}, 3.0)};
    test::Sim sim = test::compile(scene);
    sim.work.force.setZero();
    core::addDrag(*sim.model, sim.state, sim.work);
    QCOMPARE(Eigen::Vector3d(sim.work.force.col(0)), Eigen::Vector3d(-1, 2, -3));
}

QTEST_APPLESS_MAIN(TestGravity)
#include "test_gravity.moc"
