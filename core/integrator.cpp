#include "integrator.h"

namespace core {

std::string_view integratorName(Integrator integrator)
{
    switch (integrator) {
    case Integrator::SymplecticEuler: return "symplectic-euler";
    case Integrator::ExplicitEuler: return "explicit-euler";
    }
    return "unknown";
}

std::optional<Integrator> integratorFromName(std::string_view name)
{
    for (Integrator integrator : kIntegrators)
        if (integratorName(integrator) == name)
            return integrator;
    return std::nullopt;
}

}  // namespace core
