#include "contact_scenes.h"

#include "core/model/generators.h"

#include <cmath>
#include <cstdint>

namespace bench {

namespace {

constexpr double kBallMass = 1.0;       // kg, the stacks'
constexpr double kGrainMass = 0.1;      // kg, the pile's and the heap's
constexpr double kBoxHalfWidth = 0.5;   // m, the pile's box is 1 m wide
constexpr double kPourHeight = 2.0;     // m, the heap's pour point above the floor (above the heap's top)
constexpr double kPourSpeed = 2.0;      // m/s, downwards, as a ball leaves the pour point
constexpr double kPourInterval = 0.05;  // s between two balls: 2 m/s × 0.05 s = 0.1 m, so they never touch in flight

// a cheap deterministic generator for the jitter: next(range) is in [0, range)
struct Lcg {
    std::uint32_t seed;
    int operator()(std::uint32_t range)
    {
        seed = seed * 1664525u + 1013904223u;
        return static_cast<int>((seed >> 8) % range);
    }
};

// a scene with the benchmark's settings (gravity, h, e, μ, the iterative contact solver) and a floor
core::SceneDesc ballScene(const std::string &name)
{
    core::SceneDesc scene;
    scene.name = name;
    scene.settings.timeStep = kContactTimeStep;
    scene.settings.restitution = kContactRestitution;
    scene.settings.friction = kContactFriction;
    scene.settings.contactSolver = core::ContactSolver::Iterative;
    // the stacks and piles as the benchmark measures them: balls that do not turn, beside Bullet's
    // with rotation locked (bullet-norot). With spin the 210-ball pyramid rolls apart within 10 s
    // (docs/physics.md, "Spin and rolling")
    scene.settings.spin = false;
    scene.planes = {core::PlaneDesc{{0.0, 1.0, 0.0}, 0.0}};
    return scene;
}

core::ParticleDesc ball(const Eigen::Vector3d &position, double mass,
                        const Eigen::Vector3d &velocity = Eigen::Vector3d::Zero())
{
    return core::ParticleDesc{position, velocity, mass, kBallRadius, false};
}

}  // namespace

ContactScene contactColumn(double duration)
{
    // resting on the floor and on each other: centres 2r apart from r up
    core::SceneDesc scene = ballScene("column");
    scene.particles = core::ballColumn(30, kBallRadius, kBallMass, Eigen::Vector3d::Zero());
    return {"column", scene, duration, ContactCheck::Column, 0.0};
}

ContactScene contactPyramid(double duration)
{
    // row k rests in the hollows of row k - 1: r across, √3 r up
    core::SceneDesc scene = ballScene("pyramid");
    scene.particles = core::ballPyramid(20, kBallRadius, kBallMass, Eigen::Vector3d::Zero());
    return {"pyramid", scene, duration, ContactCheck::Pyramid, 0.0};
}

ContactScene contactPile(int balls, int substeps, double duration)
{
    const std::string name = substeps == 1 ? std::string("pile") : "pile-" + std::to_string(substeps) + "sub";
    core::SceneDesc scene = ballScene(name);
    scene.settings.substeps = substeps;
    // the four walls of the box, facing in
    const double half = kBoxHalfWidth;
    scene.planes.push_back(core::PlaneDesc{{1.0, 0.0, 0.0}, -half});
    scene.planes.push_back(core::PlaneDesc{{-1.0, 0.0, 0.0}, -half});
    scene.planes.push_back(core::PlaneDesc{{0.0, 0.0, 1.0}, -half});
    scene.planes.push_back(core::PlaneDesc{{0.0, 0.0, -1.0}, -half});
    // layers of 8 × 8, 12 cm apart, each ball up to 18 mm off its lattice point across
    Lcg random{7};
    for (int k = 0; k < balls; ++k) {
        const Eigen::Vector3d at(-0.42 + 0.12 * (k % 8) + 0.002 * random(10), 0.1 + 0.12 * (k / 64),
                                 -0.42 + 0.12 * ((k / 8) % 8) + 0.002 * random(10));
        scene.particles.push_back(ball(at, kGrainMass));
    }
    return {name, scene, duration, ContactCheck::Pile, 0.0};
}

ContactScene contactHeap(int balls, double duration)
{
    core::SceneDesc scene = ballScene("heap");
    Lcg random{11};
    for (int k = 0; k < balls; ++k) {
        // within ±1 mm of the axis, across
        const Eigen::Vector3d at(1e-4 * (random(21) - 10), kPourHeight, 1e-4 * (random(21) - 10));
        scene.particles.push_back(ball(at, kGrainMass, {0.0, -kPourSpeed, 0.0}));
    }
    return {"heap", scene, duration, ContactCheck::Heap, kPourInterval};
}

}  // namespace bench
