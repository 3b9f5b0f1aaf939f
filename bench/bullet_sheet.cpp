#include "bullet_sheet.h"
#include "bullet_common.h"

#include <BulletCollision/BroadphaseCollision/btDbvtBroadphase.h>
#include <BulletCollision/CollisionDispatch/btCollisionDispatcher.h>
#include <BulletCollision/CollisionShapes/btSphereShape.h>
#include <BulletCollision/CollisionShapes/btStaticPlaneShape.h>
#include <BulletDynamics/ConstraintSolver/btSequentialImpulseConstraintSolver.h>
#include <BulletDynamics/Dynamics/btRigidBody.h>
#include <BulletSoftBody/btSoftBody.h>
#include <BulletSoftBody/btSoftBodyRigidBodyCollisionConfiguration.h>
#include <BulletSoftBody/btSoftRigidDynamicsWorld.h>

#include <algorithm>
#include <cstddef>
#include <map>
#include <vector>

namespace bench {

// Bullet's world: the sheet and the static bodies; members in the order Bullet needs them built
struct BulletSheet::World {
    btSoftBodyRigidBodyCollisionConfiguration configuration;
    btCollisionDispatcher dispatcher{&configuration};
    btDbvtBroadphase broadphase;
    btSequentialImpulseConstraintSolver solver;
    btSoftRigidDynamicsWorld world{&dispatcher, &broadphase, &solver, &configuration};
    std::vector<std::unique_ptr<btCollisionShape>> shapes;
    std::vector<std::unique_ptr<btRigidBody>> bodies;
    std::unique_ptr<btSoftBody> sheet;
    std::vector<int> nodeOf;  // per particle: its node, or -1 for a pinned ball (a rigid body)
    Eigen::Matrix3Xd fixed;   // the pinned balls' positions
    double timeStep = 0.01;   // s
    int substeps = 1;

    World() = default;
    World(const World &) = delete;
    World &operator=(const World &) = delete;
    ~World()
    {
        if (sheet)
            world.removeSoftBody(sheet.get());
        for (const std::unique_ptr<btRigidBody> &body : bodies)
            world.removeRigidBody(body.get());
    }

