// What must hold in every contact scene, whatever it is: seeded random scenes of 2 to 30 balls of
// mixed sizes and masses (in rows, racks and stacks, on a floor, between walls, on a table), with
// restitution and friction anywhere in [0, 1], speeds from 1 cm/s to 200 m/s, every integrator and
// both contact solvers. Each run is checked at every step:
//   - the energy the integrator keeps (keptEnergy: the total energy, kinetic and gravitational,
//     for the Hermite schemes; with the Euler schemes' term in ½ h m g·v) never rises by more than
//     kEnergySlack of the scene's energy scale;
//   - where no collider acts and nothing is pinned, the momentum is kept (gravity's impulse aside);
//   - no two balls end a step deep inside each other, and a row struck along its line keeps its
//     order (in the on-demand function: not yet held everywhere);
//   - nothing ends a step inside a collider by more than kColliderSlack.
// A failure names its seed and prints the least scene that still breaks the same invariant (balls
// taken out one at a time) as a scene file; SPRINGLAB_INVARIANT_SEED reruns one seed, and
// SPRINGLAB_INVARIANT_SCENES sets how many scenes a run tries (1000 in the test command;
// tools/long_tests.sh runs 10⁵ and 10⁴).

#include "core/contacts/colliders.h"
#include "core/contacts/particle_path.h"
#include "core/integrators/integrator.h"
#include "core/io/scene_file.h"
#include "core/model/diagnostics.h"
#include "core/model/generators.h"
#include "core/model/validate.h"
#include "scene_builder.h"

#include <QtTest>

#include <algorithm>
#include <cmath>
#include <optional>
#include <random>
#include <sstream>
#include <vector>

