#include "core/passes.h"
#include "core/timed.h"

namespace core {

// forces from outside the scene (steering keys, mouse spring), only while some are set
void addApplied(const Model &, State &state, Workspace &work)
{
    if (state.appliedCount == 0)
        return;
    work.force += state.applied;
}

namespace {

// the forces at the state's (x, v) into work.force, with or without the drag and the springs;
// each pass runs only if the plan needs it
void forces(const Model &model, State &state, Workspace &work, bool internal)
{
    const StepPlan &plan = model.plan;
    Profile &profile = work.profile;
    if (work.force.cols() != state.position.cols())
        work.force.resize(3, state.position.cols());  // a new workspace: once, then reused
    // gravity, when there is some, starts the forces off (one pass instead of clearing and adding)
    if (plan.gravity)
        timed(profile, Stage::Gravity, true, [&] { startWithGravity(model, state, work); });
    else
        work.force.setZero();
    timed(profile, Stage::Drag, internal && plan.drag, [&] { addDrag(model, state, work); });
    timed(profile, Stage::Springs, internal && plan.springs, [&] { addSprings(model, state, work); });
    timed(profile, Stage::Applied, state.appliedCount > 0, [&] { addApplied(model, state, work); });
    work.profile.forceEvaluations += 1;
}

}  // namespace

void computeForces(const Model &model, State &state, Workspace &work)
{
    forces(model, state, work, true);
}

void computeExternalForces(const Model &model, State &state, Workspace &work)
{
    forces(model, state, work, false);
}

// accelerations of the free particles from work.force (zero for pinned ones)
void accelerations(const Model &model, const Workspace &work, Eigen::Matrix3Xd &out)
{
    out.noalias() = work.force * model.invMass.asDiagonal();
}

}  // namespace core
