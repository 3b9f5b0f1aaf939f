#pragma once
// CapturedState: the run's state at one step, copied out for the UI thread by "Use current state
// as initial". A Snapshot has floats and no velocities, so it cannot serve: the scene's new
// initial conditions must be the run's own doubles, and its broken springs. Immutable once
// published.

#include "core/model/scene.h"
#include "core/model/state.h"

#include <memory>

namespace ui {

struct CapturedState {
    core::State state;
    std::shared_ptr<const core::SceneDesc> scene;  // the scene the worker was running
};

}  // namespace ui
