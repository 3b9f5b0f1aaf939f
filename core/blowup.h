#pragma once
// Blowup: where and when a run stopped being finite or bounded, for the message that names it.

#include <cstdint>

namespace core {

// the first value that stopped being finite or bounded, or (StepSize) an adaptive integrator that
// could not cover a sub-step within its budget of trial steps
struct Blowup {
    enum class Quantity { Position, Velocity, StepSize };
    int particle = -1;        // -1 for StepSize
    Quantity quantity = Quantity::Position;
    double value = 0.0;       // the offending component; for StepSize, the last trial step, s
    std::uint64_t step = 0;   // the step it happened in (1 = the first step)
    double time = 0.0;        // s, the time at the start of that step
    // the particle's position (m) and speed (m/s) when it was found: where it left the world
    double where[3] = {0.0, 0.0, 0.0};
    double speed = 0.0;
};

}  // namespace core
