#pragma once
// SceneDesc: plain values, exactly what a scene file holds. The GUI thread owns it; the physics
// compiles it into a Model (model.h) and a State (state.h).

#include "core/integrators/integrator.h"

#include <Eigen/Core>
#include <array>
#include <optional>
#include <string>
#include <vector>

namespace core {

// how contacts are resolved (docs/physics.md, "Contacts")
enum class ContactSolver {
    Iterative,  // the default: impacts located in time along swept paths, then an iterative solve of
                // the resting contacts with Coulomb friction
    Handout,    // the course handout's single pass: a projection and an impulse per pair, once
};

struct Settings {
    double timeStep = 0.01;  // s, one step of the simulation clock
    int substeps = 1;        // each step is split into this many equal sub-steps
    // substeps is then the least: raised when compiled to keep each sub-step inside the explicit
    // integrators' stability limit (stability.h), as stiffness and mass change
    bool autoSubsteps = false;
    Integrator integrator = Integrator::SymplecticEuler;
    int xpbdIterations = 1;  // xpbd's passes over the springs in each sub-step (the others ignore it)
    // projective and vbd: iterations of their implicit Euler solve in each sub-step (the others ignore it)
    int solverIterations = 10;
    double tolerance = 1e-6;  // m and m/s, the local error per step adaptive-rk45 aims for
    // adaptive-rk45: the step size a run saved from was about to try (s), so that the run resumed
    // from its file goes on as it would have; unset, the first step chooses (State::adaptiveStep)
    std::optional<double> adaptiveStep{};
    Eigen::Vector3d gravity{0.0, -9.81, 0.0};  // m/s², y is up
    double viscosity = 0.0;                    // kg/s, drag force -c v on every particle
    double restitution = 1.0;                  // 1 elastic .. 0 fully inelastic, for every contact
    ContactSolver contactSolver = ContactSolver::Iterative;
    double friction = 0.0;  // kinetic Coulomb coefficient μk of every contact (a plane may override it)
    // static coefficient μs: a contact sticks while its friction stays within μs times its normal
    // force; unset, it equals friction
    std::optional<double> staticFriction{};
    // rolling resistance μr: a contact's torque against rolling is at most μr times its normal
    // force times the radius (a force μr N at the centre, as a rolling tyre's); spinning friction
    // likewise about the contact's normal. A plane may override either
    double rollingFriction = 0.0;
    double spinningFriction = 0.0;
    // the balls turn: contacts act at their surfaces, so that friction makes them roll
    // (docs/physics.md, "Spin and rolling"); off, contacts act at the centres and nothing turns, as in
    // the handout and as the stacking benchmarks measure
    bool spin = true;
    bool planeCollisions = true;
    bool particleCollisions = true;
    // the sheets' triangles (SceneDesc::triangles, or those the springs span) as surfaces that
    // particles and other sheets collide with (docs/physics.md, "Triangle collisions"); off unless
    // asked for while the pass costs several times the rest of a cloth's sub-step
    bool triangleCollisions = false;
    // a sheet collides with itself too (two sheets always collide with each other)
    bool selfCollision = true;
    // m, how far apart two sheets stay; 0: each sheet's own, from its particles' radii
    double thickness = 0.0;

    bool operator==(const Settings &) const = default;
};

struct ParticleDesc {
    Eigen::Vector3d position = Eigen::Vector3d::Zero();  // m
    Eigen::Vector3d velocity = Eigen::Vector3d::Zero();  // m/s (a pinned particle is at rest)
    double mass = 1.0;                                   // kg, > 0
    double radius = 0.1;                                 // m, > 0
    bool pinned = false;                                 // infinite mass: never moves
    // rad/s, its spin (a pinned particle keeps the spin it is given: a turning wheel)
    Eigen::Vector3d angularVelocity = Eigen::Vector3d::Zero();
    // its orientation, a unit quaternion (w, x, y, z): what turns the pattern drawn on it
    Eigen::Vector4d orientation{1.0, 0.0, 0.0, 0.0};

    bool operator==(const ParticleDesc &) const = default;
};

struct SpringDesc {
    int a = 0;                // particle indices, a != b
    int b = 0;
    double stiffness = 0.0;   // N/m, k
    double damping = 0.0;     // N·s/m, kc
    double restLength = 0.0;  // m, l0
    // the strain (l - l0) / l0 past which the spring breaks for good during a run; 0: never
    double breakStrain = 0.0;

