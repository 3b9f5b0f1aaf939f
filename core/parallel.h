#pragma once
// A loop over particles or springs split across the core's threads (core/threads.h). Only loops
// whose iterations write disjoint data use it, so the result has the same bits on any number of
// threads. Small loops stay on the calling thread without entering OpenMP at all: waking the
// others costs more than they save, and even a one-thread OpenMP region allocates.

#ifdef SPRINGLAB_OPENMP
#include <omp.h>
#endif

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

// body(begin, end) once for each thread's contiguous share of [0, count) (once for all of it when
// count is small): for loops that should vectorise, which a call per iteration prevents
template <typename Body>
void parallelChunks(int count, Body &&body)
{
#ifdef SPRINGLAB_OPENMP
    if (count >= kParallelMinimum) {
#pragma omp parallel
        {
            const long long threads = omp_get_num_threads();
            const long long thread = omp_get_thread_num();
            body(static_cast<int>(count * thread / threads), static_cast<int>(count * (thread + 1) / threads));
        }
        return;
    }
#endif
    body(0, count);
}

}  // namespace core
