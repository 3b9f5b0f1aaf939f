#include "core/passes.h"

namespace core {

// A spring breaks once its strain (l - l0) / l0 passes its breaking strain: stretch only, since a
// cloth tears when pulled, not when pushed. Checked after the contacts, at the positions the
// sub-step ends with; a broken spring stays broken until the state is rebuilt from the scene.
void breakSprings(const Model &model, State &state, Workspace &)
{
    if (!model.plan.springBreaks || state.springBroken.empty())
        return;
    for (int k = 0; k < model.springCount(); ++k) {
        const double limit = model.breakStrain[k];
        if (!(limit > 0.0) || state.springBroken[static_cast<std::size_t>(k)] != 0)
            continue;
        const int a = model.springA[static_cast<std::size_t>(k)];
        const int b = model.springB[static_cast<std::size_t>(k)];
        const double rest = model.restLength[k];
        const double length = (state.position.col(a) - state.position.col(b)).norm();
        if (length - rest > limit * rest) {
            state.springBroken[static_cast<std::size_t>(k)] = 1;
            // capacity for every spring was reserved with the flags: this never allocates
            state.breaks.push_back({k, state.step + 1, state.time});
        }
    }
}

}  // namespace core
