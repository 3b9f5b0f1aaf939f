#pragma once
// What implicit-euler's, projective's and vbd's solves did, in words for the stability panel and
// springlab-sim's warnings (docs/physics.md, "Stiff solvers").

#include "core/integrators/integrator.h"
#include "core/profile.h"

#include <string>

namespace core {

// projective and vbd: a sub-step whose iterations left more than this share of the energy's
// gradient has barely moved off its first guess, the inertial move: its springs act far softer than
// set. (Less converged than that is the rule on stiff cloth, not a fault: the stiff-cloth example on
// projective leaves up to half the gradient at 0.88% stretch, under xpbd's 2.0%.)
inline constexpr double kUnconvergedResidual = 0.9;

// "10 iterations a sub-step, residual up to 3.2e-3" for the run so far; empty before any solve
std::string solverSummary(Integrator integrator, const Profile &profile);

// the last sub-step's solve: "last sub-step: 10 iterations, residual 3.2e-3"; empty for the other
// integrators and before any solve
std::string lastSolveSummary(Integrator integrator, const Profile &profile);

// a warning when a solve stopped at its cap (conjugate gradients) or left more than
// kUnconvergedResidual of the gradient (projective, vbd), with what to change; else empty
std::string solverWarning(Integrator integrator, const Profile &profile);

}  // namespace core
