// The editing tools' scene changes, on plain SceneDescs: each keeps springs and the steerable
// particle pointing at the same particles, and does nothing outside what it names.

#include "ui/document/scene_edits.h"

#include "core/contacts/contact_impulses.h"
#include "core/model/generators.h"
#include "core/model/parameters.h"
#include "core/model/validate.h"

#include <QTest>

namespace {

core::ParticleDesc particleAt(double x, double y = 0.0, double z = 0.0)
{
    core::ParticleDesc p;
    p.position = {x, y, z};
    p.velocity = {0.0, 1.0, 0.0};
    return p;
}

// four particles in a row along x, 1 m apart, joined 0-1, 1-2, 2-3
core::SceneDesc row()
{
    core::SceneDesc scene;
    for (int i = 0; i < 4; ++i)
        scene.particles.push_back(particleAt(i));
    for (int i = 0; i < 3; ++i)
        scene.springs.push_back({i, i + 1, 10.0 + i, 0.5, 1.0});
    scene.steerable = 3;
    return scene;
}

// an L of five particles, neither flat nor symmetric, moving, joined in a chain, with particle 4
// outside the transformed set and joined to 3; contacts saved between 0 and 1, 3 and 4, and 4 and
// plane 0
core::SceneDesc bent()
{
    core::SceneDesc scene;
    const Eigen::Vector3d at[] = {{0.0, 0.0, 0.0}, {1.0, 0.0, 0.0}, {2.0, 0.5, 0.0}, {2.0, 1.5, -1.0}, {5.0, 2.0, 1.0}};
    for (int i = 0; i < 5; ++i) {
        core::ParticleDesc p;
        p.position = at[i];
        p.velocity = {0.1 * i, -0.3, 0.2 + i};
        scene.particles.push_back(p);
    }
    scene.particles[2].pinned = true;
    scene.particles[2].velocity.setZero();
    for (int i = 0; i < 4; ++i)
        scene.springs.push_back({i, i + 1, 100.0, 0.5, 0.9 + 0.1 * i});
    const Eigen::Vector3d none = Eigen::Vector3d::Zero();
    scene.contactImpulses = {{0, 1, 0.5, {0.0, 0.1, 0.0}}, {3, 4, 0.2, none}, {4, -1, 1.0, none}};
    return scene;
}

const std::vector<int> kTransformed{0, 1, 2, 3};

bool near(const Eigen::Vector3d &a, const Eigen::Vector3d &b, double tolerance = 1e-12)
{
    return (a - b).norm() <= tolerance * std::max(1.0, b.norm());
}

}  // namespace

class TestSceneEdits : public QObject {
    Q_OBJECT

private slots:
    void selectionStaysSortedAndUnique()
    {
        ui::Selection s;
        s.toggleParticle(5);
        s.toggleParticle(2);
        s.toggleParticle(9);
        s.toggleParticle(5);
        QCOMPARE(s.particles, (std::vector<int>{2, 9}));
        QVERIFY(s.hasParticle(9) && !s.hasParticle(5));
        std::vector<int> v{3, 1, 3, 2};
        ui::normalise(v);
        QCOMPARE(v, (std::vector<int>{1, 2, 3}));
        s.springs = {0, 4};
        s.clamp(row());  // 4 particles, 3 springs
        QCOMPARE(s.particles, (std::vector<int>{2}));
        QCOMPARE(s.springs, (std::vector<int>{0}));
    }

    void springRestLengthIsTheCurrentDistance()
    {
        core::SceneDesc scene = row();
        scene.particles[3].position = {3.0, 4.0, 0.0};
        const int s = ui::addSpring(scene, 0, 3, 50.0, 2.0);
        QCOMPARE(s, 3);
        QCOMPARE(scene.springs[3].restLength, 5.0);
        QCOMPARE(scene.springs[3].stiffness, 50.0);
        QCOMPARE(scene.springs[3].damping, 2.0);
        // refused: the same pair either way round, a particle to itself, out of range
        QCOMPARE(ui::addSpring(scene, 3, 0, 1.0, 0.0), -1);
        QCOMPARE(ui::addSpring(scene, 1, 1, 1.0, 0.0), -1);
        QCOMPARE(ui::addSpring(scene, 1, 7, 1.0, 0.0), -1);
        QCOMPARE(scene.springs.size(), std::size_t(4));
    }

