#pragma once
// Times one pass of the step into the state's profile. A pass the plan skips is neither run nor
// counted, so its profile entry stays at zero calls and zero seconds.

#include "state.h"

#include <chrono>

namespace core {

template <typename Pass>
void timed(State &state, Stage stage, bool planned, Pass &&pass)
{
    if (!planned)
        return;
    const auto start = std::chrono::steady_clock::now();
    pass();
    StageTiming &timing = state.profile[stage];
    timing.calls += 1;
    timing.seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace core
