#include "passes.h"
#include "timed.h"

namespace core {

// forces from outside the scene (steering keys, mouse spring), only while some are set
void addApplied(const Model &, State &state)
{
    if (state.appliedCount == 0)
        return;
    state.force += state.applied;
}

// all forces at the state's (x, v) into state.force; each pass runs only if the plan needs it
void computeForces(const Model &model, State &state)
{
    const StepPlan &plan = model.plan;
    // gravity, when there is some, starts the forces off (one pass instead of clearing and adding)
    if (plan.gravity)
        timed(state, Stage::Gravity, true, [&] { startWithGravity(model, state); });
    else
        state.force.setZero();
    timed(state, Stage::Drag, plan.drag, [&] { addDrag(model, state); });
    timed(state, Stage::Springs, plan.springs, [&] { addSprings(model, state); });
    timed(state, Stage::Applied, state.appliedCount > 0, [&] { addApplied(model, state); });
    state.forceEvaluations += 1;
}

// accelerations of the free particles from state.force (zero for pinned ones)
void accelerations(const Model &model, const State &state, Eigen::Matrix3Xd &out)
{
    out.noalias() = state.force * model.invMass.asDiagonal();
}

}  // namespace core
