// Vertex block descent (Chen, Liu, Yang and Yuksel, SIGGRAPH 2024): one implicit Euler sub-step
// of h as the minimisation of
//   G(x) = Σ_i m_i/(2h²) |x_i − y_i|² + Σ_i c/(2h) |x_i − x0_i|²
//        + Σ_s [ k/2 (l − l0)² + c_s/(2h) (l − l_start)² ],
// y = x0 + h v0 + h² w f_ext (gravity and applied forces), c the medium's viscosity, c_s the
// spring's damper: its term is the damper's dissipation over the sub-step, so its gradient is
// c_s l̇ along the spring, as the explicit damper's force. The minimiser is the backward Euler step.
// Each iteration visits the free particles colour by colour (vertex_colours.h) and moves each by
// one Newton step on G with the others held: Δx_i = −H_i⁻¹ g_i, g_i and H_i the gradient and the
// 3 × 3 Hessian of the terms touching i, each spring's Hessian φ″ u uᵀ + max(0, φ′/l)(I − u uᵀ)
// (clamped positive, so each step descends). No spring joins two particles of one colour, so a
// colour's particles move at once, in parallel, with the same bits on any thread count.
// The sweeps are plain Gauss-Seidel: the paper's Chebyshev acceleration (variational.h, as
// projective takes it) made the 1000-link stiff-chain example gain energy where it struck the floor
// at 10 sub-steps of 10 iterations, from a fall worth about 15 J: ρ = 0.9 blew up (279 J with a
// restart whenever the residual grew), ρ = 0.7 ended with 140 J, ρ = 0.5 with 22 J; plain, 8.8 J.
// The velocity is the move: v = (x − x0)/h. Contacts are resolved after the solve, as for xpbd.
#include "core/integrators/integrator.h"
#include "core/integrators/variational.h"
#include "core/integrators/vertex_colours.h"
#include "core/parallel.h"
#include "core/passes.h"

#include <Eigen/Dense>
#include <cmath>

