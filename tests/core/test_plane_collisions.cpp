// Particle–plane contacts: projection out of the plane, reflection with restitution, rest.
#include "core/model/diagnostics.h"
#include "core/passes.h"
#include "core/step.h"
#include "scene_builder.h"

#include <QtTest>

class TestPlaneCollisions : public QObject {
    Q_OBJECT

private slots:
    void pushedOutAndReflected_data();
    void pushedOutAndReflected();
    void separatingParticleKeepsItsVelocity();
    void tiltedPlane();
    void ballComesToRestWithoutSinking();
    void pinnedParticleIgnoresPlanes();
};

namespace {

test::Sim floorScene(Eigen::Vector3d position, Eigen::Vector3d velocity, double restitution)
{
    core::SceneDesc scene = test::quietScene();
    scene.settings.planeCollisions = true;
    scene.settings.restitution = restitution;
    scene.particles = {test::particle(position, velocity, 1.0, 0.5)};
    scene.planes = {core::PlaneDesc{{0, 1, 0}, 1.0}};  // the floor y = 1
    return test::compile(scene);
}

}  // namespace

void TestPlaneCollisions::pushedOutAndReflected_data()
{
    QTest::addColumn<double>("restitution");
    QTest::addColumn<double>("expectedVy");
    QTest::newRow("elastic") << 1.0 << 4.0;
    QTest::newRow("half") << 0.5 << 2.0;
    QTest::newRow("inelastic") << 0.0 << 0.0;
}

void TestPlaneCollisions::pushedOutAndReflected()
{
    QFETCH(double, restitution);
    QFETCH(double, expectedVy);
    // centre 0.2 m above the floor, radius 0.5: pushed up by 0.3 m; tangential velocity kept
    test::Sim sim = floorScene({3, 1.2, 0}, {2, -4, 0}, restitution);
    core::collidePlanes(*sim.model, sim.state, sim.work);
    QCOMPARE(Eigen::Vector3d(sim.state.position.col(0)), Eigen::Vector3d(3, 1.5, 0));
    QCOMPARE(Eigen::Vector3d(sim.state.velocity.col(0)), Eigen::Vector3d(2, expectedVy, 0));
}

void TestPlaneCollisions::separatingParticleKeepsItsVelocity()
{
    test::Sim sim = floorScene({0, 1.2, 0}, {0, 3, 0}, 1.0);
    core::collidePlanes(*sim.model, sim.state, sim.work);
    QCOMPARE(sim.state.position(1, 0), 1.5);
    QCOMPARE(Eigen::Vector3d(sim.state.velocity.col(0)), Eigen::Vector3d(0, 3, 0));
}

void TestPlaneCollisions::tiltedPlane()
{
    // the plane x + y = 0 (normal (1,1,0)/√2): a particle at the origin of radius 0.5 ends at
    // distance 0.5 along the normal, moving away from it
    core::SceneDesc scene = test::quietScene();
    scene.settings.planeCollisions = true;
    scene.particles = {test::particle({0, 0, 0}, {-1, -1, 0}, 1.0, 0.5)};
    scene.planes = {core::PlaneDesc{Eigen::Vector3d(1, 1, 0).normalized(), 0.0}};
    test::Sim sim = test::compile(scene);
    core::collidePlanes(*sim.model, sim.state, sim.work);
    const Eigen::Vector3d n = Eigen::Vector3d(1, 1, 0).normalized();
    QVERIFY(std::abs(n.dot(sim.state.position.col(0)) - 0.5) < 1e-15);
    QVERIFY((sim.state.velocity.col(0) - Eigen::Vector3d(1, 1, 0)).norm() < 1e-14);
}

void TestPlaneCollisions::ballComesToRestWithoutSinking()
{
    // a ball dropped on the floor with e = 0.5 under gravity
    core::SceneDesc scene = test::quietScene();
    scene.settings.gravity = {0, -9.81, 0};
    scene.settings.planeCollisions = true;
    scene.settings.restitution = 0.5;
    scene.settings.timeStep = 0.005;
    scene.particles = {test::particle({0, 2, 0}, {0, 0, 0}, 1.0, 0.25)};
    scene.planes = {core::PlaneDesc{{0, 1, 0}, 0.0}};
    test::Sim sim = test::compile(scene);
    double lowest = 2.0;
    for (int i = 0; i < 2000; ++i) {  // 10 s
        QVERIFY(sim.step());
        lowest = std::min(lowest, sim.state.position(1, 0));
    }
    // never below the floor (a rounding error at most), and at rest on it at the end
    QVERIFY2(lowest >= 0.25 - 1e-12, qPrintable(QString::number(lowest, 'g', 17)));
    QVERIFY(std::abs(sim.state.position(1, 0) - 0.25) < 1e-3);
    QVERIFY(std::abs(sim.state.velocity(1, 0)) < 0.05);
}

void TestPlaneCollisions::pinnedParticleIgnoresPlanes()
{
    core::SceneDesc scene = test::quietScene();
    scene.settings.planeCollisions = true;
    scene.particles = {test::particle({0, -3, 0}, {0, 0, 0}, 1.0, 0.5, true)};
    scene.planes = {core::PlaneDesc{{0, 1, 0}, 0.0}};
    test::Sim sim = test::compile(scene);
    QVERIFY(!sim.model->plan.planeCollisions);  // nothing free: the pass is not even planned
    core::collidePlanes(*sim.model, sim.state, sim.work);
    QCOMPARE(sim.state.position(1, 0), -3.0);
}

QTEST_APPLESS_MAIN(TestPlaneCollisions)
#include "test_plane_collisions.moc"