    void pinningStopsTheParticle()
    {
        core::SceneDesc scene = row();
        ui::togglePinned(scene, {1, 2});
        QVERIFY(scene.particles[1].pinned && scene.particles[2].pinned);
        QCOMPARE(scene.particles[1].velocity, Eigen::Vector3d::Zero());
        QVERIFY(!scene.particles[0].pinned);
        ui::togglePinned(scene, {1});
        QVERIFY(!scene.particles[1].pinned);
        ui::setPinned(scene, {0, 2, 99}, true);
        QVERIFY(scene.particles[0].pinned && scene.particles[2].pinned);
    }

    void deletingAParticleTakesItsSpringsAndRenumbers()
    {
        core::SceneDesc scene = row();
        ui::removeItems(scene, ui::Selection{{1}, {}});
        QCOMPARE(scene.particles.size(), std::size_t(3));
        QCOMPARE(scene.particles[1].position.x(), 2.0);  // old 2
        // 0-1 and 1-2 went with particle 1; old 2-3 is now 1-2 with its own stiffness
        QCOMPARE(scene.springs.size(), std::size_t(1));
        QCOMPARE(scene.springs[0].a, 1);
        QCOMPARE(scene.springs[0].b, 2);
        QCOMPARE(scene.springs[0].stiffness, 12.0);
        QCOMPARE(scene.steerable, 2);

        // a selected spring alone goes, its particles stay; deleting the steerable one clears it
        core::SceneDesc other = row();
        ui::removeItems(other, ui::Selection{{3}, {0}});
        QCOMPARE(other.particles.size(), std::size_t(3));
        QCOMPARE(other.springs.size(), std::size_t(1));
        QCOMPARE(other.springs[0].a, 1);
        QCOMPARE(other.springs[0].b, 2);
        QCOMPARE(other.steerable, -1);
    }

    void deletingRenumbersTheSavedContactImpulses()
    {
        // a saved run's contact impulses follow their particles: those of a deleted particle go,
        // the others are renumbered and stay sorted, so the file still loads and the run starts
        // from them
        const Eigen::Vector3d kNone = Eigen::Vector3d::Zero();
        core::SceneDesc scene = row();
        scene.planes.push_back(core::PlaneDesc{});
        scene.contactImpulses = {{0, 1, 0.5, kNone}, {1, -1, 0.25, kNone}, {2, 3, 0.125, kNone}, {3, -1, 1.0, kNone}};
        ui::removeItems(scene, ui::Selection{{1}, {}});
        const std::vector<core::ContactImpulse> expected{{1, 2, 0.125, kNone}, {2, -1, 1.0, kNone}};
        QCOMPARE(scene.contactImpulses, expected);
        QVERIFY(!core::findProblem(scene));

        // and a removed plane takes its own, the planes after it moving down by one
        std::vector<core::ContactImpulse> onPlanes{{0, -1, 0.5, kNone}, {0, -2, 0.25, kNone}, {1, -3, 0.125, kNone}};
        core::removePlaneFromContactImpulses(onPlanes, 1);
        const std::vector<core::ContactImpulse> left{{0, -1, 0.5, kNone}, {1, -2, 0.125, kNone}};
        QCOMPARE(onPlanes, left);
    }

    void copyTakesTheSpringsWithin()
    {
        const core::SceneDesc scene = row();
        // particles 1 and 2: only the spring 1-2 lies within
        ui::Fragment f = ui::copyItems(scene, ui::Selection{{1, 2}, {}});
        QCOMPARE(f.particles.size(), std::size_t(2));
        QCOMPARE(f.springs.size(), std::size_t(1));
        QCOMPARE(f.springs[0].a, 0);
        QCOMPARE(f.springs[0].b, 1);
        QCOMPARE(f.springs[0].stiffness, 11.0);
        // a selected spring brings its ends
        f = ui::copyItems(scene, ui::Selection{{}, {2}});
        QCOMPARE(f.particles.size(), std::size_t(2));
        QCOMPARE(f.particles[0].position.x(), 2.0);
        QCOMPARE(f.springs.size(), std::size_t(1));
    }

