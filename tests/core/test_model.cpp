// Compiling a scene: structure of arrays, unit normals, and the step plan.
#include "scene_builder.h"

#include <QtTest>

Q_DECLARE_METATYPE(core::SceneDesc)

class TestModel : public QObject {
    Q_OBJECT

private slots:
    void arraysFollowTheScene();
    void planFollowsTheScene_data();
    void planFollowsTheScene();
};

void TestModel::arraysFollowTheScene()
{
    core::SceneDesc scene = test::quietScene();
    scene.particles = {test::particle({0, 0, 0}, {0, 0, 0}, 2.0, 0.3), test::particle({1, 0, 0}, {0, 0, 0}, 4.0, 0.2, true),
                       test::particle({2, 0, 0}, {0, 0, 0}, 0.5, 0.1)};
    scene.springs = {{0, 2, 7, 0.5, 1.5}};
    scene.planes = {core::PlaneDesc{{0, 3, 4}, -1.0}};
    auto model = core::compileModel(scene);
    QCOMPARE(model->particleCount(), 3);
    QCOMPARE(model->invMass[0], 0.5);
    QCOMPARE(model->invMass[1], 0.0);
    QVERIFY(model->isPinned(1));
    QCOMPARE(model->mass[1], 4.0);
    QCOMPARE(model->radius[0], 0.3);
    QCOMPARE(model->freeParticles, (std::vector<int>{0, 2}));
    QCOMPARE(model->springA, std::vector<int>{0});
    QCOMPARE(model->springB, std::vector<int>{2});
    QCOMPARE(model->restLength[0], 1.5);
    QCOMPARE(Eigen::Vector3d(model->planeNormal.col(0)), Eigen::Vector3d(0, 0.6, 0.8));
    QCOMPARE(model->planeOffset[0], -1.0);
}

void TestModel::planFollowsTheScene_data()
{
    QTest::addColumn<core::SceneDesc>("scene");
    QTest::addColumn<bool>("gravity");
    QTest::addColumn<bool>("drag");
    QTest::addColumn<bool>("springs");
    QTest::addColumn<bool>("planes");
    QTest::addColumn<bool>("pairs");

    core::SceneDesc base;  // default settings: gravity on, no drag, both collision switches on
    base.particles = {test::particle({0, 0, 0}), test::particle({1, 0, 0})};
    QTest::newRow("defaults, no planes, no springs") << base << true << false << false << false << true;

    core::SceneDesc withAll = base;
    withAll.settings.viscosity = 0.2;
    withAll.springs = {{0, 1, 1, 0, 1}};
    withAll.planes = {core::PlaneDesc{}};
    QTest::newRow("everything") << withAll << true << true << true << true << true;

    core::SceneDesc allPinned = withAll;
    for (auto &p : allPinned.particles)
        p.pinned = true;
    QTest::newRow("all pinned: nothing can move") << allPinned << false << false << true << false << false;

    core::SceneDesc switchedOff = withAll;
    switchedOff.settings.planeCollisions = false;
    switchedOff.settings.particleCollisions = false;
    switchedOff.settings.gravity = Eigen::Vector3d::Zero();
    QTest::newRow("switched off") << switchedOff << false << true << true << false << false;

    core::SceneDesc single = withAll;
    single.particles.resize(1);
    single.springs.clear();
    QTest::newRow("one particle: no pairs") << single << true << true << false << true << false;
}

void TestModel::planFollowsTheScene()
{
    QFETCH(core::SceneDesc, scene);
    QFETCH(bool, gravity);
    QFETCH(bool, drag);
    QFETCH(bool, springs);
    QFETCH(bool, planes);
    QFETCH(bool, pairs);
    const core::StepPlan plan = core::compileModel(scene)->plan;
    QCOMPARE(plan.gravity, gravity);
    QCOMPARE(plan.drag, drag);
    QCOMPARE(plan.springs, springs);
    QCOMPARE(plan.planeCollisions, planes);
    QCOMPARE(plan.particleCollisions, pairs);
}

QTEST_APPLESS_MAIN(TestModel)
#include "test_model.moc"