    void addStatic(std::unique_ptr<btCollisionShape> shape, const btVector3 &at, double friction)
    {
        btRigidBody::btRigidBodyConstructionInfo info(0, nullptr, shape.get());
        info.m_startWorldTransform.setOrigin(at);
        info.m_friction = static_cast<btScalar>(friction);
        bodies.push_back(std::make_unique<btRigidBody>(info));
        world.addRigidBody(bodies.back().get());
        shapes.push_back(std::move(shape));
    }
};

namespace {

// the most clusters a sheet's self-collision gets, and the k-means passes that make them
constexpr int kMostClusters = 8192;
constexpr int kClusterIterations = 8;

// a pinned particle that is no triangle's corner: a ball the sheet falls on, not a node of it
std::vector<bool> sheetParticles(const core::SceneDesc &scene)
{
    std::vector<bool> inSheet(scene.particles.size(), false);
    for (const std::array<int, 3> &t : scene.triangles)
        for (const int i : t)
            inSheet[std::size_t(i)] = true;
    return inSheet;
}

}  // namespace

BulletSheet::BulletSheet(const core::SceneDesc &scene) : m_world(std::make_unique<World>())
{
    World &w = *m_world;
    btSoftBodyWorldInfo &info = w.world.getWorldInfo();
    info.m_gravity = toBullet(scene.settings.gravity);
    w.world.setGravity(info.m_gravity);
    w.timeStep = scene.settings.timeStep;
    w.substeps = scene.settings.substeps;

    // the nodes: the sheet's particles, a pinned one of mass 0 (Bullet's static node)
    const std::vector<bool> inSheet = sheetParticles(scene);
    std::vector<btVector3> positions;
    std::vector<btScalar> masses;
    w.nodeOf.assign(scene.particles.size(), -1);
    w.fixed.resize(3, static_cast<Eigen::Index>(scene.particles.size()));
    double radius = 0.0;
    for (std::size_t i = 0; i < scene.particles.size(); ++i) {
        const core::ParticleDesc &p = scene.particles[i];
        w.fixed.col(static_cast<Eigen::Index>(i)) = p.position;
        if (!inSheet[i]) {
            if (p.pinned)  // a pinned ball: a static sphere
                w.addStatic(std::make_unique<btSphereShape>(static_cast<btScalar>(p.radius)), toBullet(p.position),
                            scene.settings.friction);
            continue;
        }
        w.nodeOf[i] = static_cast<int>(positions.size());
        positions.push_back(toBullet(p.position));
        masses.push_back(p.pinned ? btScalar(0) : static_cast<btScalar>(p.mass));
        radius = std::max(radius, p.radius);
    }
    w.sheet = std::make_unique<btSoftBody>(&info, static_cast<int>(positions.size()), positions.data(), masses.data());
    btSoftBody &sheet = *w.sheet;
    for (std::size_t i = 0; i < scene.particles.size(); ++i)
        if (w.nodeOf[i] >= 0 && !scene.particles[i].pinned)
            sheet.m_nodes[w.nodeOf[i]].m_v = toBullet(scene.particles[i].velocity);

    // the links, a material per stiffness as in bullet_cloth.cpp; the faces, the scene's triangles
    double stiffest = 0.0;
    for (const core::SpringDesc &s : scene.springs)
        stiffest = std::max(stiffest, s.stiffness);
    std::map<double, btSoftBody::Material *> materials;
    for (const core::SpringDesc &s : scene.springs) {
        if (w.nodeOf[std::size_t(s.a)] < 0 || w.nodeOf[std::size_t(s.b)] < 0)
            continue;
        btSoftBody::Material *&material = materials[s.stiffness];
        if (!material) {
            material = sheet.appendMaterial();
            material->m_kLST = static_cast<btScalar>(s.stiffness / stiffest);
        }
        sheet.appendLink(w.nodeOf[std::size_t(s.a)], w.nodeOf[std::size_t(s.b)], material, false);
    }
    for (const std::array<int, 3> &t : scene.triangles)
        sheet.appendFace(w.nodeOf[std::size_t(t[0])], w.nodeOf[std::size_t(t[1])], w.nodeOf[std::size_t(t[2])]);

    // collisions: nodes against the rigid bodies by their distance fields, faces against faces by
    // a cluster per face, up to kMostClusters faces (Bullet keeps a clusters² table of which
    // clusters touch: a 200 x 200 sheet's 79 202 faces overflow its int size and crash it), else
    // that many clusters by Bullet's k-means; the margin the beads' radius, Bullet's friction the scene's
    sheet.m_cfg.piterations = 4;
    sheet.m_cfg.kDF = static_cast<btScalar>(scene.settings.friction);
    sheet.m_cfg.collisions = btSoftBody::fCollision::SDF_RS | btSoftBody::fCollision::CL_SS |
                             btSoftBody::fCollision::CL_SELF;
    sheet.getCollisionShape()->setMargin(static_cast<btScalar>(radius));
    if (sheet.m_faces.size() <= kMostClusters)
        sheet.generateClusters(0);
    else
        sheet.generateClusters(kMostClusters, kClusterIterations);
    sheet.setActivationState(DISABLE_DEACTIVATION);
    w.world.addSoftBody(&sheet);

    // the planes: a static plane each (a bounded rectangle is taken as its whole plane)
    for (const core::PlaneDesc &plane : scene.planes)
        w.addStatic(std::make_unique<btStaticPlaneShape>(toBullet(plane.normal), static_cast<btScalar>(plane.offset)),
                    btVector3(0, 0, 0), plane.friction.value_or(scene.settings.friction));
}

BulletSheet::~BulletSheet() = default;

void BulletSheet::step()
{
    // maxSubSteps 0: one internal step of exactly h, no interpolation
    const double h = m_world->timeStep / m_world->substeps;
    for (int sub = 0; sub < m_world->substeps; ++sub)
        m_world->world.stepSimulation(static_cast<btScalar>(h), 0);
}

Eigen::Matrix3Xd BulletSheet::positions() const
{
    Eigen::Matrix3Xd x = m_world->fixed;
    for (std::size_t i = 0; i < m_world->nodeOf.size(); ++i) {
        const int node = m_world->nodeOf[i];
        if (node < 0)
            continue;
        const btVector3 &p = m_world->sheet->m_nodes[node].m_x;
        x.col(static_cast<Eigen::Index>(i)) = Eigen::Vector3d(double(p.x()), double(p.y()), double(p.z()));
    }
    return x;
}

std::string BulletSheet::description()
{
    return "Bullet " + std::to_string(BT_BULLET_VERSION / 100) + "." + std::to_string(BT_BULLET_VERSION % 100) +
           (sizeof(btScalar) == sizeof(double) ? " (double precision)" : " (single precision)") +
           ", one btSoftBody in a btSoftRigidDynamicsWorld, stepSimulation(h, 0): 4 position iterations, "
           "collisions SDF_RS | CL_SS | CL_SELF with a cluster per face (" + std::to_string(kMostClusters) +
           " clusters by k-means, " + std::to_string(kClusterIterations) +
           " iterations, for more faces), margin the beads' radius";
}

}  // namespace bench
