#pragma once
// The pile: balls of r = 5 cm and 0.1 kg (e = 0.5, μ = 0.5) on a jittered lattice of 8 × 8
// a layer, 12 cm apart, dropped into a box 1 m wide, and what a run of it is judged by: kinetic
// energy against 1e-3 N m g r, the deepest overlap, and the total energy over every 1 s window.
// Shared by test_contacts (300 balls) and test_piles (1000).

#include "scene_builder.h"

#include <algorithm>
#include <vector>

namespace test {

inline constexpr double kPileGravity = 9.81;  // m/s², down y
inline constexpr double kPileRadius = 0.05;   // m
inline constexpr double kPileMass = 0.1;      // kg

inline core::SceneDesc droppedPile(int balls, int substeps)
{
    core::SceneDesc scene;
    scene.name = "pile";
    scene.settings.substeps = substeps;
    scene.settings.restitution = 0.5;
    scene.settings.friction = 0.5;
    const double half = 0.5;
    scene.planes = {core::PlaneDesc{{0, 1, 0}, 0.0}, core::PlaneDesc{{1, 0, 0}, -half},
                    core::PlaneDesc{{-1, 0, 0}, -half}, core::PlaneDesc{{0, 0, 1}, -half},
                    core::PlaneDesc{{0, 0, -1}, -half}};
    Lcg random{7};
    for (int k = 0; k < balls; ++k) {
        const Eigen::Vector3d at(-0.42 + 0.12 * (k % 8) + 0.002 * random(10), 0.1 + 0.12 * (k / 64),
                                 -0.42 + 0.12 * ((k / 8) % 8) + 0.002 * random(10));
        scene.particles.push_back(particle(at, Eigen::Vector3d::Zero(), kPileMass, kPileRadius));
    }
    return scene;
}

// J, ½ Σ m v²
inline double kineticEnergy(const Sim &sim)
{
    double e = 0.0;
    for (int i = 0; i < sim.model->particleCount(); ++i)
        e += 0.5 * sim.model->mass[i] * sim.state.velocity.col(i).squaredNorm();
    return e;
}

// J, kinetic and potential (the floor y = 0 is zero)
inline double totalEnergy(const Sim &sim)
{
    double e = kineticEnergy(sim);
    for (int i = 0; i < sim.model->particleCount(); ++i)
        e += sim.model->mass[i] * kPileGravity * sim.state.position(1, i);
    return e;
}

// m, the deepest overlap of any two particles or of a particle and the floor y = 0
inline double deepestOverlap(const Sim &sim)
{
    double deepest = 0.0;
    const int n = sim.model->particleCount();
    for (int i = 0; i < n; ++i) {
        deepest = std::max(deepest, sim.model->radius[i] - sim.state.position(1, i));
        for (int j = i + 1; j < n; ++j)
            deepest = std::max(deepest, sim.model->radius[i] + sim.model->radius[j] -
                                            (sim.state.position.col(i) - sim.state.position.col(j)).norm());
    }
    return deepest;
}

// J, the settle threshold: 1e-3 N m g r
inline double settleThreshold(int balls)
{
    return 1e-3 * balls * kPileMass * kPileGravity * kPileRadius;
}

// the first index i ≥ from at which energies[i] exceeds energies[i - window] by more than
// `tolerance` of it, or -1: the total energy rose over a window of `window` steps
inline int firstRise(const std::vector<double> &energies, std::size_t window, std::size_t from, double tolerance)
{
    for (std::size_t i = std::max(window, from); i < energies.size(); ++i)
        if (energies[i] > energies[i - window] + tolerance * std::abs(energies[i - window]))
            return static_cast<int>(i);
    return -1;
}

}  // namespace test
