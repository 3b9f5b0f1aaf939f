#pragma once
// One step of the simulation: forces, integration, collisions, checks (see step.cpp).

#include "core/model/model.h"
#include "core/model/parameters.h"
#include "core/model/state.h"
#include "core/model/workspace.h"

namespace core {

// the largest position or velocity component the checks let through (m, m/s): a scene file's
// range, so that a run never reaches a state its file could not hold
inline constexpr double kBlowupBound = kStateLimit;

// advances the state by model.timeStep in model.substeps equal sub-steps; returns false (and sets
// work.blowup) if a value stopped being finite or bounded, in which case the state is not stepped
// again until work.blowup is cleared. Also false, with work.interrupted set, when work.interrupt
// was raised before a sub-step: the state is then half-way and must be restored by the caller.
bool step(const Model &model, State &state, Workspace &work);

}  // namespace core
