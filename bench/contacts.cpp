// The contacts benchmark. Each scene of contact_scenes.h runs in each engine from the same
// SceneDesc, for the same simulated time at the same step:
//
// - springlab: the core itself, core::compileModel and core::step on one thread
//   (core::setThreadCount(1), like for like with Bullet's single-threaded world); whatever the
//   core's contact solver does at the time of the run is what is measured.
// - bullet: Bullet's rigid spheres and static planes (bullet_spheres.h), its sequential-impulse
//   solver at its defaults; only where libbullet-dev was found at configure time.
// - bullet-norot: the same with each sphere's rotation locked (an angular factor of 0), so that
//   its balls, like the core's particles, cannot roll: the solvers compared on one model.
//
// The heap's balls are poured: ball k enters at k × the scene's interval, before that step. The
// core has no way to add a particle to a compiled model, so each entry compiles the scene again
// from the balls there so far at their current positions and velocities (core::storeState), as the
// editor does for a structural change; Bullet adds a body to its world. Both happen outside the
// timed steps.
//
// What is read off a run, the same way for both engines (contact_measures.h), from positions and
// velocities only:
// - stands (the column and the pyramid): the column's top ball, or the pyramid's ball that moved
//   most, ends within 1% of r of where it started;
// - settles: the kinetic energy ½ Σ m v² stays below 1e-3 N m g r all through the last second of
//   the run (its last half, if shorter); the settle time is when it went below for the last time
//   (the end of the last step at or above it, or of the last step a ball was still to be poured);
// - the deepest overlap of two balls or of a ball and a plane (floor or wall) over that last
//   second, after every step: a pile's overlaps come and go;
// - the heap's angle of repose, fitted through its outer surface and as a cone (Repose).
// Bullet's spheres rotate and roll, and its kinetic energy here is the translational one only; the
// core's particles do not rotate, so its friction stops a ball as it would a sliding block.
//
// Timing: CPU time of the process (bench_common.h) around each call that steps, summed over the
// run, over the number of steps: ms per step of h (all its sub-steps), averaged over the whole run
// (the drop and the rest alike). Each engine runs each scene `repetitions` times from the start and
// the median is taken; the physics is read off the first run, and every later one must end on the
// same positions to the bit (both engines are deterministic on one thread), or the run says so.
#include "contacts.h"

#include "bench_common.h"
#include "contact_measures.h"
#include "contact_scenes.h"
#include "contacts_plot.h"
#ifdef SPRINGLAB_HAVE_BULLET
#include "bullet_spheres.h"
#endif

#include "core/model/model.h"
#include "core/model/state.h"
#include "core/step.h"
#include "core/threads.h"
#include "core/model/workspace.h"

#include <QDir>
#include <QElapsedTimer>
#include <QSaveFile>

#include <algorithm>
#include <cmath>
#include <memory>
#include <vector>

namespace bench {

namespace {

constexpr double kStandFraction = 0.01;   // of r: a stack stands while no ball ends further from its start
constexpr double kSettleFraction = 1e-3;  // settled: kinetic energy below this × N m g r
// s at the end of a run (its last half, if shorter) over which the deepest overlap is taken, and
// all through which the kinetic energy must stay under the threshold for the scene to have settled
constexpr double kEndWindow = 1.0;
#ifndef SPRINGLAB_HAVE_BULLET
constexpr const char *kBulletNotBuilt =
    "not built (libbullet-dev not found, or SPRINGLAB_BULLET off, when springlab-bench was configured)";
#endif

// how the run is sized; --quick shrinks it
struct Plan {
    double columnSeconds = 60.0;
    double pyramidSeconds = 10.0;
    int pileBalls = 1000;
    double pileSeconds = 10.0;
    int pileSubsteps = 4;  // the second pile's
    int heapBalls = 400;   // poured over 20 s
    double heapSeconds = 30.0;
    int repetitions = 3;
};

Plan planFor(bool quick)
{
    Plan plan;
    if (quick) {
        plan.columnSeconds = 1.0;
        plan.pyramidSeconds = 0.5;
        plan.pileSeconds = 0.2;
        plan.heapBalls = 30;  // poured over 1.5 s; the last lands by 2.2 s
        plan.heapSeconds = 4.0;
    }
    return plan;
}

// the core stepping a scene whose balls may enter during the run: each entry compiles the scene
// again from the balls there so far, at their current positions and velocities
class SpringlabBalls {
public:
    explicit SpringlabBalls(const core::SceneDesc &scene) : m_all(scene), m_live(scene) { m_live.particles.clear(); }

