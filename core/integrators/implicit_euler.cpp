// Backward Euler, linearised once per step (Baraff and Witkin, "Large steps in cloth simulation",
// 1998): solve (M - h ∂f/∂v - h² ∂f/∂x) Δv = h (f + h ∂f/∂x v), then v += Δv, x += h v.
//
// A spring's stiffness Jacobian is -k [(1 - l0/l)(I - u uᵀ) + u uᵀ]; the transverse term is
// clamped at zero when the spring is compressed (l < l0) so that the matrix stays symmetric
// positive definite. Pinned particles are not unknowns: their Δv is 0. Two solves:
//   - conjugate gradients (first), never building the matrix (one pass over the springs per
//     product), preconditioned by the inverse of each particle's 3 × 3 diagonal block, stopped at
//     a relative residual of 1e-10 or 1000 iterations;
//   - direct: the matrix assembled over the free particles' coordinates and factored by a sparse
//     Cholesky (sparse_cholesky.h: CHOLMOD's, else Eigen's LDLᵀ), its ordering and symbolic analysis made once per pattern,
//     the numbers each sub-step. Exact to rounding whatever the stiffness; faster or slower than
//     the conjugate gradients by the scene (a 64 × 64 cloth at 1e7 N/m: 0.19 s a step against
//     0.11 s; the 32 × 32 stiff-cloth example at 1e6: 19 ms against 27 ms), but the choice may not
//     hang on a timing: the bits would then hang on the machine's load.
// A sub-step whose conjugate gradients stop at their cap is solved directly, and so is every later
// sub-step of that model (Workspace::ImplicitSolve; the benchmark times each alone).
#include "core/passes.h"
#include "core/springs/spring_jacobian.h"

#include "core/integrators/sparse_cholesky.h"
#include <Eigen/Dense>
#include <algorithm>


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


// spring k's 3 × 3 block of the system, h² K + h D by the same Jacobian as applySystem: it adds to
// the (a, a) and (b, b) blocks and subtracts from (a, b) and (b, a)
Eigen::Matrix3d springBlock(const Model &model, const State &state, double h, int k)
{
    const Eigen::Vector3d d = state.position.col(model.springA[std::size_t(k)]) -
                              state.position.col(model.springB[std::size_t(k)]);
    const double length = d.norm();
    if (!(length > 0.0))
        return Eigen::Matrix3d::Zero();  // no direction: the spring adds nothing, as in applySystem
    const Eigen::Vector3d u = d / length;
    const double transverse = std::max(0.0, 1.0 - model.restLength[k] / length);
    const Eigen::Matrix3d uu = u * u.transpose();
    return h * h * model.stiffness[k] * (transverse * (Eigen::Matrix3d::Identity() - uu) + uu) +
           h * model.damping[k] * uu;
}

}  // namespace

struct ImplicitSolver {
    std::vector<int> row;  // each particle's first coordinate's row, −1 when pinned
    // the sparsity pattern the symbolic analysis was made for (a break, a pin or a new spring changes it)
    std::vector<int> outer, inner;
    std::vector<Eigen::Triplet<double>> entries;
    Eigen::SparseMatrix<double> matrix;
    SparseLdlt ldlt;
    Eigen::VectorXd rhs, solution;
    std::vector<Eigen::Matrix3d> blocks;  // the conjugate gradients' preconditioner, inverted
    const Model *directFor = nullptr;     // Auto: the model whose conjugate gradients hit their cap
};

