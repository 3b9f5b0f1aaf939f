#pragma once
// Small helpers for building test scenes by hand.

#include "core/model.h"
#include "core/scene.h"
#include "core/state.h"

#include <memory>

namespace test {

inline core::ParticleDesc particle(Eigen::Vector3d position, Eigen::Vector3d velocity = Eigen::Vector3d::Zero(),
                                   double mass = 1.0, double radius = 0.1, bool pinned = false)
{
    return core::ParticleDesc{position, velocity, mass, radius, pinned};
}

// a scene with no gravity and no collisions: only what a test adds acts
inline core::SceneDesc quietScene()
{
    core::SceneDesc scene;
    scene.name = "test";
    scene.settings.gravity = Eigen::Vector3d::Zero();
    scene.settings.planeCollisions = false;
    scene.settings.particleCollisions = false;
    return scene;
}

// a compiled model and its initial state, kept together
struct Sim {
    std::shared_ptr<const core::Model> model;
    core::State state;
};

inline Sim compile(const core::SceneDesc &scene)
{
    auto model = core::compileModel(scene);
    core::State state = core::makeState(*model, scene);
    return Sim{model, std::move(state)};
}

}  // namespace test
