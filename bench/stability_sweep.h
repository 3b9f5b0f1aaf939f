#pragma once
// The measurement behind `springlab-bench stability`: on a spring chain, the largest time step an
// integrator stays stable at, found by bisection, next to the limit core/integrators/stability.h predicts.

#include "core/integrators/integrator.h"
#include "core/model/scene.h"

#include <optional>

namespace bench {

// one cell of the sweep: a chain of `particles` particles (the first pinned), every particle of
// `mass` kg, every link of `stiffness` N/m
struct ChainCase {
    double stiffness = 1e3;  // N/m
    double mass = 1.0;       // kg
    int particles = 2;
};

// the damping ratio of each link on its own (ζ of one particle on one spring): small, but enough
// to give explicit Euler a limit (it has none on undamped springs)
inline constexpr double kLinkDampingRatio = 0.05;

// stable: the total energy stays below this many times its start for every step of the run
inline constexpr double kEnergyGrowthLimit = 10.0;

// the chain, along x at rest length, no gravity and no contacts, with seeded random velocities
// along x that excite every mode; the motion stays on the x axis, so the springs act exactly
// linearly and the linear theory applies without approximation
core::SceneDesc stabilityChain(const ChainCase &chain);

// the largest stable sub-step core/integrators/stability.h predicts for this chain (s)
double theoreticalStep(const core::SceneDesc &scene, core::Integrator integrator);

// whether the chain run with `integrator` at `timeStep` for `steps` steps keeps its energy below
// kEnergyGrowthLimit × the start (a blow-up caught by the step's checks counts as unstable)
bool stableAt(const core::SceneDesc &scene, core::Integrator integrator, double timeStep, int steps);

struct LimitSearch {
    int steps = 100000;              // steps each trial runs
    double relativeWidth = 1e-3;     // bisect until unstable / stable - 1 is below this
    double largestTimeStep = 1.0;    // s, the largest a scene may have (parameter table)
};

// the largest stable step, by bisection on a log scale from a bracket around `theory`; nullopt
// when theory is not a positive finite step, when twice it is past the largest time step allowed,
// or when no bracket is found there
std::optional<double> measureStableStep(const core::SceneDesc &scene, core::Integrator integrator, double theory,
                                        const LimitSearch &search);

}  // namespace bench
