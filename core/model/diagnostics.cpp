#include "core/model/diagnostics.h"

namespace core {

Energies energies(const Model &model, const State &state)
{
    Energies e;
    // kinetic: free particles only (pinned ones are at rest)
    for (int i : model.freeParticles)
        e.kinetic += 0.5 * model.mass[i] * state.velocity.col(i).squaredNorm();
    // and turning, where the scene can: ½ I ω² (I = m / (m / I), 0 for a particle of no radius)
    if (model.plan.spin && state.angularVelocity.cols() == model.particleCount())
        for (int i : model.freeParticles)
            if (model.invInertia[i] > 0.0)
                e.kinetic += 0.5 / model.invInertia[i] * state.angularVelocity.col(i).squaredNorm();

    // gravitational: -m g·x, zero at the origin
    for (int i = 0; i < model.particleCount(); ++i)
        e.gravitational -= model.mass[i] * model.gravity.dot(state.position.col(i));

    // elastic: ½ k (l - l0)²
    for (int k = 0; k < model.springCount(); ++k) {
        if (state.isBroken(k))
            continue;
        const int a = model.springA[static_cast<std::size_t>(k)];
        const int b = model.springB[static_cast<std::size_t>(k)];
        const double stretch = (state.position.col(a) - state.position.col(b)).norm() - model.restLength[k];
        e.spring += 0.5 * model.stiffness[k] * stretch * stretch;
    }
    return e;
}

Eigen::Vector3d momentum(const Model &model, const State &state)
{
    Eigen::Vector3d p = Eigen::Vector3d::Zero();
    for (int i : model.freeParticles)
        p += model.mass[i] * state.velocity.col(i);
    return p;
}

}  // namespace core
