#include "naive_cloth.h"

#include <cstddef>

namespace bench::naive {

void Gravity::apply(std::vector<Particle *> &particles)
{
    for (Particle *p : particles)
        p->force += p->mass * m_g;
}

void Spring::apply(std::vector<Particle *> &)
{
    const Eigen::Vector3d d = m_a->position - m_b->position;
    const double length = d.norm();
    const Eigen::Vector3d u = length > 0.0 ? Eigen::Vector3d(d / length) : Eigen::Vector3d::UnitY();
    const double approach = (m_a->velocity - m_b->velocity).dot(u);
    const Eigen::Vector3d f = (-m_stiffness * (length - m_restLength) - m_damping * approach) * u;
    m_a->force += f;
    m_b->force -= f;
}

ParticleSystem::ParticleSystem(const core::SceneDesc &scene)
{
    for (const core::ParticleDesc &desc : scene.particles) {
        auto *p = new Particle;
        p->position = desc.position;
        p->velocity = desc.pinned ? Eigen::Vector3d::Zero() : desc.velocity;
        p->mass = desc.mass;
        p->pinned = desc.pinned;
        m_particles.push_back(p);
    }
    m_forces.push_back(new Gravity(scene.settings.gravity));
    for (const core::SpringDesc &s : scene.springs)
        m_forces.push_back(new Spring(m_particles[static_cast<std::size_t>(s.a)],
                                      m_particles[static_cast<std::size_t>(s.b)], s.restLength, s.stiffness,
                                      s.damping));
    m_timeStep = scene.settings.timeStep;
    m_substeps = scene.settings.substeps;
}

ParticleSystem::~ParticleSystem()
{
    for (Force *force : m_forces)
        delete force;
    for (Particle *p : m_particles)
        delete p;
}

void ParticleSystem::step()
{
    const double h = m_timeStep / m_substeps;
    for (int sub = 0; sub < m_substeps; ++sub) {
        // clear the forces, let every force field add its own, then move each particle
        for (Particle *p : m_particles)
            p->force.setZero();
        for (Force *force : m_forces)
            force->apply(m_particles);
        for (Particle *p : m_particles) {
            if (p->pinned)
                continue;
            p->velocity += h * p->force / p->mass;
            p->position += h * p->velocity;
        }
    }
}

Eigen::Vector3d ParticleSystem::position(int particle) const
{
    return m_particles[static_cast<std::size_t>(particle)]->position;
}

}  // namespace bench::naive