    void pasteAppendsMovedCopies()
    {
        core::SceneDesc scene = row();
        const ui::Fragment f = ui::copyItems(scene, ui::Selection{{0, 1}, {}});
        const ui::Selection added = ui::pasteFragment(scene, f, {0.0, 0.0, 2.0});
        QCOMPARE(added.particles, (std::vector<int>{4, 5}));
        QCOMPARE(added.springs, (std::vector<int>{3}));
        QCOMPARE(scene.particles[5].position, Eigen::Vector3d(1.0, 0.0, 2.0));
        QCOMPARE(scene.springs[3].a, 4);
        QCOMPARE(scene.springs[3].b, 5);
        QCOMPARE(scene.springs[3].restLength, 1.0);
        // the originals are untouched
        QCOMPARE(scene.particles[1].position, Eigen::Vector3d(1.0, 0.0, 0.0));
    }

    void generatedSceneIsAppendedAroundTheCentre()
    {
        core::SceneDesc scene = row();
        const core::SceneDesc before = scene;
        core::ClothOptions options;
        options.rows = 3;
        options.cols = 4;
        const core::SceneDesc cloth = core::makeCloth(options);
        const ui::Selection added = ui::addGenerated(scene, cloth, {1.0, 2.0, 3.0});
        QCOMPARE(scene.particles.size(), before.particles.size() + cloth.particles.size());
        QCOMPARE(scene.springs.size(), before.springs.size() + cloth.springs.size());
        QCOMPARE(added.particles.front(), 4);
        QCOMPARE(added.particles.size(), cloth.particles.size());
        QCOMPARE(added.springs.front(), 3);
        QCOMPARE(added.springs.size(), cloth.springs.size());
        // what was there is untouched; the cloth's springs join its own particles, at the same rest
        // lengths, and the middle of its box is at the centre
        QVERIFY(std::equal(before.particles.begin(), before.particles.end(), scene.particles.begin()));
        QVERIFY(std::equal(before.springs.begin(), before.springs.end(), scene.springs.begin()));
        for (std::size_t s = 0; s < cloth.springs.size(); ++s) {
            const core::SpringDesc &spring = scene.springs[std::size_t(added.springs[s])];
            QCOMPARE(spring.a, cloth.springs[s].a + 4);
            QCOMPARE(spring.b, cloth.springs[s].b + 4);
            QCOMPARE(spring.restLength, cloth.springs[s].restLength);
        }
        const Eigen::Vector3d first = scene.particles[4].position;
        const Eigen::Vector3d last = scene.particles.back().position;
        QVERIFY((0.5 * (first + last) - Eigen::Vector3d(1.0, 2.0, 3.0)).norm() < 1e-12);
        QVERIFY(scene.particles[4].pinned);
        // the cloth's substeps came along; the scene's other settings stayed
        QCOMPARE(scene.settings.substeps, options.substeps);
        QCOMPARE(scene.settings.timeStep, before.settings.timeStep);
        QCOMPARE(scene.steerable, before.steerable);
        QVERIFY(ui::addGenerated(scene, core::SceneDesc{}, {}).empty());
    }

    void moveStartsFromWhereTheParticlesWereSeen()
    {
        core::SceneDesc scene = row();
        ui::moveParticles(scene, {0, 2}, {{5.0, 5.0, 5.0}, {7.0, 0.0, 0.0}}, {0.5, 0.0, -1.0});
        QCOMPARE(scene.particles[0].position, Eigen::Vector3d(5.5, 5.0, 4.0));
        QCOMPARE(scene.particles[2].position, Eigen::Vector3d(7.5, 0.0, -1.0));
        QCOMPARE(scene.particles[1].position, Eigen::Vector3d(1.0, 0.0, 0.0));
    }

