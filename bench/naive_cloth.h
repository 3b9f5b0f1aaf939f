#pragma once
// The naive reference of the throughput benchmark: a particle system the way a course framework
// builds one. Every particle is an object on the heap, every spring is a force object holding
// pointers to its two particles, and the system keeps a list of polymorphic forces whose virtual
// apply() it calls one by one (gravity first, then each spring), then integrates with symplectic
// Euler particle by particle. The physics is the core's (gravity, damped springs, pinned
// particles never move); only the organisation of the data and the calls differs, which is what
// the benchmark measures (docs/benchmarks.md).

#include "core/model/scene.h"

#include <Eigen/Core>
#include <memory>
#include <vector>

namespace bench::naive {

struct Particle {
    Eigen::Vector3d position = Eigen::Vector3d::Zero();  // m
    Eigen::Vector3d velocity = Eigen::Vector3d::Zero();  // m/s
    Eigen::Vector3d force = Eigen::Vector3d::Zero();     // N, this sub-step's
    double mass = 1.0;                                   // kg
    bool pinned = false;
};

class Force {
public:
    virtual ~Force() = default;
    // adds this force's contribution to the particles it acts on
    virtual void apply(std::vector<Particle *> &particles) = 0;
};

// m g on every particle
class Gravity : public Force {
public:
    explicit Gravity(const Eigen::Vector3d &g) : m_g(g) {}
    void apply(std::vector<Particle *> &particles) override;

private:
    Eigen::Vector3d m_g;  // m/s²
};

// a damped spring between two particles
class Spring : public Force {
public:
    Spring(Particle *a, Particle *b, double restLength, double stiffness, double damping)
        : m_a(a), m_b(b), m_restLength(restLength), m_stiffness(stiffness), m_damping(damping)
    {
    }
    void apply(std::vector<Particle *> &particles) override;

private:
    Particle *m_a;
    Particle *m_b;
    double m_restLength;  // m
    double m_stiffness;   // N/m
    double m_damping;     // N·s/m
};

class ParticleSystem {
public:
    // one Particle per particle and one Spring per spring of the scene, plus its gravity
    explicit ParticleSystem(const core::SceneDesc &scene);
    ~ParticleSystem();
    ParticleSystem(const ParticleSystem &) = delete;
    ParticleSystem &operator=(const ParticleSystem &) = delete;

    // advances by the scene's time step in its number of sub-steps
    void step();

    int particleCount() const { return static_cast<int>(m_particles.size()); }
    Eigen::Vector3d position(int particle) const;

private:
    std::vector<Particle *> m_particles;
    std::vector<Force *> m_forces;
    double m_timeStep = 0.01;  // s
    int m_substeps = 1;
};

}  // namespace bench::naive
