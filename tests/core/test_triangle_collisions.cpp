// Triangle collisions: a cloth is a surface. Balls of 1-10 cm at 1-30 m/s onto a cell and onto a
// bead of a 21 x 21 cloth stay above it; a pinned net stops a 2 cm particle at 100 m/s; a sheet
// dropped over a post thinner than its cells stays over it; a sheet that crumples on the floor,
// two sheets dropped on each other and a torn sheet never cross themselves or each other, counted
// at every step; a ball struck across a sheet turns to rolling on it as on a floor, and a sheet
// turns a spinning ball set down on it into rolling; and a scene without triangles never runs the pass.
#include "core/contacts/surface_crossings.h"
#include "core/contacts/triangle_geometry.h"
#include "core/integrators/stability.h"
#include "core/model/generators.h"
#include "core/model/state_hash.h"
#include "core/threads.h"
#include "scene_builder.h"

#include <QtTest>

#include <cmath>

class TestTriangleCollisions : public QObject {
    Q_OBJECT

private slots:
    void distancesAreExact();
    void impactTimeHasNoFalseNegatives();
    void ballStaysAboveTheCloth_data();
    void ballStaysAboveTheCloth();
    void pinnedNetStopsAFastParticle();
    void softSheetHoldsAHeavyBall();
    void sheetOverAThinPost();
    void crumplingSheetNeverCrossesItself();
    void twoSheetsDroppedOnEachOther();
    void tornSheetCollidesAsTorn();
    void sceneWithoutTrianglesSkipsThePass();
    void selfCollisionSwitchesOff();
    void tornSheetResumesBitForBit();
    void sameBitsOnOneAndTwoThreads();
    void sheetFlyingApartStopsAsBlownUp();
    void ballRollsOnASheet();
    void spinningBallSetDownOnASheetRollsAway();
};

namespace {

using Vec = Eigen::Vector3d;

// a cloth of rows x cols particles, 5 cm apart, in the plane y = height centred on the y axis, its four corners pinned
// (a trampoline) or none
core::SceneDesc clothScene(int rows, int cols, double beadRadius, double height, bool pinCorners, double stiffness = 3000.0)
{
    core::ClothOptions o;
    o.rows = rows;
    o.cols = cols;
    o.radius = beadRadius;
    o.height = height;
    o.structuralStiffness = stiffness;
    o.shearStiffness = stiffness / 5;
    o.bendStiffness = stiffness / 30;
    o.pinCorners = false;
    o.sheetCollisions = true;
    core::SceneDesc scene = core::makeCloth(o);
    if (pinCorners)
        for (int i : {0, cols - 1, (rows - 1) * cols, rows * cols - 1})
            scene.particles[std::size_t(i)].pinned = true;
    scene.settings.particleCollisions = false;  // the sheet alone keeps the ball out
    scene.planes = {core::floorPlane(0.0)};
    return scene;
}

int crossings(const test::Sim &sim)
{
    return core::countCrossings(*sim.model->surface, sim.state.position, sim.state.springBroken);
}

// how many times the ray from p along `direction` (2 m, tilted a little off the vertical so that
// it never runs along a grid line) passes through the sheet's whole triangles
int sheetsAlong(const test::Sim &sim, const Vec &p, double direction)
{
    const Vec ray = 2.0 * direction * Vec(0.0013, 1.0, 0.0007);
    const core::ClothSurface &s = *sim.model->surface;
    int hits = 0;
    for (int t = 0; t < s.triangleCount(); ++t) {
        const Vec a = sim.state.position.col(s.corners[std::size_t(3 * t)]);
        const Vec b = sim.state.position.col(s.corners[std::size_t(3 * t + 1)]);
        const Vec c = sim.state.position.col(s.corners[std::size_t(3 * t + 2)]);
        if (core::segmentCrossesTriangle(p, p + ray, a, b, c))
            ++hits;
    }
    return hits;
}

}  // namespace

