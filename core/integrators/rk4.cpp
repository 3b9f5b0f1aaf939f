#include "core/passes.h"

namespace core {

// classic fourth-order Runge-Kutta on y = (x, v), y' = (v, a(x, v)): four force evaluations
void rk4(const Model &model, State &state, Workspace &work, double h)
{
    Eigen::Matrix3Xd &x0 = scratch(state, work, 0);
    Eigen::Matrix3Xd &v0 = scratch(state, work, 1);
    Eigen::Matrix3Xd &sumX = scratch(state, work, 2);
    Eigen::Matrix3Xd &sumV = scratch(state, work, 3);
    Eigen::Matrix3Xd &a = scratch(state, work, 4);
    x0 = state.position;
    v0 = state.velocity;

    // stages 1 to 4: derivative at the current trial state, weights 1 2 2 1, next trial at c h
    constexpr double weight[4] = {1.0, 2.0, 2.0, 1.0};
    const double next[4] = {0.5 * h, 0.5 * h, h, 0.0};
    for (int stage = 0; stage < 4; ++stage) {
        computeForces(model, state, work);
        accelerations(model, work, a);
        if (stage == 0) {
            sumX = state.velocity;
            sumV = a;
        } else {
            sumX += weight[stage] * state.velocity;
            sumV += weight[stage] * a;
        }
        if (stage < 3) {
            state.position = x0 + next[stage] * state.velocity;
            state.velocity = v0 + next[stage] * a;
        }
    }
    state.position = x0 + (h / 6.0) * sumX;
    state.velocity = v0 + (h / 6.0) * sumV;
}

}  // namespace core
