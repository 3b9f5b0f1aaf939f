#pragma once
// State: what changes as the simulation runs. Only the thread that steps touches it. Scratch
// buffers live here so that a step allocates nothing.

#include "contact_grid.h"
#include "model.h"

#include <Eigen/Core>
#include <array>
#include <cstdint>
#include <optional>
#include <string_view>
#include <vector>

namespace core {

// the passes of one sub-step, in the order they run
enum class Stage { Gravity, Drag, Springs, Applied, Integrate, PlaneCollisions, ParticleCollisions, Breaks, Check };
inline constexpr int kStageCount = 9;
std::string_view stageName(Stage stage);

struct StageTiming {
    std::uint64_t calls = 0;
    double seconds = 0.0;
};

struct Profile {
    std::array<StageTiming, kStageCount> stages{};
    const StageTiming &operator[](Stage stage) const { return stages[static_cast<int>(stage)]; }
    StageTiming &operator[](Stage stage) { return stages[static_cast<int>(stage)]; }
};

// the first value that stopped being finite or bounded, or (StepSize) an adaptive integrator that
// could not cover a sub-step within its budget of trial steps
struct Blowup {
    enum class Quantity { Position, Velocity, StepSize };
    int particle = -1;        // -1 for StepSize
    Quantity quantity = Quantity::Position;
    double value = 0.0;       // the offending component; for StepSize, the last trial step, s
    std::uint64_t step = 0;   // the step it happened in (1 = the first step)
    double time = 0.0;        // s, the time at the start of that step
};

// a spring that broke: which, and when
struct SpringBreak {
    int spring = -1;
    std::uint64_t step = 0;  // the step it broke in (1 = the first step)
    double time = 0.0;       // s, the time at the end of that step's sub-step
};

struct State {
    Eigen::Matrix3Xd position;  // m, one column per particle
    Eigen::Matrix3Xd velocity;  // m/s
    Eigen::Matrix3Xd force;     // N, scratch: the forces of the current sub-step

    // forces applied from outside the scene (the steering keys, the mouse), N per particle;
    // appliedCount says how many columns are non-zero so that the pass costs nothing without them
    Eigen::Matrix3Xd applied;
    int appliedCount = 0;

    double time = 0.0;       // s
    std::uint64_t step = 0;  // steps taken since the initial conditions

    // work done, for cost estimates: force evaluations, and the adaptive and implicit schemes' own
    std::uint64_t forceEvaluations = 0;
    std::uint64_t rejectedSteps = 0;  // adaptive-rk45: trial steps thrown away
    double adaptiveStep = 0.0;        // adaptive-rk45: the step size to try next, s (0: not yet chosen)
    int solverIterations = 0;         // implicit-euler: conjugate-gradient iterations of the last solve

    // scratch arrays of the integrators (state-sized, made on first use)
    std::array<Eigen::Matrix3Xd, 18> scratchArrays;
    // scratch of the spring pass: each spring's force on its end a (made on first use)
    Eigen::Matrix3Xd springForce;
    // scratch of the fused lattice sub-step (spring_blocks.cpp): each thread's window of particles
    // and its block's forces (made on first use, and again when the thread count changes)
    std::vector<double> blockScratch;
    // set by the Euler updates when every free particle's new position and velocity is finite and
    // bounded (checked in the same loop that wrote them); the step clears it before integrating and
    // when a contact pass moves particles, and the finite check then only checks the pinned ones
    bool freeParticlesChecked = false;

    // breakable springs (the plan's springBreaks): 1 per spring once broken, for good; a broken
    // spring exerts no force and stores no energy. Empty when no spring can break. breaks lists
    // them in the order they broke, its capacity reserved so that a break allocates nothing
    std::vector<std::uint8_t> springBroken;
    std::vector<SpringBreak> breaks;
    bool isBroken(int spring) const
    {
        return !springBroken.empty() && springBroken[static_cast<std::size_t>(spring)] != 0;
    }

    ContactGrid contacts;  // scratch of the particle-pair pass: its grid and pairs (broad_phase.cpp)

    Profile profile;
    std::optional<Blowup> blowup;  // set once the run has blown up; stepping then stops
};

// the initial state of a scene (pinned particles start, and stay, at rest)
State makeState(const Model &model, const SceneDesc &scene);

// sizes the breakable springs' flags to the model, when it has springs that can break: kept as they
// are for the same number of springs (a parameter change), all whole again for another number
void fitSpringBreaks(const Model &model, State &state);

// sets (or, with a zero force, clears) the force applied from outside to one particle
void setAppliedForce(State &state, int particle, const Eigen::Vector3d &force);

// writes the state's positions and velocities into the scene as its new initial conditions, and
// leaves out the springs that broke, so that a run from it goes on as this one would
void storeState(const State &state, SceneDesc &scene);

}  // namespace core
