#include "plain_cloth.h"

#include <cmath>
#include <cstddef>

namespace bench {

PlainCloth::PlainCloth(const core::SceneDesc &scene)
{
    const std::size_t n = scene.particles.size();
    m_position.resize(3 * n);
    m_velocity.resize(3 * n);
    m_force.assign(3 * n, 0.0);
    m_mass.resize(n);
    m_invMass.resize(n);
    for (std::size_t i = 0; i < n; ++i) {
        const core::ParticleDesc &p = scene.particles[i];
        for (std::size_t axis = 0; axis < 3; ++axis) {
            m_position[3 * i + axis] = p.position[static_cast<Eigen::Index>(axis)];
            m_velocity[3 * i + axis] = p.pinned ? 0.0 : p.velocity[static_cast<Eigen::Index>(axis)];
        }
        m_mass[i] = p.mass;
        m_invMass[i] = p.pinned ? 0.0 : 1.0 / p.mass;
    }
    for (const core::SpringDesc &s : scene.springs) {
        m_a.push_back(s.a);
        m_b.push_back(s.b);
        m_restLength.push_back(s.restLength);
        m_stiffness.push_back(s.stiffness);
        m_damping.push_back(s.damping);
    }
    for (int axis = 0; axis < 3; ++axis)
        m_gravity[axis] = scene.settings.gravity[axis];
    m_timeStep = scene.settings.timeStep;
    m_substeps = scene.settings.substeps;
}

void PlainCloth::step()
{
    const double h = m_timeStep / m_substeps;
    for (int sub = 0; sub < m_substeps; ++sub)
        substep(h);
}

Eigen::Vector3d PlainCloth::position(int particle) const
{
    const std::size_t i = 3 * static_cast<std::size_t>(particle);
    return {m_position[i], m_position[i + 1], m_position[i + 2]};
}

void PlainCloth::substep(double h)
{
    const std::size_t n = m_invMass.size();
    double *const x = m_position.data();
    double *const v = m_velocity.data();
    double *const f = m_force.data();

    // gravity: f = m g, which also clears the forces of the last sub-step
    for (std::size_t i = 0; i < n; ++i)
        for (std::size_t axis = 0; axis < 3; ++axis)
            f[3 * i + axis] = m_gravity[axis] * m_mass[i];

    // damped springs, scattered to both ends: -k (l - l0) u - kc ((va - vb)·u) u on end a
    const std::size_t springs = m_a.size();
    for (std::size_t k = 0; k < springs; ++k) {
        const std::size_t a = 3 * static_cast<std::size_t>(m_a[k]);
        const std::size_t b = 3 * static_cast<std::size_t>(m_b[k]);
        const double dx = x[a] - x[b], dy = x[a + 1] - x[b + 1], dz = x[a + 2] - x[b + 2];
        const double length = std::sqrt(dx * dx + dy * dy + dz * dz);
        double ux = 0.0, uy = 1.0, uz = 0.0;  // coincident ends: +y, as the core does
        if (length > 0.0) {
            ux = dx / length;
            uy = dy / length;
            uz = dz / length;
        }
        const double approach = (v[a] - v[b]) * ux + (v[a + 1] - v[b + 1]) * uy + (v[a + 2] - v[b + 2]) * uz;
        const double magnitude = -m_stiffness[k] * (length - m_restLength[k]) - m_damping[k] * approach;
        const double fx = magnitude * ux, fy = magnitude * uy, fz = magnitude * uz;
        f[a] += fx;
        f[a + 1] += fy;
        f[a + 2] += fz;
        f[b] -= fx;
        f[b + 1] -= fy;
        f[b + 2] -= fz;
    }

    // symplectic Euler on the free particles: the new velocity moves the particle
    for (std::size_t i = 0; i < n; ++i) {
        const double w = m_invMass[i];
        if (w == 0.0)
            continue;
        for (std::size_t axis = 0; axis < 3; ++axis) {
            v[3 * i + axis] += (h * w) * f[3 * i + axis];
            x[3 * i + axis] += h * v[3 * i + axis];
        }
    }
}

}  // namespace bench
