#pragma once
// A loop over particles or springs split across the core's threads (core/threads.h). Only loops
// whose iterations write disjoint data use it, so the result has the same bits on any number of
// threads. Small loops stay on the calling thread without entering OpenMP at all: waking the
// others costs more than they save, and even a one-thread OpenMP region allocates.

#include <exception>
#include <utility>

#ifdef SPRINGLAB_OPENMP
#include <omp.h>
#endif

namespace core {

// the fewest iterations worth splitting
inline constexpr int kParallelMinimum = 4096;

// whether a loop of count iterations is split across threads: large enough, and more than one
// thread to split it across (a one-thread region still costs a call into the runtime and a wake)
inline bool splitAcrossThreads(int count)
{
#ifdef SPRINGLAB_OPENMP
    return count >= kParallelMinimum && omp_get_max_threads() > 1;
#else
    (void)count;
    return false;
#endif
}

// body(i) for i in [0, count), split across the threads when count is large enough
template <typename Body>
void parallelFor(int count, Body &&body)
{
#ifdef SPRINGLAB_OPENMP
    if (splitAcrossThreads(count)) {
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
    if (splitAcrossThreads(count)) {
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

// body(thread, begin, end) once for each of twoPhaseShares(count) contiguous shares of [0, count),
// in parallel: for passes that collect into one list per share and join the lists in share order,
// which gives the order one thread would have made whatever the count. A list may grow, so a body
// may throw (std::bad_alloc): an exception must not leave a parallel region (the program would
// end), so the first is kept and thrown again on the calling thread once every share is done
template <typename Body>
void parallelShares(int count, Body &&body)
{
#ifdef SPRINGLAB_OPENMP
    if (splitAcrossThreads(count)) {
        std::exception_ptr failure;
#pragma omp parallel
        {
            const long long threads = omp_get_num_threads();
            const long long thread = omp_get_thread_num();
            try {
                body(static_cast<int>(thread), static_cast<int>(count * thread / threads),
                     static_cast<int>(count * (thread + 1) / threads));
            } catch (...) {
#pragma omp critical(springlab_parallel_shares)
                if (!failure)
                    failure = std::current_exception();
            }
        }
        if (failure)
            std::rethrow_exception(failure);
        return;
    }
#endif
    body(0, 0, count);
}

// How a two-phase pass shares out its work: across the threads (0 shares, the default), or, for
// its tests, `shares` shares one after another on the calling thread, as if there were that many
// threads, in ascending or descending order. In one order each thread moves its particles before
// the next thread starts, in the other before the previous one does: the two ways a real schedule
// can hand a neighbour's particles over too late. A value passed in, never a setting of its own.
struct SharesInTurn {
    int shares = 0;
    bool descending = false;
};

// how many shares parallelChunksInTwoPhases() cuts count into: the scratch to make for it
inline int twoPhaseShares(int count, SharesInTurn inTurn = {})
{
    if (inTurn.shares > 0)
        return inTurn.shares;
#ifdef SPRINGLAB_OPENMP
    if (splitAcrossThreads(count))
        return omp_get_max_threads();
#endif
    (void)count;
    return 1;
}

// each thread's contiguous share of [0, count): first(thread, begin, end) on every share, then,
// once every thread has finished its first, second(thread, begin, end) on the same share. For a
// pass whose threads must copy what their neighbours are about to overwrite. inTurn: see above
template <typename First, typename Second>
void parallelChunksInTwoPhases(int count, First &&first, Second &&second, SharesInTurn inTurn = {})
{
    const auto share = [count](long long thread, long long threads) {
        return std::pair<int, int>(static_cast<int>(count * thread / threads), static_cast<int>(count * (thread + 1) / threads));
    };
    if (inTurn.shares > 0) {
        for (int pass = 0; pass < 2; ++pass)
            for (int k = 0; k < inTurn.shares; ++k) {
                const int thread = inTurn.descending ? inTurn.shares - 1 - k : k;
                const auto [begin, end] = share(thread, inTurn.shares);
                if (pass == 0)
                    first(thread, begin, end);
                else
                    second(thread, begin, end);
            }
        return;
    }
#ifdef SPRINGLAB_OPENMP
    if (splitAcrossThreads(count)) {
#pragma omp parallel
        {
            const int threads = omp_get_num_threads();
            const int thread = omp_get_thread_num();
            const auto [begin, end] = share(thread, threads);
            first(thread, begin, end);
#pragma omp barrier
            second(thread, begin, end);
        }
        return;
    }
#endif
    first(0, 0, count);
    second(0, 0, count);
}

}  // namespace core
