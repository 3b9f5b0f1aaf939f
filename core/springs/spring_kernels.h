#pragma once
// What the vectorised kernels share: the target clones they are built with, the handout's damped
// spring, how a run of springs is cut at the edges of a stretch of particles and in which order its
// forces reach their ends, the chunk size and the signed add of the spring passes (springs.cpp,
// spring_blocks.cpp), and the arithmetic of the passes that the fused sub-step repeats over lanes
// (gravity.cpp's start, integrate.cpp's Euler update), so that both give the same bits by
// construction.

#include "core/geometry.h"
#include "core/model/model.h"
#include "core/step.h"

#include <algorithm>

#include <cmath>

// target clones where CMake's check found that they build and run (SPRINGLAB_KERNEL_CLONES,
// cmake/springlab_kernels.cmake, which keeps the same list; never under ThreadSanitizer, whose
// runtime is not up yet when the clones' resolver runs); elsewhere one version for the target the
// core is compiled for, which SPRINGLAB_KERNEL_ARCH can set to one clone's (presets baseline, avx2)
// so that a machine tests the code of a clone it would not pick.
#if defined(SPRINGLAB_KERNEL_CLONES)
#define SPRINGLAB_SIMD_CLONES __attribute__((target_clones("arch=x86-64-v4", "avx2", "default")))
#else
#define SPRINGLAB_SIMD_CLONES
#endif

