#include "core/springs/spring_kernels.h"
#include "core/geometry.h"
#include "core/parallel.h"
#include "core/passes.h"

#include <algorithm>
#include <cmath>
#include <cstdint>

namespace core {

namespace {

// the handout's damped spring k on end a: -k (l - l0) u - kc ((va - vb)·u) u, u = (xa - xb) / l
Eigen::Vector3d springForce(const Model &model, const State &state, int k)
{
    const auto &x = state.position;
    const auto &v = state.velocity;
    const int a = model.springA[static_cast<std::size_t>(k)];
    const int b = model.springB[static_cast<std::size_t>(k)];
    const Eigen::Vector3d d = x.col(a) - x.col(b);
    const double length = d.norm();
    const Eigen::Vector3d u = directionOr(d, length);
    const double stretch = length - model.restLength[k];
    const double approach = (v.col(a) - v.col(b)).dot(u);
    return (-model.stiffness[k] * stretch - model.damping[k] * approach) * u;
}

// springs [begin, end) of any list, their ends gathered by index, three values per spring into out.
// Scenes with breakable springs pass their broken flags; the others build without them and pay
// nothing for them.
template <bool Breakable>
SPRINGLAB_SIMD_CLONES void springForces(int begin, int end, const int *__restrict springA,
                                        const int *__restrict springB, const double *__restrict restLength,
                                        const double *__restrict stiffness, const double *__restrict damping,
                                        const std::uint8_t *__restrict broken, const double *__restrict x,
                                        const double *__restrict v, double *__restrict out)
{
#pragma omp simd
    for (int k = begin; k < end; ++k) {
        const int a = 3 * springA[k];
        const int b = 3 * springB[k];
        dampedSpring(x + a, x + b, v + a, v + b, restLength[k], stiffness[k], damping[k],
                     Breakable && broken[k] != 0, out + 3 * k);
    }
}

// springs j = 0 … count - 1 of a run, ends a + j and b + j: the ends are read with unit stride.
// The arrays start at the run's first spring (parameters, flags) and at its first ends (x, v).
template <bool Breakable>
SPRINGLAB_SIMD_CLONES void runForces(int count, const double *__restrict restLength, const double *__restrict stiffness,
                                     const double *__restrict damping, const std::uint8_t *__restrict broken,
                                     const double *__restrict xa, const double *__restrict xb,
                                     const double *__restrict va, const double *__restrict vb, double *__restrict out)
{
#pragma omp simd
    for (int j = 0; j < count; ++j)
        dampedSpring(xa + 3 * j, xb + 3 * j, va + 3 * j, vb + 3 * j, restLength[j], stiffness[j], damping[j],
                     Breakable && broken[j] != 0, out + 3 * j);
}

// The run's springs j in [lo, hi), a chunk at a time: compute the chunk's forces, then add them
// to the ends of those springs that lie in this thread's particles (sides), in the plain loop's
// order (addInPlainOrder).
template <bool Breakable>
void runPiece(const Model &model, State &state, Workspace &work, const SpringRun &run, int lo, int hi, const RunSides &sides)
{
    double chunk[3 * kSpringChunk];
    const double *x = state.position.data();
    const double *v = state.velocity.data();
    double *f = work.force.data();
    const std::uint8_t *broken = Breakable ? state.springBroken.data() + run.first : nullptr;
    for (int begin = lo; begin < hi; begin += kSpringChunk) {
        const int end = std::min(hi, begin + kSpringChunk);
        const int spring = run.first + begin;
        runForces<Breakable>(end - begin, model.restLength.data() + spring, model.stiffness.data() + spring,
                             model.damping.data() + spring, Breakable ? broken + begin : nullptr,
                             x + 3 * (run.a + begin), x + 3 * (run.b + begin), v + 3 * (run.a + begin),
                             v + 3 * (run.b + begin), chunk);
        addInPlainOrder(run, sides, [&](int lowest, int highest, int particle, double sign) {
            const int from = std::max(begin, lowest);
            const int to = std::min(end, highest);
            if (from < to)
                addSigned(3 * (to - from), sign, chunk + 3 * (from - begin), f + 3 * (particle + from));
        });
    }
}

// every run's forces on particles [first, last): the springs with an end there, each once (a
// spring whose other end is another thread's is computed by both, with the same bits)
template <bool Breakable>
void runsOnParticles(const Model &model, State &state, Workspace &work, int first, int last)
{
    for (const SpringRun &run : model.springLayout.runs)
        forEachRunPiece(run, first, last, [&](int lo, int hi, const RunSides &sides) {
            runPiece<Breakable>(model, state, work, run, lo, hi, sides);
        });
}

}  // namespace

void addSprings(const Model &model, State &state, Workspace &work)
{
    if (!model.plan.springs)
        return;
    // the pass the layout chose when the model was compiled
    switch (model.springLayout.pass) {
    case SpringPass::Runs: addSpringRuns(model, state, work); return;
    case SpringPass::Gathered: addSpringsGathered(model, state, work); return;
    }
}

// Each thread takes a contiguous share of the particles, and that share a block at a time: run by
// run, the forces of the springs with an end in the block, in the plain loop's order (runPiece).
// The same bits as addSpringsReference on any number of threads and for any block size. A block's
// positions, velocities and forces (576 KB) stay in the cache while every run passes over them;
// without blocks a large cloth streams them from memory once for each kind of spring. The blocks
// are the fused sub-step's (kSpringBlock), for the same reason.
void addSpringRuns(const Model &model, State &state, Workspace &work)
{
    const bool breakable = !state.springBroken.empty();
    parallelChunks(model.particleCount(), [&](int first, int last) {
        for (int begin = first; begin < last; begin += kSpringBlock) {
            const int end = std::min(last, begin + kSpringBlock);
            if (breakable)
                runsOnParticles<true>(model, state, work, begin, end);
            else
                runsOnParticles<false>(model, state, work, begin, end);
        }
    });
}

// Two passes with no write shared between iterations, so both split across threads with the same
// bits: each spring's force on end a, then each particle sums the forces of its springs in
// ascending spring order (+ at end a, - at end b, Newton's third law). That order is the order
// in which addSpringsReference's scatter adds them, so the two agree to the bit.
void addSpringsGathered(const Model &model, State &state, Workspace &work)
{
    const int springs = model.springCount();
    Eigen::Matrix3Xd &perSpring = work.springForce;
    if (perSpring.cols() != springs)
        perSpring.resize(3, springs);  // once, on first use: later steps reuse it

    const bool breakable = !state.springBroken.empty();
    parallelChunks(springs, [&](int begin, int end) {
        const auto kernel = breakable ? springForces<true> : springForces<false>;
        kernel(begin, end, model.springA.data(), model.springB.data(), model.restLength.data(),
               model.stiffness.data(), model.damping.data(), state.springBroken.data(), state.position.data(),
               state.velocity.data(), perSpring.data());
    });

    const int n = model.particleCount();
    const int *offsets = model.springOffsets.data();
    const int *ends = model.springEnds.data();
    parallelFor(n, [&](int i) {
        Eigen::Vector3d sum = work.force.col(i);
        for (int e = offsets[i]; e < offsets[i + 1]; ++e) {
            const int end = ends[e];
            if (end & 1)
                sum -= perSpring.col(end >> 1);
            else
                sum += perSpring.col(end >> 1);
        }
        work.force.col(i) = sum;
    });
}

// the plain loop over the spring list, scattering into both ends: the reference the tests hold
// addSprings to
void addSpringsReference(const Model &model, State &state, Workspace &work)
{
    if (!model.plan.springs)
        return;
    for (int k = 0; k < model.springCount(); ++k) {
        if (state.isBroken(k))
            continue;
        const Eigen::Vector3d fa = springForce(model, state, k);
        work.force.col(model.springA[static_cast<std::size_t>(k)]) += fa;
        work.force.col(model.springB[static_cast<std::size_t>(k)]) -= fa;
    }
}

}  // namespace core
