#include "geometry.h"
#include "passes.h"

#include <cmath>

namespace core {

namespace {

// resolves one overlapping pair as the handout does, with inverse masses so that a pinned
// particle (inverse mass 0) is the immovable side
void resolvePair(const Model &model, State &state, int i, int j)
{
    const double wi = model.invMass[i];
    const double wj = model.invMass[j];
    const double w = wi + wj;
    if (w == 0.0)
        return;  // two pinned particles: nothing can move

    const Eigen::Vector3d d = state.position.col(i) - state.position.col(j);
    const double contact = model.radius[i] + model.radius[j];
    const double squared = d.squaredNorm();
    if (squared >= contact * contact)
        return;
    const double distance = std::sqrt(squared);
    const Eigen::Vector3d k = directionOr(d, distance);

    // position: each moves by the penetration weighted by the other's mass (m_j/(m_i+m_j) = w_i/w)
    const double penetration = contact - distance;
    state.position.col(i) += (wi / w * penetration) * k;
    state.position.col(j) -= (wj / w * penetration) * k;

    // velocity: an impulse along k with restitution, only if the two are approaching
    const double approach = k.dot(state.velocity.col(i) - state.velocity.col(j));
    if (approach >= 0.0)
        return;
    const double a = (1.0 + model.restitution) * approach / w;
    state.velocity.col(i) -= (a * wi) * k;
    state.velocity.col(j) += (a * wj) * k;
}

}  // namespace

// every pair i < j in a fixed order (brute force; the reference any broad phase must match)
void collideParticles(const Model &model, State &state)
{
    if (!model.plan.particleCollisions)
        return;
    const int n = model.particleCount();
    for (int i = 0; i < n; ++i)
        for (int j = i + 1; j < n; ++j)
            resolvePair(model, state, i, j);
}

}  // namespace core
