// The rolling benchmark. Each scene is one ball (r = 5 cm, 170 g) on a plane, h = 0.01 s in 4
// sub-steps, e = 0, one friction coefficient (Bullet has one), read after a fixed time:
//
// - strike: struck at v0 = 2 m/s without spin on a floor of μ = 0.2: it slides until t =
//   2 v0 / (7 μ g) = 0.291 s, then rolls at 5 v0 / 7 = 1.429 m/s; read: when its point of contact
//   stopped slipping (to 0.1% of v0) and its speed at 1 s;
// - roll: from rest on a 20° slope of μ = 0.5 (tan θ ≤ 7 μ / 2): rolls at (5/7) g sin θ; read: its
//   speed down the slope at 1 s;
// - slide: from rest on a 45° slope of μ = 0.2 (tan θ > 7 μ / 2): slides at g (sin θ − μ cos θ) while
//   its spin rises at (5/2) μ g cos θ / r; read: speed and spin at 1 s;
// - backspin: struck at 1 m/s with a backspin of 3 v0 / r on μ = 0.3: rolls back at
//   (5 v0 − 2 r ω0) / 7 = −0.143 m/s; read: its speed at 2 s.
//
// Engines: springlab, the core with spin (its default); bullet, btRigidBody spheres that rotate,
// Bullet's defaults (no rolling friction), where libbullet-dev was found.
#include "rolling.h"

#include "bench_common.h"
#ifdef SPRINGLAB_HAVE_BULLET
#include "bullet_spheres.h"
#endif

#include "core/model/model.h"
#include "core/model/state.h"
#include "core/model/workspace.h"
#include "core/step.h"


#include <cmath>
#include <functional>
#include <memory>
#include <vector>

