#include "geometry.h"
#include "passes.h"

namespace core {

// damped springs exactly as the handout: on end a, -k (l - l0) u - kc ((va - vb)·u) u with
// u = (xa - xb) / l; end b gets the opposite force (Newton's third law)
void addSprings(const Model &model, State &state)
{
    if (!model.plan.springs)
        return;
    const auto &x = state.position;
    const auto &v = state.velocity;
    auto &f = state.force;
    const int count = model.springCount();
    for (int k = 0; k < count; ++k) {
        const int a = model.springA[static_cast<std::size_t>(k)];
        const int b = model.springB[static_cast<std::size_t>(k)];
        const Eigen::Vector3d d = x.col(a) - x.col(b);
        const double length = d.norm();
        const Eigen::Vector3d u = directionOr(d, length);
        const double stretch = length - model.restLength[k];
        const double approach = (v.col(a) - v.col(b)).dot(u);
        const Eigen::Vector3d fa = (-model.stiffness[k] * stretch - model.damping[k] * approach) * u;
        f.col(a) += fa;
        f.col(b) -= fa;
    }
}

}  // namespace core
