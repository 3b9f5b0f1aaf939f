#pragma once
// The stages of one sub-step, each a free function of (const Model&, State&, Workspace&) in its
// own file: the State is what the run is, the Workspace what the stage may use besides. Each
// returns at once when the step plan says the scene does not need it.

#include "core/model/model.h"
#include "core/model/state.h"
#include "core/model/workspace.h"

namespace core {

struct SharesInTurn;  // parallel.h

// forces at (x, v) into work.force
void addGravity(const Model &model, State &state, Workspace &work);        // gravity.cpp: m g
void startWithGravity(const Model &model, State &state, Workspace &work);  // gravity.cpp: forces = m g
void addDrag(const Model &model, State &state, Workspace &work);           // drag.cpp: -c v
void addSprings(const Model &model, State &state, Workspace &work);        // springs.cpp: damped springs
// the two ways addSprings() takes, by runs of lattice-like springs or by gathering each
// particle's springs, public for the tests; neither checks the plan
void addSpringRuns(const Model &model, State &state, Workspace &work);
void addSpringsGathered(const Model &model, State &state, Workspace &work);
void addSpringsReference(const Model &model, State &state, Workspace &work);  // springs.cpp: the plain scatter loop
void addApplied(const Model &model, State &state, Workspace &work);           // forces.cpp: forces from outside
void computeForces(const Model &model, State &state, Workspace &work);        // forces.cpp: all of the above
// gravity and the applied forces alone, for xpbd, which takes the springs as constraints and the
// drag in its kick (forces.cpp)
void computeExternalForces(const Model &model, State &state, Workspace &work);
void accelerations(const Model &model, const Workspace &work, Eigen::Matrix3Xd &out);  // forces.cpp: w F

// advances the free particles by h with the model's integrator, which calls computeForces() as
// often as its scheme needs (integrate.cpp, with rk4.cpp, implicit_euler.cpp, adaptive_rk45.cpp).
// Returns whether it checked every free particle's new values as it wrote them (the Euler schemes
// do), so that the finite check need not read them again
bool integrate(const Model &model, State &state, Workspace &work, double h);
void rk4(const Model &model, State &state, Workspace &work, double h);
void implicitEuler(const Model &model, State &state, Workspace &work, double h);
void adaptiveRk45(const Model &model, State &state, Workspace &work, double h);
void xpbd(const Model &model, State &state, Workspace &work, double h);  // xpbd.cpp
void projective(const Model &model, State &state, Workspace &work, double h);  // projective.cpp
void vbd(const Model &model, State &state, Workspace &work, double h);         // vbd.cpp
// the plan's fused path (SubStepPath::FusedLattice): the symplectic or explicit Euler sub-step of a
// lattice, forces and update fused block by block, the same bits as computeForces() and the
// update; returns whether every new value of the free particles is finite and bounded
// (spring_blocks.cpp)
bool stepSpringBlocks(const Model &model, State &state, Workspace &work, double h);
// the same with its thread shares run one after another on the calling thread, for the tests
bool stepSpringBlocks(const Model &model, State &state, Workspace &work, double h, const SharesInTurn &inTurn);

// the restitution of a contact approaching at normalSpeed (< 0): the scene's, or 0 for a resting
// contact slower than model.restingSpeed
inline double contactRestitution(const Model &model, double normalSpeed)
{
    return -normalSpeed > model.restingSpeed ? model.restitution : 0.0;
}

// scratch arrays of the state's size, made on first use (a step allocates nothing after that)
Eigen::Matrix3Xd &scratch(const State &state, Workspace &work, int index);

// the handout's contact passes: a projection and an impulse for each contact, once
void collidePlanes(const Model &model, State &state, Workspace &work);     // plane_collisions.cpp
void collideParticles(const Model &model, State &state, Workspace &work);  // particle_collisions.cpp

// the iterative contact solver (contacts.cpp): the positions and velocities at the sub-step's start,
// kept before the integrator moves them; then, after it, the impacts along the paths and the
// resting contacts
void rememberSubStepStart(const Model &model, const State &state, Workspace &work);
void solveContacts(const Model &model, State &state, Workspace &work);
void resolveImpacts(const Model &model, State &state, Workspace &work, double h);  // contact_impacts.cpp
void solveRestingContacts(const Model &model, State &state, Workspace &work, double h);       // contact_solve.cpp
// m/s: a contact approaching slower than this along its normal is resting, not an impact
double restingThreshold(const Model &model, const Eigen::Vector3d &normal);
// the triangle collisions (triangle_collisions.cpp): the positions at the sub-step's start, then,
// after the contacts, every particle and sheet edge kept off the sheets' triangles
void rememberTriangleStart(const Model &model, const State &state, Workspace &work);
void collideTriangles(const Model &model, State &state, Workspace &work);

// the particles' orientations turned by their spins over the sub-step (integrators/orientation.cpp),
// where the plan has spin
void turnParticles(const Model &model, State &state, double h);
void breakSprings(const Model &model, State &state, Workspace &work);      // spring_breaks.cpp
// every position and velocity finite and bounded (only the pinned particles' when freeChecked says
// the integrator checked the free ones); else records the first culprit in work.blowup
bool checkFinite(const Model &model, State &state, Workspace &work, bool freeChecked);  // checks.cpp

}  // namespace core
