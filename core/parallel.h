#pragma once
// A loop over particles or springs split across the core's threads (core/threads.h). Only loops
// whose iterations write disjoint data use it, so the result has the same bits on any number of
// threads. Small loops stay on the calling thread without entering OpenMP at all: waking the
// others costs more than they save, and even a one-thread OpenMP region allocates.

namespace core {

// the fewest iterations worth splitting
inline constexpr int kParallelMinimum = 4096;

// body(i) for i in [0, count), split across the threads when count is large enough
template <typename Body>
void parallelFor(int count, Body &&body)
{
#ifdef SPRINGLAB_OPENMP
    if (count >= kParallelMinimum) {
#pragma omp parallel for schedule(static)
        for (int i = 0; i < count; ++i)
            body(i);
        return;
    }
#endif
    for (int i = 0; i < count; ++i)
        body(i);
}

}  // namespace core
