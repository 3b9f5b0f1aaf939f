// Particle–particle contacts: conservation laws, restitution, pinned particles, degenerate cases.
#include "core/model/diagnostics.h"
#include "core/passes.h"
#include "scene_builder.h"

#include <QtTest>

class TestParticleCollisions : public QObject {
    Q_OBJECT

private slots:
    void momentumAndEnergy_data();
    void momentumAndEnergy();
    void positionsCorrectedByMass();
    void separatingPairKeepsVelocities();
    void pinnedParticleIsImmovable();
    void coincidentCentresGiveNoNaN();
    void newContactsWaitForTheNextPass();
};

namespace {

// two particles overlapping by 0.1 m along a skew axis, approaching
test::Sim pair(double m1, double m2, double restitution, Eigen::Vector3d u1, Eigen::Vector3d u2)
{
    core::SceneDesc scene = test::quietScene();
    scene.settings.particleCollisions = true;
    scene.settings.restitution = restitution;
    const Eigen::Vector3d axis = Eigen::Vector3d(2, -1, 2) / 3.0;
    scene.particles = {test::particle(0.9 * axis, u1, m1, 0.5), test::particle({0, 0, 0}, u2, m2, 0.5)};
    return test::compile(scene);
}

}  // namespace

void TestParticleCollisions::momentumAndEnergy_data()
{
    QTest::addColumn<double>("m1");
    QTest::addColumn<double>("m2");
    QTest::addColumn<double>("restitution");
    QTest::newRow("equal, elastic") << 1.0 << 1.0 << 1.0;
    QTest::newRow("unequal, elastic") << 3.0 << 0.5 << 1.0;
    QTest::newRow("unequal, e=0.6") << 2.0 << 5.0 << 0.6;
    QTest::newRow("inelastic") << 1.0 << 4.0 << 0.0;
}

void TestParticleCollisions::momentumAndEnergy()
{
    QFETCH(double, m1);
    QFETCH(double, m2);
    QFETCH(double, restitution);
    const Eigen::Vector3d u1(-2, 1, 0.5);
    const Eigen::Vector3d u2(1, 0.5, -1);
    test::Sim sim = pair(m1, m2, restitution, u1, u2);
    const Eigen::Vector3d p0 = core::momentum(*sim.model, sim.state);
    const double e0 = core::energies(*sim.model, sim.state).kinetic;

    core::collideParticles(*sim.model, sim.state, sim.work);

    // momentum is conserved
    QVERIFY((core::momentum(*sim.model, sim.state) - p0).norm() < 1e-12);
    // kinetic energy lost: (1 - e²) ½ μ s², s the approach speed along the contact normal
    const Eigen::Vector3d k = Eigen::Vector3d(2, -1, 2) / 3.0;
    const double s = k.dot(u1 - u2);
    QVERIFY(s < 0.0);
    const double mu = m1 * m2 / (m1 + m2);
    const double expectedLoss = (1.0 - restitution * restitution) * 0.5 * mu * s * s;
    const double loss = e0 - core::energies(*sim.model, sim.state).kinetic;
    QVERIFY2(std::abs(loss - expectedLoss) < 1e-12, qPrintable(QString("loss %1, expected %2").arg(loss).arg(expectedLoss)));
    // afterwards they separate at e times the approach speed
    const double after = k.dot(sim.state.velocity.col(0) - sim.state.velocity.col(1));
    QVERIFY(std::abs(after + restitution * s) < 1e-12);
}

void TestParticleCollisions::positionsCorrectedByMass()
{
    // overlap 0.1 m; the lighter (1 kg) moves 4/5 of it, the heavier (4 kg) 1/5
    test::Sim sim = pair(1.0, 4.0, 1.0, Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero());
    const Eigen::Vector3d k = Eigen::Vector3d(2, -1, 2) / 3.0;
    core::collideParticles(*sim.model, sim.state, sim.work);
    QVERIFY((sim.state.position.col(0) - (0.9 + 0.08) * k).norm() < 1e-14);
    QVERIFY((sim.state.position.col(1) - (-0.02) * k).norm() < 1e-14);
    QVERIFY(std::abs((sim.state.position.col(0) - sim.state.position.col(1)).norm() - 1.0) < 1e-14);
}

