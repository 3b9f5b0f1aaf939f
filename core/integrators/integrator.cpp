#include "core/integrators/integrator.h"

namespace core {

std::string_view integratorName(Integrator integrator)
{
    switch (integrator) {
    case Integrator::SymplecticEuler: return "symplectic-euler";
    case Integrator::ExplicitEuler: return "explicit-euler";
    case Integrator::VelocityVerlet: return "velocity-verlet";
    case Integrator::Rk4: return "rk4";
    case Integrator::ImplicitEuler: return "implicit-euler";
    case Integrator::AdaptiveRk45: return "adaptive-rk45";
    case Integrator::Xpbd: return "xpbd";
    case Integrator::Projective: return "projective";
    case Integrator::Vbd: return "vbd";
    }
    return "unknown";
}

int integratorOrder(Integrator integrator)
{
    switch (integrator) {
    case Integrator::SymplecticEuler: return 1;
    case Integrator::ExplicitEuler: return 1;
    case Integrator::VelocityVerlet: return 2;
    case Integrator::Rk4: return 4;
    case Integrator::ImplicitEuler: return 1;
    case Integrator::AdaptiveRk45: return 5;
    case Integrator::Xpbd: return 1;
    case Integrator::Projective: return 1;
    case Integrator::Vbd: return 1;
    }
    return 1;
}

std::optional<Integrator> integratorFromName(std::string_view name)
{
    for (Integrator integrator : kIntegrators)
        if (integratorName(integrator) == name)
            return integrator;
    return std::nullopt;
}

}  // namespace core
