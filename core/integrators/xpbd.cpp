// One xpbd sub-step of h:
//   1. the kick: v += h w f for gravity and the applied forces, the drag taken implicitly,
//      v ← v / (1 + h c w), so that no viscosity can make it unstable;
//   2. the prediction x += h v, the sub-step's start kept as x₀;
//   3. Model::xpbdIterations passes over the springs, each a distance constraint C = |xa − xb| − l0
//      with compliance α = 1/k, α̃ = α/h², and XPBD's damping γ = c / (k h):
//        Δλ = (−C − α̃ λ − γ ∇C·(x − x₀)) / ((1 + γ)(wa + wb) + α̃),   λ += Δλ,
//      the ends moved by wa Δλ n and −wb Δλ n, λ starting at 0 each sub-step. One pass a sub-step
//      (the default) is how "Small Steps in Physics Simulation" (Macklin et al. 2019) runs it: with
//      small steps that converges, and the constraint keeps its stiffness whatever the step, where an
//      explicit spring of k = 1e8 needs sub-steps under 2/ω. More passes hold a stiff spring closer to
//      its rest length at the same sub-step;
//   4. the velocity the move made, v = (x − x₀) / h.
// The springs are projected in the order xpbd_layout.h fixes: block by block (all blocks at once),
// then the seams between blocks, in batches that the kernel below runs as one vectorised loop. No
// two springs of a batch, and no two tasks run at once, move the same particle, so the bits do not
// depend on the thread count. On several threads the whole sub-step is one parallel region, which
// waits for all threads once after the prediction and once after each phase of each pass. A pinned
// particle has w = 0 and never moves.

#include "core/integrators/integrator.h"
#include "core/parallel.h"
#include "core/passes.h"
#include "core/springs/spring_kernels.h"
#include "core/integrators/xpbd_layout.h"

#include <algorithm>
#include <cmath>
#include <cstdint>

