// Scene validation: each kind of bad value is named with its path and reason.
#include "core/model/validate.h"
#include "scene_builder.h"

#include <QtTest>
#include <limits>

Q_DECLARE_METATYPE(core::SceneDesc)

class TestValidate : public QObject {
    Q_OBJECT

private slots:
    void goodSceneHasNoProblem();
    void badValuesAreNamed_data();
    void badValuesAreNamed();
    void unitNormalKeepsUnitVectorsBitForBit();
};

namespace {

core::SceneDesc goodScene()
{
    core::SceneDesc scene;
    scene.particles = {test::particle({0, 1, 0}), test::particle({1, 1, 0})};
    scene.springs = {{0, 1, 100, 1, 1}};
    scene.planes = {core::PlaneDesc{}};
    return scene;
}

}  // namespace

void TestValidate::goodSceneHasNoProblem()
{
    QVERIFY(!core::findProblem(goodScene()));
}

void TestValidate::badValuesAreNamed_data()
{
    QTest::addColumn<core::SceneDesc>("scene");
    QTest::addColumn<QString>("path");
    QTest::addColumn<QString>("reason");
    const double nan = std::numeric_limits<double>::quiet_NaN();
    const double inf = std::numeric_limits<double>::infinity();

    auto with = [](auto change) {
        core::SceneDesc scene = goodScene();
        change(scene);
        return scene;
    };
    QTest::newRow("zero mass") << with([](auto &s) { s.particles[1].mass = 0; }) << "particles[1].mass" << "greater than 0";
    QTest::newRow("negative mass") << with([](auto &s) { s.particles[0].mass = -1; }) << "particles[0].mass" << "got -1 kg";
    QTest::newRow("NaN mass") << with([=](auto &s) { s.particles[0].mass = nan; }) << "particles[0].mass" << "NaN";
    QTest::newRow("negative radius") << with([](auto &s) { s.particles[1].radius = -0.5; }) << "particles[1].radius" << "greater than 0";
    QTest::newRow("infinite position") << with([=](auto &s) { s.particles[1].position.z() = inf; }) << "particles[1].position[2]" << "finite";
    QTest::newRow("NaN velocity") << with([=](auto &s) { s.particles[0].velocity.x() = nan; }) << "particles[0].velocity[0]" << "NaN";
    QTest::newRow("huge time step") << with([](auto &s) { s.settings.timeStep = 5; }) << "settings.timeStep" << "at most 1 s";
    QTest::newRow("zero time step") << with([](auto &s) { s.settings.timeStep = 0; }) << "settings.timeStep" << "greater than 0";
    QTest::newRow("zero substeps") << with([](auto &s) { s.settings.substeps = 0; }) << "settings.substeps" << "at least 1";
    QTest::newRow("restitution above 1") << with([](auto &s) { s.settings.restitution = 1.5; }) << "settings.restitution" << "at most 1";
    QTest::newRow("negative viscosity") << with([](auto &s) { s.settings.viscosity = -0.1; }) << "settings.viscosity" << "at least 0";
    QTest::newRow("spring index out of range") << with([](auto &s) { s.springs[0].b = 2; }) << "springs[0].particles[1]" << "out of range";
    QTest::newRow("negative spring index") << with([](auto &s) { s.springs[0].a = -1; }) << "springs[0].particles[0]" << "out of range";
    QTest::newRow("self spring") << with([](auto &s) { s.springs[0].b = 0; }) << "springs[0].particles" << "to itself";
    QTest::newRow("negative stiffness") << with([](auto &s) { s.springs[0].stiffness = -3; }) << "springs[0].stiffness" << "at least 0";
    QTest::newRow("negative rest length") << with([](auto &s) { s.springs[0].restLength = -1; }) << "springs[0].restLength" << "at least 0";
    QTest::newRow("negative breaking strain") << with([](auto &s) { s.springs[0].breakStrain = -0.5; }) << "springs[0].breakStrain" << "at least 0";
    QTest::newRow("NaN breaking strain") << with([=](auto &s) { s.springs[0].breakStrain = nan; }) << "springs[0].breakStrain" << "NaN";
    QTest::newRow("breaking strain, no rest length") << with([](auto &s) { s.springs[0].restLength = 0; s.springs[0].breakStrain = 0.5; }) << "springs[0].breakStrain" << "rest length greater than 0";
    QTest::newRow("zero normal") << with([](auto &s) { s.planes[0].normal = Eigen::Vector3d::Zero(); }) << "planes[0].normal" << "zero";
    QTest::newRow("steerable out of range") << with([](auto &s) { s.steerable = 7; }) << "steerable" << "out of range";
}

void TestValidate::badValuesAreNamed()
{
    QFETCH(core::SceneDesc, scene);
    QFETCH(QString, path);
    QFETCH(QString, reason);
    const auto problem = core::findProblem(scene);
    QVERIFY(problem.has_value());
    QCOMPARE(QString::fromStdString(problem->path), path);
    QVERIFY2(QString::fromStdString(problem->message).contains(reason), problem->message.c_str());
}

void TestValidate::unitNormalKeepsUnitVectorsBitForBit()
{
    const Eigen::Vector3d once = core::unitNormal({1, 2, 3});
    QVERIFY(std::abs(once.norm() - 1.0) < 1e-15);
    QVERIFY(core::unitNormal(once) == once);
    QCOMPARE(core::unitNormal({0, 0, 5}), Eigen::Vector3d(0, 0, 1));
}

QTEST_APPLESS_MAIN(TestValidate)
#include "test_validate.moc"
