// The Euler sub-step of a lattice-like model (SpringLayout::blocks), a block of particles at a
// time, with every force pass and the update fused. Run separately, gravity, the springs and the
// update each stream the particle arrays from memory, and the spring kernel spends its time turning
// xyz triples into vectors, twelve reads per particle. Here each thread walks its share of the
// particles block by block, and for each block
//   1. takes the positions and velocities of the block and of the springs' reach either side into
//      one array per component (the window), each particle once, as the window slides on;
//   2. sums the block's forces there: gravity, drag, the springs run by run
//      (SpringLayout::blockRuns, or the short runs joined into long ones, SpringLayout::joined),
//      the applied forces, each particle in the plain passes' order. A run whose ends lie kFarEnds
//      or more apart adds each spring's force to its ends as it computes it; one whose ends are
//      nearer computes a chunk of forces, then adds them (addChunk), as its ends share vectors;
//   3. moves the block's free particles, checking what it writes.
// The window holds the old values, so a block's springs see the state at the start of the sub-step
// even after the block before it has moved. The particles just past a thread's share belong to the
// next thread, which may move them first: each thread copies its neighbours' reach before any
// thread moves anything (the first phase).
//
// Every force and every update comes from the same operations in the same order as the separate
// passes (computeForces, then the Euler update), so the bits are theirs, on any number of threads.

#include "core/springs/spring_kernels.h"
#include "core/parallel.h"
#include "core/passes.h"
#include "core/step.h"

#include <algorithm>
#include <array>
#include <atomic>
#include <cassert>
#include <cstdlib>
#include <cstring>
#include <type_traits>

