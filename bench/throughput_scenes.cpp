#include "throughput_scenes.h"

#include "core/model/generators.h"

#include <cmath>
#include <numbers>
#include <random>
#include <string>

namespace bench {

core::SceneDesc throughputCloth(int n)
{
    core::ClothOptions options;
    options.rows = n;
    options.cols = n;
    options.substeps = 1;
    core::SceneDesc scene = core::makeCloth(options);
    scene.name = "cloth-" + std::to_string(n);
    scene.settings.timeStep = kClothTimeStep;
    scene.settings.substeps = 1;
    scene.settings.integrator = core::Integrator::SymplecticEuler;
    scene.settings.planeCollisions = false;
    scene.settings.particleCollisions = false;
    return scene;
}

core::SceneDesc throughputBox(int particles)
{
    core::SceneDesc scene;
    scene.name = "box-" + std::to_string(particles);
    scene.settings.timeStep = kBoxTimeStep;
    scene.settings.substeps = 1;
    scene.settings.integrator = core::Integrator::SymplecticEuler;
    scene.settings.restitution = 0.9;
    scene.settings.planeCollisions = true;
    scene.settings.particleCollisions = true;

    // the box's side from the volume fraction: n (4/3) π r³ = φ L³
    const double r = kBoxRadius;
    const double ball = 4.0 / 3.0 * std::numbers::pi * r * r * r;  // m³
    const double side = std::cbrt(particles * ball / kBoxVolumeFraction);  // m
    const double half = 0.5 * side;

    // a lattice of m³ ≥ n cells of at least 2.4 r, filled from the floor up; each particle at its
    // cell's centre moved by up to 0.1 r, so that none overlaps another or a wall at the start
    int m = 1;
    while (static_cast<long long>(m) * m * m < particles)
        ++m;
    const double cell = side / m;
    std::mt19937_64 random(20240611);
    const auto uniform = [&random] { return static_cast<double>(random() >> 11) * 0x1.0p-53 * 2.0 - 1.0; };
    scene.particles.reserve(static_cast<std::size_t>(particles));
    for (int i = 0; i < particles; ++i) {
        const int ix = i % m, iz = (i / m) % m, iy = i / (m * m);
        core::ParticleDesc p;
        const double jx = uniform(), jy = uniform(), jz = uniform();
        p.position = Eigen::Vector3d(-half + (ix + 0.5) * cell + 0.1 * r * jx, (iy + 0.5) * cell + 0.1 * r * jy,
                                     -half + (iz + 0.5) * cell + 0.1 * r * jz);
        const double vx = uniform(), vy = uniform(), vz = uniform();
        p.velocity = Eigen::Vector3d(vx, vy, vz);  // m/s
        p.mass = 1.0;
        p.radius = r;
        scene.particles.push_back(p);
    }

    // the walls, normals pointing in: floor at y = 0, ceiling at y = side, four sides at ±side/2
    scene.planes = core::boxPlanes(half, side);
    return scene;
}

double clothBytesPerSubstep(long long particles, long long springs)
{
    constexpr double kPerParticle = 20.0 * sizeof(double);                // B
    constexpr double kPerSpring = 2.0 * sizeof(int) + 3.0 * sizeof(double);  // B
    return kPerParticle * static_cast<double>(particles) + kPerSpring * static_cast<double>(springs);
}

double boxBytesPerSubstep(long long particles)
{
    constexpr double kPerParticle = 15.0 * sizeof(double);  // B
    return kPerParticle * static_cast<double>(particles);
}

}  // namespace bench
