// The editing tools' scene changes, on plain SceneDescs: each keeps springs and the steerable
// particle pointing at the same particles, and does nothing outside what it names.

#include "ui/document/scene_edits.h"

#include "core/contact_impulses.h"
#include "core/generators.h"
#include "core/validate.h"

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

    void gridSnapping()
    {
        QVERIFY((ui::snapToGrid({0.26, -0.04, 1.0}, 0.1) - Eigen::Vector3d(0.3, 0.0, 1.0)).norm() < 1e-12);
        QVERIFY((ui::snapToGrid({0.26, -0.04, 1.0}, 0.25) - Eigen::Vector3d(0.25, 0.0, 1.0)).norm() < 1e-12);
        QCOMPARE(ui::snapToGrid({0.26, -0.04, 1.0}, 0.0), Eigen::Vector3d(0.26, -0.04, 1.0));
    }
};

QTEST_APPLESS_MAIN(TestSceneEdits)
#include "test_scene_edits.moc"
