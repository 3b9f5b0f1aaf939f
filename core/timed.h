#pragma once
// Times one stage of the step into the profile. A stage the plan skips is neither run nor counted,
// so its entry stays at zero calls and zero seconds. Stages may run inside others (an integrator
// evaluates the forces): each is charged its own time only, the inner stages' time taken off the
// outer one's, so the entries add up to the step's time.

#include "core/profile.h"

#include <chrono>

namespace core {

template <typename Pass>
void timed(Profile &profile, Stage stage, bool planned, Pass &&pass)
{
    if (!planned)
        return;
    const double outerNested = profile.nestedSeconds;
    profile.nestedSeconds = 0.0;
    const auto start = std::chrono::steady_clock::now();
    pass();
    const double total = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    StageTiming &timing = profile[stage];
    timing.calls += 1;
    timing.seconds += total - profile.nestedSeconds;
    profile.nestedSeconds = outerNested + total;
}

}  // namespace core
