#include "core/springs/spring_jacobian.h"

#include "core/geometry.h"

#include <algorithm>

namespace core {

void addSpringJacobians(const Model &model, const State &state, const Eigen::Matrix3Xd &y, double stiffnessScale,
                        double dampingScale, Eigen::Matrix3Xd &out)
{
    addSpringJacobians(model, state, y, stiffnessScale, dampingScale, out, 0, model.springCount());
}

void addSpringJacobians(const Model &model, const State &state, const Eigen::Matrix3Xd &y, double stiffnessScale,
                        double dampingScale, Eigen::Matrix3Xd &out, int first, int last)
{
    for (int k = first; k < last; ++k) {
        if (state.isBroken(k))
            continue;
        const int a = model.springA[static_cast<std::size_t>(k)];
        const int b = model.springB[static_cast<std::size_t>(k)];
        // the spring's direction and transverse stiffness (per k) at the current positions
        const Eigen::Vector3d d = state.position.col(a) - state.position.col(b);
        const double length = d.norm();
        const Eigen::Vector3d u = directionOr(d, length);
        const double transverse = length > 0.0 ? std::max(0.0, 1.0 - model.restLength[k] / length) : 0.0;

        const Eigen::Vector3d dy = y.col(a) - y.col(b);
        const Eigen::Vector3d alongPart = u.dot(dy) * u;
        const Eigen::Vector3d t = (stiffnessScale * model.stiffness[k]) * (transverse * (dy - alongPart) + alongPart) +
                                  (dampingScale * model.damping[k]) * alongPart;
        out.col(a) += t;
        out.col(b) -= t;
    }
}

}  // namespace core
