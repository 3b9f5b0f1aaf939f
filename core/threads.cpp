#include "core/threads.h"

#include <algorithm>

#ifdef SPRINGLAB_OPENMP
#include <omp.h>
#endif

namespace core {

int threadCount()
{
#ifdef SPRINGLAB_OPENMP
    return omp_get_max_threads();
#else
    return 1;
#endif
}

int maxThreadCount()
{
#ifdef SPRINGLAB_OPENMP
    return std::max(1, omp_get_num_procs());
#else
    return 1;
#endif
}

void setThreadCount(int threads)
{
#ifdef SPRINGLAB_OPENMP
    omp_set_num_threads(std::clamp(threads, 1, maxThreadCount()));
#else
    (void)threads;
#endif
}

}  // namespace core
