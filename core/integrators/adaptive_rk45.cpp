// Dormand-Prince 5(4): an embedded Runge-Kutta pair. Each trial step evaluates the forces seven
// times; the difference between the fifth- and fourth-order solutions estimates the local error,
// which must stay under the model's tolerance (an absolute bound, in m for positions and m/s for
// velocities, on every component). A rejected step is retried smaller; an accepted one keeps the
// fifth-order solution and suggests the next step size. The step never exceeds the sub-step h it
// is asked to cover, so contacts are still resolved at every sub-step boundary.
#include "core/passes.h"

#include <algorithm>
#include <cmath>

namespace core {

namespace {

// the Butcher tableau of Dormand and Prince (1980)
constexpr int kStages = 7;
constexpr double kA[kStages][kStages] = {
    {0, 0, 0, 0, 0, 0, 0},
    {1.0 / 5, 0, 0, 0, 0, 0, 0},
    {3.0 / 40, 9.0 / 40, 0, 0, 0, 0, 0},
    {44.0 / 45, -56.0 / 15, 32.0 / 9, 0, 0, 0, 0},
    {19372.0 / 6561, -25360.0 / 2187, 64448.0 / 6561, -212.0 / 729, 0, 0, 0},
    {9017.0 / 3168, -355.0 / 33, 46732.0 / 5247, 49.0 / 176, -5103.0 / 18656, 0, 0},
    {35.0 / 384, 0, 500.0 / 1113, 125.0 / 192, -2187.0 / 6784, 11.0 / 84, 0},
};
// fifth-order weights minus fourth-order weights: the error estimate
constexpr double kE[kStages] = {71.0 / 57600,      0, -71.0 / 16695, 71.0 / 1920, -17253.0 / 339200,
                                22.0 / 525, -1.0 / 40};

constexpr double kSafety = 0.9;
constexpr double kMinShrink = 0.2;
constexpr double kMaxGrow = 5.0;
// trial steps one sub-step may take before the run stops as too stiff: far more than any scene
// the scheme suits needs (those take a handful), few enough to stop in well under a second on a
// small scene instead of shrinking the step for ever
constexpr int kMaxTrialsPerSubStep = 100000;

// scratch slots: x0, v0, the accelerations, then kx and kv per stage
constexpr int kX0 = 0, kV0 = 1, kAcc = 2, kKx = 3, kKv = 3 + kStages;

// one trial step of size dt from (x0, v0); leaves the fifth-order solution in the state and
// returns the error norm (≤ 1: within tolerance)
double trialStep(const Model &model, State &state, Workspace &work, double dt)
{
    const Eigen::Matrix3Xd &x0 = scratch(state, work, kX0);
    const Eigen::Matrix3Xd &v0 = scratch(state, work, kV0);
    Eigen::Matrix3Xd &a = scratch(state, work, kAcc);
    for (int stage = 0; stage < kStages; ++stage) {
        // the trial state of this stage: y0 + dt Σ a_ij k_j
        state.position = x0;
        state.velocity = v0;
        for (int j = 0; j < stage; ++j) {
            if (kA[stage][j] == 0.0)
                continue;
            state.position += (dt * kA[stage][j]) * scratch(state, work, kKx + j);
            state.velocity += (dt * kA[stage][j]) * scratch(state, work, kKv + j);
        }
        computeForces(model, state, work);
        accelerations(model, work, a);
        scratch(state, work, kKx + stage) = state.velocity;
        scratch(state, work, kKv + stage) = a;
    }
    // the last stage's trial state is the fifth-order solution (its row of the tableau is the
    // fifth-order weights); the error is dt Σ e_j k_j, measured in units of the tolerance
    double worst = 0.0;
    for (int axis = 0; axis < 2; ++axis) {
        Eigen::Matrix3Xd &error = a;  // reused: the accelerations are stored in the stages
        error.setZero();
        for (int j = 0; j < kStages; ++j)
            if (kE[j] != 0.0)
                error += (dt * kE[j]) * scratch(state, work, (axis == 0 ? kKx : kKv) + j);
        worst = std::max(worst, error.cwiseAbs().maxCoeff());
    }
    return worst / model.tolerance;
}

}  // namespace

void adaptiveRk45(const Model &model, State &state, Workspace &work, double h)
{
    Eigen::Matrix3Xd &x0 = scratch(state, work, kX0);
    Eigen::Matrix3Xd &v0 = scratch(state, work, kV0);
    double dt = state.adaptiveStep > 0.0 ? std::min(state.adaptiveStep, h) : h;
    double covered = 0.0;
    for (int trials = 0; covered < h; ++trials) {
        // a scene far too stiff for an explicit method (strong drag on a light particle) would
        // otherwise shrink the step without end: stop and say so
        if (trials == kMaxTrialsPerSubStep) {
            work.blowup = Blowup{-1, Blowup::Quantity::StepSize, dt, 0, 0.0};
            return;
        }
        // a stiff scene may take many trials: a long step stops among them when asked
        if (interruptRequested(work)) {
            work.interrupted = true;
            return;
        }
        const bool last = dt >= h - covered;
        const double trial = last ? h - covered : dt;
        x0 = state.position;
        v0 = state.velocity;
        const double error = trialStep(model, state, work, trial);
        const double factor =
            error == 0.0 ? kMaxGrow : std::clamp(kSafety * std::pow(error, -0.2), kMinShrink, kMaxGrow);
        // accept within tolerance; a step this small that still misses it means the scene is
        // beyond the scheme (or the tolerance below rounding): stop and say so
        const bool tiny = trial <= 1e-12 * h;
        if (tiny && !(error <= 1.0)) {
            state.position = x0;
            state.velocity = v0;
            work.blowup = Blowup{-1, Blowup::Quantity::StepSize, trial, 0, 0.0};
            return;
        }
        if (error <= 1.0 || tiny) {
            covered = last ? h : covered + trial;
            if (!last || factor < 1.0)
                dt = std::max(trial * factor, 1e-12 * h);  // a shortened final step says nothing about the next one
        } else {
            work.profile.rejectedSteps += 1;
            state.position = x0;
            state.velocity = v0;
            dt = trial * (std::isfinite(factor) ? factor : kMinShrink);
        }
    }
    state.adaptiveStep = dt;
}

}  // namespace core