namespace {

// the energy a step may gain, as a share of the scene's energy scale (its kinetic energy and the
// work its weight can do across the scene's height): far below what a user could see, and above
// the round-off of sums of a few dozen terms in doubles
constexpr double kEnergySlack = 1e-6;
// how deep two balls may end a step inside each other, as a share of their contact distance: the
// resting solve leaves stacked balls overlapping by what a sub-step's gravity adds, far less
constexpr double kPairSlack = 0.2;
// how deep a particle may end inside a collider, as a share of its radius: the resting solver
// leaves a resting particle sunk by what gravity adds in a sub-step, g h², at most
constexpr double kColliderSlack = 0.02;

struct RandomScene {
    core::SceneDesc scene;
    int steps = 0;
    std::string shape;  // what the generator made, for the failure message
    bool alongX = false;  // a row struck along its line with nothing else moving it: order along x kept
};

core::Integrator anyIntegrator(std::mt19937 &random)
{
    const core::Integrator all[] = {core::Integrator::SymplecticEuler, core::Integrator::ExplicitEuler,
                                    core::Integrator::VelocityVerlet,  core::Integrator::Rk4,
                                    core::Integrator::ImplicitEuler,   core::Integrator::Xpbd};
    return all[random() % std::size(all)];
}

double uniform(std::mt19937 &random, double lo, double hi)
{
    return std::uniform_real_distribution<double>(lo, hi)(random);
}

// a speed from 1 cm/s to 200 m/s, spread evenly over its decades
double anySpeed(std::mt19937 &random)
{
    return std::pow(10.0, uniform(random, -2.0, std::log10(200.0)));
}

Eigen::Vector3d anyDirection(std::mt19937 &random)
{
    Eigen::Vector3d d(uniform(random, -1.0, 1.0), uniform(random, -1.0, 1.0), uniform(random, -1.0, 1.0));
    return d.norm() > 1e-3 ? Eigen::Vector3d(d.normalized()) : Eigen::Vector3d::UnitX();
}

// which scenes a run draws: with or without gravity, and whether the handout's passes may be the
// solver (see the test functions)
struct Draw {
    bool gravity = false;
    bool handout = false;
    bool through = false;  // check that nothing ends inside another and rows keep their order
};

RandomScene makeScene(std::uint32_t seed, const Draw &draw)
{
    std::mt19937 random(seed);
    RandomScene made;
    core::SceneDesc &scene = made.scene;
    scene.name = "invariants";
    core::Settings &s = scene.settings;
    s.integrator = anyIntegrator(random);
    const bool handout = random() % 4 == 0;
    s.contactSolver = handout && draw.handout ? core::ContactSolver::Handout : core::ContactSolver::Iterative;
    s.restitution = random() % 4 == 0 ? 1.0 : uniform(random, 0.0, 1.0);
    s.friction = random() % 3 == 0 ? 0.0 : uniform(random, 0.0, 1.0);
    s.timeStep = random() % 2 == 0 ? 0.01 : 0.001;
    s.substeps = 1 + int(random() % 4);
    const bool gravity = random() % 4 != 0 && draw.gravity;
    s.gravity = gravity ? Eigen::Vector3d(0.0, -9.81, 0.0) : Eigen::Vector3d::Zero();

    const int count = 2 + int(random() % 29);
    const double radius = uniform(random, 0.02, 0.1);
    const auto ball = [&](const Eigen::Vector3d &at) {
        const double r = radius * (random() % 3 == 0 ? uniform(random, 0.5, 1.5) : 1.0);
        const double mass = random() % 3 == 0 ? uniform(random, 0.1, 10.0) : 1.0;
        scene.particles.push_back(test::particle(at, Eigen::Vector3d::Zero(), mass, r));
    };
    // the arrangement: a row along x, a rack (a triangle), a stack, or a loose cloud
    switch (random() % 4) {
    case 0:
        made.shape = "row";
        for (int k = 0; k < count; ++k)
            ball(Eigen::Vector3d(3.0 * radius * k, 1.6 * radius, 0.0));
        break;
    case 1:
        made.shape = "rack";
        for (int row = 0, k = 0; k < count; ++row)
            for (int c = 0; c <= row && k < count; ++c, ++k)
                ball(Eigen::Vector3d(3.2 * radius * row, 1.6 * radius, 3.2 * radius * (c - 0.5 * row)));
        break;
    case 2:
        made.shape = "stack";
        for (int k = 0; k < count; ++k)
            ball(Eigen::Vector3d(0.0, 1.6 * radius + 3.2 * radius * k, 0.0));
        break;
    default:
        made.shape = "cloud";
        for (int k = 0; k < count; ++k)
            ball(Eigen::Vector3d(uniform(random, -0.5, 0.5), uniform(random, 0.2, 1.0), uniform(random, -0.5, 0.5)));
        break;
    }
    // a striker, or every ball thrown
    if (random() % 2 == 0) {
        made.shape += ", struck";
        made.alongX = made.shape == "row, struck" && !gravity;
        const double speed = anySpeed(random);
        scene.particles.front().velocity = speed * Eigen::Vector3d(1.0, 0.0, 0.0);
        scene.particles.front().position.x() -= 4.0 * radius;
    } else {
        made.shape += ", thrown";
        for (core::ParticleDesc &p : scene.particles)
            p.velocity = anySpeed(random) * anyDirection(random);
    }

    // no two balls overlapping at the start (a cloud may have drawn them so, or the striker been
    // drawn back into one): the later moved up above the earlier, and looked at again against all
    // the earlier ones, since the move may have put it into one it had cleared (it only rises, so
    // this ends)
    bool lifted = false;
    for (std::size_t i = 0; i < scene.particles.size(); ++i)
        for (bool moved = true; moved;) {
            moved = false;
            for (std::size_t j = 0; j < i; ++j) {
                core::ParticleDesc &p = scene.particles[i];
                const core::ParticleDesc &q = scene.particles[j];
                if ((p.position - q.position).norm() < 1.01 * (p.radius + q.radius)) {
                    p.position.y() = std::max(p.position.y(), q.position.y() + 1.01 * (p.radius + q.radius));
                    moved = lifted = true;
                }
            }
        }
    // a ball lifted off a row is off its line: the row's balls may pass under it untouched (seed
    // 5953: the last ball of a row was lifted clear of its neighbour, which then passed under it
    // 2.5 mm clear), so the order along x is no longer one they must keep
    if (lifted)
        made.alongX = false;

    // the colliders: a floor (always under gravity), walls beyond the balls, a table clear of them
    s.planeCollisions = gravity || random() % 2 == 0;
    if (s.planeCollisions) {
        scene.planes.push_back(core::floorPlane());
        if (random() % 2 == 0) {
            made.shape += ", walls";
            double lo = 0.0, hi = 0.0;
            for (const core::ParticleDesc &p : scene.particles) {
                lo = std::min(lo, p.position.x() - p.radius);
                hi = std::max(hi, p.position.x() + p.radius);
            }
            scene.planes.push_back(core::PlaneDesc{Eigen::Vector3d(1.0, 0.0, 0.0), lo - 0.2});
            scene.planes.push_back(core::PlaneDesc{Eigen::Vector3d(-1.0, 0.0, 0.0), -(hi + 0.2)});
        }
        // a 0.8 m square table at 0.6 m, where no ball starts in it
        const bool clear = std::none_of(scene.particles.begin(), scene.particles.end(), [](const core::ParticleDesc &p) {
            return std::abs(p.position.y() - 0.6) < p.radius && std::abs(p.position.x()) < 0.4 + p.radius &&
                   std::abs(p.position.z()) < 0.4 + p.radius;
        });
        if (random() % 3 == 0 && clear) {
            made.shape += ", table";
            core::PlaneDesc table{Eigen::Vector3d(0.0, 1.0, 0.0), 0.6};
            table.size = Eigen::Vector2d(0.8, 0.8);
            table.centre = Eigen::Vector3d(0.0, 0.6, 0.0);
            table.axis = Eigen::Vector3d(1.0, 0.0, 0.0);
            scene.planes.push_back(table);
        }
        for (core::PlaneDesc &plane : scene.planes)
            plane.friction = random() % 2 == 0 ? std::optional<double>() : std::optional<double>(uniform(random, 0.0, 1.0));
    }
    made.steps = static_cast<int>(std::lround(0.5 / s.timeStep));
    return made;
}

double energyScale(const core::Model &model, const core::State &state)
{
    const core::Energies e = core::energies(model, state);
    double weight = 0.0;
    for (int i : model.freeParticles)
        weight += model.gravity.norm() / model.invMass[i];
    return e.kinetic + weight * 2.0 + 1e-9;  // 2 m: the most a scene here rises or falls
}

double totalEnergy(const core::Model &model, const core::State &state)
{
    const core::Energies e = core::energies(model, state);
    return e.kinetic + e.gravitational + e.spring;
}

// what the integrator keeps in flight under gravity. The Hermite schemes (velocity Verlet, RK4)
// are exact under a constant force and keep the energy E itself. The Euler schemes keep
// Q = E ± ½ h Σ m g·v instead (+ for the kick-drift ones, symplectic and implicit Euler and xpbd;
// − for explicit Euler), h the sub-step: E falls by ½ m g² h² a sub-step of free flight under
// symplectic Euler (rises, under explicit Euler) while Q holds, and a ball's height is set by Q.
// E differs from Q by at most ½ h m |g| |v|, so a bounce, which turns v, moves E by up to
// h m |g| |v| while keeping the height: Q is what must never rise (docs/physics.md, "Energy")
double keptEnergy(const core::Model &model, const core::State &state)
{
    const core::PathShape shape = core::pathShape(model.integrator);
    const double sign = shape == core::PathShape::KickDrift ? 1.0 : shape == core::PathShape::DriftKick ? -1.0 : 0.0;
    double energy = totalEnergy(model, state);
    for (int i : model.freeParticles)
        energy += sign * 0.5 * model.subStep() * model.gravity.dot(state.velocity.col(i)) / model.invMass[i];
    return energy;
}

// whether a point lies over a rectangle's outline (its projection inside it)
bool overOutline(const core::Collider &rectangle, const Eigen::Vector3d &point)
{
    const Eigen::Vector3d local = point - rectangle.centre;
    return std::abs(rectangle.axisU.dot(local)) <= rectangle.halfWidth &&
           std::abs(rectangle.axisV.dot(local)) <= rectangle.halfHeight;
}

// where the straight line from `from` along `direction` (for a length of at most 1 of it) meets
// the collider's plane, if it does
std::optional<Eigen::Vector3d> meetsPlane(const core::Collider &collider, const Eigen::Vector3d &from,
                                          const Eigen::Vector3d &direction)
{
    const double height = collider.normal.dot(from) - collider.offset;
    const double rate = collider.normal.dot(direction);
    if (rate == 0.0)
        return std::nullopt;
    const double at = -height / rate;
    if (!(at >= 0.0 && at <= 1.0))
        return std::nullopt;
    return from + at * direction;
}

// the side of a collider a ball must still be on after a step of length h from `before` (moving at
// vBefore) to `after` (at vAfter). A plane's side never changes; a rectangle's (a table top) may: a
// ball beside it can pass round its edge to the other side without touching it. The check sees
// the step's ends only, so the path is stood for by three straight lines, each of which bends from
// it by at most g h² / 2, far less than a radius: the step's first leg (from `before` along
// vBefore), its last (back from `after` along -vAfter), and the chord between its ends. A ball that
// changed sides went round the edge where the first or the last leg meets the plane outside the
// outline (the last after a bounce off a wall: seeds 19781, 23626, 61422), or, where neither meets
// it within the step, where the chord does; else it went through the sheet
double sideToKeep(const core::Collider &collider, const Eigen::Vector3d &before, const Eigen::Vector3d &after,
                  const Eigen::Vector3d &vBefore, const Eigen::Vector3d &vAfter, double h)
{
    const double side = core::sideOf(collider, before);
    if (!collider.bounded || core::sideOf(collider, after) == side)
        return side;
    const std::optional<Eigen::Vector3d> first = meetsPlane(collider, before, h * vBefore);
    const std::optional<Eigen::Vector3d> last = meetsPlane(collider, after, -h * vAfter);
    bool round = false;
    if (first || last) {
        round = (first && !overOutline(collider, *first)) || (last && !overOutline(collider, *last));
    } else if (const std::optional<Eigen::Vector3d> chord = meetsPlane(collider, before, after - before)) {
        round = !overOutline(collider, *chord);
    }
    return round ? core::sideOf(collider, after) : side;
}

// a broken invariant: which (for the minimiser: a smaller scene must break the same one), at which
// step, and the whole message
struct Failure {
    QString kind;
    int step = -1;
    QString message;
    bool failed() const { return step >= 0; }
};

// the first invariant the scene breaks, or none
Failure check(std::uint32_t seed, const RandomScene &made, const Draw &draw)
{
    const core::SceneDesc &scene = made.scene;
    if (const auto problem = core::findProblem(scene))
        return {QStringLiteral("invalid"), 0,
                QStringLiteral("seed %1 made a scene the validator refuses: %2").arg(seed).arg(QString::fromStdString(problem->message))};
    test::Sim sim = test::compile(scene);
    const core::Model &model = *sim.model;
    const double scale = energyScale(model, sim.state);
    double highest = keptEnergy(model, sim.state);
    const bool free = model.colliders.empty();
    const Eigen::Vector3d momentum0 = core::momentum(model, sim.state);
    double mass = 0.0;
    for (int i : model.freeParticles)
        mass += 1.0 / model.invMass[i];

    const auto describe = [&](const char *kind, const QString &what, int step) {
        std::ostringstream text;
        text << "seed " << seed << " (" << made.shape << ", " << model.particleCount() << " balls, "
             << core::integratorName(model.integrator) << ", "
             << (scene.settings.contactSolver == core::ContactSolver::Handout ? "handout" : "iterative")
             << " solver, e " << model.restitution << ", mu " << scene.settings.friction << ", h "
             << scene.settings.timeStep << " s x " << model.substeps << (model.gravity.norm() > 0.0 ? ", gravity" : ", no gravity")
             << "), step " << step << ": ";
        return Failure{QLatin1String(kind), step, QString::fromStdString(text.str()) + what};
    };

    for (int step = 0; step < made.steps; ++step) {
        const Eigen::Matrix3Xd before = sim.state.position;
        const Eigen::Matrix3Xd velocityBefore = sim.state.velocity;
        if (!sim.step())
            return describe("blew up", QStringLiteral("blew up"), step);
        const core::State &state = sim.state;

        // energy
        const double energy = keptEnergy(model, state);
        const double allowed = highest + kEnergySlack * scale;
        if (energy > allowed)
            return describe("energy", QStringLiteral("the energy rose from %1 J to %2 J (slack %3 J)")
                                .arg(highest, 0, 'g', 12).arg(energy, 0, 'g', 12).arg(allowed - highest), step);
        highest = std::max(highest, energy);

        // momentum, where nothing else acts: gravity's impulse m g t aside
        if (free) {
            const Eigen::Vector3d expected = momentum0 + mass * model.gravity * state.time;
            const Eigen::Vector3d got = core::momentum(model, state);
            // (round-off of a few dozen impulses a step, summed over the run)
            if ((got - expected).norm() > 1e-6 * (1.0 + momentum0.norm() + mass * model.gravity.norm() * state.time))
                return describe("momentum", QStringLiteral("the momentum moved by %1 N s").arg((got - expected).norm()), step);
        }

        // nothing through anything: no pair ends a step deep inside each other, and a row struck
        // along its line (all its motion along x) keeps its order along x
        for (int i = 0; draw.through && i < model.particleCount(); ++i)
            for (int j = i + 1; j < model.particleCount(); ++j) {
                const double contact = model.radius[i] + model.radius[j];
                const double distance = (state.position.col(i) - state.position.col(j)).norm();
                if (distance < (1.0 - kPairSlack) * contact)
                    return describe("overlap", QStringLiteral("balls %1 and %2 end %3 m inside each other").arg(i).arg(j).arg(contact - distance), step);
            }
        if (draw.through && made.alongX)
            for (int i = 0; i + 1 < model.particleCount(); ++i)
                if (!(state.position(0, i) < state.position(0, i + 1)))
                    return describe("order", QStringLiteral("balls %1 and %2 changed places along the row").arg(i).arg(i + 1), step);

        // nothing inside a collider
        for (int i : model.freeParticles)
            for (const core::Collider &collider : model.colliders) {
                const double side = sideToKeep(collider, before.col(i), state.position.col(i), velocityBefore.col(i),
                                               state.velocity.col(i), model.timeStep);
                const core::Separation s = core::separation(collider, state.position.col(i), side);
                if (s.distance < model.radius[i] * (1.0 - kColliderSlack) &&
                    core::separation(collider, before.col(i), side).distance >= model.radius[i] * (1.0 - kColliderSlack))
                    return describe("collider", QStringLiteral("ball %1 ended %2 m inside a collider").arg(i).arg(model.radius[i] - s.distance), step);
            }
    }
    return {};
}

// the failing scene cut down to what still breaks the same invariant: its balls taken out one at a
// time while it does, and run only to the step it breaks at. Printed as a scene file with the
// failure, so that it can be opened in the editor or run by springlab-sim
RandomScene minimal(std::uint32_t seed, RandomScene made, const Draw &draw, Failure &failure)
{
    made.steps = failure.step + 1;
    for (std::size_t k = made.scene.particles.size(); k-- > 0 && made.scene.particles.size() > 1;) {
        RandomScene fewer = made;
        fewer.scene.particles.erase(fewer.scene.particles.begin() + std::ptrdiff_t(k));
        const Failure still = check(seed, fewer, draw);
        if (still.failed() && still.kind == failure.kind) {
            made = std::move(fewer);
            made.steps = still.step + 1;
            failure = still;
        }
    }
    return made;
}

// runs the scenes of these seeds and returns the failures, each also printed with the least scene
// that still breaks the same invariant
QStringList runSeeds(const Draw &draw, std::uint32_t first, std::uint32_t count)
{
    QStringList failures;
    for (std::uint32_t seed = first; seed < first + count; ++seed) {
        const RandomScene made = makeScene(seed, draw);
        Failure failure = check(seed, made, draw);
        if (!failure.failed())
            continue;
        const RandomScene least = minimal(seed, made, draw, failure);
        qWarning("%s\nthe least scene that breaks it (%d steps):\n%s", qPrintable(failure.message), least.steps,
                 io::sceneToJson(least.scene).constData());
        failures << failure.message;
    }
    return failures;
}

// runs `scenes` seeded scenes (SPRINGLAB_INVARIANT_SCENES, or one: SPRINGLAB_INVARIANT_SEED) and
// returns the failures, each also printed
QStringList runScenes(const Draw &draw, std::uint32_t scenes)
{
    const QByteArray only = qgetenv("SPRINGLAB_INVARIANT_SEED");
    const QByteArray count = qgetenv("SPRINGLAB_INVARIANT_SCENES");
    const std::uint32_t first = only.isEmpty() ? 1u : only.toUInt();
#if defined(SPRINGLAB_UNDER_SANITIZERS)
    // under the sanitizers a fifth of them: they look for memory faults, which the first scenes
    // meet as well as the rest, and each scene runs ten times slower (3.5 minutes for all three)
    scenes /= 5;
#endif
    const std::uint32_t n = !only.isEmpty() ? 1u : (count.isEmpty() ? scenes : count.toUInt());
    return runSeeds(draw, first, n);
}

}  // namespace

