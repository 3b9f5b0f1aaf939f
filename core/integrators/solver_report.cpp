#include "core/integrators/solver_report.h"

#include <sstream>

namespace core {

std::string solverSummary(Integrator integrator, const Profile &profile)
{
    if (profile.solves == 0)
        return {};
    std::ostringstream text;
    text.precision(2);
    const double mean = double(profile.solverIterationsTotal) / double(profile.solves);
    if (integrator == Integrator::ImplicitEuler && profile.solverIterationsTotal == 0)
        text << "direct solve";
    else
        text << mean << " iterations a sub-step (most " << profile.mostSolverIterations << ")";
    text << ", residual up to " << std::scientific << profile.worstSolverResidual;
    if (profile.solverCapHits > 0)
        text << ", " << profile.solverCapHits << " sub-steps stopped at the iteration cap";
    return text.str();
}

std::string lastSolveSummary(Integrator integrator, const Profile &profile)
{
    if (profile.solves == 0 || !(integrator == Integrator::ImplicitEuler || isVariational(integrator)))
        return {};
    std::ostringstream text;
    text.precision(2);
    text << "last sub-step: ";
    if (profile.solverIterations == 0)
        text << "direct solve";
    else
        text << profile.solverIterations << " iterations";
    text << ", residual " << std::scientific << profile.solverResidual;
    if (isVariational(integrator) && profile.solverResidual > kUnconvergedResidual)
        text << " (not converged: raise Solver iterations)";
    return text.str();
}

std::string solverWarning(Integrator integrator, const Profile &profile)
{
    const std::string_view name = integratorName(integrator);
    std::ostringstream text;
    text.precision(2);
    if (profile.solverCapHits > 0) {
        text << std::string(name) << "'s conjugate gradients stopped at their cap of iterations in "
             << profile.solverCapHits << " sub-steps (residual up to " << std::scientific << profile.worstSolverResidual
             << "): its steps are not the implicit Euler steps it claims; use more substeps";
        return text.str();
    }
    if (isVariational(integrator) && profile.solves > 0 && profile.worstSolverResidual > kUnconvergedResidual) {
        text << std::string(name) << "'s iterations left up to " << std::fixed << 100.0 * profile.worstSolverResidual
             << "% of the energy's gradient in a sub-step: its springs act softer than set; raise "
                "settings.solverIterations or the substeps";
        return text.str();
    }
    return {};
}

}  // namespace core
