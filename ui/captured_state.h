#pragma once
// CapturedState: the worker's positions and velocities at one step, copied out for the UI thread
// by "Use current state as initial". A Snapshot has floats and no velocities, so it cannot serve:
// the scene's new initial conditions must be the run's own doubles. Immutable once published.

#include "core/scene.h"

#include <Eigen/Core>
#include <cstdint>
#include <memory>

namespace ui {

struct CapturedState {
    Eigen::Matrix3Xd position;  // m, one column per particle
    Eigen::Matrix3Xd velocity;  // m/s
    double time = 0.0;          // s, when it was captured
    std::uint64_t step = 0;
    std::shared_ptr<const core::SceneDesc> scene;  // the scene the worker was running

    int particleCount() const { return static_cast<int>(position.cols()); }
};

}  // namespace ui