namespace {

// whether the matrix's pattern is the one analysed; if not, it becomes it
bool samePattern(ImplicitSolver &s)
{
    const Eigen::SparseMatrix<double> &m = s.matrix;
    const int *outer = m.outerIndexPtr();
    const int *inner = m.innerIndexPtr();
    const auto nonZeros = static_cast<std::size_t>(m.nonZeros());
    const auto columns = static_cast<std::size_t>(m.cols()) + 1;
    if (s.outer.size() == columns && s.inner.size() == nonZeros && std::equal(s.outer.begin(), s.outer.end(), outer) &&
        std::equal(s.inner.begin(), s.inner.end(), inner))
        return true;
    s.outer.assign(outer, outer + columns);
    s.inner.assign(inner, inner + nonZeros);
    return false;
}

void solveDirectly(const Model &model, const State &state, Workspace &work, double h, const Eigen::Matrix3Xd &b,
                   Eigen::Matrix3Xd &dv)
{
    if (!work.implicitSolver)
        work.implicitSolver = std::make_shared<ImplicitSolver>();
    ImplicitSolver &s = *work.implicitSolver;
    const int n = model.particleCount();
    s.row.assign(static_cast<std::size_t>(n), -1);
    int rows = 0;
    for (int i : model.freeParticles) {
        s.row[static_cast<std::size_t>(i)] = rows;
        rows += 3;
    }
    // every entry of the pattern, zeros included, so that the pattern stays that of the analysis
    s.entries.clear();
    for (int i : model.freeParticles)
        for (int axis = 0; axis < 3; ++axis)
            s.entries.emplace_back(s.row[std::size_t(i)] + axis, s.row[std::size_t(i)] + axis,
                                   model.mass[i] + h * model.viscosity);
    for (int k = 0; k < model.springCount(); ++k) {
        if (state.isBroken(k))
            continue;
        const Eigen::Matrix3d block = springBlock(model, state, h, k);
        const int ra = s.row[std::size_t(model.springA[std::size_t(k)])];
        const int rb = s.row[std::size_t(model.springB[std::size_t(k)])];
        for (int r = 0; r < 3; ++r)
            for (int c = 0; c < 3; ++c) {
                if (ra >= 0)
                    s.entries.emplace_back(ra + r, ra + c, block(r, c));
                if (rb >= 0)
                    s.entries.emplace_back(rb + r, rb + c, block(r, c));
                if (ra >= 0 && rb >= 0) {
                    s.entries.emplace_back(ra + r, rb + c, -block(r, c));
                    s.entries.emplace_back(rb + r, ra + c, -block(r, c));
                }
            }
    }
    s.matrix.resize(rows, rows);
    s.matrix.setFromTriplets(s.entries.begin(), s.entries.end());
    // the ordering and symbolic factorisation once per pattern (a break, a pin or an edit changes it)
    s.matrix.makeCompressed();
    dv.setZero();
    if (rows == 0) {  // nothing free: nothing to solve (and CHOLMOD refuses an empty matrix)
        work.profile.recordSolve(0, 0.0);
        return;
    }
    if (!samePattern(s)) {
        s.ldlt.analyzePattern(s.matrix);
        if (s.ldlt.info() != Eigen::Success) {  // a factor that was never analysed must not be used
            s.outer.clear();
            work.profile.recordSolve(0, 1.0);
            return;
        }
    }
    s.ldlt.factorize(s.matrix);
    work.profile.factorisations += 1;
    s.rhs.resize(rows);
    for (int i : model.freeParticles)
        s.rhs.segment<3>(s.row[std::size_t(i)]) = b.col(i);
    if (s.ldlt.info() != Eigen::Success) {
        work.profile.recordSolve(0, 1.0);  // nothing solved: Δv stays 0
        return;
    }
    s.solution = s.ldlt.solve(s.rhs);
    for (int i : model.freeParticles)
        dv.col(i) = s.solution.segment<3>(s.row[std::size_t(i)]);
    const double bNorm = s.rhs.norm();
    work.profile.recordSolve(0, bNorm > 0.0 ? (s.matrix * s.solution - s.rhs).norm() / bNorm : 0.0);
}

// returns whether they converged before the cap; a capped solve is reported (and its cap hit
// counted) only when `last`, nothing solving after them
bool solveByConjugateGradients(const Model &model, const State &state, Workspace &work, double h,
                               const Eigen::Matrix3Xd &b, Eigen::Matrix3Xd &dv, bool last)
{
    Eigen::Matrix3Xd &r = scratch(state, work, 2);
    Eigen::Matrix3Xd &p = scratch(state, work, 3);
    Eigen::Matrix3Xd &ap = scratch(state, work, 4);
    Eigen::Matrix3Xd &z = scratch(state, work, 5);
    if (!work.implicitSolver)
        work.implicitSolver = std::make_shared<ImplicitSolver>();
    std::vector<Eigen::Matrix3d> &blocks = work.implicitSolver->blocks;
    const int n = model.particleCount();

    // block-Jacobi preconditioner: each particle's 3 × 3 diagonal block, inverted
    blocks.assign(static_cast<std::size_t>(n), Eigen::Matrix3d::Zero());
    for (int i = 0; i < n; ++i)
        blocks[std::size_t(i)].diagonal().setConstant(model.isPinned(i) ? 1.0 : model.mass[i] + h * model.viscosity);
    for (int k = 0; k < model.springCount(); ++k) {
        if (state.isBroken(k))
            continue;
        const Eigen::Matrix3d block = springBlock(model, state, h, k);
        for (int end : {model.springA[static_cast<std::size_t>(k)], model.springB[static_cast<std::size_t>(k)]})
            if (!model.isPinned(end))
                blocks[std::size_t(end)] += block;
    }
    for (Eigen::Matrix3d &m : blocks)
        m = m.inverse().eval();
    const auto precondition = [&](const Eigen::Matrix3Xd &in, Eigen::Matrix3Xd &out) {
        for (int i = 0; i < n; ++i)
            out.col(i) = blocks[std::size_t(i)] * in.col(i);
    };

    // preconditioned conjugate gradients from Δv = 0
    dv.setZero();
    r = b;
    precondition(r, z);
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
        precondition(r, z);
        const double rzNext = r.cwiseProduct(z).sum();
        p = z + (rzNext / rz) * p;
        rz = rzNext;
        ++iteration;
    }
    const bool capped = iteration == kMaxIterations && r.squaredNorm() > stop;
    if (capped && !last)
        return false;  // the factorisation solves it, and reports
    const double bNorm = b.norm();
    work.profile.recordSolve(iteration, bNorm > 0.0 ? r.norm() / bNorm : 0.0);
    if (capped)
        work.profile.solverCapHits += 1;
    return !capped;
}

}  // namespace

