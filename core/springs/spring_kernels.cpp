#include "core/springs/spring_kernels.h"

namespace core {

// one clone per target, called once per chunk and side: too large a loop to gain from inlining
SPRINGLAB_SIMD_CLONES void addSigned(int count, double sign, const double *__restrict perSpring, double *__restrict force)
{
#pragma omp simd
    for (int i = 0; i < count; ++i)
        force[i] = sign > 0.0 ? force[i] + perSpring[i] : force[i] - perSpring[i];
}

}  // namespace core
