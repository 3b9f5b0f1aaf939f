#include "core/passes.h"

namespace core {

// viscous drag of the medium, -c v (pinned particles are at rest, so they get none)
void addDrag(const Model &model, State &state, Workspace &work)
{
    if (!model.plan.drag)
        return;
    work.force.noalias() -= model.viscosity * state.velocity;
}

}  // namespace core
