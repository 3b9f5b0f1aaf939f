#include "core/model/state.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <limits>

namespace core {

State makeState(const Model &model, const SceneDesc &scene)
{
    assert(static_cast<int>(scene.particles.size()) == model.particleCount());
    const Eigen::Index n = model.particleCount();
    State state;
    state.position.resize(3, n);
    state.velocity.resize(3, n);
    fitSpringBreaks(model, state);
    for (Eigen::Index i = 0; i < n; ++i) {
        const ParticleDesc &p = scene.particles[static_cast<std::size_t>(i)];
        state.position.col(i) = p.position;
        // a pinned particle has infinite mass: it is at rest, whatever the file says
        state.velocity.col(i) = p.pinned ? Eigen::Vector3d::Zero() : p.velocity;
    }
    if (model.plan.spin) {
        state.angularVelocity.resize(3, n);
        state.orientation.resize(4, n);
        for (Eigen::Index i = 0; i < n; ++i) {
            const ParticleDesc &p = scene.particles[static_cast<std::size_t>(i)];
            state.angularVelocity.col(i) = p.angularVelocity;
            // a unit quaternion as it is, to the bit (a run saved and resumed goes on the same);
            // one that is not (typed by hand) made unit
            const double squared = p.orientation.squaredNorm();
            state.orientation.col(i) =
                std::abs(squared - 1.0) <= 8.0 * std::numeric_limits<double>::epsilon() ? p.orientation
                : squared > 0.0 ? Eigen::Vector4d(p.orientation / std::sqrt(squared))
                                : Eigen::Vector4d(1, 0, 0, 0);
        }
    }
    state.adaptiveStep = scene.settings.adaptiveStep.value_or(0.0);
    state.contactImpulses = scene.contactImpulses;
    // the solver finds them by binary search
    std::sort(state.contactImpulses.begin(), state.contactImpulses.end());
    return state;
}

void fitSpringBreaks(const Model &model, State &state)
{
    const auto springs = static_cast<std::size_t>(model.springCount());
    if (!model.plan.springBreaks) {
        // nothing can break: an unbroken state needs no flags (a broken one keeps them)
        if (state.breaks.empty())
            state.springBroken.clear();
        return;
    }
    if (state.springBroken.size() != springs) {
        state.springBroken.assign(springs, 0);
        state.breaks.clear();
    }
    state.breaks.reserve(springs);
}

void fitSpin(const Model &model, State &state)
{
    const Eigen::Index n = model.particleCount();
    if (!model.plan.spin || (state.angularVelocity.cols() == n && state.orientation.cols() == n))
        return;
    state.angularVelocity.setZero(3, n);
    state.orientation.resize(4, n);
    state.orientation.row(0).setOnes();
    state.orientation.bottomRows(3).setZero();
}

void setAppliedForce(State &state, int particle, const Eigen::Vector3d &force)
{
    assert(particle >= 0 && particle < state.particleCount());
    if (state.applied.cols() != state.position.cols())
        state.applied.setZero(3, state.position.cols());  // the first force set since none was
    const bool wasSet = !state.applied.col(particle).isZero(0.0);
    const bool isSet = !force.isZero(0.0);
    state.applied.col(particle) = force;
    state.appliedCount += static_cast<int>(isSet) - static_cast<int>(wasSet);
    if (state.appliedCount == 0)
        state.applied.resize(3, 0);  // none left: the state holds no forces
}

void storeState(const State &state, SceneDesc &scene)
{
    assert(static_cast<Eigen::Index>(scene.particles.size()) == state.position.cols());
    for (std::size_t i = 0; i < scene.particles.size(); ++i) {
        const auto column = static_cast<Eigen::Index>(i);
        scene.particles[i].position = state.position.col(column);
        scene.particles[i].velocity = state.velocity.col(column);
        if (state.angularVelocity.cols() == state.position.cols()) {
            scene.particles[i].angularVelocity = state.angularVelocity.col(column);
            scene.particles[i].orientation = state.orientation.col(column);
        }
    }
    // the adaptive step size goes with the state it was chosen for
    scene.settings.adaptiveStep.reset();
    if (state.adaptiveStep > 0.0)
        scene.settings.adaptiveStep = state.adaptiveStep;
    // and the contact impulses with the contacts they were found for
    scene.contactImpulses = state.contactImpulses;
    if (state.breaks.empty())
        return;
    assert(state.springBroken.size() == scene.springs.size());
    // the triangles it lists that a broken spring tore go too: a torn sheet goes on as torn
    if (!scene.triangles.empty()) {
        const SpringTriangles listed = sceneTriangles(scene);
        std::size_t whole = 0;
        for (std::size_t t = 0; t < scene.triangles.size(); ++t) {
            bool torn = false;
            for (std::size_t s = 0; s < 3; ++s) {
                const int spring = listed.sides[3 * t + s];
                torn = torn || (spring >= 0 && state.springBroken[std::size_t(spring)] != 0);
            }
            if (!torn)
                scene.triangles[whole++] = scene.triangles[t];
        }
        scene.triangles.resize(whole);
    }
    std::size_t kept = 0;
    for (std::size_t k = 0; k < scene.springs.size(); ++k)
        if (state.springBroken[k] == 0)
            scene.springs[kept++] = scene.springs[k];
    scene.springs.resize(kept);
}

}  // namespace core
