#pragma once
// A runner holding a scene, as the worker's first message leaves it: for the tests that drive
// ui::SimulationRunner directly, without a thread or a window.

#include "session/simulation_runner.h"

#include <memory>

namespace test {

inline ui::SimulationRunner runnerWith(std::shared_ptr<const core::SceneDesc> scene)
{
    ui::SimulationRunner runner;
    runner.apply(ui::SetSceneEdit{std::move(scene), ui::SceneChange::Replace});
    return runner;
}

}  // namespace test
