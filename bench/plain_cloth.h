#pragma once
// The plain reference of the throughput benchmark: the physics of core/forces/gravity.cpp,
// core/springs/springs.cpp and symplectic Euler (core/integrators/integrate.cpp) as the simplest loops over flat
// arrays, on one thread. No Eigen, no step plan, no profile, no checks: what a careful
// programmer writes in an afternoon. Measured side by side with the core, it shows what the
// core's structure costs or saves (docs/benchmarks.md).

#include "core/model/scene.h"

#include <Eigen/Core>
#include <vector>

namespace bench {

class PlainCloth {
public:
    // copies the particles, springs and settings of a scene of springs and particles (its
    // contacts, drag and applied forces are not modelled: the cloth scenes have none)
    explicit PlainCloth(const core::SceneDesc &scene);

    // advances by the scene's time step in its number of sub-steps
    void step();

    int particleCount() const { return static_cast<int>(m_invMass.size()); }
    Eigen::Vector3d position(int particle) const;

private:
    void substep(double h);

    // particles: x, y, z interleaved per particle
    std::vector<double> m_position;  // m
    std::vector<double> m_velocity;  // m/s
    std::vector<double> m_force;     // N, scratch
    std::vector<double> m_mass;      // kg
    std::vector<double> m_invMass;   // 1/kg, 0 when pinned
    // springs
    std::vector<int> m_a;
    std::vector<int> m_b;
    std::vector<double> m_restLength;  // m
    std::vector<double> m_stiffness;   // N/m
    std::vector<double> m_damping;     // N·s/m
    // settings
    double m_gravity[3] = {0.0, 0.0, 0.0};  // m/s²
    double m_timeStep = 0.01;                // s
    int m_substeps = 1;
};

}  // namespace bench