void TestTriangleCollisions::distancesAreExact()
{
    // a point over a triangle's face, off its side, off its corner; a degenerate triangle
    const Vec a(0, 0, 0), b(1, 0, 0), c(0, 0, 1);
    QCOMPARE(core::pointTriangle(Vec(0.2, 0.5, 0.2), a, b, c).squaredDistance, 0.25);
    QVERIFY(std::abs(core::pointTriangle(Vec(0.5, 0.0, -2.0), a, b, c).squaredDistance - 4.0) < 1e-15);
    QVERIFY(std::abs(core::pointTriangle(Vec(-1, 1, -1), a, b, c).squaredDistance - 3.0) < 1e-15);
    QVERIFY(std::abs(core::pointTriangle(Vec(0.5, 1, 0), a, b, Vec(2, 0, 0)).squaredDistance - 1.0) < 1e-15);
    // crossing edges 1 m apart, parallel edges, an edge of zero length
    QVERIFY(std::abs(core::edgeEdge(Vec(-1, 0, 0), Vec(1, 0, 0), Vec(0, 1, -1), Vec(0, 1, 1)).squaredDistance - 1.0) < 1e-15);
    QVERIFY(std::abs(core::edgeEdge(Vec(0, 0, 0), Vec(1, 0, 0), Vec(0.5, 2, 0), Vec(3, 2, 0)).squaredDistance - 4.0) < 1e-15);
    QVERIFY(std::abs(core::edgeEdge(Vec(0, 0, 0), Vec(0, 0, 0), Vec(3, 0, 0), Vec(3, 0, 2)).squaredDistance - 9.0) < 1e-15);
}

void TestTriangleCollisions::impactTimeHasNoFalseNegatives()
{
    // random point-triangle and edge-edge motions: whenever the sampled motion comes within the
    // distance, the search reports an impact no later than the first such sample
    test::Lcg next{12345};
    auto r = [&] { return next(2001) / 1000.0 - 1.0; };
    int meetings = 0;
    for (int trial = 0; trial < 4000; ++trial) {
        const core::PairKind kind = trial % 2 ? core::PairKind::EdgeEdge : core::PairKind::PointTriangle;
        std::array<Vec, 4> x, d;
        for (std::size_t k = 0; k < 4; ++k) {
            x[k] = Vec(r(), r(), r());
            d[k] = 2.0 * Vec(r(), r(), r());
        }
        const double distance = 0.05;
        const double start = std::sqrt(core::closest(kind, x).squaredDistance);
        if (start <= distance)
            continue;
        const double t = core::additiveImpact(kind, x, d, distance, start - distance);
        double first = 2.0;
        for (int s = 0; s <= 2000; ++s) {
            const double u = s / 2000.0;
            std::array<Vec, 4> y;
            for (std::size_t k = 0; k < 4; ++k)
                y[k] = x[k] + u * d[k];
            if (core::closest(kind, y).squaredDistance <= distance * distance) {
                first = u;
                break;
            }
        }
        if (first <= 1.0) {
            ++meetings;
            QVERIFY2(t <= first, qPrintable(QString("trial %1: impact at %2, met at %3").arg(trial).arg(t).arg(first)));
        }
        if (t <= 1.0) {  // where it stops, the pair is still apart
            std::array<Vec, 4> y;
            for (std::size_t k = 0; k < 4; ++k)
                y[k] = x[k] + t * d[k];
            QVERIFY(core::closest(kind, y).squaredDistance > distance * distance);
        }
    }
    QVERIFY(meetings > 200);
}

void TestTriangleCollisions::ballStaysAboveTheCloth_data()
{
    QTest::addColumn<double>("radius");
    QTest::addColumn<double>("speed");
    QTest::addColumn<bool>("onBead");
    for (double radius : {0.01, 0.02, 0.05, 0.1})
        for (double speed : {1.0, 5.0, 30.0})
            for (bool onBead : {false, true})
                QTest::addRow("r %g cm, %g m/s, onto a %s", radius * 100, speed, onBead ? "bead" : "cell")
                    << radius << speed << onBead;
}

