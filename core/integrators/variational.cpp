#include "core/integrators/variational.h"

#include "core/passes.h"

#include <utility>

namespace core {

void startVariationalStep(const Model &model, State &state, Workspace &work, double h, Eigen::Matrix3Xd &x0,
                          Eigen::Matrix3Xd &y)
{
    computeExternalForces(model, state, work);
    work.profile.forceEvaluations += 1;
    x0 = state.position;
    for (int i : model.freeParticles) {
        y.col(i) = x0.col(i) + h * state.velocity.col(i) + (h * h * model.invMass[i]) * work.force.col(i);
        state.position.col(i) = y.col(i);
    }
}

void startLengths(const Model &model, const Eigen::Matrix3Xd &x0, std::vector<double> &lengths)
{
    lengths.resize(std::size_t(model.springCount()));
    for (int k = 0; k < model.springCount(); ++k)
        lengths[std::size_t(k)] = (x0.col(model.springA[std::size_t(k)]) - x0.col(model.springB[std::size_t(k)])).norm();
}

void velocityFromMove(const Model &model, State &state, const Eigen::Matrix3Xd &x0, double h)
{
    for (int i : model.freeParticles)
        state.velocity.col(i) = (state.position.col(i) - x0.col(i)) / h;
}

ChebyshevAcceleration::ChebyshevAcceleration(double rho, const Eigen::Matrix3Xd &start, Eigen::Matrix3Xd &before,
                                             Eigen::Matrix3Xd &last)
    : m_rho(rho), m_before(before), m_last(last)
{
    m_last = start;  // x⁽⁰⁾
}

void ChebyshevAcceleration::afterIteration(const Model &model, int n, int iterations, Eigen::Matrix3Xd &x)
{
    const double rho2 = m_rho * m_rho;
    m_omega = n == 1 ? 1.0 : n == 2 ? 2.0 / (2.0 - rho2) : 4.0 / (4.0 - rho2 * m_omega);
    if (n >= 2 && n < iterations)
        for (int i : model.freeParticles)
            x.col(i) = m_omega * (x.col(i) - m_before.col(i)) + m_before.col(i);
    if (n == iterations)
        return;  // nothing comes after it
    std::swap(m_before, m_last);  // x⁽ⁿ⁻¹⁾ is the next iteration's x⁽ⁿ⁻²⁾
    m_last = x;
}

}  // namespace core