namespace core {

namespace {


struct VbdPass {
    const Model &model;
    const double *x0;       // the sub-step's start
    const double *y;        // the inertial target
    const double *startLength;   // each spring's length at the sub-step's start
    const std::uint8_t *broken;  // null when no spring can break
    double *x;              // the iterate, moved in place
    double *gradientSquared;  // |g_i|² at the visit, row 0 of a 3 × N array
    double h;
};

// one particle's Newton step on G with its neighbours held
inline void visit(const VbdPass &p, int i)
{
    const Model &model = p.model;
    const double inertia = model.mass[i] / (p.h * p.h) + model.viscosity / p.h;
    const Eigen::Map<const Eigen::Vector3d> xi(p.x + 3 * i);
    const Eigen::Map<const Eigen::Vector3d> yi(p.y + 3 * i);
    const Eigen::Map<const Eigen::Vector3d> si(p.x0 + 3 * i);
    Eigen::Vector3d g = (model.mass[i] / (p.h * p.h)) * (xi - yi) + (model.viscosity / p.h) * (xi - si);
    Eigen::Matrix3d H = inertia * Eigen::Matrix3d::Identity();
    for (int e = model.springOffsets[std::size_t(i)]; e < model.springOffsets[std::size_t(i) + 1]; ++e) {
        const int end = model.springEnds[std::size_t(e)];
        const int k = end / 2;
        if (p.broken && p.broken[k])
            continue;
        const int j = end % 2 == 0 ? model.springB[std::size_t(k)] : model.springA[std::size_t(k)];
        const Eigen::Map<const Eigen::Vector3d> xj(p.x + 3 * j);
        const Eigen::Vector3d d = xi - xj;
        const double l = d.norm();
        if (!(l > 0.0))
            continue;  // ends together: no direction to push along
        const Eigen::Vector3d u = d / l;
        const double lStart = p.startLength[k];
        const double damper = model.damping[k] / p.h;
        const double slope = model.stiffness[k] * (l - model.restLength[k]) + damper * (l - lStart);  // φ′
        const double curvature = model.stiffness[k] + damper;                                        // φ″
        g += slope * u;
        const Eigen::Matrix3d uu = u * u.transpose();
        H += curvature * uu + std::max(0.0, slope / l) * (Eigen::Matrix3d::Identity() - uu);
    }
    p.gradientSquared[3 * i] = g.squaredNorm();
    // H is symmetric positive definite (the inertia alone makes it so): its inverse by cofactors
    const double c00 = H(1, 1) * H(2, 2) - H(1, 2) * H(1, 2);
    const double c01 = H(0, 2) * H(1, 2) - H(0, 1) * H(2, 2);
    const double c02 = H(0, 1) * H(1, 2) - H(0, 2) * H(1, 1);
    const double c11 = H(0, 0) * H(2, 2) - H(0, 2) * H(0, 2);
    const double c12 = H(0, 1) * H(0, 2) - H(0, 0) * H(1, 2);
    const double c22 = H(0, 0) * H(1, 1) - H(0, 1) * H(0, 1);
    const double det = H(0, 0) * c00 + H(0, 1) * c01 + H(0, 2) * c02;
    if (!(det > 0.0))
        return;  // rounding has lost the definiteness: leave the particle where it is
    const double inverse = 1.0 / det;
    double *moved = p.x + 3 * i;
    moved[0] -= inverse * (c00 * g[0] + c01 * g[1] + c02 * g[2]);
    moved[1] -= inverse * (c01 * g[0] + c11 * g[1] + c12 * g[2]);
    moved[2] -= inverse * (c02 * g[0] + c12 * g[1] + c22 * g[2]);
}

}  // namespace

struct VbdTornColours {
    // what it was made for: the model (its address, which a later model may take again, so its
    // sizes too) and the broken flags
    const Model *model = nullptr;
    int particles = -1;
    int springs = -1;
    std::vector<std::uint8_t> broken;
    std::vector<int> order, colours;
};

namespace {

// the colours a sweep visits: colour c's particles are order[start[c] .. start[c + 1])
struct Colours {
    const std::vector<int> &order;
    const std::vector<int> &start;
};

// the model's colours, or, once springs have broken, the colours without them (made again only
// when another breaks): the colours a file stored from this state would be compiled with, so that a
// resumed run visits the particles in the same colours and goes on to the same bits
Colours coloursFor(const Model &model, const State &state, Workspace &work)
{
    if (state.breaks.empty())
        return {model.vbdOrder, model.vbdColours};
    if (!work.vbdTorn)
        work.vbdTorn = std::make_shared<VbdTornColours>();
    VbdTornColours &torn = *work.vbdTorn;
    if (torn.model != &model || torn.particles != model.particleCount() || torn.springs != model.springCount() ||
        torn.broken != state.springBroken) {
        colourVertices(model, state.springBroken, torn.order, torn.colours);
        torn.model = &model;
        torn.particles = model.particleCount();
        torn.springs = model.springCount();
        torn.broken = state.springBroken;
    }
    return {torn.order, torn.colours};
}

}  // namespace

void vbd(const Model &model, State &state, Workspace &work, double h)
{
    Eigen::Matrix3Xd &x0 = scratch(state, work, 0);
    Eigen::Matrix3Xd &y = scratch(state, work, 1);
    Eigen::Matrix3Xd &gradient = scratch(state, work, 4);  // row 0: |g_i|² at the last visit
    startVariationalStep(model, state, work, h, x0, y);
    const int iterations = model.plan.springs ? model.solverIterations : 0;
    startLengths(model, x0, work.springLengths);
    const VbdPass pass{model,
                       x0.data(),
                       y.data(),
                       work.springLengths.data(),
                       state.springBroken.empty() ? nullptr : state.springBroken.data(),
                       state.position.data(),
                       gradient.data(),
                       h};
    const auto sweepGradient = [&] {
        double sum = 0.0;
        for (int i : model.freeParticles)
            sum += gradient(0, i);
        return std::sqrt(sum);
    };
    const Colours colours = coloursFor(model, state, work);
    double first = 0.0, lastGradient = 0.0;
    for (int n = 1; n <= iterations; ++n) {
        for (std::size_t c = 0; c + 1 < colours.start.size(); ++c) {
            const int begin = colours.start[c];
            parallelChunks(colours.start[c + 1] - begin, [&](int from, int to) {
                for (int t = from; t < to; ++t)
                    visit(pass, colours.order[std::size_t(begin + t)]);
            });
        }
        lastGradient = sweepGradient();
        if (n == 1)
            first = lastGradient;
    }
    if (iterations > 0)
        work.profile.recordSolve(iterations, first > 0.0 ? lastGradient / first : 0.0);
    velocityFromMove(model, state, x0, h);
}

}  // namespace core
