#pragma once
// How many threads the core's parallel loops (OpenMP) use. Results never depend on it: each loop
// writes per particle, gathering in a fixed order, so 1 and N threads give the same bits. Without
// OpenMP (a build with SPRINGLAB_OPENMP off, e.g. under ThreadSanitizer, which cannot see inside
// libgomp) every loop runs on the calling thread and the count is always 1.

namespace core {

// the threads the loops use now
int threadCount();
// the most the loops may use: the machine's hardware threads (1 without OpenMP)
int maxThreadCount();
// sets the threads the loops use, clamped to [1, maxThreadCount()]; process-wide
void setThreadCount(int threads);

}  // namespace core