    void particleLimitCountsTheWholeScene()
    {
        // the generators' limit, for the scene as a whole
        QCOMPARE(ui::kMaxSceneParticles, std::size_t(core::kMaxGeneratedParticles));
        core::SceneDesc scene;
        scene.particles.resize(ui::kMaxSceneParticles - 10);
        QVERIFY(!ui::particlesPastLimit(scene, 10));
        QCOMPARE(ui::particlesPastLimit(scene, 11), std::optional<std::size_t>(ui::kMaxSceneParticles + 1));
        scene.particles.resize(ui::kMaxSceneParticles);
        QCOMPARE(ui::particlesPastLimit(scene, ui::kMaxSceneParticles), std::optional<std::size_t>(2 * ui::kMaxSceneParticles));
    }

    void selectedParticlesTakeTheEndsOfSelectedSprings()
    {
        const core::SceneDesc scene = row();
        QCOMPARE(ui::selectedParticles(scene, ui::Selection{{3, 0}, {1}}), (std::vector<int>{0, 1, 2, 3}));
        QCOMPARE(ui::selectedParticles(scene, ui::Selection{{7}, {9}}), std::vector<int>{});
    }

    void transformRoundTripGivesTheSceneBack()
    {
        // scale, turn and move; then turn back and move back, then unscale: where everything began
        const core::SceneDesc before = bent();
        ui::SelectionTransform there;
        there.translation = {0.3, -2.0, 7.5};
        there.angleDegrees = 37.0;
        there.axis = {1.0, 2.0, -0.5};
        there.scale = {2.0, 0.5, -3.0};
        there.scaleRestLengths = true;
        core::SceneDesc scene = before;
        ui::transformParticles(scene, kTransformed, there);
        QVERIFY(!near(scene.particles[0].position, before.particles[0].position, 1e-3));

        ui::SelectionTransform turnBack;
        turnBack.translation = -there.translation;
        turnBack.angleDegrees = -there.angleDegrees;
        turnBack.axis = there.axis;
        ui::transformParticles(scene, kTransformed, turnBack);
        ui::SelectionTransform unscale;
        unscale.scale = there.scale.cwiseInverse();
        unscale.scaleRestLengths = true;
        ui::transformParticles(scene, kTransformed, unscale);

        for (std::size_t i = 0; i < before.particles.size(); ++i) {
            QVERIFY2(near(scene.particles[i].position, before.particles[i].position), qPrintable(QString::number(i)));
            QVERIFY2(near(scene.particles[i].velocity, before.particles[i].velocity), qPrintable(QString::number(i)));
        }
        for (std::size_t s = 0; s < before.springs.size(); ++s)
            QVERIFY(std::abs(scene.springs[s].restLength - before.springs[s].restLength) < 1e-12);
    }

    void rotationKeepsDistancesAndTheCentroid()
    {
        const core::SceneDesc before = bent();
        ui::SelectionTransform turn;
        turn.angleDegrees = 123.0;
        turn.axis = {0.2, -1.0, 0.7};
        core::SceneDesc scene = before;
        ui::transformParticles(scene, kTransformed, turn);
        QVERIFY(near(ui::centroid(scene, kTransformed), ui::centroid(before, kTransformed)));
        for (int i : kTransformed) {
            for (int j : kTransformed) {
                const double was = (before.particles[std::size_t(i)].position - before.particles[std::size_t(j)].position).norm();
                const double is = (scene.particles[std::size_t(i)].position - scene.particles[std::size_t(j)].position).norm();
                QVERIFY2(std::abs(is - was) < 1e-12, qPrintable(QStringLiteral("%1-%2: %3 %4").arg(i).arg(j).arg(is).arg(was)));
            }
            // speeds stay; the pinned particle stays at rest
            QVERIFY(std::abs(scene.particles[std::size_t(i)].velocity.norm() - before.particles[std::size_t(i)].velocity.norm()) < 1e-12);
        }
        QCOMPARE(scene.particles[2].velocity, Eigen::Vector3d::Zero().eval());
        // the particle outside, and every rest length, untouched
        QCOMPARE(scene.particles[4], before.particles[4]);
        QCOMPARE(scene.springs, before.springs);

        // a quarter turn about z takes x to y, positions and velocities alike (right-handed)
        core::SceneDesc pair;
        pair.particles.resize(2);
        pair.particles[0].position = {-1.0, 0.0, 0.0};
        pair.particles[1].position = {1.0, 0.0, 0.0};
        pair.particles[1].velocity = {2.0, 0.0, 0.0};
        ui::SelectionTransform quarter;
        quarter.angleDegrees = 90.0;
        quarter.axis = {0.0, 0.0, 5.0};
        ui::transformParticles(pair, {0, 1}, quarter);
        QVERIFY(near(pair.particles[1].position, {0.0, 1.0, 0.0}, 1e-15));
        QVERIFY(near(pair.particles[1].velocity, {0.0, 2.0, 0.0}, 1e-15));
    }

