#pragma once
// Model: a SceneDesc compiled for stepping. Structure-of-arrays, immutable once built, shared
// between threads as std::shared_ptr<const Model>. The step plan says which passes this scene
// needs; a pass the plan leaves out is never run.

#include "core/contacts/cloth_surface.h"
#include "core/meshes/embedded_surface.h"
#include "core/contacts/colliders.h"
#include "core/model/scene.h"
#include "core/springs/spring_layout.h"
#include "core/springs/spring_triangles.h"
#include "core/integrators/xpbd_layout.h"

#include <Eigen/Core>
#include <memory>
#include <vector>

namespace core {

struct State;

// a solid sphere's moment of inertia over m r²
inline constexpr double kSolidSphereInertia = 0.4;

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
    // switched on, a sheet's triangle, and something free: particles and sheet edges against the
    // sheets' triangles (triangle_collisions.cpp)
    bool triangleCollisions = false;
    // the contacts go through the iterative solver (contacts.cpp) rather than the handout's passes:
    // its choice, and a contact pass planned
    bool contactSolver = false;
    // the iterative solver and a two-sided plane or rectangle: the resting solve keeps each
    // particle on the side of it where the impacts left it (ContactScratch::sidePosition)
    bool twoSidedColliders = false;
    // the particles turn (State::angularVelocity, orientation): a contact (a sheet's triangles
    // included) can have friction, rolling resistance or spinning friction, or a particle is given
    // a spin. Without it a contact acts at the centre and nothing turns, as in the handout
    bool spin = false;
    SubStepPath subStep = SubStepPath::Stages;

    bool operator==(const StepPlan &) const = default;
};

struct Model {
    // settings
    double timeStep = 0.01;  // s
    int substeps = 1;
    int xpbdIterations = 1;  // xpbd's passes over the springs a sub-step
    int solverIterations = 10;  // projective's and vbd's iterations a sub-step
    Integrator integrator = Integrator::SymplecticEuler;
    double tolerance = 1e-6;  // adaptive-rk45's error target per step
    Eigen::Vector3d gravity = Eigen::Vector3d::Zero();  // m/s²
    double viscosity = 0.0;                             // kg/s
    double restitution = 1.0;
    // m/s: contacts approaching slower than this are inelastic, so that a particle resting under
    // gravity settles instead of hopping (see docs/physics.md); 0 without gravity
    double restingSpeed = 0.0;
    ContactSolver contactSolver = ContactSolver::Iterative;
    double friction = 0.0;        // μk of particle pairs
    double staticFriction = 0.0;  // μs of particle pairs
    double rollingFriction = 0.0;   // μr of particle pairs
    double spinningFriction = 0.0;  // about the normal, of particle pairs

    // particles; a pinned particle has inverse mass 0 (infinite mass)
    Eigen::VectorXd mass;     // kg
    Eigen::VectorXd invMass;  // 1/kg, 0 when pinned
    Eigen::VectorXd radius;   // m
    // 1/(kg m²), a solid sphere's 1 / (2/5 m r²); 0 when pinned or of no radius. Set while the
    // plan has spin
    Eigen::VectorXd invInertia;
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
    // the same list as the vectorised kernels walk it, and the spring pass it takes
    SpringLayout springLayout;
    // for xpbd, set only while it is the integrator: the order it projects the springs in, and their
    // data in that order (xpbd_layout.h)
    XpbdLayout xpbdLayout;
    // for vbd, set only while it is the integrator: the particles in colour order, no two of a colour
    // joined by a spring, colour c's being vbdOrder[vbdColours[c] .. vbdColours[c + 1]) (vbd.cpp)
    std::vector<int> vbdOrder;
    std::vector<int> vbdColours;
    // the spring mesh's triangles, for drawing it as a sheet (spring_triangles.h); found once, here,
    // and shared by every snapshot of the model
    std::shared_ptr<const SpringTriangles> triangles;
    // the triangles that collide, in sheets with their thickness (cloth_surface.h); set while the
    // plan has triangle collisions
    std::shared_ptr<const ClothSurface> surface;
    // the soft bodies' imported surfaces, carried by their lattices, for drawing them shaded
    // (embedded_surface.h); null when the scene has none
    std::shared_ptr<const EmbeddedSurface> embedded;

    // planes n·p = offset, unit normals
    Eigen::Matrix3Xd planeNormal;
    Eigen::VectorXd planeOffset;  // m
    // the same planes as the iterative contact solver reads them: sides, bounds and friction
    std::vector<Collider> colliders;

    StepPlan plan;

    int particleCount() const { return static_cast<int>(mass.size()); }
    int springCount() const { return static_cast<int>(springA.size()); }
    int planeCount() const { return static_cast<int>(planeOffset.size()); }
    bool isPinned(int particle) const { return invMass[particle] == 0.0; }
    double subStep() const { return timeStep / substeps; }
};

// compiles a scene that findProblem() accepts (asserted in debug builds); `before`, the model of
// the same scene before an edit, lends its triangles when the edit left every spring's ends as
// they were (finding them is most of the cost of compiling a large cloth)
std::shared_ptr<const Model> compileModel(const SceneDesc &scene, const Model *before = nullptr);

// the model's integrator, and the sub-step path the plan takes with it
void setIntegrator(Model &model, Integrator integrator);

// auto substeps count from the scene's initial state; a run carried on from another state (the
// editor after a blow-up, its stretched springs vibrating faster) may need more. The model with at
// least as many as that state asks too, or the same model when it has enough.
std::shared_ptr<const Model> autoSubstepsAlsoFor(const std::shared_ptr<const Model> &model, const SceneDesc &scene,
                                                 const State &state);

}  // namespace core
