#pragma once
// The Bullet peer of the throughput benchmark: a throughput cloth built as one btSoftBody, Bullet's
// soft-body cloth, in a btSoftRigidDynamicsWorld and stepped by Bullet itself. Compiled only when
// CMake finds Debian's libbullet-dev (SPRINGLAB_HAVE_BULLET, bench/CMakeLists.txt).
//
// The scene is the core's: one node per particle at its position, velocity and mass, a pinned
// particle a node of mass 0, one link per spring (btSoftBody::appendLink, rest length the
// spring's), the scene's gravity and sub-step. The computation is Bullet's, not the core's: a link
// is a position constraint projected once a sub-step, not a damped force spring, so the positions
// differ from the core's beyond round-off and the benchmark checks only that the scene is the same
// (throughput.cpp, docs/benchmarks.md). Bullet's types stay in bullet_cloth.cpp.

#include "core/model/scene.h"

#include <Eigen/Core>
#include <memory>
#include <string>

namespace bench {

class BulletCloth {
public:
    // a btSoftBody of the scene's particles and springs (its contacts are not modelled: the cloth
    // scenes have none)
    explicit BulletCloth(const core::SceneDesc &scene);
    ~BulletCloth();
    BulletCloth(const BulletCloth &) = delete;
    BulletCloth &operator=(const BulletCloth &) = delete;

    // advances by the scene's time step in its number of sub-steps, one Bullet step per sub-step
    void step();

    int particleCount() const;
    Eigen::Vector3d position(int particle) const;

    // Bullet's version, precision and the soft body's solver settings, for the run's output
    static std::string description();

private:
    struct World;
    std::unique_ptr<World> m_world;
};

}  // namespace bench
