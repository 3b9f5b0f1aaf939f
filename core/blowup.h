#pragma once
// Blowup: where and when a run stopped being finite or bounded, for the message that names it.

#include <cstdint>

namespace core {

// the first value that stopped being finite or bounded, (StepSize) an adaptive integrator that
// could not cover a sub-step within its budget of trial steps, (SheetPairs) the triangle
// collisions finding more pairs within reach than a sheet that is not flying apart can have, or
// (Energy) a total energy that grew a thousandfold with no work done on the scene
struct Blowup {
    enum class Quantity { Position, Velocity, StepSize, SheetPairs, Energy };
    int particle = -1;        // -1 for StepSize and SheetPairs; for Energy, the fastest
    Quantity quantity = Quantity::Position;
    // the offending component; for StepSize, the last trial step, s; for SheetPairs, the most pairs
    // a sub-step may test
    double value = 0.0;
    std::uint64_t step = 0;   // the step it happened in (1 = the first step)
    double time = 0.0;        // s, the time at the start of that step
    // the particle's position (m) and speed (m/s) when it was found: where it left the world
    double where[3] = {0.0, 0.0, 0.0};
    double speed = 0.0;
    double from = 0.0;        // Energy: the energy it grew from, J (value: the energy it reached)
};

}  // namespace core