void TestTriangleCollisions::ballStaysAboveTheCloth()
{
    QFETCH(double, radius);
    QFETCH(double, speed);
    QFETCH(bool, onBead);
    // a 21 x 21 trampoline of 1 cm beads 5 cm apart, 0.5 m above the floor: a 2 cm ball fits
    // through a cell between the beads
    core::SceneDesc scene = clothScene(21, 21, 0.01, 0.5, true);
    const Vec target = onBead ? Vec(0.0, 0.5, 0.0) : Vec(0.025, 0.5, 0.025);
    scene.settings.restitution = 0.5;
    scene.particles.push_back(test::particle(target + Vec(0, radius + 0.02, 0), Vec(0, -speed, 0), 0.1, radius));
    test::Sim sim = test::compile(scene);
    QVERIFY(sim.model->plan.triangleCollisions);
    const int ball = sim.model->particleCount() - 1;
    // the ball is never under the sheet (it may be thrown off its edge), nothing crosses
    for (int step = 0; step < 60; ++step) {
        QVERIFY(sim.step());
        QCOMPARE(crossings(sim), 0);
        QVERIFY2(sheetsAlong(sim, sim.state.position.col(ball), 1.0) == 0,
                 qPrintable(QString("step %1: the ball is under the sheet").arg(step)));
    }
}

void TestTriangleCollisions::pinnedNetStopsAFastParticle()
{
    // every particle of the net pinned: a static collider; a 2 cm particle at 100 m/s
    core::SceneDesc scene = clothScene(11, 11, 0.005, 0.5, false);
    for (core::ParticleDesc &p : scene.particles)
        p.pinned = true;
    scene.settings.restitution = 0.5;
    scene.particles.push_back(test::particle(Vec(0.01, 0.6, 0.02), Vec(0, -100, 0), 0.01, 0.02));
    test::Sim sim = test::compile(scene);
    const int ball = sim.model->particleCount() - 1;
    double lowest = 1.0;
    for (int step = 0; step < 20; ++step) {
        QVERIFY(sim.step());
        lowest = std::min(lowest, sim.state.position(1, ball));
    }
    QVERIFY2(lowest > 0.5, qPrintable(QString("lowest %1").arg(lowest)));
    // bounced at half its speed at most
    QVERIFY(sim.state.velocity(1, ball) > 0.0);
    QVERIFY(sim.state.velocity.col(ball).norm() <= 50.0 + 1e-9);
}

void TestTriangleCollisions::softSheetHoldsAHeavyBall()
{
    // k = 500 N/m and a 1 kg ball of 3 cm at 5 m/s: it stretches the sheet but not through it
    core::SceneDesc scene = clothScene(21, 21, 0.01, 0.5, true, 500.0);
    scene.particles.push_back(test::particle(Vec(0.025, 0.56, 0.025), Vec(0, -5, 0), 1.0, 0.03));
    test::Sim sim = test::compile(scene);
    const int ball = sim.model->particleCount() - 1;
    int worst = 0;
    for (int step = 0; step < 100; ++step) {
        QVERIFY(sim.step());
        worst = std::max(worst, crossings(sim));
    }
    QCOMPARE(worst, 0);
    // held in the sheet's hollow, above it
    QVERIFY(sheetsAlong(sim, sim.state.position.col(ball), -1.0) % 2 == 1);
    QCOMPARE(sheetsAlong(sim, sim.state.position.col(ball), 1.0), 0);
}

void TestTriangleCollisions::sheetOverAThinPost()
{
    // a 1 cm post (a pinned particle) under a sheet of 5 cm cells: the sheet drapes over it
    core::SceneDesc scene = clothScene(15, 15, 0.01, 0.4, false);
    scene.settings.friction = 0.3;
    scene.particles.push_back(test::particle(Vec(0.0125, 0.25, 0.0125), Vec::Zero(), 1.0, 0.01, true));
    test::Sim sim = test::compile(scene);
    const int post = sim.model->particleCount() - 1;
    int worst = 0;
    for (int step = 0; step < 100; ++step) {
        QVERIFY(sim.step());
        worst = std::max(worst, crossings(sim));
    }
    QCOMPARE(worst, 0);
    // the post is under the sheet: the ray up from it meets the sheet
    const Vec p = sim.state.position.col(post);
    QCOMPARE(sheetsAlong(sim, p, 1.0), 1);
}

