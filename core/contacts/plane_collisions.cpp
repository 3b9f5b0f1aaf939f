#include "core/passes.h"

namespace core {

// one-sided planes n·p = offset: a particle closer than its radius is pushed back out along n and,
// if it is moving into the plane, its normal velocity is reflected and scaled by e. A plane is a
// half-space, so a particle found anywhere behind it, however fast it came, is put back in front:
// nothing tunnels through a plane
void collidePlanes(const Model &model, State &state, Workspace &)
{
    if (!model.plan.planeCollisions)
        return;
    const int planes = model.planeCount();
    for (int i : model.freeParticles) {
        for (int k = 0; k < planes; ++k) {
            const auto n = model.planeNormal.col(k);
            const double distance = n.dot(state.position.col(i)) - model.planeOffset[k];
            const double r = model.radius[i];
            if (!(distance < r))
                continue;  // in front (or NaN: never spread to the plane's side)
            state.position.col(i) += (r - distance) * n;
            const double normalSpeed = state.velocity.col(i).dot(n);
            if (normalSpeed < 0.0)
                state.velocity.col(i) -= ((1.0 + contactRestitution(model, normalSpeed)) * normalSpeed) * n;
        }
    }
}

}  // namespace core