class TestContactInvariants : public QObject {
    Q_OBJECT
private slots:
    void theCheckTellsThroughFromRound();
    void impactsKeepTheInvariants();
    void underGravityKeepTheEnergy();
    void nothingPassesThroughAnything();
    void columnsOnceBrokenHold();
    void handoutPassesKeepTheInvariants();
};

void TestContactInvariants::theCheckTellsThroughFromRound()
{
    // the check of a table top itself, on steps made by hand (a 0.8 m table at y = 0.6, h = 0.01 s):
    // a ball through the middle of the top, straight, or through it then off a wall, must keep the
    // side it began on; one that passed round the edge, straight or off a wall, the side it came to
    core::PlaneDesc desc{Eigen::Vector3d(0.0, 1.0, 0.0), 0.6};
    desc.size = Eigen::Vector2d(0.8, 0.8);
    desc.centre = Eigen::Vector3d(0.0, 0.6, 0.0);
    desc.axis = Eigen::Vector3d(1.0, 0.0, 0.0);
    core::SceneDesc scene;
    scene.planes = {desc};
    scene.particles = {test::particle(Eigen::Vector3d::Zero())};
    const test::Sim sim = test::compile(scene);
    const core::Collider &table = sim.model->colliders.front();
    const double h = 0.01;
    const Eigen::Vector3d up(0.0, 40.0, 0.0);
    // straight up through the middle: below stays below
    QCOMPARE(sideToKeep(table, {0.0, 0.4, 0.0}, {0.0, 0.8, 0.0}, up, up, h), -1.0);
    // up through the top near its edge, then back off a wall at x = 0.45 (its last leg comes from the wall)
    QCOMPARE(sideToKeep(table, {0.3, 0.45, 0.0}, {0.3, 0.75, 0.0}, {15.0, 30.0, 0.0}, {-10.0, 30.0, 0.0}, h), -1.0);
    // up beside the edge and over the top in a straight line: above
    QCOMPARE(sideToKeep(table, {0.8, 0.3, 0.0}, {0.4, 0.7, 0.0}, {-40.0, 40.0, 0.0}, {-40.0, 40.0, 0.0}, h), 1.0);
    // up beside the edge, off a wall at x = 0.55 and back over the top (seed 61422's kind)
    QCOMPARE(sideToKeep(table, {0.26, 0.03, 0.0}, {0.37, 0.72, 0.0}, {66.0, 97.0, 0.0}, {-36.5, 67.0, 0.0}, h), 1.0);
}

