#include "passes.h"

namespace core {

// weight m g on every particle (a pinned one is never integrated, so its share is harmless)
void addGravity(const Model &model, State &state)
{
    if (!model.plan.gravity)
        return;
    state.force.noalias() += model.gravity * model.mass.transpose();
}

}  // namespace core
