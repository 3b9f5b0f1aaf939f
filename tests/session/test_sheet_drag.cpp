// A sheet dragged into a ball by the editor's mouse spring (applyGrabForce, as the Drag tool pulls)
// pushes the ball ahead of it: the ball stays on its side of the sheet at every step, and no edge
// of the sheet passes through it, with either contact solver.

#include "session/timeline.h"

#include "core/contacts/surface_crossings.h"
#include "core/model/generators.h"
#include "core/model/workspace.h"
#include "core/step.h"

#include <QtTest>

namespace {

using Vec = Eigen::Vector3d;

// how many of the sheet's triangles the segment from p straight up 2 m (tilted a little off the
// vertical, so that it never runs along a grid line) passes through
int sheetsAbove(const core::Model &model, const core::State &state, const Vec &p)
{
    const core::ClothSurface &s = *model.surface;
    const Vec q = p + 2.0 * Vec(0.0013, 1.0, 0.0007);
    int hits = 0;
    for (int t = 0; t < s.triangleCount(); ++t)
        if (core::segmentCrossesTriangle(p, q, state.position.col(s.corners[std::size_t(3 * t)]),
                                         state.position.col(s.corners[std::size_t(3 * t + 1)]),
                                         state.position.col(s.corners[std::size_t(3 * t + 2)])))
            ++hits;
    return hits;
}

}  // namespace

class TestSheetDrag : public QObject {
    Q_OBJECT

private slots:
    void draggedSheetPushesTheBall_data();
    void draggedSheetPushesTheBall();
};

void TestSheetDrag::draggedSheetPushesTheBall_data()
{
    QTest::addColumn<bool>("iterative");
    QTest::newRow("iterative solver") << true;
    QTest::newRow("handout's passes") << false;
}

void TestSheetDrag::draggedSheetPushesTheBall()
{
    QFETCH(bool, iterative);
    // a 21 x 21 sheet (5 cm cells, 1 cm beads) 30 cm up, no gravity; a 0.5 kg ball of 2 cm, which
    // with a bead's radius is less than a cell's half-diagonal, 10 cm under a cell's middle; the
    // sheet's middle bead dragged to 1.3 m under the ball
    core::ClothOptions o;
    o.rows = o.cols = 21;
    o.radius = 0.01;
    o.height = 0.3;
    o.pinCorners = false;
    o.sheetCollisions = true;
    core::SceneDesc scene = core::makeCloth(o);
    scene.settings.gravity = Vec::Zero();
    scene.settings.particleCollisions = false;
    scene.settings.contactSolver = iterative ? core::ContactSolver::Iterative : core::ContactSolver::Handout;
    scene.particles.push_back(core::ParticleDesc{Vec(0.025, 0.2, 0.025), Vec::Zero(), 0.5, 0.02, false});
    const std::shared_ptr<const core::Model> model = core::compileModel(scene);
    QVERIFY(model->plan.triangleCollisions);
    core::State state = core::makeState(*model, scene);
    core::Workspace work;
    const int ball = model->particleCount() - 1;
    ui::HeldForces held;
    held.grabParticle = 10 * 21 + 10;
    held.grabTarget = Vec(0.0, -1.1, 0.0);
    for (int step = 0; step < 100; ++step) {
        ui::applyGrabForce(*model, state, held);
        QVERIFY(core::step(*model, state, work));
        QCOMPARE(core::countCrossings(*model->surface, state.position, state.springBroken), 0);
        QVERIFY2(sheetsAbove(*model, state, state.position.col(ball)) == 1,
                 qPrintable(QString("step %1: the ball is not under the sheet").arg(step)));
    }
    // the ball was pushed, not passed: it has moved well down with the sheet
    QVERIFY2(state.position(1, ball) < -0.2, qPrintable(QString::number(state.position(1, ball))));

    // without the triangle collisions the sheet's beads pass around the ball: the scene tests something
    scene.settings.triangleCollisions = false;
    const std::shared_ptr<const core::Model> bare = core::compileModel(scene);
    core::State free = core::makeState(*bare, scene);
    core::Workspace freeWork;
    for (int step = 0; step < 100; ++step) {
        ui::applyGrabForce(*bare, free, held);
        QVERIFY(core::step(*bare, free, freeWork));
    }
    QVERIFY2(free.position(1, ball) > 0.1, qPrintable(QString::number(free.position(1, ball))));
}

QTEST_GUILESS_MAIN(TestSheetDrag)
#include "test_sheet_drag.moc"
