#include "model.h"

#include "parameters.h"
#include "stability.h"
#include "state.h"
#include "validate.h"

#include <algorithm>
#include <cassert>
#include <cstdlib>
#include <utility>

namespace core {

namespace {

// the runs with an end in each block of kSpringBlock particles, ascending (Model::blockRuns)
void indexByBlock(const std::vector<Model::SpringRun> &runs, int particles, std::vector<int> &offsets,
                  std::vector<int> &list)
{
    const int blocks = (particles + kSpringBlock - 1) / kSpringBlock;
    std::vector<std::vector<int>> byBlock(static_cast<std::size_t>(blocks));
    for (int r = 0; r < static_cast<int>(runs.size()); ++r) {
        const Model::SpringRun &run = runs[static_cast<std::size_t>(r)];
        for (const int end : {run.a, run.b})
            for (int q = end / kSpringBlock; q <= (end + run.count - 1) / kSpringBlock; ++q) {
                std::vector<int> &blockList = byBlock[static_cast<std::size_t>(q)];
                if (blockList.empty() || blockList.back() != r)
                    blockList.push_back(r);
            }
    }
    offsets.assign(1, 0);
    for (const std::vector<int> &blockList : byBlock) {
        list.insert(list.end(), blockList.begin(), blockList.end());
        offsets.push_back(static_cast<int>(list.size()));
    }
}

// whether springs [first, last) all have spring first's rest length, stiffness and damping, to the bit
bool sameParameters(const Model &model, int first, int last)
{
    const auto same = [&](const Eigen::VectorXd &values) {
        return (values.segment(first, last - first).array() == values[first]).all();
    };
    return same(model.restLength) && same(model.stiffness) && same(model.damping);
}

// whether run `next`, which follows `last` in the list, can join it (Model::JoinedRuns)
bool joins(const Model::SpringRun &last, const Model::SpringRun &next)
{
    const int gap = next.a - (last.a + last.count);
    return last.count < kJoinRunsBelow && next.count < kJoinRunsBelow && next.b - next.a == last.b - last.a &&
           gap >= 0 && gap <= kJoinGap;
}

// Model::joined, or nothing where no two runs join
void joinShortRuns(Model &model)
{
    const std::vector<Model::SpringRun> &runs = model.springRuns;
    bool any = false;
    for (std::size_t r = 1; r < runs.size() && !any; ++r)
        any = joins(runs[r - 1], runs[r]);
    if (!any)
        return;
    // the joined runs, each with its springs' place in the padded arrays
    std::vector<Model::SpringRun> &joined = model.joined.runs;
    std::vector<std::pair<int, int>> pieces;  // (padded index, spring) of each run's first spring
    int padded = 0;
    for (std::size_t r = 0; r < runs.size(); ++r) {
        const Model::SpringRun &run = runs[r];
        if (r > 0 && joins(runs[r - 1], run)) {
            Model::SpringRun &into = joined.back();
            into.count = run.a - into.a + run.count;
            into.uniform = false;  // the padding's parameters are not the springs'
        } else {
            joined.push_back(Model::SpringRun{padded, run.count, run.a, run.b, run.uniform});
        }
        pieces.emplace_back(joined.back().first + (run.a - joined.back().a), run.first);
        padded = joined.back().first + joined.back().count;
    }
    // padding: no rest length, stiffness or damping, so a force of ±0
    model.joined.restLength.setZero(padded);
    model.joined.stiffness.setZero(padded);
    model.joined.damping.setZero(padded);
    for (std::size_t r = 0; r < runs.size(); ++r) {
        const auto [at, spring] = pieces[r];
        model.joined.restLength.segment(at, runs[r].count) = model.restLength.segment(spring, runs[r].count);
        model.joined.stiffness.segment(at, runs[r].count) = model.stiffness.segment(spring, runs[r].count);
        model.joined.damping.segment(at, runs[r].count) = model.damping.segment(spring, runs[r].count);
    }
}

}  // namespace

std::shared_ptr<const Model> compileModel(const SceneDesc &scene)
{
    assert(!findProblem(scene) && "compileModel needs a validated scene");
    auto model = std::make_shared<Model>();
    const Settings &s = scene.settings;

    // settings
    model->timeStep = s.timeStep;
    model->substeps = s.substeps;
    model->integrator = s.integrator;
    model->tolerance = s.tolerance;
    model->gravity = s.gravity;
    model->viscosity = s.viscosity;
    model->restitution = s.restitution;

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

    // runs of springs whose ends both step by one
    for (int k = 0; k < static_cast<int>(springs);) {
        Model::SpringRun run{k, 1, model->springA[static_cast<std::size_t>(k)], model->springB[static_cast<std::size_t>(k)]};
        while (k + run.count < springs && model->springA[static_cast<std::size_t>(k + run.count)] == run.a + run.count &&
               model->springB[static_cast<std::size_t>(k + run.count)] == run.b + run.count)
            ++run.count;
        run.uniform = sameParameters(*model, run.first, run.first + run.count);
        model->springRuns.push_back(run);
        model->springReach = std::max(model->springReach, std::abs(run.b - run.a));
        k += run.count;
    }

    // planes
    const auto planes = static_cast<Eigen::Index>(scene.planes.size());
    model->planeNormal.resize(3, planes);
    model->planeOffset.resize(planes);
    for (Eigen::Index k = 0; k < planes; ++k) {
        const PlaneDesc &plane = scene.planes[static_cast<std::size_t>(k)];
        model->planeNormal.col(k) = unitNormal(plane.normal);
        model->planeOffset[k] = plane.offset;
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

    // which runs reach into each block of particles, for the fused sub-step, and the short ones
    // joined where no spring can break (a state with broken flags steps by the list's runs)
    if (model->usesSpringRuns() && model->springReach <= kSpringBlock) {
        indexByBlock(model->springRuns, static_cast<int>(n), model->blockRunOffsets, model->blockRuns);
        if (!plan.springBreaks)
            joinShortRuns(*model);
        if (!model->joined.runs.empty())
            indexByBlock(model->joined.runs, static_cast<int>(n), model->joined.blockRunOffsets, model->joined.blockRuns);
    }

    setIntegrator(*model, s.integrator);

    // auto substeps: as many as the stability limit at the initial state asks, and no fewer than the
    // scene's own
    if (s.autoSubsteps)
        model->substeps = stableSubsteps(stabilityLimit(*model, makeState(*model, scene)), s.integrator, s.timeStep,
                                         s.substeps, static_cast<int>(parameterInfo(Parameter::Substeps).maximum));

    // two sub-steps' worth of speed gained under gravity: what a resting contact picks up between
    // projections, well below any real impact
    model->restingSpeed = 2.0 * s.gravity.norm() * model->subStep();
    return model;
}

void setIntegrator(Model &model, Integrator integrator)
{
    model.integrator = integrator;
    // the Euler schemes fuse the forces and their update on a lattice whose springs reach no
    // further than the next block of particles
    const bool euler = integrator == Integrator::SymplecticEuler || integrator == Integrator::ExplicitEuler;
    model.plan.subStep = euler && model.usesSpringBlocks() ? SubStepPath::FusedLattice : SubStepPath::Stages;
}

}  // namespace core
