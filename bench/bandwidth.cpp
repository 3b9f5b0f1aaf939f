// STREAM's triad on std::threads. Each thread owns one contiguous slice of the three arrays: it
// fills its slice itself (first touch puts the pages near it) and runs the triad on it. A
// repetition is timed from before the threads start to after the last one ends, so thread start-up
// is included; at 3 × 128 MiB a repetition takes tens of milliseconds and the start-up is lost in
// the noise. The result check at the end keeps the compiler from dropping the loops.
#include "bandwidth.h"

#include <algorithm>
#include <cassert>
#include <chrono>
#include <cmath>
#include <memory>
#include <thread>
#include <vector>

namespace bench {

namespace {

constexpr double kScalar = 3.0;

// uninitialised storage: the first touch belongs to the thread that will use the slice
std::unique_ptr<double[]> rawArray(std::size_t elements)
{
    return std::unique_ptr<double[]>(new double[elements]);
}

// runs job(begin, end) for every thread's slice of [0, elements) and waits for all of them
template <typename Job>
void onSlices(int threads, std::size_t elements, Job job)
{
    std::vector<std::thread> workers;
    workers.reserve(static_cast<std::size_t>(threads));
    const std::size_t share = (elements + static_cast<std::size_t>(threads) - 1) / static_cast<std::size_t>(threads);
    for (int t = 0; t < threads; ++t) {
        const std::size_t begin = std::min(elements, share * static_cast<std::size_t>(t));
        const std::size_t end = std::min(elements, begin + share);
        workers.emplace_back([=] { job(begin, end); });
    }
    for (std::thread &worker : workers)
        worker.join();
}

}  // namespace

TriadResult measureTriad(int threads, const TriadOptions &options)
{
    assert(threads >= 1 && options.elements > 0 && options.repetitions >= 1);
    const std::size_t n = options.elements;
    const std::unique_ptr<double[]> a = rawArray(n), b = rawArray(n), c = rawArray(n);
    double *const pa = a.get();
    double *const pb = b.get();
    double *const pc = c.get();

    // first touch, by the thread that owns the slice
    onSlices(threads, n, [=](std::size_t begin, std::size_t end) {
        for (std::size_t i = begin; i < end; ++i) {
            pa[i] = 0.0;
            pb[i] = 1.0;
            pc[i] = 2.0;
        }
    });

    // the triad, best of the repetitions
    TriadResult result;
    result.threads = threads;
    result.bestSeconds = INFINITY;
    for (int r = 0; r < options.repetitions; ++r) {
        const auto start = std::chrono::steady_clock::now();
        onSlices(threads, n, [=](std::size_t begin, std::size_t end) {
            for (std::size_t i = begin; i < end; ++i)
                pa[i] = pb[i] + kScalar * pc[i];
        });
        const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        result.bestSeconds = std::min(result.bestSeconds, seconds);
    }

    // every a[i] is 1 + 3 × 2: the loops really ran
    if (pa[0] != 7.0 || pa[n / 2] != 7.0 || pa[n - 1] != 7.0)
        return {threads, 0.0, result.bestSeconds};
    result.bytesPerSecond = 3.0 * sizeof(double) * static_cast<double>(n) / result.bestSeconds;
    return result;
}

}  // namespace bench
