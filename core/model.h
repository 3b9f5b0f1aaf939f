#pragma once
// Model: a SceneDesc compiled for stepping. Structure-of-arrays, immutable once built, shared
// between threads as std::shared_ptr<const Model>. The step plan says which passes this scene
// needs; a pass the plan leaves out is never run.

#include "scene.h"

#include <Eigen/Core>
#include <memory>
#include <vector>

namespace core {

// how a sub-step forces and integrates (step.cpp branches on it)
enum class SubStepPath {
    Stages,        // the force passes one after another, inside the model's integrator
    FusedLattice,  // symplectic or explicit Euler on a lattice: forces and update fused, block by
                   // block (spring_blocks.cpp), the same bits as Stages
};

// which passes of the step this scene needs, and the path its sub-step takes
struct StepPlan {
    bool gravity = false;             // g != 0 and something free to fall
    bool drag = false;                // viscosity > 0 and something free
    bool springs = false;             // at least one spring
    bool planeCollisions = false;     // switched on, a plane, and something free
    bool particleCollisions = false;  // switched on, two particles, one of them free
    bool springBreaks = false;        // a spring with a breaking strain
    SubStepPath subStep = SubStepPath::Stages;

    bool operator==(const StepPlan &) const = default;
};

// particles per block of the fused lattice sub-step (spring_blocks.cpp): a block's forces and its
// positions and velocities with the springs' reach either side stay in the L2 cache (786 KB for a
// 1024 × 1024 cloth, whose bend springs reach 2048 particles). A spring with its ends in two blocks
// is computed for each, so a larger block computes fewer twice: 8192 was 10-20% faster than 4096
// on the 1024 × 1024 cloth and no slower on the smaller ones (docs/benchmarks.md)
inline constexpr int kSpringBlock = 8192;
// Model::joined: runs this short are worth joining, across gaps of at most this many particles
inline constexpr int kJoinRunsBelow = 128;
inline constexpr int kJoinGap = 8;

struct Model {
    // settings
    double timeStep = 0.01;  // s
    int substeps = 1;
    Integrator integrator = Integrator::SymplecticEuler;
    double tolerance = 1e-6;  // adaptive-rk45's error target per step
    Eigen::Vector3d gravity = Eigen::Vector3d::Zero();  // m/s²
    double viscosity = 0.0;                             // kg/s
    double restitution = 1.0;
    // m/s: contacts approaching slower than this are inelastic, so that a particle resting under
    // gravity settles instead of hopping (see docs/physics.md); 0 without gravity
    double restingSpeed = 0.0;

    // particles; a pinned particle has inverse mass 0 (infinite mass)
    Eigen::VectorXd mass;     // kg
    Eigen::VectorXd invMass;  // 1/kg, 0 when pinned
    Eigen::VectorXd radius;   // m
    std::vector<int> freeParticles;  // indices of the particles that are not pinned, ascending
    // the same as stretches of consecutive indices, [freeRanges[2 r], freeRanges[2 r + 1]): the
    // integrators' loops read and write them with unit stride
    std::vector<int> freeRanges;

    // springs
    std::vector<int> springA;
    std::vector<int> springB;
    Eigen::VectorXd restLength;  // m
    Eigen::VectorXd stiffness;   // N/m
    Eigen::VectorXd damping;     // N·s/m
    Eigen::VectorXd breakStrain;  // (l - l0) / l0 past which the spring breaks; 0: never
    // each particle's springs, for gathering their forces: particle i's are
    // springEnds[springOffsets[i] .. springOffsets[i + 1]), ascending, each 2 k for spring k's end a
    // and 2 k + 1 for its end b
    std::vector<int> springOffsets;
    std::vector<int> springEnds;
    // the spring list cut into runs of consecutive springs whose two ends both step by one
    // particle from one spring to the next, as a lattice's springs do when they are made row by
    // row: a run's springs are (a + j, b + j), j = 0 … count - 1, springs first + j. Over a run
    // the ends are read and the forces added with unit stride, with no gathers. The spring pass
    // takes that road when the runs are long (usesSpringRuns()).
    struct SpringRun {
        int first = 0;  // the run's first spring
        int count = 0;
        int a = 0;      // end a of its first spring
        int b = 0;      // end b of its first spring
        // every spring of the run has the first's rest length, stiffness and damping: the kernels
        // read them once, not once a spring (a cloth's run is one kind of spring)
        bool uniform = false;
    };
    std::vector<SpringRun> springRuns;
    // the farthest apart the two ends of a run lie in the numbering, max |b - a|: how far past a
    // block of particles its springs reach
    int springReach = 0;
    // the runs with an end in each block of kSpringBlock particles, ascending: block q's are
    // blockRuns[blockRunOffsets[q] .. blockRunOffsets[q + 1]). Made only for models that use the
    // blocks (usesSpringBlocks())
    std::vector<int> blockRunOffsets;
    std::vector<int> blockRuns;
    // The runs once more for the fused sub-step, short ones joined: runs shorter than
    // kJoinRunsBelow with the same offset b - a that follow each other in the list, each starting a
    // few particles (at most kJoinGap) past the last one's end, become one run. The particles in
    // between are ends of padding springs with no rest length, stiffness or damping, whose force is
    // exactly zero, and a force sum never is -0 (it starts at 0 + m g), so adding the padding's ±0
    // changes no bit. A 64 × 64 cloth's rows of 63 springs become a run of 4095, which the kernels
    // take in full vectors instead of a remainder and a dozen calls a row. A joined run's `first`
    // indexes the three arrays here, one value per spring of the run, padding included. The
    // broken flags are the state's, one per spring of the list, so a state with flags steps by
    // springRuns; so does a model whose springs can break, which has none. Empty where no run was
    // joined.
    struct JoinedRuns {
        std::vector<SpringRun> runs;
        Eigen::VectorXd restLength;  // m
        Eigen::VectorXd stiffness;   // N/m
        Eigen::VectorXd damping;     // N·s/m
        std::vector<int> blockRunOffsets;  // as blockRunOffsets and blockRuns, for these runs
        std::vector<int> blockRuns;
    };
    JoinedRuns joined;

    // planes n·p = offset, unit normals
    Eigen::Matrix3Xd planeNormal;
    Eigen::VectorXd planeOffset;  // m

    StepPlan plan;

    int particleCount() const { return static_cast<int>(mass.size()); }
    int springCount() const { return static_cast<int>(springA.size()); }
    int planeCount() const { return static_cast<int>(planeOffset.size()); }
    // runs of 8 springs or more on average: shorter ones cost more in bookkeeping than they save
    bool usesSpringRuns() const { return !springRuns.empty() && springCount() >= 8 * static_cast<int>(springRuns.size()); }
    // the Euler schemes step such a model a block of particles at a time, forces and update fused
    // (spring_blocks.cpp): its springs must not reach past the next block
    bool usesSpringBlocks() const { return plan.springs && usesSpringRuns() && springReach <= kSpringBlock; }
    bool isPinned(int particle) const { return invMass[particle] == 0.0; }
    double subStep() const { return timeStep / substeps; }
};

// compiles a scene that findProblem() accepts (asserted in debug builds)
std::shared_ptr<const Model> compileModel(const SceneDesc &scene);

// the model's integrator, and the sub-step path the plan takes with it
void setIntegrator(Model &model, Integrator integrator);

}  // namespace core