void TestTriangleCollisions::crumplingSheetNeverCrossesItself()
{
    // a 25 x 25 sheet of 1.5 cm beads held upright 30 cm above the floor, a little wavy so that it
    // buckles, let fall: it folds onto itself on the floor
    core::SceneDesc scene = clothScene(25, 25, 0.015, 0.0, false);
    for (core::ParticleDesc &p : scene.particles) {
        const double y = 0.3 + p.position.z() + 25 * 0.025;
        p.position = Vec(p.position.x(), y, 0.02 * std::sin(17.0 * y) + 0.01 * std::sin(23.0 * p.position.x()));
    }
    scene.settings.friction = 0.3;
    test::Sim sim = test::compile(scene);
    int worst = 0;
    double highest = 0.0;
    for (int step = 0; step < 150; ++step) {
        QVERIFY(sim.step());
        worst = std::max(worst, crossings(sim));
    }
    for (int i = 0; i < sim.model->particleCount(); ++i)
        highest = std::max(highest, sim.state.position(1, i));
    QCOMPARE(worst, 0);
    // it has come down: a heap on the floor, not a standing sheet
    QVERIFY2(highest < 0.4, qPrintable(QString("highest particle at %1 m").arg(highest)));
    // and the same sheet without triangle collisions crosses itself: the scene tests something
    scene.settings.triangleCollisions = false;
    test::Sim free = test::compile(scene);
    const core::ClothSurface surface = core::makeClothSurface(scene, *free.model->triangles);
    int freeCrossings = 0;
    for (int step = 0; step < 150; ++step) {
        QVERIFY(free.step());
        freeCrossings = std::max(freeCrossings, core::countCrossings(surface, free.state.position, free.state.springBroken));
    }
    QVERIFY2(freeCrossings > 0, "the scene never folds through itself without the collisions");
    qInfo("without triangle collisions: %d crossings", freeCrossings);
    qInfo("impacts %llu, zone rounds %llu, stops %llu", (unsigned long long)sim.work.triangles.impacts,
          (unsigned long long)sim.work.triangles.zoneRounds, (unsigned long long)sim.work.triangles.stops);
}

void TestTriangleCollisions::twoSheetsDroppedOnEachOther()
{
    core::SceneDesc scene = clothScene(12, 12, 0.01, 0.1, false);
    const core::SceneDesc upper = clothScene(12, 12, 0.01, 0.3, false);
    const int offset = int(scene.particles.size());
    for (core::ParticleDesc p : upper.particles) {
        p.position += Vec(0.03, 0.0, 0.02);
        scene.particles.push_back(p);
    }
    for (core::SpringDesc s : upper.springs) {
        s.a += offset;
        s.b += offset;
        scene.springs.push_back(s);
    }
    for (const std::array<int, 3> &t : upper.triangles)
        scene.triangles.push_back({t[0] + offset, t[1] + offset, t[2] + offset});
    test::Sim sim = test::compile(scene);
    QCOMPARE(int(sim.model->surface->sheetThickness.size()), 2);
    int worst = 0;
    for (int step = 0; step < 100; ++step) {
        QVERIFY(sim.step());
        worst = std::max(worst, crossings(sim));
    }
    QCOMPARE(worst, 0);
    // the upper sheet lies on the lower: where they overlap, the ray down from each of the upper's
    // particles passes through the lower sheet once
    int checked = 0;
    for (int i = offset; i < 2 * offset; ++i) {
        const Vec p = sim.state.position.col(i);
        if (std::abs(p.x()) > 0.1 || std::abs(p.z()) > 0.1)
            continue;
        ++checked;
        QVERIFY2(sheetsAlong(sim, p, -1.0) % 2 == 1, qPrintable(QString("particle %1 at y %2").arg(i).arg(p.y())));
    }
    QVERIFY(checked > 8);
}