void TestParticleCollisions::separatingPairKeepsVelocities()
{
    const Eigen::Vector3d k = Eigen::Vector3d(2, -1, 2) / 3.0;
    test::Sim sim = pair(1.0, 1.0, 1.0, k, -k);
    core::collideParticles(*sim.model, sim.state, sim.work);
    QCOMPARE(Eigen::Vector3d(sim.state.velocity.col(0)), k);
    QCOMPARE(Eigen::Vector3d(sim.state.velocity.col(1)), Eigen::Vector3d(-k));
}

void TestParticleCollisions::pinnedParticleIsImmovable()
{
    // a particle thrown at a pinned one bounces off it; the pinned one stays put
    core::SceneDesc scene = test::quietScene();
    scene.settings.particleCollisions = true;
    scene.settings.restitution = 1.0;
    scene.particles = {test::particle({0.8, 0, 0}, {-3, 0, 0}, 1.0, 0.5), test::particle({0, 0, 0}, {0, 0, 0}, 100.0, 0.5, true)};
    test::Sim sim = test::compile(scene);
    core::collideParticles(*sim.model, sim.state, sim.work);
    QCOMPARE(Eigen::Vector3d(sim.state.position.col(1)), Eigen::Vector3d(0, 0, 0));
    QCOMPARE(Eigen::Vector3d(sim.state.velocity.col(1)), Eigen::Vector3d(0, 0, 0));
    QCOMPARE(Eigen::Vector3d(sim.state.position.col(0)), Eigen::Vector3d(1, 0, 0));
    QCOMPARE(Eigen::Vector3d(sim.state.velocity.col(0)), Eigen::Vector3d(3, 0, 0));
}

void TestParticleCollisions::coincidentCentresGiveNoNaN()
{
    core::SceneDesc scene = test::quietScene();
    scene.settings.particleCollisions = true;
    scene.particles = {test::particle({1, 1, 1}, {0, 0, 0}), test::particle({1, 1, 1}, {0, 0, 0})};
    test::Sim sim = test::compile(scene);
    core::collideParticles(*sim.model, sim.state, sim.work);
    QVERIFY(sim.state.position.allFinite());
    QVERIFY(sim.state.velocity.allFinite());
    QVERIFY(std::abs((sim.state.position.col(0) - sim.state.position.col(1)).norm() - 0.2) < 1e-15);
}

void TestParticleCollisions::newContactsWaitForTheNextPass()
{
    // a overlaps b; resolving them pushes b into c, which it did not touch when the pass began:
    // that pair is left to the next pass, which resolves it
    core::SceneDesc scene = test::quietScene();
    scene.settings.particleCollisions = true;
    scene.particles = {test::particle({0, 0, 0}, {0, 0, 0}, 1.0, 0.5), test::particle({0.9, 0, 0}, {0, 0, 0}, 1.0, 0.5),
                       test::particle({1.92, 0, 0}, {0, 0, 0}, 1.0, 0.5)};
    test::Sim sim = test::compile(scene);
    core::collideParticles(*sim.model, sim.state, sim.work);
    QCOMPARE(sim.state.position(0, 2), 1.92);
    QVERIFY(sim.state.position(0, 2) - sim.state.position(0, 1) < 1.0 - 0.02);  // now they overlap
    core::collideParticles(*sim.model, sim.state, sim.work);
    QVERIFY(sim.state.position(0, 2) - sim.state.position(0, 1) > 1.0 - 1e-12);
}

QTEST_APPLESS_MAIN(TestParticleCollisions)
#include "test_particle_collisions.moc"