    bool operator==(const SpringDesc &) const = default;
};

// the plane n·p = offset; particles live on the side n points to, or on both when it is two-sided.
// With a size it is a rectangle of that plane instead (always two-sided: a thin sheet with edges)
struct PlaneDesc {
    Eigen::Vector3d normal{0.0, 1.0, 0.0};  // unit length once loaded
    double offset = 0.0;                    // m
    bool twoSided = false;
    // this plane's Coulomb coefficient, static and kinetic alike; unset: the settings'
    std::optional<double> friction{};
    // m, the rectangle's width along `axis` and height along normal × axis; zero: the whole plane
    Eigen::Vector2d size = Eigen::Vector2d::Zero();
    // m, the rectangle's centre is the point of the plane nearest this
    Eigen::Vector3d centre = Eigen::Vector3d::Zero();
    // the direction of the width, projected onto the plane; zero (or along the normal): the
    // direction the viewport uses, normal × y (normal × x when the normal is near y)
    Eigen::Vector3d axis = Eigen::Vector3d::Zero();
    // this plane's rolling resistance and spinning friction; unset: the settings'
    std::optional<double> rollingFriction{};
    std::optional<double> spinningFriction{};

    bool bounded() const { return size[0] > 0.0 && size[1] > 0.0; }

    bool operator==(const PlaneDesc &) const = default;
};

// a contact's impulses at the end of a sub-step, where the iterative contact solver starts the next
// sub-step's iterations ("warm starting"): free particle i with particle j, or with plane -1 - j
// when j < 0. A run carries them in its State, and a state saved as a scene keeps them, so that
// the run resumed from the file goes on as it would have
struct ContactImpulse {
    int i = 0;
    int j = 0;
    double normal = 0.0;                                 // N·s, pushing i away from j
    Eigen::Vector3d friction = Eigen::Vector3d::Zero();  // N·s, on i, along the contact's surface

    bool withPlane() const { return j < 0; }
    int plane() const { return -1 - j; }
    bool operator==(const ContactImpulse &) const = default;
    bool operator<(const ContactImpulse &other) const { return i != other.i ? i < other.i : j < other.j; }
};

// what a mesh brought in from a file became (docs/scene-format.md, "Meshes")
enum class MeshKind {
    Cloth,     // a particle per (welded) vertex, springs along its edges and across its folds
    Soft,      // a lattice of particles filling its inside; the surface rides on the lattice
    Collider,  // pinned particles at its vertices, its triangles a surface others collide with
};

// a surface mesh the scene carries: drawn shaded, and what Export Animation writes. Its vertices
// are those of the file it came from, in the file's order (split vertices included), each a
// weighted sum of particles' positions, so that a point cache of it applies to that very file
struct MeshDesc {
    std::string name;    // shown in the editor and given to exported files
    std::string source;  // the file it was imported from, as given (for the user: never read)
    MeshKind kind = MeshKind::Cloth;
    // vertex v is the sum of weights[k] × the position of particles[k] for k in
    // [offsets[v], offsets[v + 1]): one particle of weight 1 for a cloth's or a collider's vertex,
    // the eight corners of its lattice cell for a soft body's
    std::vector<int> offsets{0};
    std::vector<int> particles;
    std::vector<double> weights;
    std::vector<std::array<int, 3>> faces;  // three vertex indices each, counter-clockwise outside
    // how the file's coordinates were placed in the scene: scene = turn(zUp) (scale × file) + offset,
    // where turn maps a z-up file's (x, y, z) to (x, z, -y); the exports undo it, so that what they
    // write lies where the file's own vertices do
    double scale = 1.0;
    bool zUp = false;
    Eigen::Vector3d offset = Eigen::Vector3d::Zero();

    int vertexCount() const { return static_cast<int>(offsets.size()) - 1; }
    bool operator==(const MeshDesc &) const = default;
};

struct SceneDesc {
    std::string name;
    Settings settings;
    std::vector<ParticleDesc> particles;
    std::vector<SpringDesc> springs;
    std::vector<PlaneDesc> planes;
    int steerable = -1;  // the particle the arrow keys push (the pool's cue ball); -1: none
    std::vector<ContactImpulse> contactImpulses;  // sorted by (i, j); empty in a scene not yet run
    // the triangles of its sheets, three particle indices each, for drawing and for the triangle
    // collisions; empty: those its springs span (core/contacts/cloth_surface.h, sceneTriangles)
    std::vector<std::array<int, 3>> triangles;
    std::vector<MeshDesc> meshes;  // the surfaces imported from mesh files

    bool operator==(const SceneDesc &) const = default;
};

}  // namespace core