void TestTriangleCollisions::tornSheetCollidesAsTorn()
{
    // a sheet whose springs break under a heavy ball: the ball tears through, and what stays whole
    // never crosses
    core::SceneDesc scene = clothScene(15, 15, 0.01, 0.5, true);
    for (core::SpringDesc &s : scene.springs)
        s.breakStrain = 0.3;
    scene.particles.push_back(test::particle(Vec(0.025, 0.6, 0.025), Vec(0, -8, 0), 5.0, 0.06));
    test::Sim sim = test::compile(scene);
    int worst = 0;
    for (int step = 0; step < 80; ++step) {
        QVERIFY(sim.step());
        worst = std::max(worst, crossings(sim));
    }
    QCOMPARE(worst, 0);
    QVERIFY(!sim.state.breaks.empty());
}

void TestTriangleCollisions::sceneWithoutTrianglesSkipsThePass()
{
    core::SceneDesc scene = core::makeChain({});
    test::Sim sim = test::compile(scene);
    QVERIFY(!sim.model->plan.triangleCollisions);
    for (int step = 0; step < 5; ++step)
        QVERIFY(sim.step());
    QCOMPARE(sim.work.profile[core::Stage::TriangleCollisions].calls, std::uint64_t(0));
    // a cloth has it, unless it is switched off
    core::SceneDesc cloth = clothScene(4, 4, 0.01, 0.5, true);
    QVERIFY(test::compile(cloth).model->plan.triangleCollisions);
    cloth.settings.triangleCollisions = false;
    QVERIFY(!test::compile(cloth).model->plan.triangleCollisions);
}

void TestTriangleCollisions::selfCollisionSwitchesOff()
{
    // a 6 x 6 sheet folded in half, its upper half 1 cm over the lower (within the thickness)
    core::SceneDesc scene = clothScene(6, 6, 0.01, 0.5, true);
    for (int r = 3; r < 6; ++r)
        for (int c = 0; c < 6; ++c)
            scene.particles[std::size_t(6 * r + c)].position =
                scene.particles[std::size_t(6 * (5 - r) + c)].position + Vec(0.0, 0.01, 0.0);
    scene.settings.selfCollision = false;
    test::Sim sim = test::compile(scene);
    QVERIFY(sim.model->plan.triangleCollisions);
    QVERIFY(sim.step());
    // the sheet alone: no pair to test, though its halves touch
    QVERIFY(sim.work.triangles.candidates.empty());
    scene.settings.selfCollision = true;
    test::Sim self = test::compile(scene);
    QVERIFY(self.step());
    QVERIFY(!self.work.triangles.candidates.empty());
}

void TestTriangleCollisions::tornSheetResumesBitForBit()
{
    // a run stored as a scene after springs broke (the torn triangles left out of its list) and
    // resumed goes on as the uninterrupted run, to the bit
    core::SceneDesc scene = clothScene(12, 12, 0.01, 0.5, true);
    for (core::SpringDesc &s : scene.springs)
        s.breakStrain = 0.2;
    scene.particles.push_back(test::particle(Vec(0.025, 0.56, 0.025), Vec(0, -6, 0), 3.0, 0.05));
    test::Sim whole = test::compile(scene);
    for (int step = 0; step < 30; ++step)
        QVERIFY(whole.step());
    QVERIFY(!whole.state.breaks.empty());
    core::SceneDesc stored = scene;
    core::storeState(whole.state, stored);
    QVERIFY(stored.triangles.size() < scene.triangles.size());
    test::Sim resumed = test::compile(stored);
    for (int step = 0; step < 30; ++step) {
        QVERIFY(whole.step());
        QVERIFY(resumed.step());
    }
    // the resumed run has the broken springs left out: compare the particles
    QVERIFY(whole.state.position == resumed.state.position);
    QVERIFY(whole.state.velocity == resumed.state.velocity);
}