namespace core {

namespace {

// the two ends of the springs of a chunk, one array per component, already at the chunk's first
struct EndLanes {
    const double *x, *y, *z, *vx, *vy, *vz;
};

// the chunk's forces on end a, one array per component
struct ForceLanes {
    double *x, *y, *z;
};

// a chunk's broken flags as doubles (1 or 0), for chunkForces: compared there as bytes, they
// made the compiler use two lanes where it could use eight
SPRINGLAB_SIMD_CLONES void widenFlags(int count, const std::uint8_t *__restrict flags, double *__restrict out)
{
#pragma omp simd
    for (int j = 0; j < count; ++j)
        out[j] = flags[j] != 0 ? 1.0 : 0.0;
}

// Uniform: every spring has the first's parameters (SpringRun::uniform), read once
template <bool Breakable, bool Uniform>
SPRINGLAB_SIMD_CLONES void chunkForces(int count, const double *__restrict restLength, const double *__restrict stiffness,
                                       const double *__restrict damping, const double *__restrict broken,
                                       EndLanes a, EndLanes b, ForceLanes out)
{
#pragma omp simd
    for (int j = 0; j < count; ++j) {
        const int k = Uniform ? 0 : j;
        const SpringEnds ends{a.x[j] - b.x[j], a.y[j] - b.y[j], a.z[j] - b.z[j],
                              a.vx[j] - b.vx[j], a.vy[j] - b.vy[j], a.vz[j] - b.vz[j]};
        dampedSpring(ends, restLength[k], stiffness[k], damping[k], Breakable && broken[j] != 0.0, out.x[j], out.y[j],
                     out.z[j]);
    }
}

// Which ends of a stretch of springs lie in the block: their forces are added there
enum Ends { EndA = 1, EndB = 2, BothEnds = 3 };

// The ends of a run at least kFarEnds apart in the numbering: its springs' forces go straight to
// their ends' sums, +f at end a and -f at end b, as each is computed. A spring's two ends are then
// never in one vector, and a particle's end-b force (spring q - b) is added a vector or more before
// or after its end-a force (spring q - a), in the plain loop's order either way (ascending j).
// safelen: the compiler must not take more than 8 springs at once, nor move one vector's reads
// of the sums above the last one's writes (the pointers may alias, so they are not restrict).
// The divider bounds this loop, and the sums' reads and writes fit in the slots it leaves.
constexpr int kFarEnds = 8;

template <bool Breakable, bool Uniform, int Sides>
SPRINGLAB_SIMD_CLONES void chunkForcesAdded(int count, const double *__restrict restLength,
                                            const double *__restrict stiffness, const double *__restrict damping,
                                            const double *__restrict broken, EndLanes a, EndLanes b, ForceLanes toA,
                                            ForceLanes toB)
{
#pragma omp simd safelen(kFarEnds)
    for (int j = 0; j < count; ++j) {
        const int k = Uniform ? 0 : j;
        const SpringEnds ends{a.x[j] - b.x[j], a.y[j] - b.y[j], a.z[j] - b.z[j],
                              a.vx[j] - b.vx[j], a.vy[j] - b.vy[j], a.vz[j] - b.vz[j]};
        double fx, fy, fz;
        dampedSpring(ends, restLength[k], stiffness[k], damping[k], Breakable && broken[j] != 0.0, fx, fy, fz);
        // both ends' sums read before either is written, so that no read waits on the other end's
        // write (ends a multiple of 512 particles apart share their addresses' low 12 bits, which
        // is what the CPU compares first); side by side, 3-6% faster at N = 512 and 1024
        constexpr bool atA = (Sides & EndA) != 0;
        constexpr bool atB = (Sides & EndB) != 0;
        const double ax = atA ? toA.x[j] : 0.0, ay = atA ? toA.y[j] : 0.0, az = atA ? toA.z[j] : 0.0;
        const double bx = atB ? toB.x[j] : 0.0, by = atB ? toB.y[j] : 0.0, bz = atB ? toB.z[j] : 0.0;
        if constexpr (atB) {
            toB.x[j] = bx - fx;
            toB.y[j] = by - fy;
            toB.z[j] = bz - fz;
        }
        if constexpr (atA) {
            toA.x[j] = ax + fx;
            toA.y[j] = ay + fy;
            toA.z[j] = az + fz;
        }
    }
}

// force[i] ± first[i], then ± second[i], over count values: a particle that is end a of one of the
// chunk's springs and end b of another gets both in one read and one write
SPRINGLAB_SIMD_CLONES void addTwoLanes(int count, double firstSign, const double *__restrict first, double secondSign,
                                       const double *__restrict second, double *__restrict force)
{
#pragma omp simd
    for (int i = 0; i < count; ++i) {
        const double once = firstSign > 0.0 ? force[i] + first[i] : force[i] - first[i];
        force[i] = secondSign > 0.0 ? once + second[i] : once - second[i];
    }
}

// One thread's scratch, carved out of State::blockScratch: the window of positions and velocities
// (particles [lo, hi), index p - lo), the copy of the next thread's first particles (the trail,
// index p - last), and the block's forces (index p - begin).
struct Slot {
    std::array<double *, 6> window;  // x, y, z, vx, vy, vz
    std::array<double *, 6> trail;
    std::array<double *, 3> force;
    int lo = 0;
    int hi = 0;
};

// Each lane of a slot starts a cache line past where the one before it ends: lanes whose lengths are
// multiples of 4 KiB (a block of 8192 particles with a reach of 512 or 1024) would otherwise all
// start at the same place within a page, so the kernels' dozen streams would fall into one set of
// the L1 cache and evict each other (a 512 × 512 cloth's sub-step took 20% longer than a 520 × 520
// one's)
constexpr std::size_t kLaneSkew = 8;  // doubles

std::size_t slotSize(int reach)
{
    return 6 * (static_cast<std::size_t>(kSpringBlock + 2 * reach) + kLaneSkew) +
           6 * (static_cast<std::size_t>(reach) + kLaneSkew) + 3 * (static_cast<std::size_t>(kSpringBlock) + kLaneSkew);
}

Slot slotAt(double *base, int reach)
{
    Slot slot;
    const std::size_t window = static_cast<std::size_t>(kSpringBlock + 2 * reach) + kLaneSkew;
    for (std::size_t k = 0; k < 6; ++k)
        slot.window[k] = base + k * window;
    base += 6 * window;
    const std::size_t trail = static_cast<std::size_t>(reach) + kLaneSkew;
    for (std::size_t k = 0; k < 6; ++k)
        slot.trail[k] = base + k * trail;
    base += 6 * trail;
    const std::size_t force = static_cast<std::size_t>(kSpringBlock) + kLaneSkew;
    for (std::size_t k = 0; k < 3; ++k)
        slot.force[k] = base + k * force;
    return slot;
}

// particles [from, to) of the xyz triples x and v into the lanes out, at index p - origin. One
// loop over the particles with all six values in it: the compiler turns the triples into lanes with
// shuffles, which cost far less than a gather per component
SPRINGLAB_SIMD_CLONES void splitTriples(const double *__restrict x, const double *__restrict v, int from, int to,
                                        int origin, const std::array<double *, 6> &out)
{
    double *__restrict px = out[0] - origin;
    double *__restrict py = out[1] - origin;
    double *__restrict pz = out[2] - origin;
    double *__restrict qx = out[3] - origin;
    double *__restrict qy = out[4] - origin;
    double *__restrict qz = out[5] - origin;
#pragma omp simd
    for (int p = from; p < to; ++p) {
        px[p] = x[3 * p];
        py[p] = x[3 * p + 1];
        pz[p] = x[3 * p + 2];
        qx[p] = v[3 * p];
        qy[p] = v[3 * p + 1];
        qz[p] = v[3 * p + 2];
    }
}

// the runs a sub-step walks and their springs' parameters: the joined runs (SpringLayout::joined),
// or the list's own where none were joined or the state has broken flags (one per spring of the list)
struct RunSet {
    const std::vector<SpringRun> &runs;
    const std::vector<int> &blockRunOffsets;
    const std::vector<int> &blockRuns;
    const double *restLength;
    const double *stiffness;
    const double *damping;
};

RunSet runSetFor(const Model &model, bool breakable)
{
    const SpringLayout &layout = model.springLayout;
    const SpringLayout::JoinedRuns &joined = layout.joined;
    if (breakable || joined.runs.empty())
        return RunSet{layout.runs, layout.blockRunOffsets, layout.blockRuns, model.restLength.data(),
                      model.stiffness.data(), model.damping.data()};
    return RunSet{joined.runs, joined.blockRunOffsets, joined.blockRuns, joined.restLength.data(),
                  joined.stiffness.data(), joined.damping.data()};
}

// what one sub-step needs, the same for every thread
struct Pass {
    const Model &model;
    State &state;
    double h;
    int reach;  // SpringLayout::reach
    RunSet runs;
    // raised from another thread to stop the step (Workspace::interrupt; null: never); each share
    // then stops at its next block and says so in `cut`: the caller discards the half-done step
    const std::atomic<bool> *interrupt = nullptr;
    std::atomic<bool> *cut = nullptr;
};

// the window extended to hold particles [slot.hi, to): this thread's own from the arrays (not moved
// yet), the next thread's from the trail
void extendWindow(const Pass &pass, Slot &slot, int last, int to)
{
    const int own = std::min(to, last);
    if (slot.hi < own)
        splitTriples(pass.state.position.data(), pass.state.velocity.data(), slot.hi, own, slot.lo, slot.window);
    const int from = std::max(slot.hi, last);
    if (from < to)
        for (int k = 0; k < 6; ++k)
            std::memcpy(slot.window[static_cast<std::size_t>(k)] + (from - slot.lo),
                        slot.trail[static_cast<std::size_t>(k)] + (from - last),
                        static_cast<std::size_t>(to - from) * sizeof(double));
    slot.hi = std::max(slot.hi, to);
}

// the window's particles before lo dropped (they are out of every later block's reach)
void slideWindow(Slot &slot, int lo)
{
    if (lo <= slot.lo)
        return;
    for (double *lane : slot.window)
        std::memmove(lane, lane + (lo - slot.lo), static_cast<std::size_t>(slot.hi - lo) * sizeof(double));
    slot.lo = lo;
}

// gravity: the forces of particles [begin, end) set to 0 + m g, as the passes do
void startForces(const Pass &pass, const Slot &slot, int begin, int end)
{
    const Model &model = pass.model;
    const double *mass = model.mass.data();
    for (int axis = 0; axis < 3; ++axis) {
        double *__restrict f = slot.force[static_cast<std::size_t>(axis)] - begin;
        const double g = model.gravity[axis];
        if (model.plan.gravity) {
#pragma omp simd
            for (int p = begin; p < end; ++p)
                f[p] = startingForce(g, mass[p]);
        } else {
            std::fill(f + begin, f + end, 0.0);
        }
    }
}

void addDragForces(const Pass &pass, const Slot &slot, int begin, int end)
{
    const double c = pass.model.viscosity;
    for (int axis = 0; axis < 3; ++axis) {
        double *__restrict f = slot.force[static_cast<std::size_t>(axis)] - begin;
        const double *__restrict v = slot.window[static_cast<std::size_t>(3 + axis)] - slot.lo;
#pragma omp simd
        for (int p = begin; p < end; ++p)
            f[p] = f[p] - c * v[p];
    }
}

void addAppliedForces(const Pass &pass, const Slot &slot, int begin, int end)
{
    const double *applied = pass.state.applied.data();
    for (int axis = 0; axis < 3; ++axis) {
        double *__restrict f = slot.force[static_cast<std::size_t>(axis)] - begin;
#pragma omp simd
        for (int p = begin; p < end; ++p)
            f[p] = f[p] + applied[3 * p + axis];
    }
}

// The forces of a chunk of a run's springs, j in [from, to), added to their ends in the block that
// starts at begin. The particles that are end a of one of these springs and those that are end b
// are two stretches; where they overlap each particle gets both forces in one pass, in the plain
// loop's order (addInPlainOrder: end b's first when b > a). Two passes over overlapping stretches
// would each read values the other has only just written, a few lanes apart, and stall.
void addChunk(const Slot &slot, const SpringRun &run, const RunSides &sides, int from, int to, int begin,
              const double *chunk)
{
    struct Side {
        int lo, hi;   // particles, relative to the block
        int spring;   // the chunk index of the spring at particle lo
        double sign;
    };
    std::array<Side, 2> order{};
    int count = 0;
    addInPlainOrder(run, sides, [&](int lowest, int highest, int firstEnd, double sign) {
        const int j0 = std::max(from, lowest);
        const int j1 = std::min(to, highest);
        if (j0 < j1)
            order[static_cast<std::size_t>(count++)] = Side{firstEnd + j0 - begin, firstEnd + j1 - begin, j0 - from, sign};
    });
    const auto one = [&](const Side &side, int lo, int hi) {
        if (lo < hi)
            for (int axis = 0; axis < 3; ++axis)
                addSigned(hi - lo, side.sign, chunk + axis * kSpringChunk + side.spring + (lo - side.lo),
                        slot.force[static_cast<std::size_t>(axis)] + lo);
    };
    if (count == 1) {
        one(order[0], order[0].lo, order[0].hi);
        return;
    }
    if (count == 0)
        return;
    const Side &first = order[0];
    const Side &second = order[1];
    const int lo = std::max(first.lo, second.lo);
    const int hi = std::min(first.hi, second.hi);
    if (lo >= hi) {  // apart: each on its own, in either order
        one(first, first.lo, first.hi);
        one(second, second.lo, second.hi);
        return;
    }
    one(first, first.lo, lo);
    one(second, second.lo, lo);
    for (int axis = 0; axis < 3; ++axis) {
        const double *lane = chunk + axis * kSpringChunk;
        addTwoLanes(hi - lo, first.sign, lane + first.spring + (lo - first.lo), second.sign,
                    lane + second.spring + (lo - second.lo), slot.force[static_cast<std::size_t>(axis)] + lo);
    }
    one(first, hi, first.hi);
    one(second, hi, second.hi);
}

// the window's lanes from particle on
EndLanes windowLanes(const Slot &slot, int particle)
{
    const int i = particle - slot.lo;
    return EndLanes{slot.window[0] + i, slot.window[1] + i, slot.window[2] + i,
                    slot.window[3] + i, slot.window[4] + i, slot.window[5] + i};
}

// The springs j in [from, to) of a run whose ends are kFarEnds or more apart, their forces added
// straight to the ends that lie in the block that starts at begin: the chunk cut where an end
// enters or leaves the block, each stretch with the ends it has there
template <bool Breakable>
void addFarChunk(const Pass &pass, const Slot &slot, const SpringRun &run, const RunSides &sides, int from,
                 int to, int begin, const double *broken)
{
    const RunSet &set = pass.runs;
    std::array<int, 6> cuts{from, to, std::clamp(sides.aLo, from, to), std::clamp(sides.aHi, from, to),
                            std::clamp(sides.bLo, from, to), std::clamp(sides.bHi, from, to)};
    std::sort(cuts.begin(), cuts.end());
    const auto sums = [&](int particle) {
        const int i = particle - begin;
        return ForceLanes{slot.force[0] + i, slot.force[1] + i, slot.force[2] + i};
    };
    for (std::size_t c = 0; c + 1 < cuts.size(); ++c) {
        const int x = cuts[c];
        const int y = cuts[c + 1];
        if (x >= y)
            continue;
        const int here = (sides.aLo <= x && y <= sides.aHi ? EndA : 0) | (sides.bLo <= x && y <= sides.bHi ? EndB : 0);
        const int spring = run.uniform ? run.first : run.first + x;
        const double *flags = Breakable ? broken + (x - from) : nullptr;
        const EndLanes a = windowLanes(slot, run.a + x);
        const EndLanes b = windowLanes(slot, run.b + x);
        const auto kernel = [&](auto chosen) {
            constexpr int Sides = decltype(chosen)::value;
            const auto added = run.uniform ? chunkForcesAdded<Breakable, true, Sides>
                                           : chunkForcesAdded<Breakable, false, Sides>;
            added(y - x, set.restLength + spring, set.stiffness + spring, set.damping + spring, flags, a, b,
                  sums(run.a + x), sums(run.b + x));
        };
        if (here == BothEnds)
            kernel(std::integral_constant<int, BothEnds>{});
        else if (here == EndA)
            kernel(std::integral_constant<int, EndA>{});
        else if (here == EndB)
            kernel(std::integral_constant<int, EndB>{});
    }
}

// A run's springs j in [lo, hi), a chunk at a time, their forces added to the ends that lie in
// the block [begin, end) (sides), in the plain loop's order (addInPlainOrder)
template <bool Breakable>
void runOnBlock(const Pass &pass, const Slot &slot, const SpringRun &run, int lo, int hi,
                const RunSides &sides, int begin)
{
    double chunk[3 * kSpringChunk];
    double broken[Breakable ? kSpringChunk : 1];
    const ForceLanes out{chunk, chunk + kSpringChunk, chunk + 2 * kSpringChunk};
    const RunSet &set = pass.runs;
    const bool far = std::abs(run.b - run.a) >= kFarEnds;
    for (int from = lo; from < hi; from += kSpringChunk) {
        const int to = std::min(hi, from + kSpringChunk);
        if constexpr (Breakable)
            widenFlags(to - from, pass.state.springBroken.data() + run.first + from, broken);
        if (far) {
            addFarChunk<Breakable>(pass, slot, run, sides, from, to, begin, Breakable ? broken : nullptr);
            continue;
        }
        const int spring = run.uniform ? run.first : run.first + from;
        const auto forces = run.uniform ? chunkForces<Breakable, true> : chunkForces<Breakable, false>;
        forces(to - from, set.restLength + spring, set.stiffness + spring, set.damping + spring,
               Breakable ? broken : nullptr, windowLanes(slot, run.a + from), windowLanes(slot, run.b + from), out);
        addChunk(slot, run, sides, from, to, begin, chunk);
    }
}

// every spring with an end in [begin, end), which lies in one block of the model's index
template <bool Breakable>
void springsOnBlock(const Pass &pass, const Slot &slot, int begin, int end)
{
    const RunSet &set = pass.runs;
    const auto q = static_cast<std::size_t>(begin / kSpringBlock);
    for (int e = set.blockRunOffsets[q]; e < set.blockRunOffsets[q + 1]; ++e) {
        const SpringRun &run = set.runs[static_cast<std::size_t>(set.blockRuns[static_cast<std::size_t>(e)])];
        forEachRunPiece(run, begin, end, [&](int lo, int hi, const RunSides &sides) {
            runOnBlock<Breakable>(pass, slot, run, lo, hi, sides, begin);
        });
    }
}

// the Euler update of the free particles [from, to) of the block that starts at begin, from the
// window's old values, written to the state's arrays; whether any new value is bad (as
// integrate.cpp's eulerUpdate, the same eulerCoordinate)
template <bool Symplectic>
SPRINGLAB_SIMD_CLONES bool moveLanes(int from, int to, double h, const double *__restrict invMass,
                                     const std::array<const double *, 3> &force, const std::array<const double *, 6> &old,
                                     double *__restrict x, double *__restrict v)
{
    const double *__restrict fx = force[0];
    const double *__restrict fy = force[1];
    const double *__restrict fz = force[2];
    const double *__restrict px = old[0];
    const double *__restrict py = old[1];
    const double *__restrict pz = old[2];
    const double *__restrict qx = old[3];
    const double *__restrict qy = old[4];
    const double *__restrict qz = old[5];
    int bad = 0;
    // one loop with all three components, so that the triples are written with shuffles, not scatters
#pragma omp simd reduction(| : bad)
    for (int p = from; p < to; ++p) {
        const double kick = h * invMass[p];
        const double f[3] = {fx[p], fy[p], fz[p]};
        const double oldX[3] = {px[p], py[p], pz[p]};
        const double oldV[3] = {qx[p], qy[p], qz[p]};
        for (int axis = 0; axis < 3; ++axis)
            bad |= eulerCoordinate<Symplectic>(h, kick, f[axis], oldX[axis], oldV[axis], x[3 * p + axis],
                                               v[3 * p + axis]);
    }
    return bad != 0;
}

template <bool Symplectic>
bool moveParticles(const Pass &pass, const Slot &slot, int from, int to, int begin)
{
    std::array<const double *, 3> force{};
    std::array<const double *, 6> old{};
    for (std::size_t k = 0; k < 3; ++k)
        force[k] = slot.force[k] - begin;
    for (std::size_t k = 0; k < 6; ++k)
        old[k] = slot.window[k] - slot.lo;
    return moveLanes<Symplectic>(from, to, pass.h, pass.model.invMass.data(), force, old, pass.state.position.data(),
                                 pass.state.velocity.data());
}

// one thread's share [first, last), block by block; whether any new value is bad
template <bool Breakable, bool Symplectic>
bool stepShare(const Pass &pass, Slot &slot, int first, int last)
{
    const Model &model = pass.model;
    const StepPlan &plan = model.plan;
    const int n = model.particleCount();
    const std::vector<int> &ranges = model.freeRanges;
    std::size_t range = 0;  // the first free stretch that ends past the block's start
    while (range < ranges.size() && ranges[range + 1] <= first)
        range += 2;
    bool bad = false;
    for (int begin = first; begin < last;) {
        const int end = std::min(last, (begin / kSpringBlock + 1) * kSpringBlock);
        startForces(pass, slot, begin, end);
        if (plan.drag)
            addDragForces(pass, slot, begin, end);
        springsOnBlock<Breakable>(pass, slot, begin, end);
        if (pass.state.appliedCount > 0)
            addAppliedForces(pass, slot, begin, end);
        for (; range < ranges.size() && ranges[range] < end; range += 2) {
            const int from = std::max(begin, ranges[range]);
            const int to = std::min(end, ranges[range + 1]);
            if (from < to && moveParticles<Symplectic>(pass, slot, from, to, begin))
                bad = true;
            if (ranges[range + 1] > end)
                break;  // goes on into the next block
        }
        begin = end;
        // a Pause on 10⁶ particles waited for the whole pass (66 ms on one thread): stop between
        // blocks instead
        if (begin < last && pass.interrupt && pass.interrupt->load(std::memory_order_relaxed)) {
            pass.cut->store(true, std::memory_order_relaxed);
            break;
        }
        if (begin < last) {
            slideWindow(slot, std::max(0, begin - pass.reach));
            extendWindow(pass, slot, last, std::min(n, std::min(last, begin + kSpringBlock) + pass.reach));
        }
    }
    return bad;
}

template <bool Breakable, bool Symplectic>
bool stepBlocks(const Pass &pass, double *scratch, SharesInTurn inTurn)
{
    const Model &model = pass.model;
    const int n = model.particleCount();
    const int reach = pass.reach;
    const std::size_t size = slotSize(reach);
    std::atomic<bool> bad = false;
    parallelChunksInTwoPhases(
        n,
        [&](int thread, int first, int last) {
            // before anyone moves: the reach before the share (the window's start) and after it
            Slot slot = slotAt(scratch + static_cast<std::size_t>(thread) * size, reach);
            const int lo = std::max(0, first - reach);
            splitTriples(pass.state.position.data(), pass.state.velocity.data(), lo, first, lo, slot.window);
            const int trailEnd = std::min(n, last + reach);
            if (last < trailEnd)
                splitTriples(pass.state.position.data(), pass.state.velocity.data(), last, trailEnd, last, slot.trail);
        },
        [&](int thread, int first, int last) {
            if (first >= last)
                return;
            Slot slot = slotAt(scratch + static_cast<std::size_t>(thread) * size, reach);
            slot.lo = std::max(0, first - reach);
            slot.hi = first;
            const int firstEnd = std::min(last, (first / kSpringBlock + 1) * kSpringBlock);
            extendWindow(pass, slot, last, std::min(n, firstEnd + reach));
            if (stepShare<Breakable, Symplectic>(pass, slot, first, last))
                bad.store(true, std::memory_order_relaxed);
        },
        inTurn);
    return bad.load(std::memory_order_relaxed);
}

}  // namespace

bool stepSpringBlocks(const Model &model, State &state, Workspace &work, double h)
{
    return stepSpringBlocks(model, state, work, h, SharesInTurn{});
}

bool stepSpringBlocks(const Model &model, State &state, Workspace &work, double h, const SharesInTurn &inTurn)
{
    assert(model.plan.subStep == SubStepPath::FusedLattice);
    const bool symplectic = model.integrator == Integrator::SymplecticEuler;
    const int reach = model.springLayout.reach;
    const std::size_t size = slotSize(reach) * static_cast<std::size_t>(twoPhaseShares(model.particleCount(), inTurn));
    if (work.blockScratch.size() != size)
        work.blockScratch.resize(size);  // on first use, and when the thread count changes
    const bool breakable = !state.springBroken.empty();
    std::atomic<bool> cut = false;
    const Pass pass{model, state, h, reach, runSetFor(model, breakable), work.interrupt, &cut};
    double *scratch = work.blockScratch.data();
    bool bad = false;
    if (breakable)
        bad = symplectic ? stepBlocks<true, true>(pass, scratch, inTurn) : stepBlocks<true, false>(pass, scratch, inTurn);
    else
        bad = symplectic ? stepBlocks<false, true>(pass, scratch, inTurn)
                         : stepBlocks<false, false>(pass, scratch, inTurn);
    work.profile.forceEvaluations += 1;
    if (cut.load(std::memory_order_relaxed)) {
        // half the particles moved: the step stops here (stopsHere sees it) and is put back
        work.interrupted = true;
        ++work.springPassesCut;
    }
    return !bad;
}

}  // namespace core
