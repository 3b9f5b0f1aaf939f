#pragma once
// What projective.cpp and vbd.cpp share: both minimise the same backward Euler energy G(x) over a
// sub-step (docs/physics.md, "Stiff solvers"), starting from the inertial target, accelerating
// their iterations the same way and taking the velocity from the move.

#include "core/model/model.h"
#include "core/model/state.h"
#include "core/model/workspace.h"

#include <Eigen/Core>
#include <vector>

namespace core {

// x0 = the sub-step's start; y = x0 + h v + h² w f_ext (gravity and applied forces), the inertial
// target; the free particles moved to y, the first guess. One force evaluation
void startVariationalStep(const Model &model, State &state, Workspace &work, double h, Eigen::Matrix3Xd &x0,
                          Eigen::Matrix3Xd &y);

// each spring's length at the sub-step's start, into lengths (sized to the springs)
void startLengths(const Model &model, const Eigen::Matrix3Xd &x0, std::vector<double> &lengths);

// v = (x − x0) / h for the free particles (pinned ones stay where they are, at rest)
void velocityFromMove(const Model &model, State &state, const Eigen::Matrix3Xd &x0, double h);

// Chebyshev semi-iterative acceleration (Wang 2015): after iteration n's plain iterate is in x,
//   x⁽ⁿ⁾ = ω_n (x̃⁽ⁿ⁾ − x⁽ⁿ⁻²⁾) + x⁽ⁿ⁻²⁾,  ω_1 = 1, ω_2 = 2/(2 − ρ²), ω_n = 4/(4 − ρ² ω_{n−1}).
// The last iterate is left plain: over-relaxing a converged iterate carries it off the minimum
// again, and over many steps that shifts the statics. `before` and `last` are scratch arrays of
// the state's size, kept by the caller
class ChebyshevAcceleration {
public:
    ChebyshevAcceleration(double rho, const Eigen::Matrix3Xd &start, Eigen::Matrix3Xd &before, Eigen::Matrix3Xd &last);
    void afterIteration(const Model &model, int n, int iterations, Eigen::Matrix3Xd &x);

private:
    double m_rho;
    double m_omega = 1.0;
    Eigen::Matrix3Xd &m_before;  // x⁽ⁿ⁻²⁾
    Eigen::Matrix3Xd &m_last;    // x⁽ⁿ⁻¹⁾
};

}  // namespace core
