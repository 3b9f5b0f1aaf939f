#pragma once
// The machine's memory bandwidth, measured the way STREAM's triad does: a[i] = b[i] + s c[i] over
// three arrays of doubles much larger than the last-level cache, the best of several repetitions.
// The throughput benchmark divides the bytes a step must move by it to get a lower bound on the
// time of a step (throughput.cpp, docs/benchmarks.md).

#include <cstddef>

namespace bench {

struct TriadOptions {
    std::size_t elements = std::size_t{1} << 24;  // per array: 3 × 128 MiB by default
    int repetitions = 10;                         // the best one counts
};

struct TriadResult {
    int threads = 1;
    double bytesPerSecond = 0.0;  // B/s, STREAM's accounting: 24 B per element (read b and c, write a)
    double bestSeconds = 0.0;     // s, the fastest repetition
};

// runs the triad on `threads` std::threads, each on its own contiguous share of the arrays (which
// it also first touches, so that its pages are local to it)
TriadResult measureTriad(int threads, const TriadOptions &options);

}  // namespace bench
