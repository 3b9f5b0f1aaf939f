#pragma once
// The integration schemes a scene can choose, and their names in scene files and on the command line.

#include <optional>
#include <string_view>

namespace core {

enum class Integrator {
    SymplecticEuler,  // the handout's scheme: v += h/m F, then x += h v (new v); the default
    ExplicitEuler,    // forward Euler: x and v both from the old state; the textbook baseline
    VelocityVerlet,   // second order, symplectic (kick-drift-kick)
    Rk4,              // classic fourth-order Runge-Kutta: four force evaluations per step
    ImplicitEuler,    // backward Euler linearised once per step, conjugate-gradient solve; first order
    AdaptiveRk45,     // Dormand-Prince 5(4) with step-size control to a tolerance
    Xpbd,             // extended position-based dynamics: springs as compliant constraints (xpbd.cpp)
    Projective,       // implicit Euler by projective dynamics: local spring projections, a prefactored global solve
    Vbd,              // implicit Euler by vertex block descent: Gauss-Seidel over vertex colours, 3x3 Newton steps
};

// every integrator, in the order menus list them
inline constexpr Integrator kIntegrators[] = {Integrator::SymplecticEuler, Integrator::ExplicitEuler,
                                              Integrator::VelocityVerlet,  Integrator::Rk4,
                                              Integrator::ImplicitEuler,   Integrator::AdaptiveRk45,
                                              Integrator::Xpbd,            Integrator::Projective,
                                              Integrator::Vbd};

// the integrators that solve implicit Euler's minimisation by iterations (Settings::solverIterations)
inline constexpr bool isVariational(Integrator integrator)
{
    return integrator == Integrator::Projective || integrator == Integrator::Vbd;
}

// the order of accuracy of the global error (for adaptive-rk45: of the solution it keeps)
int integratorOrder(Integrator integrator);

std::string_view integratorName(Integrator integrator);
std::optional<Integrator> integratorFromName(std::string_view name);

}  // namespace core
