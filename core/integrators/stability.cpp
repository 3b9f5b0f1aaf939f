#include "core/integrators/stability.h"

#include "core/geometry.h"
#include "core/model/parameters.h"
#include "core/springs/spring_jacobian.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

namespace core {

namespace {

// The power iteration counts as settled once its Rayleigh quotient changes by under kSettled a
// pass, and then goes on to kTight while the work allows (at least kLeastPasses, at most
// kMostPasses, about kSpringPasses spring products in all): a quotient settled at 1e-6 can still
// sit a few per cent low, on a plateau near the second eigenvalue
constexpr double kSettled = 1e-6;
constexpr double kTight = 1e-10;
constexpr int kLeastPasses = 300;
constexpr int kMostPasses = 2000;
constexpr double kSpringPasses = 4e6;

// A spring of rest length 0 pulls its ends together along whatever line joins them, kI in every
// direction, so the power iteration's vector is any direction of that spring's top mode. Its damper
// acts along the spring, and as the ends swing through each other the spring turns to follow
// them: the motion it damps is along any line. The Jacobian at one state has the damper along
// that state's direction only, so the damping of the vector the iteration lands on was a matter
// of chance (c cos² of the angle). Counted here in every direction: kc (I - u uᵀ) added to the
// Jacobian's kc u uᵀ, which is the most damped direction of that mode, the one that sets the
// symplectic Euler limit.
void addZeroLengthDampingAcross(const Model &model, const State &state, const Eigen::Matrix3Xd &y,
                                Eigen::Matrix3Xd &out)
{
    for (int k = 0; k < model.springCount(); ++k) {
        if (model.restLength[k] != 0.0 || model.damping[k] == 0.0 || state.isBroken(k))
            continue;
        const int a = model.springA[static_cast<std::size_t>(k)];
        const int b = model.springB[static_cast<std::size_t>(k)];
        const Eigen::Vector3d d = state.position.col(a) - state.position.col(b);
        const Eigen::Vector3d u = directionOr(d, d.norm());
        const Eigen::Vector3d dy = y.col(a) - y.col(b);
        const Eigen::Vector3d t = model.damping[k] * (dy - u.dot(dy) * u);
        out.col(a) += t;
        out.col(b) -= t;
    }
}

std::string format(double value, int digits = 2)
{
    std::ostringstream out;
    out.precision(digits);
    out << value;
    return out.str();
}

// the fewest significant digits (at least 2) at which a and b read differently
int distinctDigits(double a, double b)
{
    int digits = 2;
    while (digits < 17 && format(a, digits) == format(b, digits))
        ++digits;
    return digits;
}

// the largest sub-step at which the drag -c v is stable for the model's explicit integrator: the
// velocity of the lightest free particle decays at rate c/m, and an explicit step longer than
// about 2 m/c (2.78 m/c for RK4) overshoots and grows; infinite where nothing limits it
double dragStepLimit(const Model &model)
{
    const double infinity = std::numeric_limits<double>::infinity();
    double rate = 0.0;
    for (int i : model.freeParticles)
        rate = std::max(rate, model.viscosity * model.invMass[i]);
    if (!(rate > 0.0))
        return infinity;
    switch (model.integrator) {
    case Integrator::SymplecticEuler:
    case Integrator::ExplicitEuler:
    case Integrator::VelocityVerlet: return 2.0 / rate;
    case Integrator::Rk4: return 2.785 / rate;
    case Integrator::ImplicitEuler:
    case Integrator::AdaptiveRk45:
    case Integrator::Xpbd:  // xpbd: the drag is an external force on its kick alone
    case Integrator::Projective:
    case Integrator::Vbd: return infinity;
    }
    return infinity;
}

// the largest stable sub-step for the integrator at the highest angular frequency omegaMax
double stepLimit(double omegaMax, double dampingRate, Integrator integrator)
{
    const double infinity = std::numeric_limits<double>::infinity();
    if (omegaMax <= 0.0)
        return infinity;
    switch (integrator) {
    case Integrator::SymplecticEuler:
    case Integrator::VelocityVerlet:
        return (std::sqrt(dampingRate * dampingRate + 4.0 * omegaMax * omegaMax) - dampingRate) /
               (omegaMax * omegaMax);
    case Integrator::Rk4: return 2.0 * std::sqrt(2.0) / omegaMax;
    case Integrator::ExplicitEuler:
        // stable only while damping outweighs the growth: |1 + hλ|² = 1 - γh + ω²h² < 1 for
        // λ = -γ/2 ± i√(ω² - γ²/4), so h < γ/ω² (γ ≤ 2ω)
        return dampingRate / (omegaMax * omegaMax);
    case Integrator::ImplicitEuler:
    case Integrator::AdaptiveRk45:
    case Integrator::Xpbd:  // springs are constraints with compliance 1/k: no explicit limit
    case Integrator::Projective:
    case Integrator::Vbd: return infinity;  // implicit Euler solved as a minimisation
    }
    return infinity;
}

}  // namespace

double StabilityLimit::maxSubStep(Integrator integrator) const
{
    return stepLimit(omegaMax, dampingRate, integrator);
}

double StabilityLimit::safeSubStep(Integrator integrator) const
{
    return stepLimit(omegaBound, dampingRate, integrator);
}

StabilityAnalysis::StabilityAnalysis(const Model &model, const State &state) : m_model(model), m_state(state)
{
    const int n = model.particleCount();
    if (model.springCount() == 0 || model.freeParticles.empty()) {
        m_done = true;
        return;
    }
    m_rootInvMass = model.invMass.cwiseSqrt();

    // Gershgorin on the 3×3 blocks: λ ≤ max_i Σ_springs k (w_i + √(w_i w_j))
    Eigen::VectorXd rows = Eigen::VectorXd::Zero(n);
    for (int k = 0; k < model.springCount(); ++k) {
        const int a = model.springA[static_cast<std::size_t>(k)];
        const int b = model.springB[static_cast<std::size_t>(k)];
        const double cross = m_rootInvMass[a] * m_rootInvMass[b];
        rows[a] += model.stiffness[k] * (model.invMass[a] + cross);
        rows[b] += model.stiffness[k] * (model.invMass[b] + cross);
    }
    m_limit.gershgorinOmega = std::sqrt(rows.maxCoeff());

    // power iteration from a fixed, mixed start vector (deterministic)
    m_y.resize(3, n);
    m_scaled.resize(3, n);
    m_next.resize(3, n);
    std::uint32_t seed = 12345u;
    for (int i = 0; i < n; ++i)
        for (int axis = 0; axis < 3; ++axis) {
            seed = seed * 1664525u + 1013904223u;
            m_y(axis, i) = model.invMass[i] > 0.0 ? static_cast<double>(seed >> 8) / double(1u << 24) - 0.5 : 0.0;
        }
    m_y.normalize();
    m_passes = static_cast<int>(
        std::clamp(kSpringPasses / model.springCount(), double(kLeastPasses), double(kMostPasses)));
}

bool StabilityAnalysis::run(int iterations)
{
    for (int count = 0; count < iterations && !m_done; ++count)
        while (!slice()) {
        }
    return m_done;
}

bool StabilityAnalysis::runSlice()
{
    if (!m_done)
        slice();
    return m_done;
}

// works on the product of m_y with M^-½ K M^-½ (damping: M^-½ C M^-½) into m_next, the springs in
// the order of one whole product so that the bits are the same; true once it is complete
bool StabilityAnalysis::productSlice(bool damping)
{
    if (m_nextSpring == 0) {
        m_scaled.noalias() = m_y * m_rootInvMass.asDiagonal();
        m_next.setZero();
    }
    const int springs = m_model.springCount();
    const int end = springs - m_nextSpring > kSliceSprings ? m_nextSpring + kSliceSprings : springs;
    addSpringJacobians(m_model, m_state, m_scaled, damping ? 0.0 : 1.0, damping ? 1.0 : 0.0, m_next, m_nextSpring, end);
    m_nextSpring = end;
    if (end < springs)
        return false;
    m_nextSpring = 0;
    if (damping) {
        addZeroLengthDampingAcross(m_model, m_state, m_scaled, m_next);
        m_next += m_model.viscosity * m_scaled;
    }
    m_next = m_next * m_rootInvMass.asDiagonal();
    return true;
}

// a slice of the analysis; true when it ended a product of the power iteration, or the analysis
bool StabilityAnalysis::slice()
{
    if (m_dampingProduct) {
        // the damping rate of the top mode: its Rayleigh quotient of M^-½ C M^-½
        if (!productSlice(true))
            return false;
        m_limit.dampingRate = std::max(0.0, m_y.cwiseProduct(m_next).sum());
        m_done = true;
        return true;
    }

    // one product with M^-½ K M^-½, until the Rayleigh quotient has settled tightly or the passes
    // run out
    bool settled = m_iteration >= m_passes;
    if (!settled) {
        if (!productSlice(false))
            return false;
        const double rayleigh = m_y.cwiseProduct(m_next).sum();
        const double norm = m_next.norm();
        if (!(norm > 0.0)) {
            settled = true;
        } else {
            // ‖S y − ρ y‖ of this y, before y moves on
            m_residual = (m_next - rayleigh * m_y).norm();
            m_y = m_next / norm;
            const double change = std::abs(rayleigh - m_lambda);
            m_lambda = rayleigh;
            if (m_iteration > 10 && change <= kSettled * rayleigh)
                m_limit.converged = true;
            settled = (m_limit.converged && change <= kTight * rayleigh) || ++m_iteration >= m_passes;
        }
    }
    if (!settled)
        return true;
    m_limit.omegaMax = m_limit.converged ? std::sqrt(std::max(m_lambda, 0.0)) : m_limit.gershgorinOmega;
    // The Rayleigh quotient only ever underestimates λ_max: a settled quotient can still be a few
    // per cent low where the top eigenvalues lie close together (a 20-particle network: ω 2.2% low,
    // auto substeps at 91% of the limit). For a unit y whose top eigenvector holds at least half its
    // weight, ρ + ‖S y − ρ y‖ ≥ λ_max (the residual is at least |a₁|/√(1 − a₁²) × (λ_max − ρ)), and
    // the iteration grows that weight every pass; Gershgorin caps it
    m_limit.omegaBound = m_limit.converged
                             ? std::min(m_limit.gershgorinOmega, std::sqrt(std::max(m_lambda + m_residual, 0.0)))
                             : m_limit.gershgorinOmega;
    m_limit.omegaBound = std::max(m_limit.omegaBound, m_limit.omegaMax);

    // the damping's product comes next, in slices too (within the same run() iteration)
    m_dampingProduct = true;
    return false;
}

StabilityLimit stabilityLimit(const Model &model, const State &state)
{
    StabilityAnalysis analysis(model, state);
    analysis.run(kMostPasses + 1);
    return analysis.limit();
}

std::optional<PairSpeedExcess> pairSpeedExcess(const Model &model, const State &state)
{
    const int n = model.particleCount();
    if (!model.plan.particleCollisions || n < 2)
        return std::nullopt;
    // the two highest speeds (the fastest's index kept) and the two smallest radii
    double fastest = 0.0, second = 0.0;
    int fastestIndex = -1;
    for (int i : model.freeParticles) {
        const double speed = state.velocity.col(i).norm();
        if (speed > fastest) {
            second = fastest;
            fastest = speed;
            fastestIndex = i;
        } else if (speed > second) {
            second = speed;
        }
    }
    double smallest = std::numeric_limits<double>::infinity(), nextSmallest = smallest;
    for (int i = 0; i < n; ++i) {
        const double r = model.radius[i];
        if (r < smallest) {
            nextSmallest = smallest;
            smallest = r;
        } else if (r < nextSmallest) {
            nextSmallest = r;
        }
    }
    PairSpeedExcess excess;
    excess.fastest = fastestIndex;
    excess.relativeSpeed = fastest + second;
    excess.displacement = excess.relativeSpeed * model.subStep();
    excess.contactDistance = smallest + nextSmallest;
    if (!(excess.displacement > excess.contactDistance))
        return std::nullopt;
    excess.substeps =
        static_cast<int>(std::min(std::ceil(excess.relativeSpeed * model.timeStep / excess.contactDistance), 1e9));
    return excess;
}

std::string explainPairSpeed(const PairSpeedExcess &excess)
{
    std::ostringstream out;
    out << "Particles move up to " << format(excess.displacement) << " m apart per sub-step (up to "
        << format(excess.relativeSpeed) << " m/s, particle " << excess.fastest << " the fastest), more than the "
        << format(excess.contactDistance) << " m at which the smallest pair touches: they may pass through each "
        << "other. Use ≥ " << excess.substeps << " substeps.";
    return out.str();
}

int stableSubsteps(const StabilityLimit &limit, Integrator integrator, double timeStep, int least, int most)
{
    const double maxStep = limit.safeSubStep(integrator);
    if (!(maxStep > 0.0))
        return most;  // no step is stable: as many as allowed, the message says why
    const double needed = std::ceil(timeStep / (kStableShare * maxStep));
    return needed >= double(most) ? most : std::max(least, static_cast<int>(needed));
}

// the integrators stable at any step for stiff springs and strong drag, as springlab-bench stiff
// measured them (docs/benchmarks.md, "Stiff materials"): projective the cheapest within 1% stretch,
// xpbd the one that keeps the motion at 10 ms steps
const char *const kStiffIntegrators =
    "the projective integrator (the cheapest measured for stiff springs, 2.3× less CPU than xpbd on a "
    "stiff cloth, but it damps the motion at large steps) or xpbd (keeps the motion, at 100 to 200 substeps)";

std::string explainBlowup(const Model &model, const Blowup &blowup, const StabilityLimit &limit)
{
    std::ostringstream out;
    if (blowup.quantity == Blowup::Quantity::StepSize) {
        out << integratorName(model.integrator) << " could not meet its tolerance " << format(model.tolerance)
            << " within a sub-step at t = " << format(blowup.time) << " s (step " << blowup.step
            << "): its trial steps shrank to " << format(blowup.value) << " s against a sub-step of "
            << format(model.subStep()) << " s. The scene is too stiff for an explicit method (strong drag on a "
            << "light particle, or very stiff springs): use " << kStiffIntegrators << ", or a looser tolerance.";
        return out.str();
    }
    // a particle that went past the world's edge at a finite speed has left it: said so, with where
    // and how fast, and blamed on nothing the scene does not have
    const bool holds = model.plan.springs || model.plan.planeCollisions || model.plan.particleCollisions;
    if (blowup.quantity == Blowup::Quantity::Position && std::isfinite(blowup.value) &&
        std::isfinite(blowup.speed) && blowup.speed <= kStateLimit) {
        out << "Particle " << blowup.particle << " left the world at t = " << format(blowup.time) << " s (step "
            << blowup.step << "): it was at (" << format(blowup.where[0]) << ", " << format(blowup.where[1]) << ", "
            << format(blowup.where[2]) << ") m, moving at " << format(blowup.speed) << " m/s. The world ends "
            << format(kStateLimit) << " m from the origin along each axis, the most a scene file holds.";
        if (!holds) {
            out << " Nothing in the scene holds it back (no springs, no contacts): it "
                << (model.plan.gravity ? "fell" : "coasted") << " out by its own motion. Start it slower, or add "
                << "planes to keep it in.";
            return out.str();
        }
    } else if (blowup.quantity == Blowup::Quantity::Energy) {
        out << "The total energy grew from " << format(blowup.from) << " J to " << format(blowup.value)
            << " J by t = " << format(blowup.time) << " s (step " << blowup.step
            << "), more than a thousandfold with no work done on the scene: the motion was running away";
        if (blowup.particle >= 0)
            out << " (fastest: particle " << blowup.particle << ", at " << format(blowup.speed) << " m/s at ("
                << format(blowup.where[0]) << ", " << format(blowup.where[1]) << ", " << format(blowup.where[2])
                << ") m)";
        out << ".";
    } else if (blowup.quantity == Blowup::Quantity::SheetPairs) {
        out << "The sheets flew apart at t = " << format(blowup.time) << " s (step " << blowup.step
            << "): their collisions had more than " << format(blowup.value)
            << " pairs of particles, edges and triangles within reach in one sub-step, where even a crumpled "
            << "sheet has a few per particle, so they could no longer be kept from passing through each other.";
    } else {
        out << "Particle " << blowup.particle << "'s "
            << (blowup.quantity == Blowup::Quantity::Velocity ? "velocity" : "position") << " became "
            << (std::isfinite(blowup.value) ? "too large (" + format(blowup.value) + ")" : std::string("infinite"))
            << " at t = " << format(blowup.time) << " s (step " << blowup.step << ").";
    }

    // the reason, when the step is past an explicit limit: the drag's, then the springs'
    const double h = model.subStep();
    const double maxStep = limit.maxSubStep(model.integrator);
    const std::string name(integratorName(model.integrator));
    const double most = parameterInfo(Parameter::Substeps).maximum;
    // "use ≥ N substeps" only where N is allowed; beyond, what else helps. projective and xpbd are
    // stable at any step for the causes named here: the springs (backward Euler's minimum; xpbd's
    // compliant constraints) and the drag (both take it implicitly)
    const auto advice = [&](double stableStep, const std::string &otherwise) {
        const double needed = std::ceil(model.timeStep / (kStableShare * stableStep));
        std::ostringstream text;
        if (needed <= most)
            text << "use ≥ " << static_cast<int>(needed) << " substeps or " << kStiffIntegrators << ".";
        else
            text << "it would take " << format(needed) << " substeps, more than the " << format(most)
                 << " allowed: use " << kStiffIntegrators << otherwise << ".";
        return text.str();
    };
    const double dragStep = dragStepLimit(model);
    if (dragStep < h) {
        out << " The drag (viscosity " << format(model.viscosity) << " kg/s on a particle of "
            << format(1.0 / model.invMass.maxCoeff()) << " kg) is too strong for the sub-step: " << name
            << " needs sub-steps under " << format(dragStep) << " s, and the sub-step is " << format(h) << " s; "
            << advice(dragStep, ", or a lower viscosity");
    } else if (!(maxStep >= h)) {  // NaN too: ω² past a double's range leaves the analysis no number
        const double stiffest = model.springCount() > 0 ? model.stiffness.maxCoeff() : 0.0;
        if (!std::isfinite(limit.omegaMax) || (maxStep == 0.0 && model.integrator != Integrator::ExplicitEuler)) {
            out << " The springs' stiffest vibration is faster than a double can hold (stiffness up to "
                << format(stiffest) << " N/m, lightest particle " << format(1.0 / model.invMass.maxCoeff())
                << " kg): no sub-step is stable; use softer springs or heavier particles.";
        } else if (maxStep > 0.0) {
            // enough digits that the step and the limit read differently (0.201 against 0.2)
            const int digits = distinctDigits(h, maxStep);
            // the springs' damping, where it moves the limit (symplectic Euler and Verlet narrower,
            // explicit Euler stable only through it)
            const bool damped = limit.dampingRate > 0.0 && model.integrator != Integrator::Rk4;
            out << " The time step " << format(h, digits) << " s is "
                << format(h / maxStep, distinctDigits(h / maxStep, 1.0))
                << "× the stability limit " << format(maxStep, digits) << " s for stiffness " << format(stiffest)
                << " N/m" << (damped ? " and damping rate " + format(limit.dampingRate) + " 1/s" : std::string())
                << " with " << name << ": "
                << advice(limit.safeSubStep(model.integrator), ", softer springs or heavier particles");
        } else {
            out << " " << name << " is unstable at any step on undamped springs (stiffness up to "
                << format(stiffest) << " N/m): use symplectic-euler, or " << kStiffIntegrators << ".";
        }
    } else {
        // what the scene has that could have thrown it: its contacts, else a force applied from outside
        const bool contacts = model.plan.planeCollisions || model.plan.particleCollisions;
        out << " The time step " << format(h) << " s is within "
            << (model.plan.springs ? "the springs' stability limit" : "every stability limit") << "; "
            << (contacts ? "a contact or a force applied from outside (a drag, the steering keys)"
                         : "a force applied from outside (a drag, the steering keys)")
            << " may have been too violent: try more substeps, a smaller time step"
            << (model.plan.springs ? std::string(", or ") + kStiffIntegrators + "." : std::string("."));
    }
    return out.str();
}

}  // namespace core