namespace core {

namespace {

// slots a chunk: their moves (7 lanes of 2 KB) stay in the L1 cache between the two loops
constexpr int kXpbdChunk = 256;

// a chunk's moves, one lane each: end a's (3), end b's (3), and whether the spring moves at all
struct MoveLanes {
    double *ax, *ay, *az, *bx, *by, *bz, *active;
};

// The moves of slots [0, count) of a batch, the arrays already at the chunk's first slot. Reading
// both ends by index vectorises (the compiler gathers them); writing them cannot without scatters,
// and the ends of a batch's springs never meet, so the writes are a second loop (projectBatch).
// Every clone computes the same IEEE operations in the same order, never contracted
// (cmake/springlab_flags.cmake), so all give the same bits; one division and one square root a
// spring, the rest of the divisions made once per layout and h (XpbdConstants).
// A spring that is broken, or whose ends coincide (no direction to pull along), does not move.
// Accumulate: λ per slot kept across the sub-step's passes (lambda, at the chunk's first slot)
template <bool Breakable, bool Accumulate>
SPRINGLAB_SIMD_CLONES void chunkMoves(int count, const int *__restrict a, const int *__restrict b,
                                      const double *__restrict wa, const double *__restrict wb,
                                      const double *__restrict restLength, const double *__restrict compliance,
                                      const double *__restrict gamma, const double *__restrict inverseDenominator,
                                      const double *__restrict broken, const double *x, const double *x0,
                                      double *__restrict lambda, MoveLanes out)
{
#pragma omp simd
    for (int j = 0; j < count; ++j) {
        const int pa = 3 * a[j];
        const int pb = 3 * b[j];
        const double xa[3] = {x[pa], x[pa + 1], x[pa + 2]};
        const double xb[3] = {x[pb], x[pb + 1], x[pb + 2]};
        const double dx = xa[0] - xb[0], dy = xa[1] - xb[1], dz = xa[2] - xb[2];
        const double length = std::sqrt(dx * dx + dy * dy + dz * dz);
        const bool active = length > 0.0 && !(Breakable && broken[j] != 0.0);
        const double inverse = 1.0 / (active ? length : 1.0);
        const double nx = dx * inverse, ny = dy * inverse, nz = dz * inverse;
        const double qx = (xa[0] - x0[pa]) - (xb[0] - x0[pb]);
        const double qy = (xa[1] - x0[pa + 1]) - (xb[1] - x0[pb + 1]);
        const double qz = (xa[2] - x0[pa + 2]) - (xb[2] - x0[pb + 2]);
        const double closing = nx * qx + ny * qy + nz * qz;
        double numerator = -(length - restLength[j]);
        if constexpr (Accumulate)
            numerator = numerator - compliance[j] * lambda[j];
        numerator = numerator - gamma[j] * closing;
        double step = numerator * inverseDenominator[j];
        step = active ? step : 0.0;
        if constexpr (Accumulate)
            lambda[j] = lambda[j] + step;
        const double ma = wa[j] * step;
        const double mb = wb[j] * step;
        out.ax[j] = ma * nx;
        out.ay[j] = ma * ny;
        out.az[j] = ma * nz;
        out.bx[j] = mb * nx;
        out.by[j] = mb * ny;
        out.bz[j] = mb * nz;
        out.active[j] = active ? 1.0 : 0.0;
    }
}

// the constants of slots [0, count) for the sub-step h
SPRINGLAB_SIMD_CLONES void slotConstants(int count, double h, const double *__restrict wa, const double *__restrict wb,
                                         const double *__restrict stiffness, const double *__restrict damping,
                                         double *__restrict compliance, double *__restrict gamma,
                                         double *__restrict inverseDenominator)
{
#pragma omp simd
    for (int j = 0; j < count; ++j) {
        const double alpha = 1.0 / (stiffness[j] * h * h);  // α / h²
        const double g = damping[j] / (stiffness[j] * h);
        compliance[j] = alpha;
        gamma[j] = g;
        inverseDenominator[j] = 1.0 / ((1.0 + g) * (wa[j] + wb[j]) + alpha);
    }
}

// the workspace's constants, made again when the layout or h has changed
const XpbdConstants &constantsFor(const XpbdLayout &layout, double h, Workspace &work)
{
    XpbdConstants &c = work.xpbdConstants;
    if (c.layout == layout.id && c.h == h)
        return c;
    const auto count = std::size_t(layout.slotCount());
    c.compliance.resize(count);
    c.gamma.resize(count);
    c.inverseDenominator.resize(count);
    slotConstants(layout.slotCount(), h, layout.wa.data(), layout.wb.data(), layout.stiffness.data(),
                  layout.damping.data(), c.compliance.data(), c.gamma.data(), c.inverseDenominator.data());
    c.layout = layout.id;
    c.h = h;
    return c;
}

// what a pass over the springs reads and writes
struct Pass {
    const XpbdLayout &layout;
    const XpbdConstants &constants;
    double *x;          // the positions, xyz triples
    const double *x0;   // the sub-step's start
    const std::uint8_t *broken;  // the state's broken flags by spring; null when none can break
    double *lambda;              // per slot, with more than one iteration; else null
};

// batch i's slots, a chunk at a time: the moves computed, then added to the ends
template <bool Breakable, bool Accumulate>
void projectBatch(const Pass &pass, int i)
{
    const XpbdLayout &l = pass.layout;
    double lanes[7 * kXpbdChunk];
    double flags[Breakable ? kXpbdChunk : 1];
    const MoveLanes out{lanes, lanes + kXpbdChunk, lanes + 2 * kXpbdChunk, lanes + 3 * kXpbdChunk,
                        lanes + 4 * kXpbdChunk, lanes + 5 * kXpbdChunk, lanes + 6 * kXpbdChunk};
    const bool movesB = l.batchMovesB[std::size_t(i)] != 0;
    double *x = pass.x;
    for (int from = l.batchStart[std::size_t(i)]; from < l.batchStart[std::size_t(i) + 1]; from += kXpbdChunk) {
        const int count = std::min(kXpbdChunk, l.batchStart[std::size_t(i) + 1] - from);
        const auto s = std::size_t(from);
        if constexpr (Breakable)
            for (int j = 0; j < count; ++j)
                flags[j] = pass.broken[std::size_t(l.spring[s + std::size_t(j)])] != 0 ? 1.0 : 0.0;
        const XpbdConstants &c = pass.constants;
        chunkMoves<Breakable, Accumulate>(count, l.a.data() + s, l.b.data() + s, l.wa.data() + s, l.wb.data() + s,
                                          l.restLength.data() + s, c.compliance.data() + s, c.gamma.data() + s,
                                          c.inverseDenominator.data() + s, flags, x, pass.x0,
                                          Accumulate ? pass.lambda + s : nullptr, out);
        // no two springs of a batch move the same particle: any order gives the same bits
        const int *a = l.a.data() + s;
        const int *b = l.b.data() + s;
        for (int j = 0; j < count; ++j) {
            if (out.active[j] == 0.0)
                continue;
            double *pa = x + 3 * a[j];
            pa[0] = pa[0] + out.ax[j];
            pa[1] = pa[1] + out.ay[j];
            pa[2] = pa[2] + out.az[j];
            if (movesB) {
                double *pb = x + 3 * b[j];
                pb[0] = pb[0] - out.bx[j];
                pb[1] = pb[1] - out.by[j];
                pb[2] = pb[2] - out.bz[j];
            }
        }
    }
}

void runTask(const Pass &pass, int task)
{
    const XpbdLayout &l = pass.layout;
    const bool breakable = pass.broken != nullptr;
    const bool accumulate = pass.lambda != nullptr;
    const auto batch = breakable ? (accumulate ? projectBatch<true, true> : projectBatch<true, false>)
                                 : (accumulate ? projectBatch<false, true> : projectBatch<false, false>);
    for (int i = l.taskStart[std::size_t(task)]; i < l.taskStart[std::size_t(task) + 1]; ++i)
        batch(pass, i);
}

// the free particles of [begin, end), stretch by stretch: body(from, to)
template <typename Body>
void forFree(const Model &model, int begin, int end, Body &&body)
{
    const std::vector<int> &ranges = model.freeRanges;
    for (std::size_t r = 0; r + 1 < ranges.size(); r += 2) {
        const int from = std::max(begin, ranges[r]);
        const int to = std::min(end, ranges[r + 1]);
        if (from < to)
            body(from, to);
    }
}

// The kick of free particles [from, to): v ← (v + h w f) / (1 + h c w), f summed as
// computeExternalForces() sums it (0 + m g, then + the applied force), the same bits, without a pass
// of its own. Without drag the divisor is exactly 1 and the division is left out (the same bits).
// One loop with all three components, so that the triples are read and written with shuffles
template <bool Drag, bool Applied>
SPRINGLAB_SIMD_CLONES void kickLanes(int from, int to, double h, double c, const double *__restrict g,
                                     const double *__restrict w, const double *__restrict mass,
                                     const double *__restrict applied, double *__restrict v)
{
#pragma omp simd
    for (int i = from; i < to; ++i) {
        const double kick = h * w[i];
        const double slow = 1.0 + h * c * w[i];
        for (int axis = 0; axis < 3; ++axis) {
            double f = startingForce(g[axis], mass[i]);
            if constexpr (Applied)
                f = f + applied[3 * i + axis];
            const double kicked = v[3 * i + axis] + kick * f;
            v[3 * i + axis] = Drag ? kicked / slow : kicked;
        }
    }
}

// values [from, to) of the xyz triples: the start kept, and the prediction x + h v
SPRINGLAB_SIMD_CLONES void predictLanes(int from, int to, double h, const double *__restrict v, double *__restrict x,
                                        double *__restrict x0)
{
#pragma omp simd
    for (int k = from; k < to; ++k) {
        x0[k] = x[k];
        x[k] = x[k] + h * v[k];
    }
}

// values [from, to) of the xyz triples: the velocity is the move
SPRINGLAB_SIMD_CLONES void settleLanes(int from, int to, double perSecond, const double *__restrict x,
                                       const double *__restrict x0, double *__restrict v)
{
#pragma omp simd
    for (int k = from; k < to; ++k)
        v[k] = (x[k] - x0[k]) * perSecond;
}

// 1 and 2 for particles [begin, end): the kick of the free ones, and every particle's start kept
// and moved by h v (pinned particles have v = 0 and keep it)
void kickAndPredict(const Model &model, State &state, Eigen::Matrix3Xd &start, double h, int begin, int end)
{
    double *v = state.velocity.data();
    const double *applied = state.appliedCount > 0 ? state.applied.data() : nullptr;
    // no gravity: 0 + 0 m, the 0 the passes start from
    const double g[3] = {model.plan.gravity ? model.gravity[0] : 0.0, model.plan.gravity ? model.gravity[1] : 0.0,
                         model.plan.gravity ? model.gravity[2] : 0.0};
    const auto kick = model.plan.drag ? (applied ? kickLanes<true, true> : kickLanes<true, false>)
                                      : (applied ? kickLanes<false, true> : kickLanes<false, false>);
    forFree(model, begin, end, [&](int from, int to) {
        kick(from, to, h, model.viscosity, g, model.invMass.data(), model.mass.data(), applied, v);
    });
    predictLanes(3 * begin, 3 * end, h, v, state.position.data(), start.data());
}

// 4 for particles [begin, end): the velocity is the move
void settle(const Model &model, State &state, const Eigen::Matrix3Xd &start, double h, int begin, int end)
{
    const double perSecond = 1.0 / h;
    forFree(model, begin, end, [&](int from, int to) {
        settleLanes(3 * from, 3 * to, perSecond, state.position.data(), start.data(), state.velocity.data());
    });
}

// The layout to project: the model's while no spring can break, else the model's without the
// broken springs. A run resumed from a file written after a break (storeState leaves the broken
// springs out) compiles exactly that layout, so both runs project in one order, to the bit. Laid
// out again only when the broken set or the model changes, into the workspace's memory: the first
// time, before any spring has broken, makes room for every later time, so a break allocates nothing
const XpbdLayout &layoutFor(const Model &model, const State &state, Workspace &work)
{
    const std::vector<std::uint8_t> &broken = state.springBroken;
    if (!model.plan.springBreaks || broken.size() != std::size_t(model.springCount()))
        return model.xpbdLayout;
    if (work.xpbdTornFrom != model.xpbdLayout.id || work.xpbdTornFlags != broken) {
        layOutXpbd(model, &broken, work.xpbdTornLayout, work.xpbdTornScratch);
        work.xpbdTornFrom = model.xpbdLayout.id;
        work.xpbdTornFlags = broken;
    }
    return work.xpbdTornLayout;
}

}  // namespace

void xpbd(const Model &model, State &state, Workspace &work, double h)
{
    Eigen::Matrix3Xd &start = scratch(state, work, 0);
    work.profile.forceEvaluations += 1;  // the external forces, summed in the kick
    const XpbdLayout &layout = layoutFor(model, state, work);
    const int n = model.particleCount();
    const int iterations = model.plan.springs ? model.xpbdIterations : 0;
    double *lambda = nullptr;
    if (iterations > 1) {
        work.xpbdLambda.assign(std::size_t(layout.slotCount()), 0.0);  // allocates on first use only
        lambda = work.xpbdLambda.data();
    }
    const Pass pass{layout, constantsFor(layout, h, work), state.position.data(), start.data(),
                    state.springBroken.empty() ? nullptr : state.springBroken.data(), lambda};

#ifdef SPRINGLAB_OPENMP
    // several threads only where a phase has several tasks to share and enough springs to pay for
    // waking them
    const bool shared = layout.phaseCount() > 0 && layout.phaseStart[1] >= 2 && splitAcrossThreads(layout.slotCount());
    if (shared) {
#pragma omp parallel
        {
            const long long threads = omp_get_num_threads();
            const long long thread = omp_get_thread_num();
            const auto share = [&](int first, int count, long long t) { return first + int(count * t / threads); };
            kickAndPredict(model, state, start, h, share(0, n, thread), share(0, n, thread + 1));
#pragma omp barrier
            for (int iteration = 0; iteration < iterations; ++iteration)
                for (int p = 0; p < layout.phaseCount(); ++p) {
                    const int first = layout.phaseStart[std::size_t(p)];
                    const int count = layout.phaseStart[std::size_t(p) + 1] - first;
                    for (int t = share(first, count, thread); t < share(first, count, thread + 1); ++t)
                        runTask(pass, t);
#pragma omp barrier
                }
            settle(model, state, start, h, share(0, n, thread), share(0, n, thread + 1));
        }
        return;
    }
#endif
    // on one thread: the same tasks in the same order, no waiting
    kickAndPredict(model, state, start, h, 0, n);
    for (int iteration = 0; iteration < iterations; ++iteration)
        for (int t = 0; t < layout.taskCount(); ++t)
            runTask(pass, t);
    settle(model, state, start, h, 0, n);
}

}  // namespace core
