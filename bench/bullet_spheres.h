#pragma once
// The Bullet peer of the contacts benchmark: a scene's balls as Bullet's rigid spheres
// (btRigidBody, btSphereShape) and its planes as static planes (btStaticPlaneShape) in a
// btDiscreteDynamicsWorld with Bullet's sequential-impulse solver, stepped by Bullet itself.
// Compiled only when CMake finds Debian's libbullet-dev (SPRINGLAB_HAVE_BULLET, bench/CMakeLists.txt).
//
// The scene is the core's: each sphere at its particle's position and velocity with its mass and
// radius, the scene's gravity, step and sub-steps. Bullet combines two bodies' restitution, and
// their friction, by multiplying them, so every body (spheres and planes alike) is given √e and √μ:
// every contact then has the scene's e and μ. Bullet has one friction coefficient, so the scene's
// static and kinetic coefficients must be equal, and a plane's own friction is not modelled (the
// benchmark's scenes have neither). Bullet's spheres rotate and roll; the core's particles do not
// (docs/benchmarks.md), so the spheres' rotation can be locked (an angular factor of 0) to compare
// like with like. Bullet's types stay in bullet_spheres.cpp.

#include "core/model/scene.h"

#include <Eigen/Core>
#include <memory>
#include <string>

namespace bench {

class BulletSpheres {
public:
    // the scene's planes and settings, and no sphere yet: enter() adds them; spheres that rotate,
    // or whose rotation is locked
    explicit BulletSpheres(const core::SceneDesc &scene, bool rotates = true);
    ~BulletSpheres();
    BulletSpheres(const BulletSpheres &) = delete;
    BulletSpheres &operator=(const BulletSpheres &) = delete;

    // adds spheres for the scene's particles up to `count` (those not added yet), as they are
    // described in the scene: where a poured ball enters
    void enter(int count);

    // advances by the scene's time step in its number of sub-steps, one Bullet step per sub-step
    void step();

    int particleCount() const;
    Eigen::Vector3d position(int particle) const;
    Eigen::Vector3d velocity(int particle) const;
    Eigen::Vector3d angularVelocity(int particle) const;  // rad/s

    // Bullet's version, precision and solver settings, for the run's output
    static std::string description();

private:
    struct World;
    std::unique_ptr<World> m_world;
};

}  // namespace bench
