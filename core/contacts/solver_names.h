#pragma once
// The contact solvers a scene can choose (core::ContactSolver, scene.h), and their names in scene
// files and on the command line, as integrator.h does for the integrators.

#include "core/model/scene.h"

#include <optional>
#include <string_view>

namespace core {

// every contact solver, in the order menus list them
inline constexpr ContactSolver kContactSolvers[] = {ContactSolver::Iterative, ContactSolver::Handout};

// "iterative", "handout"
std::string_view contactSolverName(ContactSolver solver);
std::optional<ContactSolver> contactSolverFromName(std::string_view name);

}  // namespace core
