#pragma once
// The passes of one sub-step, each a free function of (const Model&, State&) in its own file.
// Each returns at once when the step plan says the scene does not need it.

#include "model.h"
#include "state.h"

namespace core {

void addGravity(const Model &model, State &state);               // gravity.cpp: m g
void startWithGravity(const Model &model, State &state);         // gravity.cpp: forces = m g
void addDrag(const Model &model, State &state);                  // drag.cpp: -c v
void addSprings(const Model &model, State &state);               // springs.cpp: damped springs
// the two ways addSprings() takes, by runs of lattice-like springs or by gathering each
// particle's springs, public for the tests; neither checks the plan
void addSpringRuns(const Model &model, State &state);
void addSpringsGathered(const Model &model, State &state);
void addSpringsReference(const Model &model, State &state);      // springs.cpp: the plain scatter loop
void addApplied(const Model &model, State &state);               // forces.cpp: forces from outside
void computeForces(const Model &model, State &state);            // forces.cpp: all of the above
void accelerations(const Model &model, const State &state, Eigen::Matrix3Xd &out);  // forces.cpp: w F

// advances the free particles by h with the model's integrator, which calls computeForces() as
// often as its scheme needs (integrate.cpp, with rk4.cpp, implicit_euler.cpp, adaptive_rk45.cpp)
void integrate(const Model &model, State &state, double h);
void rk4(const Model &model, State &state, double h);
// the symplectic (or explicit) Euler sub-step of a model that usesSpringBlocks(): forces and update
// fused, block by block, the same bits as computeForces() and the update; returns whether every new
// value of the free particles is finite and bounded (spring_blocks.cpp)
bool stepSpringBlocks(const Model &model, State &state, double h, bool symplectic);
void implicitEuler(const Model &model, State &state, double h);
void adaptiveRk45(const Model &model, State &state, double h);

// the restitution of a contact approaching at normalSpeed (< 0): the scene's, or 0 for a resting
// contact slower than model.restingSpeed
inline double contactRestitution(const Model &model, double normalSpeed)
{
    return -normalSpeed > model.restingSpeed ? model.restitution : 0.0;
}

// scratch arrays of the state's size, made on first use (a step allocates nothing after that)
Eigen::Matrix3Xd &scratch(State &state, int index);
void collidePlanes(const Model &model, State &state);            // plane_collisions.cpp
void collideParticles(const Model &model, State &state);         // particle_collisions.cpp
void breakSprings(const Model &model, State &state);             // spring_breaks.cpp
bool checkFinite(const Model &model, State &state);              // checks.cpp

}  // namespace core
