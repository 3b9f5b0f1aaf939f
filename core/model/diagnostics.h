#pragma once
// Energies and momentum of a state, for the status bar, the plots and the tests.

#include "core/model/model.h"
#include "core/model/state.h"

#include <Eigen/Core>

namespace core {

struct Energies {
    double kinetic = 0.0;        // J, ½ m v² (and ½ I ω² where they turn) of the free particles
    double gravitational = 0.0;  // J, -m g·x, zero at the origin
    double spring = 0.0;         // J, ½ k (l - l0)²
    double total() const { return kinetic + gravitational + spring; }
};

Energies energies(const Model &model, const State &state);

// kg·m/s, of the free particles (pinned ones are at rest)
Eigen::Vector3d momentum(const Model &model, const State &state);

}  // namespace core
