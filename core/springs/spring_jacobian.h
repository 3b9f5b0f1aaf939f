#pragma once
// Products with the springs' linearisation, without building a matrix: used by the implicit
// integrator's solve and by the stability analysis.

#include "core/model/model.h"
#include "core/model/state.h"

namespace core {

// out += stiffnessScale · (-∂f/∂x) y + dampingScale · (-∂f/∂v) y over every spring. A spring's
// stiffness Jacobian is -k [(1 - l0/l)(I - u uᵀ) + u uᵀ], its damper's -kc u uᵀ; the transverse
// factor is clamped at 0 for a compressed spring, which keeps both products positive
// semi-definite (a compressed spring's sideways instability is buckling, a physical one)
void addSpringJacobians(const Model &model, const State &state, const Eigen::Matrix3Xd &y, double stiffnessScale,
                        double dampingScale, Eigen::Matrix3Xd &out);
// the same over the springs [first, last) alone: a product taken in slices, in order, has the
// bits of the whole
void addSpringJacobians(const Model &model, const State &state, const Eigen::Matrix3Xd &y, double stiffnessScale,
                        double dampingScale, Eigen::Matrix3Xd &out, int first, int last);

}  // namespace core
