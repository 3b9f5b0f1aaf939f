// Backward Euler, linearised once per step (Baraff and Witkin, "Large steps in cloth simulation",
// 1998): solve (M - h ∂f/∂v - h² ∂f/∂x) Δv = h (f + h ∂f/∂x v), then v += Δv, x += h v.
//
// The system matrix is never built: a conjugate-gradient solve needs only its product with a
// vector, which one pass over the springs gives. That keeps the step free of allocation (every
// vector lives in the state's scratch) and its cost linear in the number of springs. A spring's
// stiffness Jacobian is -k [(1 - l0/l)(I - u uᵀ) + u uᵀ]; the transverse term is clamped at zero
// when the spring is compressed (l < l0) so that the matrix stays symmetric positive definite
// and conjugate gradients converge. Pinned particles are handled exactly: their rows are the
// identity with a zero right-hand side, so their Δv is 0.
#include "core/passes.h"
#include "core/springs/spring_jacobian.h"


namespace core {

namespace {

constexpr double kRelativeResidual = 1e-10;  // CG stops when ‖r‖ ≤ this × ‖b‖
constexpr int kMaxIterations = 1000;

// the system matrix times y: M y + h c y + h kc (u uᵀ) y + h² K y, with pinned rows the identity
void applySystem(const Model &model, const State &state, double h, const Eigen::Matrix3Xd &y, Eigen::Matrix3Xd &out)
{
    out.noalias() = y * (model.mass.array() + h * model.viscosity).matrix().asDiagonal();
    if (model.plan.springs)
        addSpringJacobians(model, state, y, h * h, h, out);
    for (int i = 0; i < model.particleCount(); ++i)
        if (model.isPinned(i))
            out.col(i) = y.col(i);
}

}  // namespace

void implicitEuler(const Model &model, State &state, Workspace &work, double h)
{
    Eigen::Matrix3Xd &b = scratch(state, work, 0);
    Eigen::Matrix3Xd &dv = scratch(state, work, 1);
    Eigen::Matrix3Xd &r = scratch(state, work, 2);
    Eigen::Matrix3Xd &p = scratch(state, work, 3);
    Eigen::Matrix3Xd &ap = scratch(state, work, 4);
    Eigen::Matrix3Xd &z = scratch(state, work, 5);
    Eigen::Matrix3Xd &diagonal = scratch(state, work, 6);

    // right-hand side h (f + h ∂f/∂x v); pinned rows 0
    computeForces(model, state, work);
    b = work.force;
    if (model.plan.springs) {
        Eigen::Matrix3Xd &kv = z;  // borrowed before the solve needs it
        kv.setZero();
        addSpringJacobians(model, state, state.velocity, 1.0, 0.0, kv);  // -∂f/∂x v
        b -= h * kv;
    }
    b *= h;
    for (int i = 0; i < model.particleCount(); ++i)
        if (model.isPinned(i))
            b.col(i).setZero();

    // Jacobi preconditioner: the mass, the drag and each spring's share on the diagonal
    for (int i = 0; i < model.particleCount(); ++i)
        diagonal.col(i).setConstant(model.isPinned(i) ? 1.0 : model.mass[i] + h * model.viscosity);
    for (int k = 0; k < model.springCount(); ++k) {
        if (state.isBroken(k))
            continue;
        const double share = h * h * model.stiffness[k] + h * model.damping[k];
        for (int end : {model.springA[static_cast<std::size_t>(k)], model.springB[static_cast<std::size_t>(k)]})
            if (!model.isPinned(end))
                diagonal.col(end).array() += share;
    }

    // preconditioned conjugate gradients from Δv = 0
    dv.setZero();
    r = b;
    z = r.cwiseQuotient(diagonal);
    p = z;
    double rz = r.cwiseProduct(z).sum();
    const double stop = kRelativeResidual * kRelativeResidual * b.squaredNorm();
    int iteration = 0;
    while (iteration < kMaxIterations && r.squaredNorm() > stop) {
        applySystem(model, state, h, p, ap);
        const double pap = p.cwiseProduct(ap).sum();
        if (!(pap > 0.0))
            break;  // converged to rounding, or not positive definite: keep what we have
        const double alpha = rz / pap;
        dv += alpha * p;
        r -= alpha * ap;
        z = r.cwiseQuotient(diagonal);
        const double rzNext = r.cwiseProduct(z).sum();
        p = z + (rzNext / rz) * p;
        rz = rzNext;
        ++iteration;
    }
    work.profile.solverIterations = iteration;

    // v += Δv, then x += h v (pinned: Δv = 0 and v = 0)
    state.velocity += dv;
    state.position += h * state.velocity;
}

}  // namespace core
