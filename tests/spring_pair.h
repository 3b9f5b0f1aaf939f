#pragma once
// A small scene and a recording of it, for the tests of files that hold them (scene and recording
// loaders, springlab-sim's input faults): two particles on a spring over a floor.

#include "core/model/model.h"
#include "core/model/scene.h"
#include "core/model/state.h"
#include "session/session_recording.h"

#include <memory>

namespace test {

inline core::SceneDesc springPairScene()
{
    core::SceneDesc scene;
    scene.name = "pair";
    core::ParticleDesc particle;
    particle.position = {0.0, 1.0, 0.0};
    scene.particles.push_back(particle);
    particle.position = {0.5, 1.2, 0.0};
    scene.particles.push_back(particle);
    scene.springs.push_back({0, 1, 100.0, 0.5, 0.5});
    scene.planes.push_back({{0.0, 1.0, 0.0}, 0.0});
    return scene;
}

// the scene played for `steps` steps from its initial state, with the hash its replay ends with
inline ui::SessionRecording playedRecording(const core::SceneDesc &scene, std::uint64_t steps)
{
    ui::SessionRecording recording;
    recording.scene = std::make_shared<const core::SceneDesc>(scene);
    recording.start = core::makeState(*core::compileModel(scene), scene);
    recording.entries.push_back({0, ui::Play{}});
    recording.steps = steps;
    recording.finalHash = ui::replay(recording).hash;
    return recording;
}

}  // namespace test
