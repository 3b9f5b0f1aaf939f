#pragma once
// The passes of one sub-step, each a free function of (const Model&, State&) in its own file.
// Each returns at once when the step plan says the scene does not need it.

#include "model.h"
#include "state.h"

namespace core {

void addGravity(const Model &model, State &state);               // gravity.cpp: m g
void addDrag(const Model &model, State &state);                  // drag.cpp: -c v
void addSprings(const Model &model, State &state);               // springs.cpp: damped springs
void addApplied(const Model &model, State &state);               // step.cpp: forces from outside
void integrate(const Model &model, State &state, double h);      // integrate.cpp
void collidePlanes(const Model &model, State &state);            // plane_collisions.cpp
void collideParticles(const Model &model, State &state);         // particle_collisions.cpp
bool checkFinite(const Model &model, State &state);              // checks.cpp

}  // namespace core
