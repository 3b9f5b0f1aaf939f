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
    // implicit-euler: conjugate-gradient iterations of the last solve (0 for the direct solve);
    // projective and vbd: the iterations of their last sub-step
    int solverIterations = 0;
    // the last solve's residual relative to its start: implicit-euler's ‖r‖/‖b‖, projective's and
    // vbd's ‖∇E‖ after their iterations over ‖∇E‖ before them (the energy's gradient, in N)
    double solverResidual = 0.0;
    // sub-steps whose conjugate-gradient solve stopped at its cap before converging
    std::uint64_t solverCapHits = 0;
    // over the run: the solves, their iterations, the most in one and the largest residual
    std::uint64_t solves = 0;
    std::uint64_t solverIterationsTotal = 0;
    int mostSolverIterations = 0;
    double worstSolverResidual = 0.0;
    // the factorisations made: implicit-euler's each sub-step, projective's once per topology,
    // step and stiffness
    std::uint64_t factorisations = 0;

    // seconds spent in the stages running now, for the stage around them (timed.h)
    double nestedSeconds = 0.0;

    // the last solve's figures, and the run's
    void recordSolve(int iterations, double residual)
    {
        solverIterations = iterations;
        solverResidual = residual;
        solves += 1;
        solverIterationsTotal += static_cast<std::uint64_t>(iterations);
        mostSolverIterations = iterations > mostSolverIterations ? iterations : mostSolverIterations;
        worstSolverResidual = residual > worstSolverResidual ? residual : worstSolverResidual;
    }
};

}  // namespace core
