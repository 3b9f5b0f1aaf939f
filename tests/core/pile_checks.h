#pragma once
// What a pile test asks of a run of the contacts benchmark's pile (bench/contact_scenes.h, measured
// with bench/contact_measures.h): its total energy, and whether that rose over a window of steps.
// Shared by test_contacts (300 balls) and test_piles (1000).

#include "bench/contact_measures.h"
#include "scene_builder.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace test {

// J, kinetic and potential (zero at y = 0), gravity along -y
inline double totalEnergy(const Sim &sim)
{
    double e = bench::kineticEnergy(sim.state.velocity, sim.model->mass);
    for (int i = 0; i < sim.model->particleCount(); ++i)
        e -= sim.model->mass[i] * sim.model->gravity.y() * sim.state.position(1, i);
    return e;
}

// J, the settle threshold: 1e-3 N m g r, for balls of radius r
inline double settleThreshold(const Sim &sim, double radius)
{
    return 1e-3 * sim.model->mass.sum() * sim.model->gravity.norm() * radius;
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
