#include "parallel.h"
#include "passes.h"

namespace core {

Eigen::Matrix3Xd &scratch(State &state, int index)
{
    Eigen::Matrix3Xd &array = state.scratchArrays[static_cast<std::size_t>(index)];
    if (array.cols() != state.position.cols())
        array.resize(3, state.position.cols());  // once, on first use: later steps reuse it
    return array;
}

namespace {

// the handout's scheme: the new velocity moves the particle
void symplecticEuler(const Model &model, State &state, double h)
{
    computeForces(model, state);
    parallelFor(static_cast<int>(model.freeParticles.size()), [&](int f) {
        const int i = model.freeParticles[static_cast<std::size_t>(f)];
        state.velocity.col(i) += (h * model.invMass[i]) * state.force.col(i);
        state.position.col(i) += h * state.velocity.col(i);
    });
}

// forward Euler: position and velocity both advance from the old state
void explicitEuler(const Model &model, State &state, double h)
{
    computeForces(model, state);
    parallelFor(static_cast<int>(model.freeParticles.size()), [&](int f) {
        const int i = model.freeParticles[static_cast<std::size_t>(f)];
        state.position.col(i) += h * state.velocity.col(i);
        state.velocity.col(i) += (h * model.invMass[i]) * state.force.col(i);
    });
}

// kick-drift-kick: half a velocity step, a full position step, half a velocity step with the
// forces at the new position. Dampers need the new velocity too, which is not known yet: they are
// given the prediction v + h a (error O(h²)), which keeps the scheme second order; without
// velocity-dependent forces it is exactly the classic velocity Verlet
void velocityVerlet(const Model &model, State &state, double h)
{
    Eigen::Matrix3Xd &a = scratch(state, 0);
    Eigen::Matrix3Xd &half = scratch(state, 1);
    computeForces(model, state);
    accelerations(model, state, a);
    half = state.velocity + (0.5 * h) * a;
    state.position += h * half;
    state.velocity += h * a;  // the prediction the dampers see
    computeForces(model, state);
    accelerations(model, state, a);
    state.velocity = half + (0.5 * h) * a;
}

}  // namespace

// advances every free particle by h; pinned ones have zero inverse mass and zero velocity, so the
// whole-array schemes leave them where they are
void integrate(const Model &model, State &state, double h)
{
    switch (model.integrator) {
    case Integrator::SymplecticEuler: symplecticEuler(model, state, h); return;
    case Integrator::ExplicitEuler: explicitEuler(model, state, h); return;
    case Integrator::VelocityVerlet: velocityVerlet(model, state, h); return;
    case Integrator::Rk4: rk4(model, state, h); return;
    case Integrator::ImplicitEuler: implicitEuler(model, state, h); return;
    case Integrator::AdaptiveRk45: adaptiveRk45(model, state, h); return;
    }
}

}  // namespace core
