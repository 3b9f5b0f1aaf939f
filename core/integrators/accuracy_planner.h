#pragma once
// The accuracy planner: which fixed-step integrator, with how many substeps, keeps the local error
// of one sub-step under a requested tolerance at the least computing cost on this machine.
//
// For an integrator of order p the local error of a sub-step h is C h^(p+1). The planner measures
// it by step doubling (error_estimate.h) from the current state, first at the scene's own
// sub-step, and solves for the sub-step the tolerance allows, h = (tol / C)^(1/(p+1)), hence the
// substep count ceil(timeStep / h). Away from small h the constant C itself changes, so the count
// is measured again where it lands, and finally settled by bisection to the smallest count whose
// measured error is within the tolerance (the error falls as the count grows). Every figure in a
// row of the plan is measured at the count it shows, not extrapolated.
//
// The error compared with the tolerance is max(‖δx‖∞, ‖δv‖∞ / ω_max), with ω_max the stiffest
// angular frequency of the springs (stability.h). The position error alone depends on the phase:
// to leading order it vanishes where the acceleration does for the Euler schemes (at the rest
// length) and at the turning points for velocity Verlet and RK4; on the damped oscillator a plan
// made at such a moment would underrate C by about 4× (RK4), 7× (velocity Verlet) and 450×
// (symplectic Euler), and miss the tolerance a quarter period later. A velocity error δv of an
// oscillation at ω becomes a position error of amplitude δv / ω, so the larger of the two is what
// the step costs over a period (on one spring closely; elsewhere it is at least the position
// error, since ω_max bounds the frequencies from above).
//
// Explicit schemes are also held below their stability limit (stability.h's maxSubStep, which
// bounds ω_max from a converged power iteration or else by Gershgorin) with a 10 % margin; a
// scheme with no stable step at all (explicit Euler on undamped springs) is never picked.
//
// Cost per simulated second = substeps × force evaluations per sub-step × seconds per evaluation
// / timeStep. Evaluations are counted on a trial sub-step: 1 for the Euler schemes, 2 for velocity
// Verlet, 4 for RK4. implicit-euler, projective and vbd do their work in a factorisation,
// back-substitutions or sweeps rather than evaluations: their sub-step is timed against a force
// evaluation on the same state and counted as that many evaluations (at least 1). The vector updates, contacts and checks of
// a sub-step are not counted: the figure is a lower bound on the whole cost, and the comparison
// between integrators is what it is for. adaptive-rk45 chooses its own steps and is not planned.
//
// The planner allocates and steps copies of the state: call it off the step path (the editor's
// worker runs it between two steps, when asked).

#include "core/integrators/integrator.h"
#include "core/model/model.h"
#include "core/profile.h"
#include "core/model/state.h"

#include <atomic>
#include <string>
#include <vector>

namespace core {

// one row of the plan: an integrator at the fewest substeps that meet the tolerance
struct PlanCandidate {
    Integrator integrator = Integrator::SymplecticEuler;
    int order = 1;
    int substeps = 1;
    double localError = 0.0;      // m per sub-step at that count, measured as above
    double errorConstant = 0.0;   // C = localError / h^(p+1), m/s^(p+1)
    double accuracyStep = 0.0;    // s, (tol / C)^(1/(p+1)): the largest sub-step C allows; inf when C = 0
    double stableStep = 0.0;      // s, the largest sub-step allowed by stability; inf when unlimited
    bool stabilityLimited = false;  // the stability limit, not the tolerance, sets the count
    double evaluationsPerSubstep = 0.0;
    double secondsPerSimulatedSecond = 0.0;  // computing time per simulated second (force evaluations)
    bool feasible = false;  // stable, within the tolerance, at most the substep cap
    std::string reason;     // why not feasible; empty when feasible
};

struct AccuracyPlan {
    double tolerance = 0.0;             // m per sub-step, as requested
    double timeStep = 0.0;              // s, the scene's, which the substeps divide
    double secondsPerEvaluation = 0.0;  // s, the measured cost of one force evaluation
    std::vector<PlanCandidate> candidates;  // every fixed-step integrator, in kIntegrators order
    int chosen = -1;  // index of the cheapest feasible candidate; -1 when none is feasible
    // the stop flag was raised before the plan was done (the editor closing): no rows, nothing
    // chosen
    bool stopped = false;

    const PlanCandidate *pick() const { return chosen >= 0 ? &candidates[static_cast<std::size_t>(chosen)] : nullptr; }
};

// the margin kept below an explicit scheme's stability limit
inline constexpr double kStabilityMargin = 0.9;

// plans for the model's timeStep from the state; tolerance in m (> 0), secondsPerEvaluation > 0.
// A plan can take minutes (a row may bisect up to the cap of substeps): a raised `stop` ends it
// between two sub-steps of its trials, stopped
AccuracyPlan planAccuracy(const Model &model, const State &state, double tolerance, double secondsPerEvaluation,
                          const std::atomic<bool> *stop = nullptr);

// the measured cost of one force evaluation: the force stages' seconds in a run's profile over
// its evaluations; 0 while it has too few evaluations to say
double profiledSecondsPerEvaluation(const Profile &profile);

// the cost of one force evaluation, timed on a copy of the state
double timedSecondsPerEvaluation(const Model &model, const State &state);

}  // namespace core