void implicitEuler(const Model &model, State &state, Workspace &work, double h)
{
    Eigen::Matrix3Xd &b = scratch(state, work, 0);
    Eigen::Matrix3Xd &dv = scratch(state, work, 1);
    Eigen::Matrix3Xd &kv = scratch(state, work, 2);

    // right-hand side h (f + h ∂f/∂x v); pinned rows 0
    computeForces(model, state, work);
    b = work.force;
    if (model.plan.springs) {
        kv.setZero();
        addSpringJacobians(model, state, state.velocity, 1.0, 0.0, kv);  // -∂f/∂x v
        b -= h * kv;
    }
    b *= h;
    for (int i = 0; i < model.particleCount(); ++i)
        if (model.isPinned(i))
            b.col(i).setZero();

    using Solve = Workspace::ImplicitSolve;
    const bool direct = work.implicitSolve == Solve::Direct ||
                        (work.implicitSolve == Solve::Auto && work.implicitSolver && work.implicitSolver->directFor == &model);
    if (direct) {
        solveDirectly(model, state, work, h, b, dv);
    } else if (!solveByConjugateGradients(model, state, work, h, b, dv, work.implicitSolve == Solve::ConjugateGradients)) {
        // capped: this model's systems are too ill-conditioned for them; the factorisation from here on
        work.implicitSolver->directFor = &model;
        solveDirectly(model, state, work, h, b, dv);
    }

    // v += Δv, then x += h v (pinned: Δv = 0 and v = 0)
    state.velocity += dv;
    state.position += h * state.velocity;
}

}  // namespace core