void TestTriangleCollisions::sameBitsOnOneAndTwoThreads()
{
    // the broad phase's searches split across threads join their shares in one order: a 64 x 64
    // sheet (4096 particles, 12 000 edges: every search splits) held upright, wavy, let fall onto
    // the floor, ends 40 steps with the same bits and candidates on one thread and on two
    if (core::maxThreadCount() < 2)
        QSKIP("one hardware thread (or a build without OpenMP): nothing to compare");
    core::SceneDesc scene = clothScene(64, 64, 0.015, 0.0, false);
    for (core::ParticleDesc &p : scene.particles) {
        const double y = 0.1 + p.position.z() + 32 * 0.05;
        p.position = Vec(p.position.x(), y, 0.02 * std::sin(17.0 * y) + 0.01 * std::sin(23.0 * p.position.x()));
    }
    const int before = core::threadCount();
    const auto run = [&](int threads) {
        core::setThreadCount(threads);
        test::Sim sim = test::compile(scene);
        for (int i = 0; i < 40; ++i)
            sim.step();
        return std::pair(core::stateHash(sim.state), sim.work.triangles.candidates.size());
    };
    const auto one = run(1);
    const auto two = run(2);
    core::setThreadCount(before);
    QVERIFY2(one.second > 0, "no candidates: the sheet never came near itself");
    QCOMPARE(two.second, one.second);
    QCOMPARE(two.first, one.first);
}

void TestTriangleCollisions::sheetFlyingApartStopsAsBlownUp()
{
    // a 45 x 45 cloth at sub-steps of 3.1 ms, past symplectic Euler's limit for its springs (about
    // 0.8 ms): it flies apart in the first step, and every pair of its features comes within reach
    // of every other. The run stops there as blown up and says why, instead of testing millions
    // of pairs a sub-step (it used to take minutes a step)
    core::SceneDesc scene = clothScene(45, 45, 0.02, 1.0, true);
    scene.settings.timeStep = 0.1;
    scene.settings.substeps = 32;
    test::Sim sim = test::compile(scene);
    const core::StabilityLimit limit = core::stabilityLimit(*sim.model, sim.state);
    QVERIFY2(limit.maxSubStep(sim.model->integrator) < sim.model->subStep(), "the scene is meant to be unstable");
    int steps = 0;
    while (steps < 3 && sim.step())
        ++steps;
    QVERIFY2(sim.work.blowup.has_value(), "a sheet flying apart went on");
    QCOMPARE(int(sim.work.blowup->quantity), int(core::Blowup::Quantity::SheetPairs));
    QCOMPARE(sim.work.blowup->step, std::uint64_t(steps + 1));
    QVERIFY(sim.work.triangles.candidates.empty());
    const QString message = QString::fromStdString(core::explainBlowup(*sim.model, *sim.work.blowup, limit));
    QVERIFY2(message.contains(QStringLiteral("flew apart")) && message.contains(QStringLiteral("stability limit")),
             qPrintable(message));

    // the same sheet within the limit goes on
    scene.settings.timeStep = 0.01;
    scene.settings.substeps = 20;
    test::Sim stable = test::compile(scene);
    for (int i = 0; i < 3; ++i)
        QVERIFY(stable.step());
}


namespace {

// a 21 x 21 sheet at y = 0.5, every particle pinned (a table of triangles), 1 cm thick, friction
// mu, nothing else to touch; and a 5 cm ball of 0.17 kg resting on it at x, moving at v
core::SceneDesc ballOnASheet(double mu, const Vec &v, bool spin)
{
    core::SceneDesc scene = clothScene(21, 21, 0.005, 0.5, false);
    for (core::ParticleDesc &p : scene.particles)
        p.pinned = true;
    scene.planes.clear();
    scene.settings.thickness = 0.01;
    scene.settings.friction = mu;
    scene.settings.restitution = 0.0;
    scene.settings.spin = spin;
    scene.settings.substeps = 4;
    scene.particles.push_back(test::particle(Vec(-0.4, 0.5 + 0.05 + 0.005, 0.0), v, 0.17, 0.05));
    return scene;
}

}  // namespace