    void wholeTurnsAndNoChangeKeepTheBits()
    {
        const core::SceneDesc before = bent();
        for (double degrees : {0.0, 360.0, -720.0}) {
            ui::SelectionTransform turn;
            turn.angleDegrees = degrees;
            turn.axis = {1.0, 1.0, 0.0};
            core::SceneDesc scene = before;
            ui::transformParticles(scene, kTransformed, turn);
            QVERIFY2(scene.particles == before.particles, qPrintable(QString::number(degrees)));
        }
        QVERIFY(ui::SelectionTransform{}.isIdentity());
        ui::SelectionTransform moved;
        moved.translation.z() = 1e-9;
        QVERIFY(!moved.isIdentity());
    }

    void scaleIsAboutTheCentroid()
    {
        const core::SceneDesc before = bent();
        const Eigen::Vector3d centre = ui::centroid(before, kTransformed);
        QVERIFY(near(centre, {1.25, 0.5, -0.25}));
        ui::SelectionTransform grow;
        grow.scale = {2.0, 2.0, 2.0};
        core::SceneDesc scene = before;
        ui::transformParticles(scene, kTransformed, grow);
        QVERIFY(near(ui::centroid(scene, kTransformed), centre));
        for (int i : kTransformed) {
            const core::ParticleDesc &p = scene.particles[std::size_t(i)];
            const core::ParticleDesc &was = before.particles[std::size_t(i)];
            QVERIFY(near(p.position - centre, 2.0 * (was.position - centre)));
            // a scale moves the particles apart; their velocities, masses and radii stay
            QCOMPARE(p.velocity, was.velocity);
            QCOMPARE(p.mass, was.mass);
            QCOMPARE(p.radius, was.radius);
        }
        // rest lengths kept unless asked
        QCOMPARE(scene.springs, before.springs);

        // asked: the springs within take their new length's share, the one to particle 4 keeps its
        // own; per axis, a spring along x takes the x factor and one along y the y factor
        grow.scaleRestLengths = true;
        scene = before;
        ui::transformParticles(scene, kTransformed, grow);
        for (int s = 0; s < 3; ++s)
            QVERIFY(std::abs(scene.springs[std::size_t(s)].restLength - 2.0 * before.springs[std::size_t(s)].restLength) < 1e-12);
        QCOMPARE(scene.springs[3].restLength, before.springs[3].restLength);

        core::SceneDesc corner;
        corner.particles.resize(3);
        corner.particles[1].position = {1.0, 0.0, 0.0};
        corner.particles[2].position = {0.0, 1.0, 0.0};
        corner.springs = {{0, 1, 10.0, 0.0, 1.0}, {0, 2, 10.0, 0.0, 0.8}};
        ui::SelectionTransform stretch;
        stretch.scale = {3.0, 0.5, 1.0};
        stretch.scaleRestLengths = true;
        ui::transformParticles(corner, {0, 1, 2}, stretch);
        QVERIFY(std::abs(corner.springs[0].restLength - 3.0) < 1e-12);
        QVERIFY(std::abs(corner.springs[1].restLength - 0.4) < 1e-12);
    }

