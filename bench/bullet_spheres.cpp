#include "bullet_spheres.h"
#include "bullet_common.h"

#include <BulletCollision/BroadphaseCollision/btDbvtBroadphase.h>
#include <BulletCollision/CollisionDispatch/btCollisionDispatcher.h>
#include <BulletCollision/CollisionDispatch/btDefaultCollisionConfiguration.h>
#include <BulletCollision/CollisionShapes/btSphereShape.h>
#include <BulletCollision/CollisionShapes/btStaticPlaneShape.h>
#include <BulletDynamics/ConstraintSolver/btSequentialImpulseConstraintSolver.h>
#include <BulletDynamics/Dynamics/btDiscreteDynamicsWorld.h>
#include <BulletDynamics/Dynamics/btRigidBody.h>

#include <cassert>
#include <cmath>
#include <cstdio>
#include <map>
#include <vector>

namespace bench {

namespace {

Eigen::Vector3d fromBullet(const btVector3 &v)
{
    return {static_cast<double>(v.x()), static_cast<double>(v.y()), static_cast<double>(v.z())};
}

// "0.2 m/s"
std::string metresPerSecond(double speed)
{
    char text[32];
    std::snprintf(text, sizeof text, "%g m/s", speed);
    return text;
}

}  // namespace

// Bullet's world, its shapes and its bodies; members in the order Bullet needs them built
struct BulletSpheres::World {
    btDefaultCollisionConfiguration configuration;
    btCollisionDispatcher dispatcher{&configuration};
    btDbvtBroadphase broadphase;
    btSequentialImpulseConstraintSolver solver;
    btDiscreteDynamicsWorld world{&dispatcher, &broadphase, &solver, &configuration};
    std::vector<std::unique_ptr<btStaticPlaneShape>> planeShapes;
    std::map<double, std::unique_ptr<btSphereShape>> sphereShapes;  // one per radius
    std::vector<std::unique_ptr<btRigidBody>> planes;
    std::vector<std::unique_ptr<btRigidBody>> spheres;
    std::vector<core::ParticleDesc> particles;  // the scene's, in the order they enter
    btScalar restitution = 0;  // √e, each body's
    btScalar friction = 0;     // √μ, each body's
    bool rotates = true;       // false: each sphere's angular factor is 0
    double timeStep = 0.01;    // s
    int substeps = 1;