void TestContactInvariants::impactsKeepTheInvariants()
{
    // the iterative solver's impacts: no gravity, so every contact is an impact or a graze, in
    // rows, racks, stacks and clouds, between walls and on a table, every integrator: energy,
    // momentum and the colliders (that nothing ends inside another ball is the next function's:
    // a few low-restitution rows still end a step overlapping, see below)
    const QStringList failures = runScenes(Draw{false, false, false}, 1000);
    QVERIFY2(failures.isEmpty(), qPrintable(QStringLiteral("%1 scenes broke an invariant:\n").arg(failures.size()) +
                                            failures.mid(0, 10).join(u'\n')));
}

void TestContactInvariants::underGravityKeepTheEnergy()
{
    // the iterative solver under gravity too, with resting contacts, piles and bounces side by
    // side: the energy the integrator keeps never rises, momentum where nothing else acts, and
    // nothing ends inside a collider
    const QStringList failures = runScenes(Draw{true, false, false}, 1000);
    QVERIFY2(failures.isEmpty(), qPrintable(QStringLiteral("%1 scenes broke an invariant:\n").arg(failures.size()) +
                                            failures.mid(0, 10).join(u'\n')));
}

void TestContactInvariants::nothingPassesThroughAnything()
{
    // every invariant, that nothing ends a step inside another ball and that a struck row keeps
    // its order included, with gravity or without (seed 4031, an elastic row struck at 155 m/s, had
    // a ball overtake another unseen until the impacts' search advanced along the pair's relative
    // path from where either path was last changed). The first 1000 seeds hold here, and all 10^5
    // in tools/long_tests.sh
    const QStringList failures = runScenes(Draw{true, false, true}, 1000);
    QVERIFY2(failures.isEmpty(), qPrintable(QStringLiteral("%1 scenes broke an invariant:\n").arg(failures.size()) +
                                            failures.mid(0, 10).join(u'\n')));
}

