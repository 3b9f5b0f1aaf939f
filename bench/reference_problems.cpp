// The exact answers used here, from the closed forms in core/integrators/reference.h:
//
// 1. oscillator: the free particle sits at (l0 + u(T), 0, 0), u the stretch of the exact solution.
// 2. bounce: the ball falls from rest, so before the first impact y = H - g t²/2. Impact n happens
//    at t_n (bounceImpactTime) and the ball leaves it at the speed that reaches the next apex,
//    v_n = √(2 g (apex_n - r)) (bounceApexHeight), so between impacts n and n + 1
//    y = r + v_n (t - t_n) - g (t - t_n)²/2.
// 3. head-on: the surfaces close at v1 - v2 across the gap, so contact is at t_c = gap / (v1 - v2);
//    before it each particle moves at its initial speed, after it at its speed after contact
//    (headOnSpeedAfter): x_i = x_i(0) + v_i t_c + v_i' (t - t_c).
//
// The contacts are instants in the exact solution but projections at the end of a sub-step in the
// simulation, so problems 2 and 3 measure how well each integrator lives with that, not its order.
#include "reference_problems.h"

#include "core/model/generators.h"
#include "core/integrators/reference.h"

#include <cassert>
#include <cmath>
#include <numbers>

namespace bench {

namespace {

// 1. damped spring–mass oscillator: the reference options, about three periods
ReferenceProblem oscillator()
{
    const core::OscillatorOptions options;
    ReferenceProblem problem{"oscillator", "1. damped spring-mass oscillator", core::makeOscillator(options), 2.0, {}};
    problem.scene.name = "reference 1: damped oscillator";
    Eigen::Matrix3Xd exact = Eigen::Matrix3Xd::Zero(3, 2);
    exact(0, 1) = options.restLength + core::oscillatorStretch(options, problem.duration);
    problem.exact = exact;
    return problem;
}

// 2. a ball bouncing on the floor, e = 0.8: the end time falls in the flight after the second impact
ReferenceProblem bounce()
{
    const core::BounceOptions options;
    ReferenceProblem problem{"bounce", "2. ball bouncing on a plane, e = 0.8", core::makeBounce(options), 1.5, {}};
    problem.scene.name = "reference 2: bouncing ball";
    const double t = problem.duration;
    double height = options.height - 0.5 * options.gravity * t * t;
    for (int impact = 0; core::bounceImpactTime(options, impact) <= t; ++impact) {
        const double since = t - core::bounceImpactTime(options, impact);
        const double leave = std::sqrt(2.0 * options.gravity * (core::bounceApexHeight(options, impact) - options.radius));
        height = options.radius + leave * since - 0.5 * options.gravity * since * since;
    }
    Eigen::Matrix3Xd exact = Eigen::Matrix3Xd::Zero(3, 1);
    exact(1, 0) = height;
    problem.exact = exact;
    return problem;
}

// 3. head-on collision, e = 1: a gap of π/10 m puts the contact at t = π/30 s, which no swept step
//    lands on exactly (a contact on a step boundary is found exactly or a step late depending on
//    the last bit of rounding, which would scatter the errors by orders of magnitude)
ReferenceProblem headOn()
{
    core::HeadOnOptions options;
    options.gap = std::numbers::pi / 10.0;
    ReferenceProblem problem{"head-on", "3. head-on collision of two particles, e = 1", core::makeHeadOn(options), 0.5,
                             {}};
    problem.scene.name = "reference 3: head-on collision";
    const double t = problem.duration;
    const double contact = options.gap / (options.speed1 - options.speed2);
    assert(contact < t);
    const double before[2] = {options.speed1, options.speed2};
    Eigen::Matrix3Xd exact = Eigen::Matrix3Xd::Zero(3, 2);
    for (int i = 0; i < 2; ++i)
        exact(0, i) = problem.scene.particles[static_cast<std::size_t>(i)].position.x() + before[i] * contact +
                      core::headOnSpeedAfter(options, i) * (t - contact);
    problem.exact = exact;
    return problem;
}

// 4. the 10-link chain released horizontally from its pinned end; no contacts, so that the
//    reference run is smooth and converges at RK4's order. Two sub-steps keep symplectic Euler
//    inside its limit (ω_max ≈ 2 √(k/m) = 200 rad/s, ω h = 1)
ReferenceProblem chain()
{
    ReferenceProblem problem{"chain", "4. 10-link chain released horizontally", core::makeChain({}), 1.0, {}};
    problem.scene.name = "reference 4: chain released horizontally";
    problem.scene.settings.substeps = 2;
    problem.scene.settings.planeCollisions = false;
    problem.scene.settings.particleCollisions = false;
    return problem;
}

// 5. a free 16 × 16 cloth dropped tilted onto the floor: its low edge lands first and the rest
//    slaps down after it. The springs are a tenth as stiff as the editor's default cloth
//    (ω_max ≤ √(2 Σk / m) ≈ 770 rad/s), so that explicit schemes are stable over a decade of
//    steps and RK4 at 1/1000 of the finest swept step stays affordable. Plane contacts on;
//    particle contacts off (the cloth's own particles never touch while it falls, and the
//    brute-force pair test would dominate the cost)
ReferenceProblem cloth()
{
    core::ClothOptions options;
    options.rows = options.cols = 16;
    options.structuralStiffness = 300.0;
    options.shearStiffness = 60.0;
    options.bendStiffness = 10.0;
    options.pinCorners = false;
    options.substeps = 8;  // ω_max h ≈ 1 for symplectic Euler in the editor
    ReferenceProblem problem{"cloth", "5. 16 x 16 cloth dropped tilted onto a plane", core::makeCloth(options), 0.25,
                             {}};
    core::SceneDesc &scene = problem.scene;
    scene.name = "reference 5: cloth dropped onto a plane";
    scene.settings.restitution = 0.5;
    scene.settings.planeCollisions = true;
    scene.settings.particleCollisions = false;
    scene.planes = {core::PlaneDesc{Eigen::Vector3d::UnitY(), 0.0}};

    // tilted 20° about the x axis, the lowest row 2 cm above the floor (surface to surface): it
    // lands at 0.06 s, the highest at about 0.24 s
    const double tilt = 20.0 * std::numbers::pi / 180.0;
    const double lowest = options.radius + 0.02;
    const double halfDepth = 0.5 * options.spacing * (options.rows - 1);
    for (core::ParticleDesc &particle : scene.particles) {
        const double z = particle.position.z();
        particle.position.y() = lowest + (z + halfDepth) * std::sin(tilt);
        particle.position.z() = z * std::cos(tilt);
    }
    return problem;
}

}  // namespace

std::vector<ReferenceProblem> referenceProblems()
{
    return {oscillator(), bounce(), headOn(), chain(), cloth()};
}

}  // namespace bench
