// The cloth-contacts benchmark. Each scene runs from one SceneDesc in each engine, for the same
// simulated time at the same step (0.01 s, 20 sub-steps):
//
// - crumple: an N x N sheet (5 cm cells, 1.5 cm beads) held upright just off the floor, a little
//   wavy so that it buckles, let fall: it folds onto itself in a heap;
// - drape: the same sheet laid flat over a pinned ball of a quarter of its width that stands on the
//   floor, let fall: it drapes over the ball and folds where it meets the floor.
//
// Engines:
// - springlab: the core, core::compileModel and core::step, on the core's threads (2 here), with
//   the triangle collisions (Settings::triangleCollisions, self-collision on, thickness automatic);
// - springlab-beads: the same with the triangle collisions off and the beads colliding as particles
//   instead (Settings::particleCollisions), as cloth did before it had a surface: what crosses
//   between the beads;
// - bullet: Bullet's soft-body cloth (bullet_sheet.h), one thread; only where libbullet-dev was
//   found at configure time.
//
// Read off every run, the same way for every engine: the crossings after every step
// (core::countCrossings: an edge of the sheet through one of its triangles that shares none of its
// particles), their most at any step and at the end; the wall time a step (median of 3 runs, each
// from the start; 1 with --quick), the simulated seconds per wall second
// (1 or more is real time), and for the core, from its profile, the share of the step the triangle
// collisions took.
#include "cloth_contacts.h"

#include "bench_common.h"
#ifdef SPRINGLAB_HAVE_BULLET
#include "bullet_sheet.h"
#endif

#include "core/contacts/cloth_surface.h"
#include "core/contacts/surface_crossings.h"
#include "core/model/generators.h"
#include "core/model/model.h"
#include "core/model/state.h"
#include "core/model/workspace.h"
#include "core/step.h"
#include "core/threads.h"

#include <QElapsedTimer>

#include <algorithm>
#include <cmath>
#include <memory>
#include <vector>

