// Writes the stress scenes of resources/scenes/stress/: scenes that push the core to its limits,
// each with a pass criterion checked by tests/stress/test_stress.cpp. Run it after changing a
// scene here: tools/make_stress_scenes resources/scenes/stress
#include "core/model/generators.h"
#include "tools/scene_writer.h"
#include "core/model/model.h"
#include "core/integrators/stability.h"
#include "core/model/state.h"

#include <cmath>
#include <cstdint>

namespace {

using core::ParticleDesc;
using core::PlaneDesc;
using Eigen::Vector3d;

// a fixed pseudo-random sequence in [-1, 1), so the files come out the same every time
class Sequence {
public:
    double next()
    {
        m_seed = m_seed * 1664525u + 1013904223u;
        return 2.0 * (static_cast<double>(m_seed >> 8) / double(1u << 24)) - 1.0;
    }

private:
    std::uint32_t m_seed = 12345u;
};

// symplectic Euler's stability limit of the scene as it starts (s)
double stableSubStep(const core::SceneDesc &scene)
{
    const auto model = core::compileModel(scene);
    const core::State state = core::makeState(*model, scene);
    return core::stabilityLimit(*model, state).maxSubStep(core::Integrator::SymplecticEuler);
}

// a 12 × 12 cloth with links of 1e7 N/m (shear and bend in the example cloth's proportions),
// pinned at two corners, swinging down from the horizontal; implicit Euler keeps it stable at
// 0.01 s, hundreds of times symplectic Euler's limit. No floor: a contact's projection
// would strain links that stiff by more than any force does
core::SceneDesc stiffCloth()
{
    core::ClothOptions options;
    options.rows = options.cols = 12;
    options.structuralStiffness = 1e7;
    options.shearStiffness = 2e6;
    options.bendStiffness = 3e5;
    options.substeps = 1;
    core::SceneDesc scene = core::makeCloth(options);
    scene.name = "stiff-cloth";
    scene.settings.integrator = core::Integrator::ImplicitEuler;
    scene.settings.planeCollisions = scene.settings.particleCollisions = false;
    return scene;
}

// 40 links of 1 kg particles, pinned at one end and released horizontally, with a 1000 kg weight
// at the free end: the light links set the stability limit, the weight sets the tension. The
// sub-steps keep each one at 90% of symplectic Euler's limit
core::SceneDesc heavyChain()
{
    core::ChainOptions options;
    options.links = 40;
    options.linkLength = 0.1;
    options.height = 5.0;
    options.mass = 1.0;
    options.stiffness = 1e7;
    options.damping = 10.0;
    core::SceneDesc scene = core::makeChain(options);
    scene.name = "heavy-chain";
    scene.particles.back().mass = 1000.0;
    scene.particles.back().radius = 0.1;
    scene.settings.planeCollisions = scene.settings.particleCollisions = false;
    scene.settings.substeps =
        static_cast<int>(std::ceil(scene.settings.timeStep / (0.9 * stableSubStep(scene))));
    return scene;
}

// 30 particles of radius 0.1 m stacked on the floor, touching, at rest
core::SceneDesc column()
{
    core::SceneDesc scene;
    scene.name = "column-30";
    scene.settings.restitution = 0.0;
    scene.settings.substeps = 10;
    scene.particles = core::ballColumn(30, 0.1, 1.0, Vector3d::Zero());
    scene.planes = {core::floorPlane()};
    return scene;
}

// a triangle of touching particles in the plane z = 0: 20 on the floor, 19 in the hollows above
// them, up to 1 at the top (210 in all), between two walls that fit the base exactly; without
// friction nothing else would hold the base together
core::SceneDesc pyramid()
{
    constexpr int kBase = 20;
    constexpr double kRadius = 0.1;
    const double halfWidth = kBase * kRadius;
    core::SceneDesc scene;
    scene.name = "pyramid-20";
    scene.settings.restitution = 0.0;
    scene.settings.substeps = 10;
    scene.particles = core::ballPyramid(kBase, kRadius, 1.0, Vector3d(-halfWidth + kRadius, 0.0, 0.0));
    scene.planes = {core::floorPlane(), PlaneDesc{Vector3d(1.0, 0.0, 0.0), -halfWidth},
                    PlaneDesc{Vector3d(-1.0, 0.0, 0.0), -halfWidth}};
    return scene;
}

// 100 particles created at one point, in a viscous medium without gravity: they must spread out
core::SceneDesc crowd()
{
    core::SceneDesc scene;
    scene.name = "crowd-100";
    scene.settings.gravity = Vector3d::Zero();
    scene.settings.viscosity = 1.0;
    scene.settings.restitution = 0.5;
    scene.settings.substeps = 4;
    scene.settings.planeCollisions = false;
    for (int i = 0; i < 100; ++i)
        scene.particles.push_back(ParticleDesc{Vector3d(0.0, 1.0, 0.0), Vector3d::Zero(), 1.0, 0.05, false});
    return scene;
}

// 1000 particles in a closed 2 m box under gravity, e = 1, thrown in every direction from a
// 10 × 10 × 10 lattice; two sub-steps keep the fastest pairs under the pair speed limit
core::SceneDesc elasticBox()
{
    core::SceneDesc scene;
    scene.name = "elastic-box-1000";
    scene.settings.restitution = 1.0;
    scene.settings.substeps = 2;
    Sequence random;
    for (int i = 0; i < 10; ++i)
        for (int j = 0; j < 10; ++j)
            for (int k = 0; k < 10; ++k) {
                const Vector3d position(-0.9 + 0.2 * i, 0.1 + 0.2 * j, -0.9 + 0.2 * k);
                const Vector3d velocity(random.next(), random.next(), random.next());
                scene.particles.push_back(ParticleDesc{position, 2.0 * velocity, 1.0, 0.05, false});
            }
    scene.planes = core::boxPlanes(1.0, 2.0);
    return scene;
}

// a thin wall of 11 × 11 pinned particles (radius 5 cm, touching) in the plane x = 1, and five
// projectiles at 1 km/s aimed at a particle, between two, and between four. The sub-step keeps
// the relative displacement under the pair speed limit of docs/physics.md for the worst aim, the
// centre of four: 1000 m/s × 62.5 µs = 6.25 cm < √(0.1² - 0.1²/2) m = 7.07 cm
core::SceneDesc projectiles()
{
    constexpr double kRadius = 0.05;
    core::SceneDesc scene;
    scene.name = "projectiles";
    scene.settings.timeStep = 1e-3;
    scene.settings.substeps = 16;
    scene.settings.restitution = 0.5;
    scene.settings.planeCollisions = false;
    for (int j = 0; j <= 10; ++j)
        for (int k = 0; k <= 10; ++k)
            scene.particles.push_back(
                ParticleDesc{Vector3d(1.0, 0.5 + 0.1 * j, -0.5 + 0.1 * k), Vector3d::Zero(), 1.0, kRadius, true});
    const Eigen::Vector2d aims[] = {{1.0, 0.0}, {1.3, 0.05}, {0.75, -0.25}, {1.25, 0.35}, {0.6, -0.4}};
    for (const Eigen::Vector2d &aim : aims)
        scene.particles.push_back(
            ParticleDesc{Vector3d(0.0, aim.x(), aim.y()), Vector3d(1000.0, 0.0, 0.0), 0.01, kRadius, false});
    return scene;
}

// the handout's kind of chain with a time step 100 times symplectic Euler's limit: 10 links of
// 0.1 kg and 1e5 N/m (limit about 1 ms) at 0.1 s
core::SceneDesc largeStep()
{
    core::ChainOptions options;
    options.links = 10;
    options.mass = 0.1;
    options.stiffness = 1e5;
    options.damping = 0.0;
    core::SceneDesc scene = core::makeChain(options);
    scene.name = "time-step-100x";
    scene.settings.timeStep = 0.1;
    scene.settings.planeCollisions = scene.settings.particleCollisions = false;
    return scene;
}

}  // namespace

int main(int argc, char **argv)
{
    return tools::writeScenes(argc, argv,
                              {stiffCloth(), heavyChain(), column(), pyramid(), crowd(), elasticBox(), projectiles(), largeStep()});
}
