#include "core/step.h"

#include "core/passes.h"
#include "core/timed.h"

namespace core {

namespace {

// the step and time of a blowup found in the sub-step that began the step at state's time
bool stopped(const State &state, Workspace &work)
{
    work.blowup->step = state.step + 1;
    work.blowup->time = state.time;
    return false;
}

}  // namespace

bool step(const Model &model, State &state, Workspace &work)
{
    work.interrupted = false;
    if (work.blowup)
        return false;
    const StepPlan &plan = model.plan;
    Profile &profile = work.profile;
    const double h = model.subStep();
    fitSpin(model, state);  // a state made before the scene could turn (a test's, an edit's)

    for (int sub = 0; sub < model.substeps; ++sub) {
        if (stopsHere(work))  // asked to stop: the step is not taken (the caller restores where it began)
            return false;
        // 1 and 2. forces at (x, v) and integration of every free particle, by the path the plan
        // chose when the model was compiled
        bool freeChecked = false;  // whether the update checked the free particles' new values
        rememberSubStepStart(model, state, work);  // the contact solver's paths start here
        rememberTriangleStart(model, state, work);
        switch (plan.subStep) {
        case SubStepPath::FusedLattice:
            // the Euler schemes on a lattice: every force pass and the update fused, a block of
            // particles at a time (spring_blocks.cpp)
            timed(profile, Stage::FusedSubStep, true, [&] { freeChecked = stepSpringBlocks(model, state, work, h); });
            break;
        case SubStepPath::Stages:
            // the integrator evaluates the forces (computeForces) as often as its scheme needs
            timed(profile, Stage::Integrate, true, [&] { freeChecked = integrate(model, state, work, h); });
            if (work.blowup)  // an adaptive integrator that could not cover the sub-step
                return stopped(state, work);
            break;
        }
        // (an adaptive integrator may have stopped among its trials already)
        if (stopsHere(work))
            return false;

        // 3. contacts (they move particles after the integrator's check): the iterative solver, or
        // the handout's projections, particles against planes, then pairs
        if (plan.planeCollisions || plan.particleCollisions)
            freeChecked = false;
        if (plan.contactSolver) {
            timed(profile, Stage::Contacts, true, [&] { solveContacts(model, state, work); });
            if (work.interrupted)  // it stops between its own stages too
                return false;
        } else {
            timed(profile, Stage::PlaneCollisions, plan.planeCollisions, [&] { collidePlanes(model, state, work); });
            timed(profile, Stage::ParticleCollisions, plan.particleCollisions,
                  [&] { collideParticles(model, state, work); });
        }

        // 3b. nothing through a sheet: particles and sheet edges against the sheets' triangles
        if (plan.triangleCollisions)
            freeChecked = false;
        timed(profile, Stage::TriangleCollisions, plan.triangleCollisions, [&] { collideTriangles(model, state, work); });
        if (work.blowup)  // more pairs within reach than a sheet that is not flying apart has
            return stopped(state, work);

        // the spins the contacts left turn the particles
        turnParticles(model, state, h);

        // springs stretched past their breaking strain break, for good
        timed(profile, Stage::Breaks, plan.springBreaks, [&] { breakSprings(model, state, work); });

        // 4. every value finite and bounded, else stop here and say where
        bool finite = true;
        timed(profile, Stage::Check, true, [&] { finite = checkFinite(model, state, work, freeChecked); });
        if (!finite)
            return stopped(state, work);
    }
    state.step += 1;
    state.time += model.timeStep;
    return true;
}

}  // namespace core
