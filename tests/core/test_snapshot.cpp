// Snapshots: floats of the state (positions and velocities), strains, pins, energies, step id; a
// snapshot filled again reuses its arrays' memory and keeps nothing of what it showed before.
#include "core/model/snapshot.h"
#include "core/step.h"
#include "scene_builder.h"

#include <QtTest>

class TestSnapshot : public QObject {
    Q_OBJECT

private slots:
    void packsTheState();
    void refillingKeepsTheMemoryAndNothingElse();
};

void TestSnapshot::packsTheState()
{
    core::SceneDesc scene = test::quietScene();
    scene.particles = {test::particle({0, 0, 0}, {0, 0, 0}, 1, 0.25, true), test::particle({1.5, 2, 3}, {1, 0, 0}, 2, 0.5)};
    scene.springs = {{0, 1, 10, 0, 2}};  // length √15.25 ≈ 3.905
    test::Sim sim = test::compile(scene);
    QVERIFY(sim.step());
    auto snap = core::makeSnapshot(*sim.model, sim.state);
    QCOMPARE(snap->step, std::uint64_t(1));
    QCOMPARE(snap->particleCount(), 2);
    QCOMPARE(snap->springCount(), 1);
    QCOMPARE(snap->positions[3], float(sim.state.position(0, 1)));
    QCOMPARE(snap->positions[5], float(sim.state.position(2, 1)));
    QCOMPARE(snap->velocities.size(), snap->positions.size());
    QCOMPARE(snap->velocities[3], float(sim.state.velocity(0, 1)));
    QCOMPARE(snap->velocities[4], float(sim.state.velocity(1, 1)));
    QVERIFY(snap->velocities[4] != 0.0f);  // the spring pulls it, one step in
    QCOMPARE(snap->velocities[0], 0.0f);   // pinned
    QCOMPARE(snap->radii[1], 0.5f);
    QCOMPARE(snap->pinned[0], std::uint8_t(1));
    QCOMPARE(snap->pinned[1], std::uint8_t(0));
    QCOMPARE(snap->springEnds[3], float(sim.state.position(0, 1)));
    const double length = (sim.state.position.col(1) - sim.state.position.col(0)).norm();
    QCOMPARE(snap->springStrain[0], float((length - 2.0) / 2.0));
    QCOMPARE(snap->energies.total(), core::energies(*sim.model, sim.state).total());
}

void TestSnapshot::refillingKeepsTheMemoryAndNothingElse()
{
    core::SceneDesc scene = test::quietScene();
    scene.particles = {test::particle({0, 0, 0}, {0, 0, 0}, 1, 0.25, true), test::particle({1.5, 2, 3}, {1, 0, 0}, 2, 0.5)};
    scene.springs = {{0, 1, 10, 0, 2}};
    test::Sim sim = test::compile(scene);
    // first a state that turns and a run that blew up: orientations, spins and the blow-up filled
    core::State turning = sim.state;
    turning.orientation.setZero(4, 2);
    turning.angularVelocity.setZero(3, 2);
    core::Blowup blowup;
    blowup.particle = 1;
    core::Snapshot into;
    core::fillSnapshot(into, *sim.model, turning, blowup);
    QCOMPARE(into.orientations.size(), std::size_t(8));
    QVERIFY(into.blowup.has_value());
    const float *positions = into.positions.data();
    const float *ends = into.springEnds.data();

    // then a step on, filled again: the same memory, the values of a snapshot made fresh, and
    // nothing left of the turning or the blow-up
    QVERIFY(sim.step());
    core::fillSnapshot(into, *sim.model, sim.state);
    const auto fresh = core::makeSnapshot(*sim.model, sim.state);
    QCOMPARE(into.positions.data(), positions);
    QCOMPARE(into.springEnds.data(), ends);
    QCOMPARE(into.step, fresh->step);
    QCOMPARE(into.positions, fresh->positions);
    QCOMPARE(into.velocities, fresh->velocities);
    QCOMPARE(into.springEnds, fresh->springEnds);
    QCOMPARE(into.springStrain, fresh->springStrain);
    QCOMPARE(into.radii, fresh->radii);
    QCOMPARE(into.pinned, fresh->pinned);
    QCOMPARE(into.energies.total(), fresh->energies.total());
    QVERIFY(into.orientations.empty());
    QVERIFY(into.angularVelocities.empty());
    QVERIFY(!into.blowup.has_value());

    // and a smaller scene's: its own sizes
    scene.particles.pop_back();
    scene.springs.clear();
    test::Sim one = test::compile(scene);
    core::fillSnapshot(into, *one.model, one.state);
    QCOMPARE(into.particleCount(), 1);
    QCOMPARE(into.springCount(), 0);
    QCOMPARE(into.positions.size(), std::size_t(3));
}

QTEST_APPLESS_MAIN(TestSnapshot)
#include "test_snapshot.moc"
