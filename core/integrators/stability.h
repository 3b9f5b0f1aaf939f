#pragma once
// How large a time step the explicit integrators can take on this scene, and what to say when a
// run blows up. The highest angular frequency ω_max of the linearised springs comes from power
// iteration on M^-½ K M^-½ (symmetric, so its Rayleigh quotient converges fast), with a Gershgorin
// bound as the fallback when the iteration has not settled, and its residual as the room kept for
// the iteration's error where a margin is promised (auto substeps). The damping rate γ of that mode
// (springs' dampers, a zero-rest-length spring's in every direction, and the medium's drag) narrows symplectic Euler's limit from 2/ω to
// (√(γ² + 4ω²) - γ)/ω².

#include "core/blowup.h"
#include "core/model/model.h"
#include "core/model/state.h"

#include <optional>
#include <string>

namespace core {

struct StabilityLimit {
    double omegaMax = 0.0;       // rad/s, the highest angular frequency (0 with no springs)
    double dampingRate = 0.0;    // 1/s, γ of that mode
    double gershgorinOmega = 0.0;  // rad/s, an upper bound on ω_max
    // rad/s, ω_max with room for the power iteration's error: √(ρ + ‖S y − ρ y‖) for its last unit
    // vector y and Rayleigh quotient ρ, or the Gershgorin bound where that is less
    double omegaBound = 0.0;
    bool converged = false;      // the power iteration settled; else omegaMax is the bound

    // the largest stable sub-step for the integrator (s); infinity when any step is stable
    // (implicit, adaptive, or nothing to oscillate), 0 when none is (explicit Euler, undamped)
    double maxSubStep(Integrator integrator) const;
    // the same at omegaBound: never above the true limit, so a share of it keeps its margin
    double safeSubStep(Integrator integrator) const;
};

// analyses the scene linearised at the state (allocates: call it off the step path)
StabilityLimit stabilityLimit(const Model &model, const State &state);

// The same analysis a few iterations at a time, so that the editor can spread it between the
// steps of a large scene (a 200 × 200 cloth takes as long as a dozen steps) and stop it for
// waiting messages: run() or runSlice() as often as wanted, then limit(); the result has the same bits as
// stabilityLimit's. It keeps a copy of the state it linearises at; the model must outlive it.
class StabilityAnalysis {
public:
    StabilityAnalysis(const Model &model, const State &state);
    // at most `iterations` more products of the power iteration; true once the limit is known
    bool run(int iterations);
    // one slice of the work: up to kSliceSprings springs of a product (one of 6·10⁶ springs took a
    // quarter of a second, too long for a Pause to wait), or the end of one; true once the limit
    // is known
    bool runSlice();
    static constexpr int kSliceSprings = 1 << 16;
    bool done() const { return m_done; }
    // the limit, once done()
    const StabilityLimit &limit() const { return m_limit; }

private:
    bool slice();
    bool productSlice(bool damping);

    const Model &m_model;
    State m_state;
    Eigen::VectorXd m_rootInvMass;
    Eigen::Matrix3Xd m_y, m_scaled, m_next;
    double m_lambda = 0.0;
    double m_residual = 0.0;  // ‖S y − ρ y‖ of the last pass
    int m_iteration = 0;
    int m_passes = 0;  // the most passes this model's size allows
    int m_nextSpring = 0;  // where the product in progress goes on
    bool m_dampingProduct = false;  // settled: the last product, the damping's, is in progress
    bool m_done = false;
    StabilityLimit m_limit;
};

// the share of the limit a sub-step is kept under where the limit sets the substeps: the energy of
// a lightly damped mode already swings widely just below it (docs/benchmarks.md, stability)
constexpr double kStableShare = 0.9;

// the fewest substeps, at least `least` and at most `most`, that keep timeStep / substeps under
// kStableShare of the limit for the integrator (its safeSubStep: the power iteration alone can
// only overestimate the limit)
int stableSubsteps(const StabilityLimit &limit, Integrator integrator, double timeStep, int least, int most);

// The pair speed limit (docs/physics.md): pairs are looked at only where the sub-steps end, so two
// particles that move apart by more than r_i + r_j in one sub-step can pass through each other. No
// pair's relative speed exceeds the sum of the two highest speeds, and no pair touches at less than
// the sum of the two smallest radii, which gives a check in one pass over the particles.
struct PairSpeedExcess {
    int fastest = -1;              // the fastest particle
    double relativeSpeed = 0.0;    // m/s, the bound: the two highest speeds together
    double displacement = 0.0;     // m, relativeSpeed × the sub-step
    double contactDistance = 0.0;  // m, the two smallest radii together
    int substeps = 1;              // the fewest substeps that bring the displacement under it
};
// nullopt when particle contacts are off or the bound is inside the limit
std::optional<PairSpeedExcess> pairSpeedExcess(const Model &model, const State &state);
// "Particles move up to 0.24 m apart per sub-step (up to 24 m/s, particle 3 the fastest), more
// than the 0.1 m at which the smallest pair touches: they may pass through each other. Use ≥ 3
// substeps."
std::string explainPairSpeed(const PairSpeedExcess &excess);

// one message naming what failed, where and why, with the fix, e.g. "Particle 17's velocity
// became infinite at t = 2.31 s (step 231). The time step 0.01 s is 3.2× the stability limit
// 0.0031 s for stiffness 1e5 N/m with symplectic-euler: use ≥ 4 substeps or the projective
// integrator (…) or xpbd (…)." The limit is best computed at the last good state.
std::string explainBlowup(const Model &model, const Blowup &blowup, const StabilityLimit &limit);

}  // namespace core
