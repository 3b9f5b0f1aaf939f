#include "passes.h"
#include "step.h"

#include <cmath>

namespace core {

namespace {

bool bad(double value)
{
    return !(std::abs(value) <= kBlowupBound);  // also true for NaN
}

}  // namespace

// true when every position and velocity is finite and bounded; else records the first culprit
// (the caller fills in the step and time)
bool checkFinite(const Model &model, State &state)
{
    const double bound = kBlowupBound;
    // fast path: one vectorisable sweep over each array (NaN fails the comparison too)
    if ((state.position.array().abs() <= bound).all() && (state.velocity.array().abs() <= bound).all())
        return true;

    // slow path, once per run: find the first particle and quantity that failed
    Blowup blowup;
    // (velocity first: it is what runs away, the position follows)
    for (int i = 0; i < model.particleCount() && blowup.particle < 0; ++i) {
        for (int axis = 0; axis < 3 && blowup.particle < 0; ++axis)
            if (bad(state.velocity(axis, i)))
                blowup = {i, Blowup::Quantity::Velocity, state.velocity(axis, i), 0, 0.0};
        for (int axis = 0; axis < 3 && blowup.particle < 0; ++axis)
            if (bad(state.position(axis, i)))
                blowup = {i, Blowup::Quantity::Position, state.position(axis, i), 0, 0.0};
    }
    state.blowup = blowup;
    return false;
}

}  // namespace core
