#include "core/parallel.h"
#include "core/passes.h"
#include "core/springs/spring_kernels.h"

namespace core {

// weight m g on every particle (a pinned one is never integrated, so its share is harmless)
void addGravity(const Model &model, State &, Workspace &work)
{
    if (!model.plan.gravity)
        return;
    work.force.noalias() += model.gravity * model.mass.transpose();
}

// the forces set to 0 + m g: the same bits as clearing them and adding m g, in one pass
// (startingForce, which the fused sub-step's start over lanes shares)
void startWithGravity(const Model &model, State &, Workspace &work)
{
    const double *mass = model.mass.data();
    const Eigen::Vector3d g = model.gravity;
    double *force = work.force.data();
    parallelChunks(model.particleCount(), [&](int begin, int end) {
#pragma omp simd
        for (int i = begin; i < end; ++i)
            for (int axis = 0; axis < 3; ++axis)
                force[3 * i + axis] = startingForce(g[axis], mass[i]);
    });
}

}  // namespace core
