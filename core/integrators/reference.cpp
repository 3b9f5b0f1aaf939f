#include "core/integrators/reference.h"

#include <cmath>

namespace core {

namespace {

SceneDesc emptyReference(const char *name)
{
    SceneDesc scene;
    scene.name = name;
    scene.settings.gravity = Eigen::Vector3d::Zero();
    scene.settings.planeCollisions = false;
    scene.settings.particleCollisions = false;
    return scene;
}

// decay rate, damped angular frequency and the constants of u(t) = e^(-σt) (A cos ωt + B sin ωt)
struct Oscillation {
    double sigma, omega, a, b;
};

Oscillation oscillation(const OscillatorOptions &o)
{
    const double sigma = o.damping / (2.0 * o.mass);
    const double omega = std::sqrt(o.stiffness / o.mass - sigma * sigma);
    return {sigma, omega, o.displacement, (o.speed + sigma * o.displacement) / omega};
}

}  // namespace

SceneDesc makeOscillator(const OscillatorOptions &o)
{
    SceneDesc scene = emptyReference("damped oscillator");
    scene.particles = {ParticleDesc{Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero(), o.mass, 0.05, true},
                       ParticleDesc{Eigen::Vector3d(o.restLength + o.displacement, 0.0, 0.0),
                                    Eigen::Vector3d(o.speed, 0.0, 0.0), o.mass, 0.05, false}};
    scene.springs = {SpringDesc{0, 1, o.stiffness, o.damping, o.restLength}};
    return scene;
}

double oscillatorStretch(const OscillatorOptions &o, double t)
{
    const Oscillation s = oscillation(o);
    return std::exp(-s.sigma * t) * (s.a * std::cos(s.omega * t) + s.b * std::sin(s.omega * t));
}

double oscillatorRate(const OscillatorOptions &o, double t)
{
    const Oscillation s = oscillation(o);
    const double c = std::cos(s.omega * t), n = std::sin(s.omega * t);
    return std::exp(-s.sigma * t) * ((s.b * s.omega - s.sigma * s.a) * c - (s.a * s.omega + s.sigma * s.b) * n);
}

SceneDesc makeBounce(const BounceOptions &o)
{
    SceneDesc scene = emptyReference("bounce");
    scene.settings.gravity = Eigen::Vector3d(0.0, -o.gravity, 0.0);
    scene.settings.restitution = o.restitution;
    scene.settings.planeCollisions = true;
    scene.particles = {ParticleDesc{Eigen::Vector3d(0.0, o.height, 0.0), Eigen::Vector3d::Zero(), 1.0, o.radius, false}};
    scene.planes = {PlaneDesc{Eigen::Vector3d::UnitY(), 0.0}};
    return scene;
}

// the fall is √(2 d / g) with d = height - radius; each bounce leaves at e^n times the first
// impact speed and flies 2 v / g
double bounceImpactTime(const BounceOptions &o, int impact)
{
    const double fall = std::sqrt(2.0 * (o.height - o.radius) / o.gravity);
    const double speed = o.gravity * fall;
    double t = fall;
    for (int n = 1; n <= impact; ++n)
        t += 2.0 * std::pow(o.restitution, n) * speed / o.gravity;
    return t;
}

double bounceApexHeight(const BounceOptions &o, int bounce)
{
    return o.radius + std::pow(o.restitution, 2 * (bounce + 1)) * (o.height - o.radius);
}

SceneDesc makeHeadOn(const HeadOnOptions &o)
{
    SceneDesc scene = emptyReference("head-on collision");
    scene.settings.restitution = o.restitution;
    scene.settings.particleCollisions = true;
    const double half = o.radius + 0.5 * o.gap;
    scene.particles = {ParticleDesc{Eigen::Vector3d(-half, 0.0, 0.0), Eigen::Vector3d(o.speed1, 0.0, 0.0), o.mass1,
                                    o.radius, false},
                       ParticleDesc{Eigen::Vector3d(half, 0.0, 0.0), Eigen::Vector3d(o.speed2, 0.0, 0.0), o.mass2,
                                    o.radius, false}};
    return scene;
}

// one-dimensional impact: momentum kept, relative speed reversed and scaled by e
double headOnSpeedAfter(const HeadOnOptions &o, int particle)
{
    const double total = o.mass1 + o.mass2;
    const double centre = (o.mass1 * o.speed1 + o.mass2 * o.speed2) / total;
    const double relative = o.speed1 - o.speed2;
    return particle == 0 ? centre - o.restitution * o.mass2 / total * relative
                         : centre + o.restitution * o.mass1 / total * relative;
}

}  // namespace core