namespace bench {

namespace {

constexpr double kG = 9.81;
constexpr double kRadius = 0.05;

// what an engine shows of its one ball
struct Ball {
    Eigen::Vector3d position, velocity, spin;
};

// one quantity read off a run, and its closed form
struct Reading {
    QString name;
    double expected = 0.0;
    std::function<double(const Ball &, double time)> read;  // nullptr: the slip's end (strike)
};

struct Scene {
    QString name;
    core::SceneDesc desc;
    double seconds = 1.0;
    std::vector<Reading> readings;
};

core::SceneDesc ballOn(const Eigen::Vector3d &normal, double friction, const Eigen::Vector3d &velocity,
                       const Eigen::Vector3d &spin)
{
    core::SceneDesc scene;
    scene.name = "rolling";
    scene.settings.friction = friction;
    scene.settings.restitution = 0.0;
    scene.settings.substeps = 4;
    scene.settings.particleCollisions = false;
    scene.planes = {core::PlaneDesc{normal, 0.0}};
    core::ParticleDesc ball{kRadius * normal, velocity, 0.17, kRadius, false};
    ball.angularVelocity = spin;
    scene.particles = {ball};
    return scene;
}

std::vector<Scene> scenes()
{
    std::vector<Scene> all;
    const Eigen::Vector3d up(0.0, 1.0, 0.0);
    {
        const double v0 = 2.0, mu = 0.2;
        Scene s{QStringLiteral("strike"), ballOn(up, mu, Eigen::Vector3d(v0, 0, 0), Eigen::Vector3d::Zero()), 1.0, {}};
        s.readings.push_back({QStringLiteral("rolls from (s)"), 2.0 * v0 / (7.0 * mu * kG), nullptr});
        s.readings.push_back(
            {QStringLiteral("speed at 1 s (m/s)"), 5.0 * v0 / 7.0, [](const Ball &b, double) { return b.velocity.x(); }});
        all.push_back(s);
    }
    for (const auto &[name, degrees, mu] : {std::tuple{QStringLiteral("roll"), 20.0, 0.5},
                                            std::tuple{QStringLiteral("slide"), 45.0, 0.2}}) {
        const double angle = degrees * M_PI / 180.0;
        const Eigen::Vector3d normal(-std::sin(angle), std::cos(angle), 0.0);
        const Eigen::Vector3d down(std::cos(angle), std::sin(angle), 0.0);
        Scene s{name, ballOn(normal, mu, Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero()), 1.0, {}};
        const bool rolls = std::tan(angle) <= 3.5 * mu;
        const double a = rolls ? 5.0 / 7.0 * kG * std::sin(angle) : kG * (std::sin(angle) - mu * std::cos(angle));
        s.readings.push_back({QStringLiteral("speed at 1 s (m/s)"), a,
                              [down](const Ball &b, double) { return -b.velocity.dot(down); }});
        const double spin = rolls ? a / kRadius : 2.5 * mu * kG * std::cos(angle) / kRadius;
        s.readings.push_back(
            {QStringLiteral("spin at 1 s (rad/s)"), spin, [](const Ball &b, double) { return std::abs(b.spin.z()); }});
        all.push_back(s);
    }
    {
        const double v0 = 1.0, w0 = 3.0 * v0 / kRadius, mu = 0.3;
        Scene s{QStringLiteral("backspin"), ballOn(up, mu, Eigen::Vector3d(v0, 0, 0), Eigen::Vector3d(0, 0, w0)), 2.0, {}};
        s.readings.push_back({QStringLiteral("speed at 2 s (m/s)"), (5.0 * v0 - 2.0 * kRadius * w0) / 7.0,
                              [](const Ball &b, double) { return b.velocity.x(); }});
        all.push_back(s);
    }
    return all;
}

// runs a scene in an engine (`advance` steps it and returns the ball), reading every quantity; NaN
// where a run failed
std::vector<double> run(const Scene &scene, const std::function<std::optional<Ball>()> &advance)
{
    const double h = scene.desc.settings.timeStep;
    const int steps = int(std::lround(scene.seconds / h));
    double rolledAt = std::nan("");
    Ball last{};
    for (int s = 1; s <= steps; ++s) {
        const std::optional<Ball> ball = advance();
        if (!ball)
            return std::vector<double>(scene.readings.size(), std::nan(""));
        last = *ball;
        // the point of contact on a floor: v + ω × (−r y)
        const double slip = ball->velocity.x() + kRadius * ball->spin.z();
        if (std::isnan(rolledAt) && std::abs(slip) < 1e-3 * std::max(1.0, std::abs(ball->velocity.x())))
            rolledAt = s * h;
    }
    std::vector<double> values;
    for (const Reading &r : scene.readings)
        values.push_back(r.read ? r.read(last, scene.seconds) : rolledAt);
    return values;
}

QString number(double value)
{
    return std::isnan(value) ? QStringLiteral("-") : QString::number(value, 'g', 5);
}

}  // namespace

int runRolling(const QString &outDir, QTextStream &out)
{
    const RunClock clock;
    out << "rolling on " << machineDescription() << ", " << loadText() << '\n';
#ifdef SPRINGLAB_HAVE_BULLET
    out << "bullet: " << QString::fromStdString(BulletSpheres::description()) << '\n';
#else
    out << "bullet: not built (libbullet-dev was not found at configure time)\n";
#endif
    const std::optional<QDir> dir = outputFolder(outDir, out);
    if (!dir)
        return 1;
    QStringList lines{QStringLiteral("scene,quantity,closed_form,springlab,bullet,springlab_error,bullet_error")};
    out << QStringLiteral("%1 %2 %3 %4 %5\n")
               .arg(QStringLiteral("scene"), -9)
               .arg(QStringLiteral("quantity"), -20)
               .arg(QStringLiteral("closed form"), 12)
               .arg(QStringLiteral("springlab"), 12)
               .arg(QStringLiteral("bullet"), 12);
    bool failed = false;
    for (const Scene &scene : scenes()) {
        const std::shared_ptr<const core::Model> model = core::compileModel(scene.desc);
        core::State state = core::makeState(*model, scene.desc);
        core::Workspace work;
        const std::vector<double> core = run(scene, [&]() -> std::optional<Ball> {
            if (!core::step(*model, state, work))
                return std::nullopt;
            return Ball{state.position.col(0), state.velocity.col(0), state.angularVelocity.col(0)};
        });
        std::vector<double> bullet(scene.readings.size(), std::nan(""));
#ifdef SPRINGLAB_HAVE_BULLET
        BulletSpheres spheres(scene.desc, true);
        spheres.enter(1);
        bullet = run(scene, [&]() -> std::optional<Ball> {
            spheres.step();
            return Ball{spheres.position(0), spheres.velocity(0), spheres.angularVelocity(0)};
        });
#endif
        for (std::size_t k = 0; k < scene.readings.size(); ++k) {
            const Reading &r = scene.readings[k];
            const auto error = [&](double v) { return std::isnan(v) ? std::nan("") : v / r.expected - 1.0; };
            failed = failed || std::isnan(core[k]);
            lines << QStringLiteral("%1,%2,%3,%4,%5,%6,%7")
                         .arg(scene.name, r.name, number(r.expected), number(core[k]), number(bullet[k]),
                              number(error(core[k])), number(error(bullet[k])));
            out << QStringLiteral("%1 %2 %3 %4 %5\n")
                       .arg(scene.name, -9)
                       .arg(r.name, -20)
                       .arg(r.expected, 12, 'g', 5)
                       .arg(number(core[k]), 12)
                       .arg(number(bullet[k]), 12);
        }
    }
    if (!writeLines(*dir, QStringLiteral("rolling.csv"), lines, out))
        return 1;
    out << loadText() << ", " << clock.text() << '\n';
    return failed ? 1 : 0;
}

}  // namespace bench
