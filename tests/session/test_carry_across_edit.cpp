// Carrying a run across a scene edit, on plain scenes and states without a runner: a parameter
// edit keeps the state; a structural edit keeps the motion of the particles it left alone, by
// index or past deletions and additions, and the broken springs while the spring list is the
// same; Use Current State as Initial and its undo map the broken springs and the break log onto
// the new spring list; another scene, or a state of another scene, carries nothing.

#include "session/carry_across_edit.h"

#include "core/model/model.h"

#include <QtTest>
#include <algorithm>

namespace {

// n free particles in a row along x, 1 m apart, each joined to the next by a breakable spring; no
// gravity and no collisions
core::SceneDesc rowScene(int n = 5)
{
    core::SceneDesc scene;
    scene.settings.gravity.setZero();
    scene.settings.planeCollisions = false;
    scene.settings.particleCollisions = false;
    for (int i = 0; i < n; ++i) {
        core::ParticleDesc particle;
        particle.position = {double(i), 0.0, 0.0};
        scene.particles.push_back(particle);
    }
    for (int i = 0; i + 1 < n; ++i) {
        core::SpringDesc spring{i, i + 1, 100.0, 0.5, 1.0};
        spring.breakStrain = 0.5;
        scene.springs.push_back(spring);
    }
    return scene;
}

// a state of scene under way: every particle moved off its description and moving, at t = 1.5 s
core::State runOf(const core::SceneDesc &scene)
{
    core::State state = core::makeState(*core::compileModel(scene), scene);
    for (Eigen::Index i = 0; i < state.position.cols(); ++i) {
        state.position.col(i) += Eigen::Vector3d(0.0, 1.0 + double(i), 0.0);
        state.velocity.col(i) = Eigen::Vector3d(double(i) + 0.5, 0.0, -1.0);
    }
    state.time = 1.5;
    state.step = 6;
    return state;
}

// the edit applied to state, the way the runner applies it
bool carry(const core::SceneDesc &previous, const core::SceneDesc &scene, ui::SceneChange change,
           core::State &state)
{
    return ui::carryAcrossEdit(&previous, scene, *core::compileModel(scene), change, state);
}

}  // namespace

class TestCarryAcrossEdit : public QObject {
    Q_OBJECT

private slots:
    void sameStructureIgnoresValues();
    void parameterEditKeepsTheState();
    void nothingIsCarriedIntoAnotherScene_data();
    void nothingIsCarriedIntoAnotherScene();
    void unchangedParticlesKeepTheirMotion();
    void deletionsAndAdditionsKeepTheOthersMotion();
    void brokenSpringsStayWhileTheSpringListIsTheSame();
    void brokenSpringsFollowTheInitialConditions();
};

void TestCarryAcrossEdit::sameStructureIgnoresValues()
{
    const core::SceneDesc scene = rowScene();
    core::SceneDesc other = scene;
    other.settings.timeStep *= 2.0;
    other.springs[1].stiffness = 400.0;
    QVERIFY(ui::sameStructure(scene, other));

    // a particle moved, a spring with other ends, a spring more: another structure
    other = scene;
    other.particles[2].position.y() = 1.0;
    QVERIFY(!ui::sameStructure(scene, other));
    other = scene;
    other.springs[1].b = 3;
    QVERIFY(!ui::sameStructure(scene, other));
    other = scene;
    other.springs.push_back(core::SpringDesc{0, 4, 10.0, 0.0, 4.0});
    QVERIFY(!ui::sameStructure(scene, other));
}

void TestCarryAcrossEdit::parameterEditKeepsTheState()
{
    const core::SceneDesc scene = rowScene();
    core::State state = runOf(scene);
    state.springBroken[2] = 1;
    state.breaks.push_back(core::SpringBreak{2, 4, 1.0});
    const core::State before = state;

    core::SceneDesc stiffer = scene;
    for (core::SpringDesc &spring : stiffer.springs)
        spring.stiffness = 400.0;
    QVERIFY(carry(scene, stiffer, ui::SceneChange::Parameters, state));
    QVERIFY(state.position == before.position);
    QVERIFY(state.velocity == before.velocity);
    QCOMPARE(state.time, before.time);
    QCOMPARE(state.step, before.step);
    QVERIFY(state.springBroken == before.springBroken);
    QVERIFY(state.breaks == before.breaks);
}