    void enter(int count)
    {
        if (count == static_cast<int>(m_live.particles.size()))
            return;
        if (m_model)
            core::storeState(m_state, m_live);
        const double time = m_state.time;
        const std::uint64_t steps = m_state.step;
        for (int i = static_cast<int>(m_live.particles.size()); i < count; ++i)
            m_live.particles.push_back(m_all.particles[static_cast<std::size_t>(i)]);
        m_model = core::compileModel(m_live);
        m_state = core::makeState(*m_model, m_live);
        m_state.time = time;
        m_state.step = steps;
    }

    bool step() { return core::step(*m_model, m_state, m_work); }

    int particleCount() const { return m_state.particleCount(); }
    Eigen::Vector3d position(int i) const { return m_state.position.col(i); }
    Eigen::Vector3d velocity(int i) const { return m_state.velocity.col(i); }

private:
    core::SceneDesc m_all;
    core::SceneDesc m_live;
    std::shared_ptr<const core::Model> m_model;
    core::State m_state;
    core::Workspace m_work;
};

#ifdef SPRINGLAB_HAVE_BULLET
// Bullet's spheres behind the same calls, rotating or with their rotation locked (Bullet has no
// failure to report: a value gone wrong shows in the kinetic energy)
template <bool Rotates>
class BulletBalls {
public:
    explicit BulletBalls(const core::SceneDesc &scene) : m_spheres(scene, Rotates) {}
    void enter(int count) { m_spheres.enter(count); }
    bool step()
    {
        m_spheres.step();
        return true;
    }
    int particleCount() const { return m_spheres.particleCount(); }
    Eigen::Vector3d position(int i) const { return m_spheres.position(i); }
    Eigen::Vector3d velocity(int i) const { return m_spheres.velocity(i); }

private:
    BulletSpheres m_spheres;
};
#endif

// what one run of a scene in an engine leaves
struct Outcome {
    Eigen::Matrix3Xd position;  // m, at the end (the balls that had entered)
    double kineticEnd = 0.0;    // J
    double kineticPeak = 0.0;   // J, the largest over the end window
    double deepestOverlap = 0.0;  // m, over the end window
    double lastUnsettled = 0.0;  // s, the end of the last step at or above the threshold, or with balls to come
    bool complete = false;       // every ball had entered by the end
    bool blewUp = false;
    double stepSeconds = 0.0;  // CPU s in the calls that step
    int steps = 0;
};

Eigen::VectorXd massesOf(const core::SceneDesc &scene)
{
    Eigen::VectorXd mass(static_cast<Eigen::Index>(scene.particles.size()));
    for (std::size_t i = 0; i < scene.particles.size(); ++i)
        mass[static_cast<Eigen::Index>(i)] = scene.particles[i].mass;
    return mass;
}

Eigen::VectorXd radiiOf(const core::SceneDesc &scene, int count)
{
    Eigen::VectorXd radius(count);
    for (int i = 0; i < count; ++i)
        radius[i] = scene.particles[static_cast<std::size_t>(i)].radius;
    return radius;
}

// s, the end window of this scene's run
double endWindow(const ContactScene &contact)
{
    return std::min(kEndWindow, 0.5 * contact.duration);
}

// J, the settle threshold: 1e-3 N m g r, with N m the scene's total mass
double settleThreshold(const core::SceneDesc &scene)
{
    return kSettleFraction * massesOf(scene).sum() * scene.settings.gravity.norm() * kBallRadius;
}

// runs the scene from its start to its duration; only the calls that step are timed
template <typename Engine>
Outcome runOnce(const ContactScene &contact, double threshold)
{
    const core::SceneDesc &scene = contact.scene;
    const int n = static_cast<int>(scene.particles.size());
    const double h = scene.settings.timeStep;
    const int steps = static_cast<int>(std::lround(contact.duration / h));
    const Eigen::VectorXd mass = massesOf(scene);
    const Eigen::VectorXd radius = radiiOf(scene, n);
    const int overlapFrom = steps - static_cast<int>(std::lround(endWindow(contact) / h));
    Eigen::Matrix3Xd position;
    // the step before which each ball enters (all at 0 unless poured)
    const auto entryStep = [&](int k) {
        return static_cast<int>(std::lround(k * contact.releaseInterval / h));
    };

    Engine engine(scene);
    Outcome outcome;
    int present = 0;
    for (int s = 0; s < steps; ++s) {
        while (present < n && entryStep(present) <= s)
            ++present;
        engine.enter(present);

        const double before = cpuSeconds();
        const bool ok = engine.step();
        outcome.stepSeconds += cpuSeconds() - before;
        ++outcome.steps;

        double energy = 0.0;
        for (int i = 0; i < present; ++i)
            energy += 0.5 * mass[i] * engine.velocity(i).squaredNorm();
        outcome.kineticEnd = energy;
        if (!ok || !std::isfinite(energy)) {
            outcome.blewUp = true;
            break;
        }
        if (energy >= threshold || present < n)
            outcome.lastUnsettled = (s + 1) * h;
        if (s >= overlapFrom) {
            outcome.kineticPeak = std::max(outcome.kineticPeak, energy);
            position.resize(3, present);
            for (int i = 0; i < present; ++i)
                position.col(i) = engine.position(i);
            outcome.deepestOverlap =
                std::max(outcome.deepestOverlap, deepestOverlap(position, radius.head(present), scene.planes));
        }
    }
    outcome.complete = present == n;
    outcome.position.resize(3, engine.particleCount());
    for (int i = 0; i < engine.particleCount(); ++i)
        outcome.position.col(i) = engine.position(i);
    return outcome;
}

// runs the scene `repetitions` times in the engine; the physics from the first run, the median time
template <typename Engine>
ContactRow measure(const ContactScene &contact, const QString &engineName, int repetitions, bool &repeatable)
{
    const core::SceneDesc &scene = contact.scene;
    const int n = static_cast<int>(scene.particles.size());
    const double threshold = settleThreshold(scene);
    std::vector<double> msPerStep;
    Outcome first;
    for (int r = 0; r < repetitions; ++r) {
        Outcome outcome = runOnce<Engine>(contact, threshold);
        msPerStep.push_back(1000.0 * outcome.stepSeconds / std::max(1, outcome.steps));
        if (r == 0)
            first = std::move(outcome);
        else if (outcome.position.cols() != first.position.cols() || outcome.position != first.position)
            repeatable = false;
    }

    ContactRow row;
    row.scene = QString::fromStdString(contact.name);
    row.engine = engineName;
    row.balls = n;
    row.substeps = scene.settings.substeps;
    row.duration = contact.duration;
    row.blewUp = first.blewUp;
    row.kineticEnd = first.kineticEnd;
    row.kineticPeak = first.kineticPeak;
    row.kineticThreshold = threshold;
    row.settled = !first.blewUp && first.complete && first.lastUnsettled <= contact.duration - endWindow(contact) + 1e-9;
    if (row.settled)
        row.settleSeconds = first.lastUnsettled;
    const int present = static_cast<int>(first.position.cols());
    const Eigen::VectorXd radius = radiiOf(scene, present);
    row.overlapMm = 1000.0 * first.deepestOverlap;
    row.msPerStep = median(msPerStep);

    // the stacks: how far the top ball, or the ball that moved most, ended from its start
    if (contact.check == ContactCheck::Column || contact.check == ContactCheck::Pyramid) {
        Eigen::Vector3d moved = Eigen::Vector3d::Zero();
        for (int i = 0; i < present; ++i) {
            const Eigen::Vector3d by = first.position.col(i) - scene.particles[static_cast<std::size_t>(i)].position;
            if ((contact.check == ContactCheck::Pyramid || i == n - 1) && by.norm() > moved.norm())
                moved = by;
        }
        if (first.blewUp || present < n)
            moved.setConstant(std::numeric_limits<double>::infinity());
        const Eigen::Vector3d down = scene.settings.gravity.normalized();
        row.movedMm = 1000.0 * moved.norm();
        row.movedDownMm = 1000.0 * moved.dot(down);
        row.movedAcrossMm = 1000.0 * (moved - moved.dot(down) * down).norm();
        row.stands = moved.norm() < kStandFraction * kBallRadius;
    }
    // the heap: its slope, about the axis it was poured along
    if (contact.check == ContactCheck::Heap && !first.blewUp) {
        const Eigen::Vector2d axis(scene.particles.front().position.x(), scene.particles.front().position.z());
        const Repose repose = reposeAngle(first.position, radius, axis);
        row.reposeFitDegrees = repose.fitDegrees;
        row.reposeConeDegrees = repose.coneDegrees;
        row.heapHeight = repose.height;
        row.heapBaseRadius = repose.baseRadius;
    }
    return row;
}

QString optionalNumber(const std::optional<double> &value, int precision)
{
    return value ? QString::number(*value, 'f', precision) : QString();
}

QString formatMs(double ms)
{
    return QString::number(ms, 'g', 4);
}

// one line per measured row, as it is measured
void printRow(const ContactRow &row, QTextStream &out)
{
    QString what;
    if (row.stands)
        what = QStringLiteral("%1 (moved %2 mm: %3 down, %4 across)")
                   .arg(*row.stands ? QStringLiteral("stands") : QStringLiteral("does NOT stand"))
                   .arg(*row.movedMm, 0, 'g', 3)
                   .arg(*row.movedDownMm, 0, 'g', 3)
                   .arg(*row.movedAcrossMm, 0, 'g', 3);
    else if (row.settled)
        what = QStringLiteral("settled at %1 s").arg(*row.settleSeconds, 0, 'f', 2);
    else
        what = QStringLiteral("not settled in %1 s (up to %2 J in the last second, threshold %3 J)")
                   .arg(row.duration)
                   .arg(row.kineticPeak, 0, 'g', 3)
                   .arg(row.kineticThreshold, 0, 'g', 3);
    if (row.reposeConeDegrees)
        what += QStringLiteral(", repose %1 (fit) %2 (cone) deg, %3 m high, base radius %4 m")
                    .arg(row.reposeFitDegrees ? QString::number(*row.reposeFitDegrees, 'f', 1)
                                              : QStringLiteral("none"))
                    .arg(*row.reposeConeDegrees, 0, 'f', 1)
                    .arg(*row.heapHeight, 0, 'f', 2)
                    .arg(*row.heapBaseRadius, 0, 'f', 2);
    out << QStringLiteral("  %1 %2 %3 balls  %4  overlap %5 mm  %6 ms/step%7\n")
               .arg(row.scene, -10)
               .arg(row.engine, -13)
               .arg(row.balls, 5)
               .arg(what)
               .arg(row.overlapMm, 0, 'f', 3)
               .arg(formatMs(row.msPerStep))
               .arg(row.blewUp ? QStringLiteral("  BLEW UP") : QString());
    out.flush();
}

bool writeCsv(const QString &path, const std::vector<ContactRow> &rows, QTextStream &out)
{
    QSaveFile file(path);
    if (!file.open(QIODevice::WriteOnly | QIODevice::Text)) {
        out << "springlab-bench: cannot write " << path << '\n';
        return false;
    }
    QTextStream csv(&file);
    csv << "scene,engine,balls,substeps,duration_s,stands,moved_mm,settled,settle_s,kinetic_end_J,"
           "kinetic_peak_J,kinetic_threshold_J,overlap_mm,repose_fit_deg,repose_cone_deg,ms_per_step\n";
    const auto yesNo = [](bool value) { return value ? QStringLiteral("yes") : QStringLiteral("no"); };
    for (const ContactRow &row : rows)
        csv << row.scene << ',' << row.engine << ',' << row.balls << ',' << row.substeps << ','
            << QString::number(row.duration, 'g', 6) << ',' << (row.stands ? yesNo(*row.stands) : QString()) << ','
            << (row.movedMm ? QString::number(*row.movedMm, 'g', 6) : QString()) << ',' << yesNo(row.settled) << ','
            << optionalNumber(row.settleSeconds, 2) << ',' << QString::number(row.kineticEnd, 'g', 6) << ','
            << QString::number(row.kineticPeak, 'g', 6) << ','
            << QString::number(row.kineticThreshold, 'g', 6) << ',' << QString::number(row.overlapMm, 'g', 6) << ','
            << optionalNumber(row.reposeFitDegrees, 2) << ',' << optionalNumber(row.reposeConeDegrees, 2) << ','
            << QString::number(row.msPerStep, 'g', 6) << '\n';
    csv.flush();
    if (!file.commit()) {
        out << "springlab-bench: cannot write " << path << '\n';
        return false;
    }
    return true;
}

#ifdef SPRINGLAB_HAVE_BULLET
// whether the engine held the scene: the stacks stand, the piles and the heap settle
bool holds(const ContactRow &row)
{
    return row.stands ? *row.stands : row.settled;
}

const ContactRow *findRow(const std::vector<ContactRow> &rows, const QString &scene, const QString &engine)
{
    for (const ContactRow &row : rows)
        if (row.scene == scene && row.engine == engine)
            return &row;
    return nullptr;
}

QString verdict(bool met)
{
    return met ? QStringLiteral("met") : QStringLiteral("NOT met");
}

// the target, scene by scene: the core holds every stack Bullet holds, at no more than
// Bullet's cost per step
void printTargets(const std::vector<ContactRow> &rows, const std::vector<ContactScene> &scenes, QTextStream &out)
{
    out << "\ntarget (issue 21, \"A benchmark beside a peer\"): springlab holds every stack bullet holds, at no "
           "more than bullet's cost per step:\n";
    for (const ContactScene &contact : scenes)
        for (const QString &peerName : {QStringLiteral("bullet"), QStringLiteral("bullet-norot")}) {
            const QString name = QString::fromStdString(contact.name);
            const ContactRow *core = findRow(rows, name, QStringLiteral("springlab"));
            const ContactRow *peer = findRow(rows, name, peerName);
            if (!core || !peer)
                continue;
            const QString held = core->stands ? QStringLiteral("stands:") : QStringLiteral("settles:");
            const double ratio = core->msPerStep / peer->msPerStep;
            out << QStringLiteral("  %1 vs %2 %3 springlab %4, peer %5  %6;  cost %7 / %8 ms = %9x  %10\n")
                       .arg(name, -10)
                       .arg(peerName, -12)
                       .arg(held, -8)
                       .arg(holds(*core) ? QStringLiteral("yes") : QStringLiteral("no "))
                       .arg(holds(*peer) ? QStringLiteral("yes") : QStringLiteral("no "))
                       .arg(verdict(holds(*core) || !holds(*peer)))
                       .arg(formatMs(core->msPerStep), formatMs(peer->msPerStep))
                       .arg(ratio, 0, 'f', 2)
                       .arg(verdict(ratio <= 1.0));
        }
}

#else
void printTargets(const std::vector<ContactRow> &, const std::vector<ContactScene> &, QTextStream &out)
{
    out << "\ntarget (issue 21, \"A benchmark beside a peer\"): not measured, bullet: " << kBulletNotBuilt << '\n';
}
#endif

}  // namespace

int runContacts(const ContactsOptions &options, QTextStream &out)
{
    const std::optional<QDir> folder = outputFolder(options.outDir, out);
    if (!folder)
        return 1;
    const QDir &dir = *folder;
    QElapsedTimer wall;
    wall.start();
    const Plan plan = planFor(options.quick);
    const int restoreThreads = core::threadCount();
    core::setThreadCount(1);

    const QString machine = machineDescription();
    const QString loadStart = loadText();
    out << "machine: " << machine << '\n';
    out << "load average at the start: " << loadStart << '\n';
    if (options.quick)
        out << "contacts --quick: a smoke test; short runs, a small heap\n";
    out << QStringLiteral("timing: CPU time of the calls that step, per step of h = %1 s, median of %2 runs "
                          "of each scene; springlab on 1 thread\n")
               .arg(kContactTimeStep)
               .arg(plan.repetitions);
    out << QStringLiteral("every ball r = %1 m, e = %2, mu = %3 (static and kinetic); settled: kinetic energy "
                          "below 1e-3 N m g r all through the last second; stands: moved less than 1% of r; "
                          "overlap: the deepest over the last second\n")
               .arg(kBallRadius)
               .arg(kContactRestitution)
               .arg(kContactFriction);
#ifdef SPRINGLAB_HAVE_BULLET
    out << "bullet: " << QString::fromStdString(BulletSpheres::description()) << '\n';
    out << "bullet-norot: the same, each sphere's rotation locked (setAngularFactor(0)), as the core's particles\n";
#else
    out << "bullet: " << kBulletNotBuilt << '\n';
#endif
    out << "note: bullet's spheres rotate and roll (no rolling friction); springlab's particles do not rotate, "
           "so friction stops a ball as it would a sliding block (bullet-norot: neither do its spheres). "
           "Kinetic energies are translational only.\n";
    out.flush();

    const std::vector<ContactScene> scenes{
        contactColumn(plan.columnSeconds),
        contactPyramid(plan.pyramidSeconds),
        contactPile(plan.pileBalls, 1, plan.pileSeconds),
        contactPile(plan.pileBalls, plan.pileSubsteps, plan.pileSeconds),
        contactHeap(plan.heapBalls, plan.heapSeconds),
    };
    std::vector<ContactRow> rows;
    bool repeatable = true;
    bool blewUp = false;
    out << '\n';
    for (const ContactScene &contact : scenes) {
        rows.push_back(measure<SpringlabBalls>(contact, QStringLiteral("springlab"), plan.repetitions, repeatable));
        printRow(rows.back(), out);
        blewUp = blewUp || rows.back().blewUp;
#ifdef SPRINGLAB_HAVE_BULLET
        rows.push_back(measure<BulletBalls<true>>(contact, QStringLiteral("bullet"), plan.repetitions, repeatable));
        printRow(rows.back(), out);
        rows.push_back(
            measure<BulletBalls<false>>(contact, QStringLiteral("bullet-norot"), plan.repetitions, repeatable));
        printRow(rows.back(), out);
#endif
    }
    core::setThreadCount(restoreThreads);
    out << (repeatable ? "every repetition ended on the same positions as the first, to the bit\n"
                       : "REPEATED runs ended on different positions: the figures are of the first run\n");
    printTargets(rows, scenes, out);

    // the CSV and the picture
    const QString csvPath = dir.filePath(QStringLiteral("contacts.csv"));
    if (!writeCsv(csvPath, rows, out))
        return 1;
    const QString note =
        QStringLiteral("%1; load average %2 at the start. CPU time per step of h = 0.01 s (all its sub-steps), "
                       "median of %3 runs; springlab on 1 thread. Bullet's spheres rotate and roll (no rolling "
                       "friction); Springlab's particles do not rotate, nor do bullet-norot's (angular factor 0). "
                       "Stack: the column's top ball, or the pyramid's ball that moved most, at the end; stands "
                       "within 1% of r. Settled: kinetic energy below 1e-3 N m g r from the time given to the end, "
                       "and all through the last second. Overlap: the deepest of two balls or a ball and a plane "
                       "over the last second.")
            .arg(machine)
            .arg(loadStart.section(QLatin1Char(' '), 0, 0))
            .arg(plan.repetitions);
    const QImage plot =
        drawContacts(QStringLiteral("Contacts beside Bullet's rigid spheres: r = 5 cm, e = 0.5, \u03BC = 0.5, h = 0.01 s"),
                     rows, note);
    const QString plotPath = dir.filePath(QStringLiteral("contacts.png"));
    if (!plot.save(plotPath)) {
        out << "springlab-bench: cannot write " << plotPath << '\n';
        return 1;
    }
    out << QStringLiteral("\nwrote %1 rows to contacts.csv, and contacts.png\n").arg(rows.size());
    out << QStringLiteral("run time: %1 s wall; load average at the end: %2\n")
               .arg(wall.elapsed() / 1000.0, 0, 'f', 0)
               .arg(loadText());
    if (blewUp) {
        out << "springlab-bench: the core blew up on a scene\n";
        return 1;
    }
    return 0;
}

}  // namespace bench