void TestContactInvariants::columnsOnceBrokenHold()
{
    // the seeds of 10^5 that once broke the last function, all columns of balls falling onto the
    // floor and onto each other: the solve pushed a column up out of its overlaps into a ball
    // falling onto it, a pair it had not gathered (balls 12 and 13 of seed 18445 ended 21% of their
    // contact distance inside each other). They hold since the solve looks again for what it
    // pushed together (gatherNewOverlaps)
    QStringList failures;
    for (std::uint32_t seed : {18445u, 38479u, 92021u})
        failures << runSeeds(Draw{true, false, true}, seed, 1);
    QVERIFY2(failures.isEmpty(), qPrintable(failures.join(u'\n')));
}

void TestContactInvariants::handoutPassesKeepTheInvariants()
{
    // the same with the handout's passes among the solvers drawn: not held, by design (they move a
    // ball out of what it sank into and reflect its velocity there, which gains energy and lets a
    // fast ball through; docs/physics.md). Run on demand (tools/long_tests.sh), never in CI
    if (!qEnvironmentVariableIsSet("SPRINGLAB_INVARIANT_HANDOUT"))
        QSKIP("the handout's passes break these by design: set SPRINGLAB_INVARIANT_HANDOUT=1 to run it");
    const QStringList failures = runScenes(Draw{true, true, true}, 1000);
    QVERIFY2(failures.isEmpty(), qPrintable(QStringLiteral("%1 scenes broke an invariant:\n").arg(failures.size()) +
                                            failures.mid(0, 10).join(u'\n')));
}

QTEST_APPLESS_MAIN(TestContactInvariants)
#include "test_contact_invariants.moc"
