#include "geometry.h"
#include "parallel.h"
#include "passes.h"

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

    parallelFor(springs, [&](int k) { perSpring.col(k) = springForce(model, state, k); });

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
        const Eigen::Vector3d fa = springForce(model, state, k);
        state.force.col(model.springA[static_cast<std::size_t>(k)]) += fa;
        state.force.col(model.springB[static_cast<std::size_t>(k)]) -= fa;
    }
}

}  // namespace core
