// One xpbd sub-step of h:
//   1. the kick: v += h w f for gravity and the applied forces, the drag taken implicitly,
//      v ← v / (1 + h c w), so that no viscosity can make it unstable;
//   2. the prediction x += h v, the sub-step's start kept as x₀;
//   3. one pass over the springs, each a distance constraint C = |xa − xb| − l0 with compliance
//      α = 1/k and XPBD's damping: Δλ = (−C − γ ∇C·(x − x₀)) / ((1 + γ)(wa + wb) + α/h²), with
//      γ = c / (k h), and the ends moved by wa Δλ n and −wb Δλ n. One iteration a sub-step, from
//      λ = 0: with small steps that is how XPBD converges (Macklin et al. 2019), and the constraint
//      keeps its stiffness whatever the step, where an explicit spring of k = 1e8 needs sub-steps
//      under 2/ω;
//   4. the velocity the move made, v = (x − x₀) / h.
// The springs are solved colour by colour (Gauss-Seidel between colours, every spring of one
// colour at once on all threads): no two springs of a colour move the same particle, so the bits do
// not depend on the thread count. A pinned particle has w = 0 and never moves.

#include "xpbd.h"

#include "integrator.h"
#include "parallel.h"
#include "passes.h"

#include <algorithm>
#include <cmath>
#include <bit>
#include <cstdint>

namespace core {

void colourSprings(Model &model)
{
    const int springs = model.springCount();
    const int n = model.particleCount();
    // a particle's colours as bits, 64 to a word; a spring's colour is at most the number of
    // springs at its two ends, so 2 × the largest degree + 1 colours are enough
    int degree = 0;
    for (int p = 0; p < n; ++p)
        degree = std::max(degree, model.springOffsets[std::size_t(p) + 1] - model.springOffsets[std::size_t(p)]);
    const std::size_t words = std::size_t(2 * degree) / 64 + 1;
    std::vector<std::uint64_t> used(std::size_t(n) * words, 0);
    std::vector<int> colour(std::size_t(springs), 0);
    int colours = 0;
    for (int k = 0; k < springs; ++k) {
        const int a = model.springA[std::size_t(k)];
        const int b = model.springB[std::size_t(k)];
        const bool moveA = !model.isPinned(a);
        const bool moveB = !model.isPinned(b);
        int c = 0;
        for (std::size_t word = 0; word < words; ++word) {
            std::uint64_t taken = 0;
            if (moveA)
                taken |= used[std::size_t(a) * words + word];
            if (moveB)
                taken |= used[std::size_t(b) * words + word];
            if (~taken != 0) {
                c = int(word) * 64 + std::countr_one(taken);
                break;
            }
        }
        colour[std::size_t(k)] = c;
        colours = std::max(colours, c + 1);
        const std::uint64_t bit = std::uint64_t(1) << (c % 64);
        if (moveA)
            used[std::size_t(a) * words + std::size_t(c / 64)] |= bit;
        if (moveB)
            used[std::size_t(b) * words + std::size_t(c / 64)] |= bit;
    }
    // counting sort of the springs by colour, in spring order within each
    model.xpbdColourStart.assign(std::size_t(colours) + 1, 0);
    for (int k = 0; k < springs; ++k)
        model.xpbdColourStart[std::size_t(colour[std::size_t(k)]) + 1] += 1;
    for (int c = 0; c < colours; ++c)
        model.xpbdColourStart[std::size_t(c) + 1] += model.xpbdColourStart[std::size_t(c)];
    std::vector<int> fill(model.xpbdColourStart.begin(), model.xpbdColourStart.end() - 1);
    model.xpbdOrder.resize(std::size_t(springs));
    for (int k = 0; k < springs; ++k)
        model.xpbdOrder[std::size_t(fill[std::size_t(colour[std::size_t(k)])]++)] = k;
}

namespace {

// one spring's constraint projected: its ends moved towards the rest length by as much as its
// compliance lets them in this sub-step
void project(const Model &model, const State &state, const Eigen::Matrix3Xd &start, Eigen::Matrix3Xd &x, int k,
             double h)
{
    if (state.isBroken(k))
        return;
    const int a = model.springA[std::size_t(k)];
    const int b = model.springB[std::size_t(k)];
    const double wa = model.invMass[a];
    const double wb = model.invMass[b];
    const double stiffness = model.stiffness[k];
    if (!(wa + wb > 0.0) || !(stiffness > 0.0))
        return;
    const Eigen::Vector3d d = x.col(a) - x.col(b);
    const double length = d.norm();
    if (!(length > 0.0))
        return;  // no direction to pull along
    const Eigen::Vector3d n = d / length;
    const double compliance = 1.0 / (stiffness * h * h);  // α / h²
    const double gamma = model.damping[k] / (stiffness * h);
    const double closing = n.dot((x.col(a) - start.col(a)) - (x.col(b) - start.col(b)));
    const double lambda =
        (-(length - model.restLength[k]) - gamma * closing) / ((1.0 + gamma) * (wa + wb) + compliance);
    x.col(a) += (wa * lambda) * n;
    x.col(b) -= (wb * lambda) * n;
}

}  // namespace

void xpbd(const Model &model, State &state, Workspace &work, double h)
{
    Eigen::Matrix3Xd &start = scratch(state, work, 0);
    computeExternalForces(model, state, work);
    // 1 and 2: the kick, the drag implicit, and the prediction; pinned particles have w = 0 and v = 0
    for (int i : model.freeParticles) {
        const double w = model.invMass[i];
        state.velocity.col(i) = (state.velocity.col(i) + (h * w) * work.force.col(i)) / (1.0 + h * model.viscosity * w);
    }
    start = state.position;
    state.position += h * state.velocity;

    // 3: the springs, colour by colour
    if (model.plan.springs) {
        const std::vector<int> &order = model.xpbdOrder;
        for (std::size_t c = 0; c + 1 < model.xpbdColourStart.size(); ++c) {
            const int first = model.xpbdColourStart[c];
            const int count = model.xpbdColourStart[c + 1] - first;
            parallelChunks(count, [&](int begin, int end) {
                for (int s = begin; s < end; ++s)
                    project(model, state, start, state.position, order[std::size_t(first + s)], h);
            });
        }
    }

    // 4: the velocity is the move
    const double perSecond = 1.0 / h;
    for (int i : model.freeParticles)
        state.velocity.col(i) = (state.position.col(i) - start.col(i)) * perSecond;
}

}  // namespace core
