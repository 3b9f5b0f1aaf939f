#include "core/model/model.h"

#include "core/model/parameters.h"
#include "core/integrators/stability.h"
#include "core/model/state.h"
#include "core/model/validate.h"
#include "core/integrators/vertex_colours.h"
#include "core/integrators/xpbd_layout.h"

#include <algorithm>
#include <cassert>

namespace core {

namespace {

// as many sub-steps as the stability limit at the state asks, and no fewer than the scene's own
int autoSubsteps(const Model &model, const Settings &s, const State &state)
{
    return stableSubsteps(stabilityLimit(model, state), s.integrator, s.timeStep, s.substeps,
                          static_cast<int>(parameterInfo(Parameter::Substeps).maximum));
}

void setSubsteps(Model &model, int substeps)
{
    model.substeps = substeps;
    // two sub-steps' worth of speed gained under gravity: what a resting contact picks up between
    // projections, well below any real impact
    model.restingSpeed = 2.0 * model.gravity.norm() * model.subStep();
}

}  // namespace

std::shared_ptr<const Model> compileModel(const SceneDesc &scene, const Model *before)
{
    assert(!findProblem(scene) && "compileModel needs a validated scene");
    auto model = std::make_shared<Model>();
    const Settings &s = scene.settings;

    // settings
    model->timeStep = s.timeStep;
    model->substeps = s.substeps;
    model->xpbdIterations = s.xpbdIterations;
    model->solverIterations = s.solverIterations;
    model->integrator = s.integrator;
    model->tolerance = s.tolerance;
    model->gravity = s.gravity;
    model->viscosity = s.viscosity;
    model->restitution = s.restitution;
    model->contactSolver = s.contactSolver;
    model->friction = s.friction;
    model->staticFriction = s.staticFriction.value_or(s.friction);
    model->rollingFriction = s.rollingFriction;
    model->spinningFriction = s.spinningFriction;

    // particles, structure of arrays
    const auto n = static_cast<Eigen::Index>(scene.particles.size());
    model->mass.resize(n);
    model->invMass.resize(n);
    model->radius.resize(n);
    for (Eigen::Index i = 0; i < n; ++i) {
        const ParticleDesc &p = scene.particles[static_cast<std::size_t>(i)];
        model->mass[i] = p.mass;
        model->invMass[i] = p.pinned ? 0.0 : 1.0 / p.mass;
        model->radius[i] = p.radius;
        if (!p.pinned)
            model->freeParticles.push_back(static_cast<int>(i));
    }
    for (std::size_t f = 0; f < model->freeParticles.size(); ++f) {
        const int i = model->freeParticles[f];
        if (f == 0 || model->freeRanges.back() != i)
            model->freeRanges.insert(model->freeRanges.end(), {i, i + 1});
        else
            model->freeRanges.back() = i + 1;
    }

    // springs
    const auto springs = static_cast<Eigen::Index>(scene.springs.size());
    model->springA.reserve(scene.springs.size());
    model->springB.reserve(scene.springs.size());
    model->restLength.resize(springs);
    model->stiffness.resize(springs);
    model->damping.resize(springs);
    model->breakStrain.resize(springs);
    for (Eigen::Index k = 0; k < springs; ++k) {
        const SpringDesc &spring = scene.springs[static_cast<std::size_t>(k)];
        model->springA.push_back(spring.a);
        model->springB.push_back(spring.b);
        model->restLength[k] = spring.restLength;
        model->stiffness[k] = spring.stiffness;
        model->damping[k] = spring.damping;
        model->breakStrain[k] = spring.breakStrain;
    }

    // each particle's springs in ascending order: a count per particle, then a running sum
    model->springOffsets.assign(static_cast<std::size_t>(n) + 1, 0);
    for (Eigen::Index k = 0; k < springs; ++k) {
        ++model->springOffsets[static_cast<std::size_t>(model->springA[static_cast<std::size_t>(k)]) + 1];
        ++model->springOffsets[static_cast<std::size_t>(model->springB[static_cast<std::size_t>(k)]) + 1];
    }
    for (std::size_t i = 1; i < model->springOffsets.size(); ++i)
        model->springOffsets[i] += model->springOffsets[i - 1];
    model->springEnds.resize(static_cast<std::size_t>(2 * springs));
    std::vector<int> filled(model->springOffsets.begin(), model->springOffsets.end() - 1);
    for (Eigen::Index k = 0; k < springs; ++k) {
        const auto a = static_cast<std::size_t>(model->springA[static_cast<std::size_t>(k)]);
        const auto b = static_cast<std::size_t>(model->springB[static_cast<std::size_t>(k)]);
        model->springEnds[static_cast<std::size_t>(filled[a]++)] = static_cast<int>(2 * k);
        model->springEnds[static_cast<std::size_t>(filled[b]++)] = static_cast<int>(2 * k + 1);
    }

    // planes
    const auto planes = static_cast<Eigen::Index>(scene.planes.size());
    model->planeNormal.resize(3, planes);
    model->planeOffset.resize(planes);
    for (Eigen::Index k = 0; k < planes; ++k) {
        const PlaneDesc &plane = scene.planes[static_cast<std::size_t>(k)];
        model->planeNormal.col(k) = unitNormal(plane.normal);
        model->planeOffset[k] = plane.offset;
        model->colliders.push_back(makeCollider(plane, s));
    }

    // the step plan: a pass this scene cannot need is never run
    const bool anythingFree = !model->freeParticles.empty();
    StepPlan &plan = model->plan;
    plan.gravity = anythingFree && !model->gravity.isZero(0.0);
    plan.drag = anythingFree && model->viscosity > 0.0;
    plan.springs = springs > 0;
    plan.springBreaks = springs > 0 && model->breakStrain.maxCoeff() > 0.0;
    plan.planeCollisions = anythingFree && s.planeCollisions && planes > 0;
    plan.particleCollisions = anythingFree && s.particleCollisions && n >= 2;
    plan.contactSolver = s.contactSolver == ContactSolver::Iterative && (plan.planeCollisions || plan.particleCollisions);
    plan.twoSidedColliders = plan.contactSolver && plan.planeCollisions &&
                             std::any_of(model->colliders.begin(), model->colliders.end(),
                                         [](const Collider &c) { return c.twoSided; });
    // the particles turn where a contact can turn them, or one is given a spin
    const auto turns = [](double friction, double staticFriction, double rolling, double spinning) {
        return friction > 0.0 || staticFriction > 0.0 || rolling > 0.0 || spinning > 0.0;
    };
    bool turned = plan.particleCollisions && turns(model->friction, model->staticFriction, model->rollingFriction,
                                                   model->spinningFriction);
    if (plan.planeCollisions)
        for (const Collider &c : model->colliders)
            turned = turned || turns(c.friction, c.staticFriction, c.rollingFriction, c.spinningFriction);
    for (const ParticleDesc &p : scene.particles)
        turned = turned || !p.angularVelocity.isZero(0.0);
    const auto setSpin = [&] {
        plan.spin = true;
        model->invInertia.setZero(n);
        for (Eigen::Index i = 0; i < n; ++i)
            if (model->invMass[i] > 0.0 && model->radius[i] > 0.0)
                model->invInertia[i] = model->invMass[i] / (kSolidSphereInertia * model->radius[i] * model->radius[i]);
    };
    if (s.spin && turned)
        setSpin();

    // the list as the kernels walk it, and the pass it takes
    model->springLayout = makeSpringLayout(SpringList{model->springA, model->springB, model->restLength,
                                                      model->stiffness, model->damping, static_cast<int>(n),
                                                      plan.springBreaks});

    setIntegrator(*model, s.integrator);

    // the triangles the viewport draws a cloth with: the model's before the edit if it had the
    // same springs between the same particles
    const bool sameSprings = before && before->particleCount() == n && before->springA == model->springA &&
                             before->springB == model->springB && before->triangles;
    const auto listedAsBefore = [&] {
        const std::vector<int> &corners = before->triangles->corners;
        if (corners.size() != 3 * scene.triangles.size())
            return false;
        for (std::size_t t = 0; t < scene.triangles.size(); ++t)
            for (std::size_t c = 0; c < 3; ++c)
                if (corners[3 * t + c] != scene.triangles[t][c])
                    return false;
        return true;
    };
    if (sameSprings && (scene.triangles.empty() ? true : listedAsBefore()))
        model->triangles = before->triangles;
    else if (listsTriangles(scene))
        model->triangles = std::make_shared<const SpringTriangles>(sceneTriangles(scene));
    else if (plan.springs)
        model->triangles = std::make_shared<const SpringTriangles>(sceneTriangles(scene));
    // the sheets among them, for the triangle collisions
    if (s.triangleCollisions && anythingFree && model->triangles && !model->triangles->empty()) {
        auto surface = std::make_shared<const ClothSurface>(makeClothSurface(scene, *model->triangles));
        if (!surface->empty()) {
            model->surface = std::move(surface);
            plan.triangleCollisions = true;
            // a sheet with friction turns what rolls on it (triangle_collisions.cpp)
            if (s.spin && !plan.spin &&
                turns(model->friction, model->staticFriction, model->rollingFriction, model->spinningFriction))
                setSpin();
        }
    }

    if (EmbeddedSurface embedded = makeEmbeddedSurface(scene); !embedded.empty())
        model->embedded = std::make_shared<const EmbeddedSurface>(std::move(embedded));

    // auto substeps: as many as the stability limit at the initial state asks, and no fewer than the
    // scene's own
    setSubsteps(*model, s.autoSubsteps ? autoSubsteps(*model, s, makeState(*model, scene)) : s.substeps);
    return model;
}

std::shared_ptr<const Model> autoSubstepsAlsoFor(const std::shared_ptr<const Model> &model, const SceneDesc &scene,
                                                 const State &state)
{
    if (!model || !scene.settings.autoSubsteps)
        return model;
    const int wanted = autoSubsteps(*model, scene.settings, state);
    if (wanted <= model->substeps)
        return model;
    auto raised = std::make_shared<Model>(*model);
    setSubsteps(*raised, wanted);
    return raised;
}

void setIntegrator(Model &model, Integrator integrator)
{
    model.integrator = integrator;
    // the Euler schemes fuse the forces and their update on a lattice whose layout is indexed by
    // block (its springs reach no further than the next block of particles)
    const bool euler = integrator == Integrator::SymplecticEuler || integrator == Integrator::ExplicitEuler;
    model.plan.subStep = euler && model.springLayout.blocks ? SubStepPath::FusedLattice : SubStepPath::Stages;
    // xpbd's colours, only while it is the integrator (a scene that never runs it pays nothing)
    if (integrator == Integrator::Xpbd && model.plan.springs) {
        model.xpbdLayout = xpbdLayout(model);
    } else {
        model.xpbdLayout = XpbdLayout{};
    }
    // vbd's vertex colours, likewise
    model.vbdOrder.clear();
    model.vbdColours.clear();
    if (integrator == Integrator::Vbd)
        colourVertices(model, model.vbdOrder, model.vbdColours);
}

}  // namespace core
