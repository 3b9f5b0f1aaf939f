// The integrators against one step worked out by hand; pinned particles never move.
#include "core/passes.h"
#include "core/step.h"
#include "scene_builder.h"

#include <QtTest>

class TestIntegrate : public QObject {
    Q_OBJECT

private slots:
    void symplecticEulerUsesNewVelocity();
    void explicitEulerUsesOldVelocity();
    void freeFallMatchesTheRecurrence();
    void pinnedNeverMoves();
};

namespace {

// one particle of mass 2 at (1, 2, 3) moving at (1, 0, -1) under a force (4, -2, 0)
test::Sim oneParticle(core::Integrator integrator)
{
    core::SceneDesc scene = test::quietScene();
    scene.settings.integrator = integrator;
    scene.particles = {test::particle({1, 2, 3}, {1, 0, -1}, 2.0)};
    test::Sim sim = test::compile(scene);
    core::setAppliedForce(sim.state, 0, Eigen::Vector3d(4, -2, 0));
    return sim;
}

}  // namespace

void TestIntegrate::symplecticEulerUsesNewVelocity()
{
    test::Sim sim = oneParticle(core::Integrator::SymplecticEuler);
    core::integrate(*sim.model, sim.state, sim.work, 0.5);
    // v = (1,0,-1) + 0.5/2 (4,-2,0) = (2, -0.5, -1); x = (1,2,3) + 0.5 v = (2, 1.75, 2.5)
    QCOMPARE(Eigen::Vector3d(sim.state.velocity.col(0)), Eigen::Vector3d(2, -0.5, -1));
    QCOMPARE(Eigen::Vector3d(sim.state.position.col(0)), Eigen::Vector3d(2, 1.75, 2.5));
}

void TestIntegrate::explicitEulerUsesOldVelocity()
{
    test::Sim sim = oneParticle(core::Integrator::ExplicitEuler);
    core::integrate(*sim.model, sim.state, sim.work, 0.5);
    // x = (1,2,3) + 0.5 (1,0,-1) = (1.5, 2, 2.5); v as above
    QCOMPARE(Eigen::Vector3d(sim.state.velocity.col(0)), Eigen::Vector3d(2, -0.5, -1));
    QCOMPARE(Eigen::Vector3d(sim.state.position.col(0)), Eigen::Vector3d(1.5, 2, 2.5));
}

void TestIntegrate::freeFallMatchesTheRecurrence()
{
    // symplectic Euler in free fall: v_n = -g n h, y_n = y0 - g h² n (n + 1) / 2
    core::SceneDesc scene = test::quietScene();
    scene.settings.gravity = {0, -10, 0};
    scene.settings.timeStep = 0.01;
    scene.particles = {test::particle({0, 100, 0})};
    test::Sim sim = test::compile(scene);
    const int n = 200;
    for (int i = 0; i < n; ++i)
        QVERIFY(sim.step());
    QVERIFY(std::abs(sim.state.velocity(1, 0) - (-10 * n * 0.01)) < 1e-12);
    QVERIFY(std::abs(sim.state.position(1, 0) - (100 - 10 * 0.01 * 0.01 * n * (n + 1) / 2.0)) < 1e-10);
    QCOMPARE(sim.state.step, std::uint64_t(n));
    QVERIFY(std::abs(sim.state.time - 2.0) < 1e-12);
}

void TestIntegrate::pinnedNeverMoves()
{
    // a pinned particle in gravity, hit by a spring, with a velocity in its description
    core::SceneDesc scene = test::quietScene();
    scene.settings.gravity = {0, -9.81, 0};
    scene.particles = {test::particle({0, 1, 0}, {5, 5, 5}, 1.0, 0.1, true), test::particle({0.5, 1, 0})};
    scene.springs = {{0, 1, 100, 1, 0.2}};
    test::Sim sim = test::compile(scene);
    for (int i = 0; i < 100; ++i)
        QVERIFY(sim.step());
    QCOMPARE(Eigen::Vector3d(sim.state.position.col(0)), Eigen::Vector3d(0, 1, 0));
    QCOMPARE(Eigen::Vector3d(sim.state.velocity.col(0)), Eigen::Vector3d(0, 0, 0));
    QVERIFY(sim.state.position(1, 1) < 1.0);  // while the free one falls
}

QTEST_APPLESS_MAIN(TestIntegrate)
#include "test_integrate.moc"
