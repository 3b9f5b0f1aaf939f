#include "step.h"

#include "passes.h"

#include <chrono>

namespace core {

namespace {

using Clock = std::chrono::steady_clock;

// runs one pass and adds its wall time to the profile; a pass the plan skips is not counted
template <typename Pass>
void timed(State &state, Stage stage, bool planned, Pass &&pass)
{
    if (!planned)
        return;
    const auto start = Clock::now();
    pass();
    StageTiming &timing = state.profile[stage];
    timing.calls += 1;
    timing.seconds += std::chrono::duration<double>(Clock::now() - start).count();
}

}  // namespace

// forces from outside the scene (steering keys, mouse spring), only while some are set
void addApplied(const Model &, State &state)
{
    if (state.appliedCount == 0)
        return;
    state.force += state.applied;
}

bool step(const Model &model, State &state)
{
    if (state.blowup)
        return false;
    const StepPlan &plan = model.plan;
    const double h = model.subStep();

    for (int sub = 0; sub < model.substeps; ++sub) {
        // 1. forces at (x, v)
        state.force.setZero();
        timed(state, Stage::Gravity, plan.gravity, [&] { addGravity(model, state); });
        timed(state, Stage::Drag, plan.drag, [&] { addDrag(model, state); });
        timed(state, Stage::Springs, plan.springs, [&] { addSprings(model, state); });
        timed(state, Stage::Applied, state.appliedCount > 0, [&] { addApplied(model, state); });

        // 2. integrate every free particle
        timed(state, Stage::Integrate, true, [&] { integrate(model, state, h); });

        // 3. contacts as projections: particles against planes, then pairs
        timed(state, Stage::PlaneCollisions, plan.planeCollisions, [&] { collidePlanes(model, state); });
        timed(state, Stage::ParticleCollisions, plan.particleCollisions, [&] { collideParticles(model, state); });

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
