#include "geometry.h"
#include "parallel.h"
#include "passes.h"

#include <cmath>
#include <cstdint>

// target clones where the compiler and CPU family support them (GCC on x86-64); elsewhere one
// portable version. Not under ThreadSanitizer: the clones' resolver runs while the program is
// being loaded, before the sanitizer's runtime is up, and its instrumented code crashes there
#if defined(__GNUC__) && !defined(__clang__) && defined(__x86_64__) && !defined(__SANITIZE_THREAD__)
#define SPRINGLAB_SIMD_CLONES __attribute__((target_clones("arch=x86-64-v4", "avx2", "default")))
#else
#define SPRINGLAB_SIMD_CLONES
#endif

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

// the handout's damped spring of springs [begin, end) on their end a, three values per spring into
// out. Flat arrays and no calls, so the compiler vectorises it across springs; the clones let one
// binary use AVX2 or AVX-512 where the CPU has them. Each value comes from the same IEEE adds,
// multiplies, divides and square roots as springForce above, in the same order and never
// contracted (cmake/springlab_flags.cmake), so every clone and the reference give the same bits.
// Breakable scenes pass their broken flags: a broken spring's force is a select to zero, which
// keeps the loop vectorised; the others build without the flags and pay nothing for them.
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
        const double dx = x[a] - x[b];
        const double dy = x[a + 1] - x[b + 1];
        const double dz = x[a + 2] - x[b + 2];
        const double length = std::sqrt(dx * dx + dy * dy + dz * dz);
        // coincident ends push along +y, as directionOr does
        const bool apart = length > 0.0;
        const double ux = apart ? dx / length : 0.0;
        const double uy = apart ? dy / length : 1.0;
        const double uz = apart ? dz / length : 0.0;
        const double approach = (v[a] - v[b]) * ux + (v[a + 1] - v[b + 1]) * uy + (v[a + 2] - v[b + 2]) * uz;
        double magnitude = -stiffness[k] * (length - restLength[k]) - damping[k] * approach;
        if constexpr (Breakable)
            magnitude = broken[k] != 0 ? 0.0 : magnitude;
        out[3 * k] = magnitude * ux;
        out[3 * k + 1] = magnitude * uy;
        out[3 * k + 2] = magnitude * uz;
    }
}

}  // namespace

// Two passes with no write shared between iterations, so both split across threads with the same
// bits: each spring's force on end a, then each particle sums the forces of its springs in
// ascending spring order (+ at end a, - at end b, Newton's third law). That order is the order
// in which addSpringsReference's scatter adds them, so the two agree to the bit.
void addSprings(const Model &model, State &state)
{
    if (!model.plan.springs)
        return;
    const int springs = model.springCount();
    Eigen::Matrix3Xd &perSpring = state.springForce;
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
        Eigen::Vector3d sum = state.force.col(i);
        for (int e = offsets[i]; e < offsets[i + 1]; ++e) {
            const int end = ends[e];
            if (end & 1)
                sum -= perSpring.col(end >> 1);
            else
                sum += perSpring.col(end >> 1);
        }
        state.force.col(i) = sum;
    });
}

// the plain loop over the spring list, scattering into both ends: the reference the tests hold
// addSprings to
void addSpringsReference(const Model &model, State &state)
{
    if (!model.plan.springs)
        return;
    for (int k = 0; k < model.springCount(); ++k) {
        if (state.isBroken(k))
            continue;
        const Eigen::Vector3d fa = springForce(model, state, k);
        state.force.col(model.springA[static_cast<std::size_t>(k)]) += fa;
        state.force.col(model.springB[static_cast<std::size_t>(k)]) -= fa;
    }
}

}  // namespace core