    void negativeFactorMirrorsPositionsAndVelocities()
    {
        core::SceneDesc scene;
        scene.particles.resize(2);
        scene.particles[0].position = {-1.0, 0.0, 0.0};
        scene.particles[1].position = {1.0, 2.0, 0.0};
        scene.particles[1].velocity = {1.0, 1.0, 1.0};
        ui::SelectionTransform mirror;
        mirror.scale = {-1.0, 1.0, 1.0};
        ui::transformParticles(scene, {0, 1}, mirror);
        QCOMPARE(scene.particles[1].position, Eigen::Vector3d(-1.0, 2.0, 0.0));
        QCOMPARE(scene.particles[1].velocity, Eigen::Vector3d(-1.0, 1.0, 1.0));
    }

    void transformDropsTheContactsOfWhatMoved()
    {
        core::SceneDesc scene = bent();
        ui::SelectionTransform move;
        move.translation = {0.0, 1.0, 0.0};
        ui::transformParticles(scene, {3}, move);
        QCOMPARE(scene.particles[3].position, Eigen::Vector3d(2.0, 2.5, -1.0));
        // 0-1 stays, 3-4 goes, 4 on the plane stays
        QCOMPARE(scene.contactImpulses.size(), std::size_t(2));
        QCOMPARE(scene.contactImpulses[0].i, 0);
        QCOMPARE(scene.contactImpulses[1].i, 4);
    }

    void gridSnapping()
    {
        QVERIFY((ui::snapToGrid({0.26, -0.04, 1.0}, 0.1) - Eigen::Vector3d(0.3, 0.0, 1.0)).norm() < 1e-12);
        QVERIFY((ui::snapToGrid({0.26, -0.04, 1.0}, 0.25) - Eigen::Vector3d(0.25, 0.0, 1.0)).norm() < 1e-12);
        QCOMPARE(ui::snapToGrid({0.26, -0.04, 1.0}, 0.0), Eigen::Vector3d(0.26, -0.04, 1.0));
    }

    void anEditCannotTakeAParticleOutOfTheWorld()
    {
        // the world ends at kStateLimit along each axis, for the loader, the saver, the run and
        // the editor alike: a particle added or moved past it is a problem, named by its path;
        // particles the edit leaves alone are not looked at
        core::SceneDesc before;
        before.particles = {core::ParticleDesc{Eigen::Vector3d(0.0, 1.0, 0.0), Eigen::Vector3d::Zero(), 1.0, 0.1, false},
                            core::ParticleDesc{Eigen::Vector3d(1.0, 1.0, 0.0), Eigen::Vector3d::Zero(), 1.0, 0.1, false}};
        core::SceneDesc after = before;
        QVERIFY(!ui::changedParticleProblem(before, after));
        after.particles[1].position.x() = 3.6e9;
        std::optional<core::SceneProblem> problem = ui::changedParticleProblem(before, after);
        QVERIFY(problem);
        QCOMPARE(QString::fromStdString(problem->path), QStringLiteral("particles[1].position[0]"));
        QVERIFY(core::findProblem(after));  // the same verdict as the whole scene's check

        // an added particle past the edge, and one at it (still inside: the bound is inclusive)
        after = before;
        after.particles.push_back(before.particles[0]);
        after.particles.back().position.z() = -core::kStateLimit;
        QVERIFY(!ui::changedParticleProblem(before, after));
        after.particles.back().position.z() = -1.01 * core::kStateLimit;
        problem = ui::changedParticleProblem(before, after);
        QVERIFY(problem);
        QCOMPARE(QString::fromStdString(problem->path), QStringLiteral("particles[2].position[2]"));

        // a particle already past the edge in `before` is not the edit's doing
        core::SceneDesc outside = before;
        outside.particles[0].position.y() = 2e9;
        core::SceneDesc moved = outside;
        moved.particles[1].position.y() = 2.0;
        QVERIFY(!ui::changedParticleProblem(outside, moved));
    }
};

QTEST_APPLESS_MAIN(TestSceneEdits)
#include "test_scene_edits.moc"
