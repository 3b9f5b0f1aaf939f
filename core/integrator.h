#pragma once
// The integration schemes a scene can choose, and their names in scene files and on the command line.

#include <optional>
#include <string_view>

namespace core {

enum class Integrator {
    SymplecticEuler,  // the handout's scheme: v += h/m F, then x += h v (new v); the default
    ExplicitEuler,    // forward Euler: x and v both from the old state; the textbook baseline
};

// every integrator, in the order menus list them
inline constexpr Integrator kIntegrators[] = {Integrator::SymplecticEuler, Integrator::ExplicitEuler};

std::string_view integratorName(Integrator integrator);
std::optional<Integrator> integratorFromName(std::string_view name);

}  // namespace core
