// Projective dynamics for mass-spring systems (Liu, Bargteil, O'Brien and Kavan, "Fast simulation
// of mass-spring systems", 2013): one implicit Euler sub-step of h as the minimisation of the same
// G(x) as vbd.cpp,
//   G(x) = Σ_i m_i/(2h²) |x_i − y_i|² + Σ_i c/(2h) |x_i − x0_i|² + Σ_s w_s/2 (l_s − l*_s)² + const,
// each spring's stiffness and damper folded into one term: w = k + c_s/h and the length it pulls to
// l* = (k l0 + (c_s/h) l_start)/w (the damper's dissipation over the sub-step, c_s/(2h)(l − l_start)²,
// completes the square with the spring's). Each iteration alternates
//   local:  d_s = l*_s (x_a − x_b)/|x_a − x_b|, every spring at once (in parallel);
//   global: (M/h² + c/h I + L) x = M/h² y + c/h x0 + Jd, L = Σ_s w_s (e_a − e_b)(e_a − e_b)ᵀ,
// whose matrix does not depend on x: it is factored once (sparse Cholesky, sparse_cholesky.h)
// and each iteration is a back-substitution for the three coordinates. Pinned particles are not unknowns: their springs move to the right-hand side. The
// matrix is made again only when a spring breaks, or the step, masses, pins, stiffnesses or
// dampers change (a live edit), the new factorisation replacing the old within the sub-step.
// Chebyshev acceleration (Wang, SIGGRAPH Asia 2015) over-relaxes the iterates (variational.h).
// The velocity is the move, v = (x − x0)/h; contacts are resolved after the solve.
#include "core/integrators/integrator.h"
#include "core/integrators/variational.h"
#include "core/parallel.h"
#include "core/passes.h"

#include "core/integrators/sparse_cholesky.h"
#include <cmath>

