#pragma once
// State: the state of a run, exactly what a resume needs and nothing else. Everything that copies
// "the state" (the timeline's keyframes, session recordings, the captured state, the last good
// state, the state hash, storeState) copies this one type. What a step uses besides it lives in a
// Workspace (workspace.h), never copied with it.

#include "core/model/model.h"

#include <Eigen/Core>
#include <cstdint>
#include <vector>

namespace core {

// a spring that broke: which, and when
struct SpringBreak {
    int spring = -1;
    std::uint64_t step = 0;  // the step it broke in (1 = the first step)
    double time = 0.0;       // s, the time at the end of that step's sub-step

    bool operator==(const SpringBreak &) const = default;
};

struct State {
    Eigen::Matrix3Xd position;  // m, one column per particle
    Eigen::Matrix3Xd velocity;  // m/s
    // while the plan has spin (else empty, so that a copy of a scene that cannot turn costs
    // nothing more): rad/s, and unit quaternions (w, x, y, z), one column per particle
    Eigen::Matrix3Xd angularVelocity;
    Eigen::Matrix4Xd orientation;

    double time = 0.0;          // s
    std::uint64_t step = 0;     // steps taken since the initial conditions
    double adaptiveStep = 0.0;  // adaptive-rk45: the step size to try next, s (0: not yet chosen)

    // forces applied from outside the scene (the steering keys, the mouse), N per particle: empty
    // while none is set (appliedCount 0), so that the pass and a copy of the state cost nothing
    Eigen::Matrix3Xd applied;
    int appliedCount = 0;

    // breakable springs (the plan's springBreaks): 1 per spring once broken, for good; a broken
    // spring exerts no force and stores no energy. Empty when no spring can break. breaks lists
    // them in the order they broke, its capacity reserved so that a break allocates nothing
    std::vector<std::uint8_t> springBroken;
    std::vector<SpringBreak> breaks;

    // the iterative contact solver's impulses at the end of the last sub-step, sorted by (i, j):
    // the next sub-step's iterations start from them (SceneDesc::contactImpulses)
    std::vector<ContactImpulse> contactImpulses;

    int particleCount() const { return static_cast<int>(position.cols()); }
    bool isBroken(int spring) const
    {
        return !springBroken.empty() && springBroken[static_cast<std::size_t>(spring)] != 0;
    }
};

// the initial state of a scene (pinned particles start, and stay, at rest)
State makeState(const Model &model, const SceneDesc &scene);

// sizes the breakable springs' flags to the model, when it has springs that can break: kept as they
// are for the same number of springs (a parameter change), all whole again for another number
void fitSpringBreaks(const Model &model, State &state);

// sizes the spin to the model: every particle at rest and unturned when the plan has spin and the
// state has none for it (a scene edited to have friction); left as it is otherwise
void fitSpin(const Model &model, State &state);

// sets (or, with a zero force, clears) the force applied from outside to one particle
void setAppliedForce(State &state, int particle, const Eigen::Vector3d &force);

// writes the state's positions, velocities and spins into the scene as its new initial conditions, and
// leaves out the springs that broke, so that a run from it goes on as this one would
void storeState(const State &state, SceneDesc &scene);

}  // namespace core
