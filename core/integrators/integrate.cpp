#include "core/parallel.h"
#include "core/passes.h"
#include "core/springs/spring_kernels.h"

#include "core/step.h"

#include <algorithm>
#include <atomic>

namespace core {

Eigen::Matrix3Xd &scratch(const State &state, Workspace &work, int index)
{
    Eigen::Matrix3Xd &array = work.scratchArrays[static_cast<std::size_t>(index)];
    if (array.cols() != state.position.cols())
        array.resize(3, state.position.cols());  // once, on first use: later steps reuse it
    return array;
}

namespace {

// one Euler update of the particles [begin, end), all free: the new velocity moves the particle
// (symplectic) or the old one does (explicit). Flat arrays with unit stride so that it vectorises;
// the same IEEE operations in the same order as (h / m) f and h v written with Eigen columns.
// Returns whether any new value is not finite or past kBlowupBound, found in the same loop (the
// finite check then need not read the arrays again). The arithmetic is eulerCoordinate's, which the
// fused sub-step's update over lanes (spring_blocks.cpp) shares.
template <bool Symplectic>
bool eulerUpdate(int begin, int end, const double *__restrict invMass, const double *__restrict force,
                 double *__restrict x, double *__restrict v, double h)
{
    int bad = 0;
#pragma omp simd reduction(| : bad)
    for (int p = begin; p < end; ++p) {
        const int i = 3 * p;
        const double kick = h * invMass[p];
        for (int axis = 0; axis < 3; ++axis)
            bad |= eulerCoordinate<Symplectic>(h, kick, force[i + axis], x[i + axis], v[i + axis], x[i + axis],
                                               v[i + axis]);
    }
    return bad != 0;
}

// returns whether every new value is finite and bounded, checked as it was written
template <bool Symplectic>
bool euler(const Model &model, State &state, Workspace &work, double h)
{
    computeForces(model, state, work);
    // each thread its share of the particles, the free stretches within it
    const std::vector<int> &ranges = model.freeRanges;
    std::atomic<bool> bad = false;
    parallelChunks(model.particleCount(), [&](int first, int last) {
        for (std::size_t r = 0; r < ranges.size(); r += 2) {
            const int begin = std::max(first, ranges[r]);
            const int end = std::min(last, ranges[r + 1]);
            if (begin < end && eulerUpdate<Symplectic>(begin, end, model.invMass.data(), work.force.data(),
                                                       state.position.data(), state.velocity.data(), h))
                bad.store(true, std::memory_order_relaxed);
        }
    });
    return !bad.load(std::memory_order_relaxed);
}

// the handout's scheme: the new velocity moves the particle
bool symplecticEuler(const Model &model, State &state, Workspace &work, double h)
{
    return euler<true>(model, state, work, h);
}

// forward Euler: position and velocity both advance from the old state
bool explicitEuler(const Model &model, State &state, Workspace &work, double h)
{
    return euler<false>(model, state, work, h);
}

// kick-drift-kick: half a velocity step, a full position step, half a velocity step with the
// forces at the new position. Dampers need the new velocity too, which is not known yet: they are
// given the prediction v + h a (error O(h²)), which keeps the scheme second order; without
// velocity-dependent forces it is exactly the classic velocity Verlet
void velocityVerlet(const Model &model, State &state, Workspace &work, double h)
{
    Eigen::Matrix3Xd &a = scratch(state, work, 0);
    Eigen::Matrix3Xd &half = scratch(state, work, 1);
    computeForces(model, state, work);
    accelerations(model, work, a);
    half = state.velocity + (0.5 * h) * a;
    state.position += h * half;
    state.velocity += h * a;  // the prediction the dampers see
    computeForces(model, state, work);
    accelerations(model, work, a);
    state.velocity = half + (0.5 * h) * a;
}

}  // namespace

// advances every free particle by h; pinned ones have zero inverse mass and zero velocity, so the
// whole-array schemes leave them where they are. The Euler schemes check what they write
bool integrate(const Model &model, State &state, Workspace &work, double h)
{
    switch (model.integrator) {
    case Integrator::SymplecticEuler: return symplecticEuler(model, state, work, h);
    case Integrator::ExplicitEuler: return explicitEuler(model, state, work, h);
    case Integrator::VelocityVerlet: velocityVerlet(model, state, work, h); return false;
    case Integrator::Rk4: rk4(model, state, work, h); return false;
    case Integrator::ImplicitEuler: implicitEuler(model, state, work, h); return false;
    case Integrator::AdaptiveRk45: adaptiveRk45(model, state, work, h); return false;
    case Integrator::Xpbd: xpbd(model, state, work, h); return false;
    case Integrator::Projective: projective(model, state, work, h); return false;
    case Integrator::Vbd: vbd(model, state, work, h); return false;
    }
    return false;
}

}  // namespace core
