// The iterative contact solver, the default (settings.contactSolver "iterative"; the handout's
// passes are plane_collisions.cpp and particle_collisions.cpp). Per sub-step, after the integrator:
//   1. impacts located in time along the particles' paths (contact_impacts.cpp);
//   2. the resting contacts solved together, velocities then positions, with Coulomb friction
//      (contact_solve.cpp).
// docs/physics.md, "Contacts", gives the model and the reasons for it.

#include "core/passes.h"

#include <cmath>

namespace core {

double restingThreshold(const Model &model, const Eigen::Vector3d &normal)
{
    // twice what gravity adds to the speed along the normal in one sub-step: a contact slower than
    // this is a particle settling under its weight, not an impact
    return 2.0 * std::abs(model.gravity.dot(normal)) * model.subStep();
}

void rememberSubStepStart(const Model &model, const State &state, Workspace &work)
{
    if (!model.plan.contactSolver)
        return;
    work.contactSolver.startPosition = state.position;
    work.contactSolver.startVelocity = state.velocity;
}

namespace {

// room for the per-particle arrays, so that a sub-step allocates nothing for them. The contacts,
// impacts and neighbour lists grow to the most the scene has needed and stay there: reserving for
// a dense packing (six contacts a particle and every free particle on every collider, 200 bytes
// each) gave a 100 000-particle cloth over a floor 281 MB of address space before it touched
// anything, and springlab-sim needed 490 MB of it to run that cloth (now 175 MB).
void reserve(const Model &model, ContactScratch &scratch)
{
    const std::size_t n = std::size_t(model.particleCount());
    if (scratch.level.capacity() >= n)
        return;
    scratch.neighbourStart.reserve(n + 1);
    scratch.level.reserve(n);
    scratch.queue.reserve(n);
    scratch.segmentOf.reserve(n);
    scratch.version.reserve(n);
    scratch.isStray.reserve(n);
    scratch.isFast.reserve(n);
    scratch.fast.reserve(n);
    scratch.zoneOf.reserve(n);
    scratch.zoneMomentum.resize(3, Eigen::Index(n));
    scratch.zoneMass.reserve(n);
    scratch.inZone.reserve(n);
}

}  // namespace

void solveContacts(const Model &model, State &state, Workspace &work)
{
    if (!model.plan.contactSolver)
        return;
    reserve(model, work.contactSolver);
    if (state.contactImpulses.capacity() < work.contactSolver.contacts.capacity())
        state.contactImpulses.reserve(work.contactSolver.contacts.capacity());
    const double h = model.subStep();
    resolveImpacts(model, state, work, h);
    if (work.interrupted)
        return;
    if (model.plan.twoSidedColliders)
        work.contactSolver.sidePosition = state.position;
    else
        work.contactSolver.sidePosition.resize(3, 0);
    solveRestingContacts(model, state, work, h);
}

}  // namespace core