namespace bench {

namespace {

constexpr double kSpacing = 0.05;     // m, the sheet's cells
constexpr double kBeadRadius = 0.015; // m

struct Scene {
    QString name;
    int size = 0;
    core::SceneDesc desc;
};

// an N x N sheet of the benchmark's cells and beads, its triangles listed
core::SceneDesc sheet(int size)
{
    core::ClothOptions o;
    o.rows = size;
    o.cols = size;
    o.spacing = kSpacing;
    o.radius = kBeadRadius;
    o.height = 0.0;
    o.pinCorners = false;
    o.sheetCollisions = true;
    core::SceneDesc scene = core::makeCloth(o);
    scene.settings.particleCollisions = false;
    scene.settings.friction = 0.3;
    scene.planes = {core::floorPlane()};
    return scene;
}

Scene crumple(int size)
{
    core::SceneDesc scene = sheet(size);
    scene.name = "crumple";
    const double half = 0.5 * kSpacing * (size - 1);
    for (core::ParticleDesc &p : scene.particles) {
        const double y = 0.05 + half + p.position.z();
        p.position = Eigen::Vector3d(p.position.x(), y, 0.02 * std::sin(17.0 * y) + 0.01 * std::sin(23.0 * p.position.x()));
    }
    return {QStringLiteral("crumple"), size, scene};
}

Scene drape(int size)
{
    core::SceneDesc scene = sheet(size);
    scene.name = "drape";
    const double width = kSpacing * (size - 1);
    const double radius = 0.25 * width;
    for (core::ParticleDesc &p : scene.particles)
        p.position.y() = 2.0 * radius + 0.05;
    // the ball under the middle of a cell, so that the sheet's beads do not land on its top
    scene.particles.push_back(core::ParticleDesc{Eigen::Vector3d(0.5 * kSpacing, radius, 0.5 * kSpacing),
                                                 Eigen::Vector3d::Zero(), 1.0, radius, true});
    return {QStringLiteral("drape"), size, scene};
}

struct Result {
    QString scene, engine;
    int size = 0;
    int steps = 0;
    double msPerStep = 0.0;      // wall, median over the runs
    double collisionShare = -1;  // of the core's step; -1 where not measured
    int mostCrossings = 0;
    int endCrossings = 0;
    bool failed = false;
};

// the crossings of the scene's sheet at positions x (no spring broken: these sheets do not tear)
int crossingsAt(const core::ClothSurface &surface, const Eigen::Matrix3Xd &x)
{
    static const std::vector<std::uint8_t> none;
    return core::countCrossings(surface, x, none);
}

Result runCore(const Scene &scene, bool collisions, int steps, int runs, const core::ClothSurface &surface)
{
    Result r{scene.name, collisions ? QStringLiteral("springlab") : QStringLiteral("springlab-beads"), scene.size, steps};
    core::SceneDesc desc = scene.desc;
    desc.settings.triangleCollisions = collisions;
    desc.settings.particleCollisions = !collisions;
    std::vector<double> times;
    for (int run = 0; run < runs; ++run) {
        const std::shared_ptr<const core::Model> model = core::compileModel(desc);
        core::State state = core::makeState(*model, desc);
        core::Workspace work;
        double wall = 0.0;
        for (int s = 0; s < steps; ++s) {
            QElapsedTimer timer;
            timer.start();
            const bool ok = core::step(*model, state, work);
            wall += double(timer.nsecsElapsed()) * 1e-9;
            if (!ok) {
                r.failed = true;
                return r;
            }
            if (run == 0) {  // the physics is read off the first run
                const int c = crossingsAt(surface, state.position);
                r.mostCrossings = std::max(r.mostCrossings, c);
                if (s + 1 == steps)
                    r.endCrossings = c;
            }
        }
        times.push_back(1e3 * wall / steps);
        if (run == 0 && collisions) {
            double total = 0.0;
            for (const core::StageTiming &stage : work.profile.stages)
                total += stage.seconds;
            r.collisionShare = total > 0.0 ? work.profile[core::Stage::TriangleCollisions].seconds / total : 0.0;
        }
    }
    r.msPerStep = median(times);
    return r;
}

#ifdef SPRINGLAB_HAVE_BULLET
Result runBullet(const Scene &scene, int steps, int runs, const core::ClothSurface &surface)
{
    Result r{scene.name, QStringLiteral("bullet"), scene.size, steps};
    std::vector<double> times;
    for (int run = 0; run < runs; ++run) {
        BulletSheet bullet(scene.desc);
        double wall = 0.0;
        for (int s = 0; s < steps; ++s) {
            QElapsedTimer timer;
            timer.start();
            bullet.step();
            wall += double(timer.nsecsElapsed()) * 1e-9;
            if (run == 0) {
                const Eigen::Matrix3Xd x = bullet.positions();
                const int c = x.allFinite() ? crossingsAt(surface, x) : -1;
                if (c < 0)
                    r.failed = true;
                r.mostCrossings = std::max(r.mostCrossings, c);
                if (s + 1 == steps)
                    r.endCrossings = c;
            }
        }
        times.push_back(1e3 * wall / steps);
    }
    r.msPerStep = median(times);
    return r;
}
#endif

QString row(const Result &r, double stepSeconds)
{
    const double realTime = r.msPerStep > 0.0 ? 1e3 * stepSeconds / r.msPerStep : 0.0;
    return QStringLiteral("%1,%2,%3,%4,%5,%6,%7,%8,%9,%10")
        .arg(r.scene)
        .arg(r.size)
        .arg(r.engine)
        .arg(r.steps)
        .arg(r.msPerStep, 0, 'f', 3)
        .arg(realTime, 0, 'f', 3)
        .arg(r.collisionShare < 0.0 ? QString() : QString::number(r.collisionShare, 'f', 3))
        .arg(r.mostCrossings)
        .arg(r.endCrossings)
        .arg(r.failed ? QStringLiteral("failed") : QStringLiteral("ok"));
}

}  // namespace

int runClothContacts(const ClothContactsOptions &options, QTextStream &out)
{
    const RunClock clock;
    out << "cloth-contacts on " << machineDescription() << ", " << core::threadCount() << " core threads, "
        << loadText() << '\n';
#ifdef SPRINGLAB_HAVE_BULLET
    out << "bullet: " << QString::fromStdString(BulletSheet::description()) << '\n';
#else
    out << "bullet: not built (libbullet-dev was not found at configure time)\n";
#endif
    std::vector<int> sizes = options.sizes;
    if (sizes.empty())
        sizes = options.quick ? std::vector<int>{16} : std::vector<int>{64, 200};
    const std::optional<QDir> dir = outputFolder(options.outDir, out);
    if (!dir)
        return 1;
    const int runs = options.quick ? 1 : 3;

    QStringList lines{QStringLiteral(
        "scene,size,engine,steps,ms_per_step,realtime_factor,collision_share,most_crossings,end_crossings,status")};
    out << QStringLiteral("%1 %2 %3 %4 %5 %6 %7\n")
               .arg(QStringLiteral("scene"), -8)
               .arg(QStringLiteral("size"), 5)
               .arg(QStringLiteral("engine"), -14)
               .arg(QStringLiteral("ms/step"), 9)
               .arg(QStringLiteral("x real time"), 11)
               .arg(QStringLiteral("collisions"), 10)
               .arg(QStringLiteral("crossings (most, end)"));
    bool failed = false;
    for (const int size : sizes) {
        for (const Scene &scene : {crumple(size), drape(size)}) {
            const double seconds = options.seconds > 0.0 ? options.seconds
                                   : options.quick        ? 0.1
                                   : size <= 64           ? 2.0
                                                          : 0.5;
            const int steps = std::max(1, int(std::lround(seconds / scene.desc.settings.timeStep)));
            const std::shared_ptr<const core::Model> model = core::compileModel(scene.desc);
            const core::ClothSurface surface = core::makeClothSurface(scene.desc, *model->triangles);
            std::vector<Result> results{runCore(scene, true, steps, runs, surface),
                                        runCore(scene, false, steps, 1, surface)};
#ifdef SPRINGLAB_HAVE_BULLET
            results.push_back(runBullet(scene, steps, runs, surface));
#endif
            for (const Result &r : results) {
                lines << row(r, scene.desc.settings.timeStep);
                failed = failed || (r.failed && r.engine == QStringLiteral("springlab"));
                out << QStringLiteral("%1 %2 %3 %4 %5 %6 %7, %8%9\n")
                           .arg(r.scene, -8)
                           .arg(r.size, 5)
                           .arg(r.engine, -14)
                           .arg(r.msPerStep, 9, 'f', 2)
                           .arg(r.msPerStep > 0.0 ? 1e3 * scene.desc.settings.timeStep / r.msPerStep : 0.0, 11, 'f', 2)
                           .arg(r.collisionShare < 0.0 ? QStringLiteral("-")
                                                       : QString::number(100.0 * r.collisionShare, 'f', 0) + '%',
                                10)
                           .arg(r.mostCrossings)
                           .arg(r.endCrossings)
                           .arg(r.failed ? QStringLiteral(" (failed)") : QString());
                out.flush();
            }
        }
    }
    if (!writeLines(*dir, QStringLiteral("cloth-contacts.csv"), lines, out))
        return 1;
    out << loadText() << ", " << clock.text() << '\n';
    return failed ? 1 : 0;
}

}  // namespace bench