namespace core {

// springs per chunk of a run: their forces (6 KB) are computed and added while in the L1 cache
inline constexpr int kSpringChunk = 256;

// force[i] ± perSpring[i] over count values, unit stride: a chunk's forces added to their ends,
// whether stored as xyz triples (3 values a spring) or one lane per component (spring_kernels.cpp)
void addSigned(int count, double sign, const double *perSpring, double *force);

// a particle's force before any pass adds to it, one component: 0 + m g, the same bits as clearing
// it and adding m g. The passes over xyz triples (gravity.cpp) and over lanes (spring_blocks.cpp)
// stay two loops, each with unit stride over its own layout
[[gnu::always_inline]] inline double startingForce(double g, double mass)
{
    return 0.0 + g * mass;
}

// One Euler update of one coordinate of a particle: the new velocity oldV + kick f, kick = h / m,
// moves it (symplectic) or the old one does (explicit). Returns 1 when a new value is not finite or
// is past kBlowupBound. The updates over xyz triples (integrate.cpp) and over the fused sub-step's
// lanes (spring_blocks.cpp) stay two loops, each vectorised over its own layout; this is what they
// compute, so their bits agree.
template <bool Symplectic>
[[gnu::always_inline]] inline int eulerCoordinate(double h, double kick, double force, double oldX, double oldV,
                                                  double &x, double &v)
{
    const double next = oldV + kick * force;
    const double moved = oldX + h * (Symplectic ? next : oldV);
    v = next;
    x = moved;
    // & rather than &&: no branch, so that the loop vectorises (NaN fails both tests)
    const int fine = static_cast<int>(std::abs(next) <= kBlowupBound) & static_cast<int>(std::abs(moved) <= kBlowupBound);
    return fine ^ 1;
}

// One spring's ends: the difference of their positions, d = xa - xb, and of their velocities.
struct SpringEnds {
    double dx, dy, dz;
    double dvx, dvy, dvz;
};

// The handout's damped spring on end a, -k (l - l0) u - kc ((va - vb)·u) u with u = d / l, into
// (fx, fy, fz). Inlined into kernels that the compiler vectorises across springs; the clones let
// one binary use AVX2 or AVX-512 where the CPU has them. Each value comes from the same IEEE adds,
// multiplies, divides and square roots as the reference (springs.cpp's springForce), in the same
// order and never contracted (cmake/springlab_flags.cmake), so every clone, every kernel and the
// reference give the same bits. A broken spring's force is a select to zero, which keeps the loops
// vectorised.
[[gnu::always_inline]] inline void dampedSpring(const SpringEnds &e, double restLength, double stiffness,
                                                double damping, bool broken, double &fx, double &fy, double &fz)
{
    const double length = std::sqrt(e.dx * e.dx + e.dy * e.dy + e.dz * e.dz);
    // coincident ends push along +y, as directionOr does; one division, as there
    const bool separate = apart(length);
    const double inverse = 1.0 / (separate ? length : 1.0);
    const double ux = separate ? e.dx * inverse : 0.0;
    const double uy = separate ? e.dy * inverse : 1.0;
    const double uz = separate ? e.dz * inverse : 0.0;
    const double approach = e.dvx * ux + e.dvy * uy + e.dvz * uz;
    double magnitude = -stiffness * (length - restLength) - damping * approach;
    magnitude = broken ? 0.0 : magnitude;
    fx = magnitude * ux;
    fy = magnitude * uy;
    fz = magnitude * uz;
}

// the same from xyz triples (positions and velocities stored particle by particle), into out[0 .. 2]
[[gnu::always_inline]] inline void dampedSpring(const double *xa, const double *xb, const double *va,
                                                const double *vb, double restLength, double stiffness,
                                                double damping, bool broken, double *out)
{
    const SpringEnds ends{xa[0] - xb[0], xa[1] - xb[1], xa[2] - xb[2], va[0] - vb[0], va[1] - vb[1], va[2] - vb[2]};
    dampedSpring(ends, restLength, stiffness, damping, broken, out[0], out[1], out[2]);
}

// The springs j of a run whose end a (j in [aLo, aHi)) or end b (j in [bLo, bHi)) lies in a
// stretch of particles
struct RunSides {
    int aLo, aHi, bLo, bHi;
};

// piece(lo, hi, sides) for the springs of the run with an end in particles [first, last): once for
// one stretch of springs j in [lo, hi), or twice when the two ends lie so far apart in the
// numbering that the springs between touch neither side
template <typename Piece>
void forEachRunPiece(const SpringRun &run, int first, int last, Piece &&piece)
{
    const RunSides s{std::max(0, first - run.a), std::min(run.count, last - run.a), std::max(0, first - run.b),
                     std::min(run.count, last - run.b)};
    const bool aSide = s.aLo < s.aHi;
    const bool bSide = s.bLo < s.bHi;
    if (!aSide && !bSide)
        return;
    if (!aSide || !bSide) {
        piece(aSide ? s.aLo : s.bLo, aSide ? s.aHi : s.bHi, s);
    } else if (std::max(s.aLo, s.bLo) <= std::min(s.aHi, s.bHi)) {
        piece(std::min(s.aLo, s.bLo), std::max(s.aHi, s.bHi), s);
    } else {
        const bool aBelow = s.aLo < s.bLo;
        piece(aBelow ? s.aLo : s.bLo, aBelow ? s.aHi : s.bHi, s);
        piece(aBelow ? s.bLo : s.aLo, aBelow ? s.bHi : s.aHi, s);
    }
}

// A chunk's forces added to its springs' ends, add(lowest, highest, firstEnd, sign) for each side.
// Within one run a particle is end a of at most one spring and end b of at most one, and the plain
// loop adds the lower-numbered spring's force first: end b's when b > a, as that spring is
// (p - b) < (p - a). Chunk by chunk in ascending j, in this order, every particle receives its
// forces in the plain loop's order, whichever stretch or thread it falls to.
template <typename AddSide>
void addInPlainOrder(const SpringRun &run, const RunSides &s, AddSide &&add)
{
    if (run.b > run.a) {
        add(s.bLo, s.bHi, run.b, -1.0);
        add(s.aLo, s.aHi, run.a, +1.0);
    } else {
        add(s.aLo, s.aHi, run.a, +1.0);
        add(s.bLo, s.bHi, run.b, -1.0);
    }
}

}  // namespace core
