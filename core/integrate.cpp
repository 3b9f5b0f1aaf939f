#include "passes.h"

namespace core {

namespace {

// the handout's scheme: the new velocity moves the particle
void symplecticEuler(const Model &model, State &state, double h)
{
    for (int i : model.freeParticles) {
        state.velocity.col(i) += (h * model.invMass[i]) * state.force.col(i);
        state.position.col(i) += h * state.velocity.col(i);
    }
}

// forward Euler: position and velocity both advance from the old state
void explicitEuler(const Model &model, State &state, double h)
{
    for (int i : model.freeParticles) {
        state.position.col(i) += h * state.velocity.col(i);
        state.velocity.col(i) += (h * model.invMass[i]) * state.force.col(i);
    }
}

}  // namespace

// advances every free particle by h from the forces in state.force; pinned ones never move
void integrate(const Model &model, State &state, double h)
{
    switch (model.integrator) {
    case Integrator::SymplecticEuler: symplecticEuler(model, state, h); return;
    case Integrator::ExplicitEuler: explicitEuler(model, state, h); return;
    }
}

}  // namespace core
