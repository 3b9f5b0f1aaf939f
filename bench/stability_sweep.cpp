#include "stability_sweep.h"

#include "core/model/diagnostics.h"
#include "core/model/generators.h"
#include "core/model/model.h"
#include "core/integrators/stability.h"
#include "core/model/state.h"
#include "core/step.h"

#include <cmath>
#include <cstdint>

namespace bench {

namespace {

constexpr double kLinkLength = 0.1;         // m
constexpr double kSpeedScale = 1e-3;        // initial speeds of this × link length × √(k/m): tiny stretches
constexpr int kBracketTries = 12;           // halvings or doublings allowed to find the bracket

}  // namespace

core::SceneDesc stabilityChain(const ChainCase &chain)
{
    core::ChainOptions options;
    options.links = chain.particles - 1;
    options.linkLength = kLinkLength;
    options.height = 0.0;
    options.mass = chain.mass;
    options.stiffness = chain.stiffness;
    // c = 2ζ√(k m): the same damping ratio for every cell of the sweep, and damping proportional
    // to stiffness, so every mode of the chain keeps explicit Euler's limit h < c/k
    options.damping = 2.0 * kLinkDampingRatio * std::sqrt(chain.stiffness * chain.mass);
    core::SceneDesc scene = core::makeChain(options);
    scene.name = "stability-chain";
    scene.settings.gravity = Eigen::Vector3d::Zero();
    scene.settings.planeCollisions = scene.settings.particleCollisions = false;

    // seeded pseudo-random speeds along the chain (a fixed linear congruential sequence, so every
    // run of the benchmark measures the same thing)
    const double speed = kSpeedScale * kLinkLength * std::sqrt(chain.stiffness / chain.mass);
    std::uint32_t seed = 2024u;
    for (std::size_t i = 1; i < scene.particles.size(); ++i) {
        seed = seed * 1664525u + 1013904223u;
        scene.particles[i].velocity.x() = speed * (static_cast<double>(seed >> 8) / double(1u << 24) - 0.5);
    }
    return scene;
}

double theoreticalStep(const core::SceneDesc &scene, core::Integrator integrator)
{
    const auto model = core::compileModel(scene);
    const core::State state = core::makeState(*model, scene);
    return core::stabilityLimit(*model, state).maxSubStep(integrator);
}

bool stableAt(const core::SceneDesc &scene, core::Integrator integrator, double timeStep, int steps)
{
    core::SceneDesc trial = scene;
    trial.settings.timeStep = timeStep;
    trial.settings.substeps = 1;
    trial.settings.integrator = integrator;
    const auto model = core::compileModel(trial);
    core::State state = core::makeState(*model, trial);
    core::Workspace work;
    const double ceiling = kEnergyGrowthLimit * core::energies(*model, state).total();
    // every step is checked: near symplectic Euler's limit the energy swings with a period of
    // about two steps, so a sparser check would miss its peaks
    for (int i = 0; i < steps; ++i)
        if (!core::step(*model, state, work) || !(core::energies(*model, state).total() < ceiling))
            return false;
    return true;
}

std::optional<double> measureStableStep(const core::SceneDesc &scene, core::Integrator integrator, double theory,
                                        const LimitSearch &search)
{
    // a bracket: a stable step below, an unstable one above; past the largest time step a scene
    // may have there is nothing to measure
    if (!(theory > 0.0 && 2.0 * theory <= search.largestTimeStep))
        return std::nullopt;
    double stable = 0.5 * theory;
    double unstable = 2.0 * theory;
    int tries = 0;
    bool unstableKnown = false;
    while (!stableAt(scene, integrator, stable, search.steps)) {
        unstable = stable;
        unstableKnown = true;
        stable *= 0.5;
        if (++tries > kBracketTries)
            return std::nullopt;
    }
    while (!unstableKnown) {
        if (unstable > search.largestTimeStep || ++tries > kBracketTries)
            return std::nullopt;
        if (!stableAt(scene, integrator, unstable, search.steps))
            break;
        stable = unstable;
        unstable *= 2.0;
    }

    // bisection on a log scale: the ratio to theory is what is reported
    while (unstable / stable - 1.0 > search.relativeWidth) {
        const double middle = std::sqrt(stable * unstable);
        (stableAt(scene, integrator, middle, search.steps) ? stable : unstable) = middle;
    }
    return stable;
}

}  // namespace bench
