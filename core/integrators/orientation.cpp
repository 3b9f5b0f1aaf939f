// The particles' orientations. A particle's spin changes only at its contacts (springs pull on its
// centre, gravity and drag act on its centre), so between them it is constant and the orientation
// turns exactly: q' = exp(½ h ω) q, with ω as the contacts leave it at the end of the sub-step, the
// same for every integrator (docs/physics.md, "Spin and rolling").

#include "core/contacts/contact_spin.h"
#include "core/passes.h"

namespace core {

void turnParticles(const Model &model, State &state, double h)
{
    if (!model.plan.spin)
        return;  // (step() has fitted the state's spin to the model)
    for (int i = 0; i < model.particleCount(); ++i)
        state.orientation.col(i) = turned(state.orientation.col(i), state.angularVelocity.col(i), h);
}

}  // namespace core
