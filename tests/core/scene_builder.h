#pragma once
// Small helpers for building test scenes by hand.

#include "core/model/model.h"
#include "core/model/scene.h"
#include "core/model/state.h"
#include "core/step.h"
#include "core/model/workspace.h"

#include <algorithm>
#include <cstdint>
#include <memory>
#include <vector>

namespace test {

inline core::ParticleDesc particle(Eigen::Vector3d position, Eigen::Vector3d velocity = Eigen::Vector3d::Zero(),
                                   double mass = 1.0, double radius = 0.1, bool pinned = false)
{
    return core::ParticleDesc{position, velocity, mass, radius, pinned};
}

// a scene with no gravity and no collisions: only what a test adds acts
inline core::SceneDesc quietScene()
{
    core::SceneDesc scene;
    scene.name = "test";
    scene.settings.gravity = Eigen::Vector3d::Zero();
    scene.settings.planeCollisions = false;
    scene.settings.particleCollisions = false;
    return scene;
}

// a compiled model, its initial state and a workspace to step it with, kept together
struct Sim {
    std::shared_ptr<const core::Model> model;
    core::State state;
    core::Workspace work;

    bool step() { return core::step(*model, state, work); }
};

inline Sim compile(const core::SceneDesc &scene)
{
    auto model = core::compileModel(scene);
    Sim sim{model, core::makeState(*model, scene), {}};
    sim.work.force.setZero(3, model->particleCount());  // for the tests that call one pass alone
    return sim;
}

// a cheap deterministic generator for test scenes: next(range) is in [0, range)
struct Lcg {
    std::uint32_t seed;
    int operator()(std::uint32_t range)
    {
        seed = seed * 1664525u + 1013904223u;
        return static_cast<int>((seed >> 8) % range);
    }
};

// About 6 springs per particle, in runs (a + j, a + offset + j) with each run's offset drawn from
// offsets and one to maxCount springs (one run in five of a single spring), random parameters:
// the springs of a lattice, cut and shuffled into every shape a run can take
inline void addRandomRuns(core::SceneDesc &scene, const std::vector<int> &offsets, int maxCount, Lcg &next)
{
    const int n = static_cast<int>(scene.particles.size());
    int springs = 0;
    while (springs < 6 * n) {
        const int offset = offsets[static_cast<std::size_t>(next(static_cast<std::uint32_t>(offsets.size())))];
        const int count = next(5) == 0 ? 1 : 1 + next(static_cast<std::uint32_t>(maxCount));
        const int low = std::max(0, -offset);
        const int high = std::min(n, n - offset) - count;  // a + count - 1 < n, b too
        if (high <= low)
            continue;
        const int a = low + next(static_cast<std::uint32_t>(high - low));
        for (int j = 0; j < count; ++j, ++springs)
            scene.springs.push_back(core::SpringDesc{a + j, a + offset + j, 10.0 + next(1000), next(10) * 0.1,
                                                     0.5 + next(100) * 1e-2});
    }
}

// the spring kernels' other roads: every 41st spring's ends made coincident (the fixed-axis
// branch) and, when breakable, every 13th spring from the 5th broken
inline void coincideAndBreak(Sim &sim, bool breakable)
{
    for (int k = 0; k < sim.model->springCount(); k += 41)
        sim.state.position.col(sim.model->springB[std::size_t(k)]) = sim.state.position.col(sim.model->springA[std::size_t(k)]);
    if (breakable) {
        sim.state.springBroken.assign(std::size_t(sim.model->springCount()), 0);
        for (int k = 5; k < sim.model->springCount(); k += 13)
            sim.state.springBroken[std::size_t(k)] = 1;
    }
}

}  // namespace test