void TestCarryAcrossEdit::nothingIsCarriedIntoAnotherScene_data()
{
    QTest::addColumn<int>("previousCount");  // 0: no previous scene
    QTest::addColumn<int>("stateCount");     // the particles of the state carried
    QTest::addColumn<int>("sceneCount");
    QTest::addColumn<ui::SceneChange>("change");
    QTest::newRow("another scene") << 5 << 5 << 5 << ui::SceneChange::Replace;
    QTest::newRow("no previous scene") << 0 << 5 << 5 << ui::SceneChange::Structure;
    QTest::newRow("a state of another scene") << 4 << 5 << 6 << ui::SceneChange::Structure;
    QTest::newRow("initial conditions, other particles") << 4 << 5 << 6 << ui::SceneChange::InitialConditions;
}

void TestCarryAcrossEdit::nothingIsCarriedIntoAnotherScene()
{
    QFETCH(int, previousCount);
    QFETCH(int, stateCount);
    QFETCH(int, sceneCount);
    QFETCH(ui::SceneChange, change);
    const core::SceneDesc previous = rowScene(std::max(previousCount, 2));
    const core::SceneDesc scene = rowScene(sceneCount);
    core::State state = runOf(rowScene(stateCount));
    const core::State before = state;
    QVERIFY(!ui::carryAcrossEdit(previousCount > 0 ? &previous : nullptr, scene, *core::compileModel(scene), change,
                                 state));
    // left as it was, for the caller to start again
    QVERIFY(state.position == before.position);
    QCOMPARE(state.step, before.step);
}

void TestCarryAcrossEdit::unchangedParticlesKeepTheirMotion()
{
    const core::SceneDesc scene = rowScene();
    core::State state = runOf(scene);
    const core::State before = state;

    // the same count: particle 1 moved in the scene, particle 3 pinned; a spring more
    core::SceneDesc edited = scene;
    edited.particles[1].position = {0.0, 0.0, 4.0};
    edited.particles[1].velocity = {0.0, 2.0, 0.0};
    edited.particles[3].pinned = true;
    edited.springs.push_back(core::SpringDesc{0, 4, 10.0, 0.0, 4.0});
    QVERIFY(carry(scene, edited, ui::SceneChange::Structure, state));
    for (Eigen::Index i : {0, 2, 4}) {
        QVERIFY(state.position.col(i) == before.position.col(i));
        QVERIFY(state.velocity.col(i) == before.velocity.col(i));
    }
    QCOMPARE(state.position.col(1), Eigen::Vector3d(0.0, 0.0, 4.0));
    QCOMPARE(state.velocity.col(1), Eigen::Vector3d(0.0, 2.0, 0.0));
    QCOMPARE(state.position.col(3), edited.particles[3].position);
    QCOMPARE(state.velocity.col(3), Eigen::Vector3d::Zero().eval());
    // the run goes on in time
    QCOMPARE(state.time, before.time);
    QCOMPARE(state.step, before.step);
}

