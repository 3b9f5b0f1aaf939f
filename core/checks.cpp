#include "core/parallel.h"
#include "core/passes.h"
#include "core/step.h"

#include <atomic>
#include <cmath>

namespace core {

namespace {

bool bad(double value)
{
    return !(std::abs(value) <= kBlowupBound);  // also true for NaN
}

// whether any of values [begin, end) is bad: a reduction with no early exit, so that it vectorises
bool anyBad(const double *__restrict values, int begin, int end)
{
    int found = 0;
#pragma omp simd reduction(| : found)
    for (int i = begin; i < end; ++i)
        found |= bad(values[i]) ? 1 : 0;
    return found != 0;
}

}  // namespace

// true when every position and velocity is finite and bounded; else records the first culprit
// (the caller fills in the step and time)
bool checkFinite(const Model &model, State &state, Workspace &work, bool freeChecked)
{
    // fast paths: the free particles checked by the integrator as it wrote them, so only the pinned
    // ones (the gaps between the free stretches); else one vectorised sweep over both arrays,
    // split across the threads
    std::atomic<bool> found = false;
    if (freeChecked) {
        const std::vector<int> &ranges = model.freeRanges;
        int begin = 0;
        for (std::size_t r = 0; r <= ranges.size(); r += 2) {
            const int end = r < ranges.size() ? ranges[r] : model.particleCount();
            if (anyBad(state.position.data(), 3 * begin, 3 * end) || anyBad(state.velocity.data(), 3 * begin, 3 * end))
                found = true;
            if (r < ranges.size())
                begin = ranges[r + 1];
        }
    } else {
        parallelChunks(3 * model.particleCount(), [&](int begin, int end) {
            if (anyBad(state.position.data(), begin, end) || anyBad(state.velocity.data(), begin, end))
                found.store(true, std::memory_order_relaxed);
        });
    }
    if (!found.load(std::memory_order_relaxed))
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
    if (blowup.particle >= 0) {
        for (int axis = 0; axis < 3; ++axis)
            blowup.where[axis] = state.position(axis, blowup.particle);
        blowup.speed = state.velocity.col(blowup.particle).norm();
    }
    work.blowup = blowup;
    return false;
}

}  // namespace core
