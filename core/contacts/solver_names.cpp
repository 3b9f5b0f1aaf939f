#include "core/contacts/solver_names.h"

namespace core {

std::string_view contactSolverName(ContactSolver solver)
{
    switch (solver) {
    case ContactSolver::Iterative: return "iterative";
    case ContactSolver::Handout: return "handout";
    }
    return "unknown";
}

std::optional<ContactSolver> contactSolverFromName(std::string_view name)
{
    for (ContactSolver solver : kContactSolvers)
        if (contactSolverName(solver) == name)
            return solver;
    return std::nullopt;
}

}  // namespace core
