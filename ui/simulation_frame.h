#pragma once
// SimulationFrame: what the worker publishes after a tick: the snapshot of the state, the model it
// was stepped with, and how fast the run keeps up with the wall clock. Immutable once published.

#include "core/model.h"
#include "core/scene.h"
#include "core/snapshot.h"

#include <cstdint>
#include <memory>

namespace ui {

struct SimulationFrame {
    std::shared_ptr<const core::Snapshot> snapshot;
    std::shared_ptr<const core::Model> model;      // the model the snapshot was stepped with
    std::shared_ptr<const core::SceneDesc> scene;  // the scene that model was compiled from
    std::uint64_t appliedEdit = 0;  // sequence number of the newest edit applied before this frame
    bool running = false;

    // measured over the last second or so of running; 0 while paused or not yet measured
    double realTimeFactor = 0.0;  // simulated seconds per wall-clock second
    double stepsPerSecond = 0.0;  // steps per wall-clock second
};

}  // namespace ui
