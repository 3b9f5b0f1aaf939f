#include "step.h"

#include "passes.h"
#include "timed.h"

#include <algorithm>
#include <chrono>

namespace core {

namespace {

// seconds spent so far in the force passes
double forceSeconds(const Profile &profile)
{
    return profile[Stage::Gravity].seconds + profile[Stage::Drag].seconds + profile[Stage::Springs].seconds +
           profile[Stage::Applied].seconds;
}

// the integrator, timed without the force passes it calls (those are timed on their own)
void integrateTimed(const Model &model, State &state, double h)
{
    const double forcesBefore = forceSeconds(state.profile);
    const auto start = std::chrono::steady_clock::now();
    integrate(model, state, h);
    const double total = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    StageTiming &timing = state.profile[Stage::Integrate];
    timing.calls += 1;
    timing.seconds += std::max(0.0, total - (forceSeconds(state.profile) - forcesBefore));
}

}  // namespace

bool step(const Model &model, State &state)
{
    if (state.blowup)
        return false;
    const StepPlan &plan = model.plan;
    const double h = model.subStep();

    for (int sub = 0; sub < model.substeps; ++sub) {
        // 1 and 2. forces at (x, v) and integration of every free particle: the integrator
        // evaluates the forces as often as its scheme needs (once for the Euler schemes)
        state.freeParticlesChecked = false;  // until an integrator says it checked what it wrote
        integrateTimed(model, state, h);
        if (state.blowup) {  // an adaptive integrator that could not cover the sub-step
            state.blowup->step = state.step + 1;
            state.blowup->time = state.time;
            return false;
        }

        // 3. contacts as projections: particles against planes, then pairs (they move particles
        // after the integrator's check)
        if (plan.planeCollisions || plan.particleCollisions)
            state.freeParticlesChecked = false;
        timed(state, Stage::PlaneCollisions, plan.planeCollisions, [&] { collidePlanes(model, state); });
        timed(state, Stage::ParticleCollisions, plan.particleCollisions, [&] { collideParticles(model, state); });

        // springs stretched past their breaking strain break, for good
        timed(state, Stage::Breaks, plan.springBreaks, [&] { breakSprings(model, state); });

        // 4. every value finite and bounded, else stop here and say where
        bool finite = true;
        timed(state, Stage::Check, true, [&] { finite = checkFinite(model, state); });
        if (!finite) {
            state.blowup->step = state.step + 1;
            state.blowup->time = state.time;
            return false;
        }
    }
    state.step += 1;
    state.time += model.timeStep;
    return true;
}

}  // namespace core
