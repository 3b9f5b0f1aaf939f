#include "bullet_cloth.h"
#include "bullet_common.h"

#include <BulletCollision/BroadphaseCollision/btDbvtBroadphase.h>
#include <BulletCollision/CollisionDispatch/btCollisionDispatcher.h>
#include <BulletDynamics/ConstraintSolver/btSequentialImpulseConstraintSolver.h>
#include <BulletSoftBody/btSoftBody.h>
#include <BulletSoftBody/btSoftBodyRigidBodyCollisionConfiguration.h>
#include <BulletSoftBody/btSoftRigidDynamicsWorld.h>

#include <algorithm>
#include <cstddef>
#include <map>
#include <vector>

namespace bench {

// Bullet's world with nothing in it but the cloth; members in the order Bullet needs them built
struct BulletCloth::World {
    btSoftBodyRigidBodyCollisionConfiguration configuration;
    btCollisionDispatcher dispatcher{&configuration};
    btDbvtBroadphase broadphase;
    btSequentialImpulseConstraintSolver solver;
    btSoftRigidDynamicsWorld world{&dispatcher, &broadphase, &solver, &configuration};
    std::unique_ptr<btSoftBody> cloth;
    double timeStep = 0.01;  // s
    int substeps = 1;

    World() = default;
    World(const World &) = delete;
    World &operator=(const World &) = delete;
    ~World()
    {
        if (cloth)
            world.removeSoftBody(cloth.get());
    }
};

BulletCloth::BulletCloth(const core::SceneDesc &scene) : m_world(std::make_unique<World>())
{
    World &w = *m_world;
    btSoftBodyWorldInfo &info = w.world.getWorldInfo();
    info.m_gravity = toBullet(scene.settings.gravity);
    w.world.setGravity(info.m_gravity);
    w.timeStep = scene.settings.timeStep;
    w.substeps = scene.settings.substeps;

    // the nodes: the particles' positions, their masses, 0 for a pinned one (Bullet's static node)
    std::vector<btVector3> positions;
    std::vector<btScalar> masses;
    positions.reserve(scene.particles.size());
    masses.reserve(scene.particles.size());
    for (const core::ParticleDesc &p : scene.particles) {
        positions.push_back(toBullet(p.position));
        masses.push_back(p.pinned ? btScalar(0) : static_cast<btScalar>(p.mass));
    }
    w.cloth = std::make_unique<btSoftBody>(&info, static_cast<int>(positions.size()), positions.data(), masses.data());
    btSoftBody &cloth = *w.cloth;
    for (std::size_t i = 0; i < scene.particles.size(); ++i)
        if (!scene.particles[i].pinned)
            cloth.m_nodes[static_cast<int>(i)].m_v = toBullet(scene.particles[i].velocity);

    // the links: one per spring, a material per stiffness whose linear stiffness coefficient
    // (kLST, 0 to 1) is the spring's stiffness over the stiffest one's; the rest lengths are the
    // nodes' distances, which are the springs' rest lengths in the cloth scenes
    double stiffest = 0.0;
    for (const core::SpringDesc &s : scene.springs)
        stiffest = std::max(stiffest, s.stiffness);
    std::map<double, btSoftBody::Material *> materials;
    for (const core::SpringDesc &s : scene.springs) {
        btSoftBody::Material *&material = materials[s.stiffness];
        if (!material) {
            material = cloth.appendMaterial();
            material->m_kLST = static_cast<btScalar>(s.stiffness / stiffest);
        }
        cloth.appendLink(s.a, s.b, material, false);
    }

    // the cheapest solver Bullet offers for a cloth without contacts: one position iteration, no
    // velocity, drift or cluster iterations, no damping, no collisions, never put to sleep
    cloth.m_cfg.piterations = 1;
    cloth.m_cfg.viterations = 0;
    cloth.m_cfg.diterations = 0;
    cloth.m_cfg.citerations = 0;
    cloth.m_cfg.kDP = 0;
    cloth.m_cfg.collisions = 0;
    cloth.setActivationState(DISABLE_DEACTIVATION);
    w.world.addSoftBody(&cloth);
}

BulletCloth::~BulletCloth() = default;

void BulletCloth::step()
{
    // maxSubSteps 0: one internal step of exactly h, no interpolation
    const double h = m_world->timeStep / m_world->substeps;
    for (int sub = 0; sub < m_world->substeps; ++sub)
        m_world->world.stepSimulation(static_cast<btScalar>(h), 0);
}

int BulletCloth::particleCount() const
{
    return m_world->cloth->m_nodes.size();
}

Eigen::Vector3d BulletCloth::position(int particle) const
{
    const btVector3 &x = m_world->cloth->m_nodes[particle].m_x;
    return {static_cast<double>(x.x()), static_cast<double>(x.y()), static_cast<double>(x.z())};
}

std::string BulletCloth::description()
{
    return "Bullet " + std::to_string(BT_BULLET_VERSION / 100) + "." + std::to_string(BT_BULLET_VERSION % 100) +
           (sizeof(btScalar) == sizeof(double) ? " (double precision)" : " (single precision)") +
           ", one btSoftBody in a btSoftRigidDynamicsWorld, stepSimulation(h, 0): 1 position iteration, "
           "no velocity, drift or cluster iterations, kDP = 0, no collisions";
}

}  // namespace bench