namespace core {

namespace {

// the spectral radius the Chebyshev weights assume (docs/physics.md, "Projective dynamics")
constexpr double kProjectiveChebyshevRho = 0.9;

}  // namespace

struct ProjectiveSolver {
    // what the factorisation was made for
    double h = 0.0;
    std::vector<double> weight;    // w_s per spring, 0 when broken
    std::vector<int> ends;         // each spring's two ends
    std::vector<double> diagonal;  // m/h² + c/h per free particle
    std::vector<int> row;          // each particle's row, −1 when pinned
    SparseLlt llt;
    Eigen::SparseMatrix<double> matrix;
    bool ok = false;
    // per sub-step and iteration, kept so that a step allocates nothing after the first
    std::vector<double> nextWeight, nextDiagonal;
    std::vector<int> nextEnds;
    Eigen::MatrixX3d rhs, solution, iterate, product;
    Eigen::Matrix3Xd target;  // d_s per spring
    std::vector<double> restTarget;  // l*_s per spring
};

namespace {

// the weights, diagonal and spring ends for this sub-step; true when they differ from those factored
bool gatherCoefficients(const Model &model, const State &state, double h, ProjectiveSolver &s)
{
    std::vector<double> &weight = s.nextWeight;
    std::vector<double> &diagonal = s.nextDiagonal;
    const int n = model.particleCount();
    const int springs = model.springCount();
    weight.resize(std::size_t(springs));
    for (int k = 0; k < springs; ++k)
        weight[std::size_t(k)] = state.isBroken(k) ? 0.0 : model.stiffness[k] + model.damping[k] / h;
    diagonal.resize(std::size_t(n));
    for (int i = 0; i < n; ++i)
        diagonal[std::size_t(i)] = model.isPinned(i) ? 0.0 : model.mass[i] / (h * h) + model.viscosity / h;
    std::vector<int> &ends = s.nextEnds;
    ends.resize(2 * std::size_t(springs));
    for (int k = 0; k < springs; ++k) {
        ends[2 * std::size_t(k)] = model.springA[std::size_t(k)];
        ends[2 * std::size_t(k) + 1] = model.springB[std::size_t(k)];
    }
    return !s.ok || s.h != h || s.weight != weight || s.diagonal != diagonal || s.ends != ends;
}

void factor(const Model &model, ProjectiveSolver &s, Workspace &work)
{
    const int n = model.particleCount();
    s.row.assign(std::size_t(n), -1);
    int rows = 0;
    for (int i : model.freeParticles)
        s.row[std::size_t(i)] = rows++;
    std::vector<Eigen::Triplet<double>> entries;
    entries.reserve(std::size_t(rows) + 4 * std::size_t(model.springCount()));
    for (int i : model.freeParticles)
        entries.emplace_back(s.row[std::size_t(i)], s.row[std::size_t(i)], s.diagonal[std::size_t(i)]);
    for (int k = 0; k < model.springCount(); ++k) {
        const double w = s.weight[std::size_t(k)];
        if (w == 0.0)
            continue;
        const int a = s.row[std::size_t(model.springA[std::size_t(k)])];
        const int b = s.row[std::size_t(model.springB[std::size_t(k)])];
        if (a >= 0)
            entries.emplace_back(a, a, w);
        if (b >= 0)
            entries.emplace_back(b, b, w);
        if (a >= 0 && b >= 0) {
            entries.emplace_back(a, b, -w);
            entries.emplace_back(b, a, -w);
        }
    }
    s.matrix.resize(rows, rows);
    s.matrix.setFromTriplets(entries.begin(), entries.end());
    // nothing free: nothing to solve (and CHOLMOD refuses an empty matrix)
    if (rows > 0)
        s.llt.compute(s.matrix);
    s.ok = rows > 0 && s.llt.info() == Eigen::Success;
    s.rhs.resize(rows, 3);
    s.solution.resize(rows, 3);
    s.target.resize(3, model.springCount());
    s.restTarget.resize(std::size_t(model.springCount()));
    work.profile.factorisations += 1;
}

// the local step at x: each spring's target d_s; then the right-hand side, gathered per particle
void localStep(const Model &model, const State &state, const Eigen::Matrix3Xd &y, const Eigen::Matrix3Xd &x0,
               double h, ProjectiveSolver &s)
{
    const Eigen::Matrix3Xd &x = state.position;
    parallelChunks(model.springCount(), [&](int from, int to) {
        for (int k = from; k < to; ++k) {
            const Eigen::Vector3d d = x.col(model.springA[std::size_t(k)]) - x.col(model.springB[std::size_t(k)]);
            const double l = d.norm();
            s.target.col(k) = l > 0.0 ? Eigen::Vector3d(d * (s.restTarget[std::size_t(k)] / l)) : Eigen::Vector3d::Zero();
        }
    });
    const double inertia = 1.0 / (h * h);
    const double drag = model.viscosity / h;
    const int free = static_cast<int>(model.freeParticles.size());
    parallelChunks(free, [&](int from, int to) {
        for (int f = from; f < to; ++f) {
            const int i = model.freeParticles[std::size_t(f)];
            Eigen::Vector3d b = (model.mass[i] * inertia) * y.col(i) + drag * x0.col(i);
            for (int e = model.springOffsets[std::size_t(i)]; e < model.springOffsets[std::size_t(i) + 1]; ++e) {
                const int end = model.springEnds[std::size_t(e)];
                const int k = end / 2;
                const double w = s.weight[std::size_t(k)];
                if (w == 0.0)
                    continue;
                const bool isA = end % 2 == 0;
                b += (isA ? w : -w) * s.target.col(k);
                const int other = isA ? model.springB[std::size_t(k)] : model.springA[std::size_t(k)];
                if (model.isPinned(other))
                    b += w * x.col(other);
            }
            s.rhs.row(s.row[std::size_t(i)]) = b.transpose();
        }
    });
}

// the global step: the back-substitutions for the three coordinates. CHOLMOD's in one call (its
// solves share a workspace); Eigen's one per coordinate, shared between the threads (each column's
// arithmetic is the same on any thread count)
void solveCoordinates(ProjectiveSolver &s)
{
#ifdef SPRINGLAB_CHOLMOD
    s.solution = s.llt.solve(s.rhs);
#else
#ifdef SPRINGLAB_OPENMP
#pragma omp parallel for schedule(static, 1) if (splitAcrossThreads(static_cast<int>(s.rhs.rows())))
#endif
    for (int c = 0; c < 3; ++c)
        s.solution.col(c) = s.llt.solve(s.rhs.col(c));
#endif
}

// ‖∇G‖ at x: the matrix times x less the right-hand side of x's own local step
double gradientNorm(const Model &model, const State &state, ProjectiveSolver &s)
{
    s.iterate.resize(s.rhs.rows(), 3);
    for (int i : model.freeParticles)
        s.iterate.row(s.row[std::size_t(i)]) = state.position.col(i).transpose();
    s.product.resize(s.rhs.rows(), 3);
    s.product.noalias() = s.matrix * s.iterate;
    return (s.product - s.rhs).norm();
}

}  // namespace

void projective(const Model &model, State &state, Workspace &work, double h)
{
    Eigen::Matrix3Xd &x0 = scratch(state, work, 0);
    Eigen::Matrix3Xd &y = scratch(state, work, 1);
    startVariationalStep(model, state, work, h, x0, y);
    const int iterations = model.plan.springs ? model.solverIterations : 0;
    if (iterations == 0) {
        velocityFromMove(model, state, x0, h);
        return;
    }

    if (!work.projective)
        work.projective = std::make_shared<ProjectiveSolver>();
    ProjectiveSolver &s = *work.projective;
    if (gatherCoefficients(model, state, h, s)) {
        s.h = h;
        std::swap(s.weight, s.nextWeight);
        std::swap(s.diagonal, s.nextDiagonal);
        std::swap(s.ends, s.nextEnds);
        factor(model, s, work);
    }
    if (!s.ok) {  // nothing free; else, with positive masses, never: the inertial move rather than garbage
        velocityFromMove(model, state, x0, h);
        return;
    }
    // each spring's length to pull to, from its length at the sub-step's start
    startLengths(model, x0, work.springLengths);
    for (int k = 0; k < model.springCount(); ++k) {
        const double w = s.weight[std::size_t(k)];
        const double damper = model.damping[k] / h;
        s.restTarget[std::size_t(k)] =
            w > 0.0 ? (model.stiffness[k] * model.restLength[k] + damper * work.springLengths[std::size_t(k)]) / w : 0.0;
    }

    ChebyshevAcceleration chebyshev(kProjectiveChebyshevRho, state.position, scratch(state, work, 2),
                                    scratch(state, work, 3));
    double first = 0.0;
    for (int n = 1; n <= iterations; ++n) {
        localStep(model, state, y, x0, h, s);
        if (n == 1)
            first = gradientNorm(model, state, s);
        solveCoordinates(s);
        for (int i : model.freeParticles)
            state.position.col(i) = s.solution.row(s.row[std::size_t(i)]).transpose();
        chebyshev.afterIteration(model, n, iterations, state.position);
    }
    localStep(model, state, y, x0, h, s);
    const double gradient = gradientNorm(model, state, s);
    work.profile.recordSolve(iterations, first > 0.0 ? gradient / first : 0.0);
    velocityFromMove(model, state, x0, h);
}

}  // namespace core