void TestTriangleCollisions::ballRollsOnASheet()
{
    // struck at 1 m/s across the sheet on mu = 0.2: friction slows it and turns it until its point
    // of contact stops, at t = 2 v0 / (7 mu g) = 0.146 s, and it rolls on at 5 v0 / 7, as on a floor
    // (test_spin); with spin off it slides to a stop, as a particle that does not turn
    const double v0 = 1.0, mu = 0.2, g = 9.81;
    test::Sim sim = test::compile(ballOnASheet(mu, Vec(v0, 0.0, 0.0), true));
    QVERIFY(sim.model->plan.spin);  // the sheet's friction alone makes the scene turn
    QVERIFY(sim.model->plan.triangleCollisions && !sim.model->plan.planeCollisions && !sim.model->plan.particleCollisions);
    const int ball = sim.state.particleCount() - 1;
    const auto slip = [&] { return sim.state.velocity(0, ball) + 0.05 * sim.state.angularVelocity(2, ball); };
    double rolledAt = -1.0;
    for (int step = 0; step < 40; ++step) {
        QVERIFY(sim.step());
        if (rolledAt < 0.0 && std::abs(slip()) < 1e-3 * v0)
            rolledAt = sim.state.time;
    }
    QVERIFY2(rolledAt > 0.0, qPrintable(QStringLiteral("it never rolled: slip %1 m/s").arg(slip())));
    QVERIFY2(std::abs(rolledAt - 2.0 * v0 / (7.0 * mu * g)) <= 0.011, qPrintable(QString::number(rolledAt)));
    QVERIFY2(std::abs(sim.state.velocity(0, ball) - 5.0 * v0 / 7.0) < 0.01 * v0,
             qPrintable(QString::number(sim.state.velocity(0, ball))));
    QVERIFY(std::abs(sim.state.position(1, ball) - 0.555) < 1e-3);  // on the sheet all along
    QCOMPARE(crossings(sim), 0);

    test::Sim sliding = test::compile(ballOnASheet(mu, Vec(v0, 0.0, 0.0), false));
    QVERIFY(!sliding.model->plan.spin);
    for (int step = 0; step < 60; ++step)
        QVERIFY(sliding.step());
    QVERIFY2(std::abs(sliding.state.velocity(0, ball)) < 1e-9, qPrintable(QString::number(sliding.state.velocity(0, ball))));
}

void TestTriangleCollisions::spinningBallSetDownOnASheetRollsAway()
{
    // a ball spinning at ω0 = 20 rad/s about -z, set down at rest on the sheet: the sheet's friction
    // drags its bottom back, so it moves off along +x, and it rolls once v = -r ω, at
    // (5 v0 - 2 r ω0) / 7 = 2 r |ω0| / 7 = 0.286 m/s, as on a floor (test_spin)
    core::SceneDesc scene = ballOnASheet(0.3, Vec::Zero(), true);
    scene.particles.back().angularVelocity = Vec(0.0, 0.0, -20.0);
    test::Sim sim = test::compile(scene);
    const int ball = sim.state.particleCount() - 1;
    for (int step = 0; step < 30; ++step)
        QVERIFY(sim.step());
    // to 2.5%, not to rounding as on a floor: each triangle the ball touches pushes along the line
    // from its own closest point, and where the ball's foot lies near an edge or a corner a
    // neighbouring triangle's closest point on that edge tilts its line a little (measured: 0.2910
    // m/s, 1.8% over)
    const double expected = 2.0 * 0.05 * 20.0 / 7.0;
    QVERIFY2(std::abs(sim.state.velocity(0, ball) - expected) < 0.025 * expected,
             qPrintable(QString::number(sim.state.velocity(0, ball))));
    QVERIFY(std::abs(sim.state.velocity(0, ball) + 0.05 * sim.state.angularVelocity(2, ball)) < 1e-3 * expected);
    QCOMPARE(crossings(sim), 0);
}

QTEST_GUILESS_MAIN(TestTriangleCollisions)
#include "test_triangle_collisions.moc"
