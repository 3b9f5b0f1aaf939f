#pragma once
// Profile: where a run's time went, stage by stage, and the work it did. Filled by the step
// (timed.h), read by the status bar, the accuracy planner and the benchmarks; never part of the
// state.

#include <array>
#include <cstdint>

namespace core {

// the stages of one sub-step, in the order they run; FusedSubStep stands for the force stages
// and the integration of a model whose plan fuses them (StepPlan::subStep); PlaneCollisions and
// ParticleCollisions are the handout's contact passes, Contacts the iterative solver,
// TriangleCollisions the sheets' (with either)
enum class Stage {
    Gravity,
    Drag,
    Springs,
    Applied,
    Integrate,
    FusedSubStep,
    PlaneCollisions,
    ParticleCollisions,
    Contacts,
    TriangleCollisions,
    Breaks,
    Check
};
inline constexpr int kStageCount = 12;

struct StageTiming {
    std::uint64_t calls = 0;
    double seconds = 0.0;  // the stage's own time: a stage timed inside another is not counted twice
};

struct Profile {
    std::array<StageTiming, kStageCount> stages{};
    const StageTiming &operator[](Stage stage) const { return stages[static_cast<int>(stage)]; }
    StageTiming &operator[](Stage stage) { return stages[static_cast<int>(stage)]; }

    // work done, for cost estimates: force evaluations, and the adaptive and implicit schemes' own
    std::uint64_t forceEvaluations = 0;
    std::uint64_t rejectedSteps = 0;  // adaptive-rk45: trial steps thrown away
    int solverIterations = 0;         // implicit-euler: conjugate-gradient iterations of the last solve

    // seconds spent in the stages running now, for the stage around them (timed.h)
    double nestedSeconds = 0.0;
};

}  // namespace core
