#pragma once
// The Bullet peer of the cloth-contacts benchmark: a sheet as one btSoftBody (a node per particle,
// a link per spring, a face per triangle) with Bullet's own collisions on: its nodes against static
// rigid bodies (the scene's planes as btStaticPlaneShape, its pinned balls as btSphereShape) by
// signed distance fields (SDF_RS), and against its own faces by clusters, one per face
// (CL_SS | CL_SELF, generateClusters(0): Bullet's self-collision for cloth). Compiled only where
// CMake finds Debian's libbullet-dev (SPRINGLAB_HAVE_BULLET). Bullet's types stay in
// bullet_sheet.cpp.

#include "core/model/scene.h"

#include <Eigen/Core>
#include <memory>
#include <string>

namespace bench {

class BulletSheet {
public:
    // the scene's sheet (its particles that are not pinned balls, its springs and triangles), its
    // planes and its pinned balls; the scene's gravity, time step and sub-steps
    explicit BulletSheet(const core::SceneDesc &scene);
    ~BulletSheet();
    BulletSheet(const BulletSheet &) = delete;
    BulletSheet &operator=(const BulletSheet &) = delete;

    // advances by the scene's time step in its number of sub-steps, one Bullet step per sub-step
    void step();

    // every particle's position: the sheet's nodes from Bullet, the pinned balls where they stand
    Eigen::Matrix3Xd positions() const;

    // Bullet's version and the soft body's collision settings, for the run's output
    static std::string description();

private:
    struct World;
    std::unique_ptr<World> m_world;
};

}  // namespace bench