    World() = default;
    World(const World &) = delete;
    World &operator=(const World &) = delete;
    ~World()
    {
        // the world reads its bodies as it goes, so they leave it before any of them is freed
        for (auto &sphere : spheres)
            world.removeRigidBody(sphere.get());
        for (auto &plane : planes)
            world.removeRigidBody(plane.get());
    }
};

BulletSpheres::BulletSpheres(const core::SceneDesc &scene, bool rotates) : m_world(std::make_unique<World>())
{
    World &w = *m_world;
    w.rotates = rotates;
    // one coefficient of friction in Bullet: the scene's static one must be its kinetic one
    assert(!scene.settings.staticFriction || *scene.settings.staticFriction == scene.settings.friction);
    w.world.setGravity(toBullet(scene.settings.gravity));
    w.timeStep = scene.settings.timeStep;
    w.substeps = scene.settings.substeps;
    w.particles = scene.particles;
    // Bullet multiplies the two bodies' values: √e × √e = e, √μ × √μ = μ on every contact
    w.restitution = static_cast<btScalar>(std::sqrt(scene.settings.restitution));
    w.friction = static_cast<btScalar>(std::sqrt(scene.settings.friction));

    // the planes n·p = offset, static (mass 0), infinite and one-sided as the core's
    for (const core::PlaneDesc &plane : scene.planes) {
        assert(!plane.friction && !plane.bounded());
        w.planeShapes.push_back(
            std::make_unique<btStaticPlaneShape>(toBullet(plane.normal), static_cast<btScalar>(plane.offset)));
        btRigidBody::btRigidBodyConstructionInfo info(0, nullptr, w.planeShapes.back().get());
        w.planes.push_back(std::make_unique<btRigidBody>(info));
        btRigidBody &body = *w.planes.back();
        body.setRestitution(w.restitution);
        body.setFriction(w.friction);
        w.world.addRigidBody(&body);
    }
}

BulletSpheres::~BulletSpheres() = default;

void BulletSpheres::enter(int count)
{
    World &w = *m_world;
    assert(count <= static_cast<int>(w.particles.size()));
    for (int i = static_cast<int>(w.spheres.size()); i < count; ++i) {
        const core::ParticleDesc &p = w.particles[static_cast<std::size_t>(i)];
        std::unique_ptr<btSphereShape> &shape = w.sphereShapes[p.radius];
        if (!shape)
            shape = std::make_unique<btSphereShape>(static_cast<btScalar>(p.radius));
        // a solid ball's inertia, 2/5 m r²
        btVector3 inertia(0, 0, 0);
        shape->calculateLocalInertia(static_cast<btScalar>(p.mass), inertia);
        btRigidBody::btRigidBodyConstructionInfo info(static_cast<btScalar>(p.mass), nullptr, shape.get(), inertia);
        info.m_startWorldTransform.setOrigin(toBullet(p.position));
        w.spheres.push_back(std::make_unique<btRigidBody>(info));
        btRigidBody &body = *w.spheres.back();
        body.setLinearVelocity(toBullet(p.velocity));
        body.setAngularVelocity(toBullet(p.angularVelocity));
        body.setRestitution(w.restitution);
        body.setFriction(w.friction);
        if (!w.rotates)
            body.setAngularFactor(0);
        // never put to sleep: the core has no sleeping, so both solve every contact every step
        body.setActivationState(DISABLE_DEACTIVATION);
        w.world.addRigidBody(&body);
    }
}

void BulletSpheres::step()
{
    // maxSubSteps 0: one internal step of exactly h, no interpolation
    const double h = m_world->timeStep / m_world->substeps;
    for (int sub = 0; sub < m_world->substeps; ++sub)
        m_world->world.stepSimulation(static_cast<btScalar>(h), 0);
}

int BulletSpheres::particleCount() const
{
    return static_cast<int>(m_world->spheres.size());
}

Eigen::Vector3d BulletSpheres::position(int particle) const
{
    return fromBullet(m_world->spheres[static_cast<std::size_t>(particle)]->getWorldTransform().getOrigin());
}

Eigen::Vector3d BulletSpheres::velocity(int particle) const
{
    return fromBullet(m_world->spheres[static_cast<std::size_t>(particle)]->getLinearVelocity());
}

Eigen::Vector3d BulletSpheres::angularVelocity(int particle) const
{
    return fromBullet(m_world->spheres[static_cast<std::size_t>(particle)]->getAngularVelocity());
}

std::string BulletSpheres::description()
{
    const btContactSolverInfo info;
    return "Bullet " + std::to_string(BT_BULLET_VERSION / 100) + "." + std::to_string(BT_BULLET_VERSION % 100) +
           (sizeof(btScalar) == sizeof(double) ? " (double precision)" : " (single precision)") +
           ", btDiscreteDynamicsWorld, btSphereShape bodies and btStaticPlaneShape planes, "
           "stepSimulation(h, 0) once a sub-step; the solver's defaults: " +
           std::to_string(info.m_numIterations) + " iterations, split impulse " +
           (info.m_splitImpulse ? "on" : "off") + ", warm starting " +
           ((info.m_solverMode & SOLVER_USE_WARMSTARTING) ? "on" : "off") +
           ", no restitution below " + metresPerSecond(info.m_restitutionVelocityThreshold) +
           "; each body sqrt(e) and sqrt(mu) (Bullet multiplies the pair's), no rolling friction, "
           "never put to sleep";
}

}  // namespace bench