void TestCarryAcrossEdit::deletionsAndAdditionsKeepTheOthersMotion()
{
    const core::SceneDesc scene = rowScene();
    core::State state = runOf(scene);
    const core::State before = state;

    // the first particle deleted, with its spring, and the others renumbered: each keeps its motion
    core::SceneDesc fewer = scene;
    fewer.particles.erase(fewer.particles.begin());
    fewer.springs.erase(fewer.springs.begin());
    for (core::SpringDesc &spring : fewer.springs) {
        --spring.a;
        --spring.b;
    }
    QVERIFY(carry(scene, fewer, ui::SceneChange::Structure, state));
    QCOMPARE(state.position.cols(), Eigen::Index(4));
    for (Eigen::Index i = 0; i < 4; ++i) {
        QVERIFY(state.position.col(i) == before.position.col(i + 1));
        QVERIFY(state.velocity.col(i) == before.velocity.col(i + 1));
    }

    // one added in the middle: it starts from its description, the others go on
    core::SceneDesc more = fewer;
    core::ParticleDesc added;
    added.position = {0.0, 3.0, 0.0};
    more.particles.insert(more.particles.begin() + 2, added);
    QVERIFY(carry(fewer, more, ui::SceneChange::Structure, state));
    QCOMPARE(state.position.cols(), Eigen::Index(5));
    for (Eigen::Index i : {0, 1, 3, 4}) {
        const Eigen::Index old = i < 2 ? i + 1 : i;
        QVERIFY(state.position.col(i) == before.position.col(old));
        QVERIFY(state.velocity.col(i) == before.velocity.col(old));
    }
    QCOMPARE(state.position.col(2), Eigen::Vector3d(0.0, 3.0, 0.0));
    QCOMPARE(state.velocity.col(2), Eigen::Vector3d::Zero().eval());
    QCOMPARE(state.step, before.step);
}

void TestCarryAcrossEdit::brokenSpringsStayWhileTheSpringListIsTheSame()
{
    const core::SceneDesc scene = rowScene();
    core::State state = runOf(scene);
    state.springBroken[1] = 1;
    state.breaks.push_back(core::SpringBreak{1, 3, 0.75});

    // a particle more, the springs as they were: still broken, still in the log
    core::SceneDesc more = scene;
    more.particles.push_back(core::ParticleDesc{});
    QVERIFY(carry(scene, more, ui::SceneChange::Structure, state));
    QCOMPARE(state.springBroken, (std::vector<std::uint8_t>{0, 1, 0, 0}));
    QCOMPARE(state.breaks.size(), std::size_t(1));
    QVERIFY(state.breaks.front() == (core::SpringBreak{1, 3, 0.75}));

    // a spring less: a flag no longer says which spring it was for, so every spring is whole
    core::SceneDesc fewer = more;
    fewer.springs.pop_back();
    QVERIFY(carry(more, fewer, ui::SceneChange::Structure, state));
    QCOMPARE(state.springBroken, (std::vector<std::uint8_t>{0, 0, 0}));
    QVERIFY(state.breaks.empty());
}

void TestCarryAcrossEdit::brokenSpringsFollowTheInitialConditions()
{
    // a run in which spring 1 broke becomes the initial conditions: that spring leaves the list
    const core::SceneDesc scene = rowScene();
    core::State state = runOf(scene);
    state.springBroken[1] = 1;
    state.breaks.push_back(core::SpringBreak{1, 3, 0.75});
    core::SceneDesc stored = scene;
    core::storeState(state, stored);
    QCOMPARE(stored.springs.size(), std::size_t(3));
    const core::State before = state;
    QVERIFY(carry(scene, stored, ui::SceneChange::InitialConditions, state));
    QVERIFY(state.position == before.position);
    QVERIFY(state.velocity == before.velocity);
    QCOMPARE(state.step, before.step);
    QCOMPARE(state.springBroken, (std::vector<std::uint8_t>{0, 0, 0}));
    QVERIFY(state.breaks.empty());

    // the run breaks the old spring 3 (now 2), then the edit is undone: the list has spring 1
    // again, broken, and the later break is renumbered to spring 3
    state.springBroken[2] = 1;
    state.breaks.push_back(core::SpringBreak{2, 7, 1.75});
    QVERIFY(carry(stored, scene, ui::SceneChange::InitialConditions, state));
    QVERIFY(state.position == before.position);
    QCOMPARE(state.springBroken, (std::vector<std::uint8_t>{0, 1, 0, 1}));
    QCOMPARE(state.breaks.size(), std::size_t(1));
    QVERIFY(state.breaks.front() == (core::SpringBreak{3, 7, 1.75}));
}

QTEST_GUILESS_MAIN(TestCarryAcrossEdit)
#include "test_carry_across_edit.moc"
