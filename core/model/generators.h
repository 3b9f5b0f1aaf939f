#pragma once
// Scene generators: functions that build a SceneDesc, shared by the examples, the editor's
// Generate menu, the tests and the benchmarks.

#include "core/model/scene.h"

#include <cstdint>
#include <optional>
#include <string>

namespace core {

// the most particles one generator may make: enough for a 447 × 447 cloth, few enough that the
// editor's undo history and the software-GL viewport stay usable
constexpr int kMaxGeneratedParticles = 200000;

// a rows × cols net of particles in the horizontal plane y = height, neighbours joined by springs
// of rest length `spacing`; the first and last rows pinned (the handout's springs scene)
struct NetOptions {
    int rows = 11;
    int cols = 11;
    double spacing = 0.4;     // m
    double height = 0.0;      // m
    double mass = 10.0;       // kg
    double radius = 0.1;      // m
    double stiffness = 4e3;   // N/m
    double damping = 0.0;     // N·s/m
    bool pinEdges = true;     // pin the rows i = 0 and i = rows - 1
};
SceneDesc makeNet(const NetOptions &options);

// a cloth: an n × m sheet in the horizontal plane y = height with structural (neighbour), shear
// (diagonal) and bend (second neighbour) springs, pinned at the two corners of its first row; with
// sheetCollisions, its cells' triangles listed (two a cell) and triangle collisions on
struct ClothOptions {
    int rows = 32;
    int cols = 32;
    double spacing = 0.05;                // m
    double height = 1.0;                  // m
    double mass = 0.005;                  // kg per particle
    double radius = 0.02;                 // m
    double structuralStiffness = 3000.0;  // N/m
    double shearStiffness = 600.0;        // N/m
    double bendStiffness = 100.0;         // N/m
    double damping = 0.02;                // N·s/m, every spring
    bool pinCorners = true;
    // m, how far apart the sheet keeps from itself and others (0: from the radius and spacing), and
    // whether it collides with itself (Settings::thickness, Settings::selfCollision)
    double thickness = 0.0;
    bool selfCollision = true;
    // the sheet collides as a surface (Settings::triangleCollisions), its cells' triangles listed
    bool sheetCollisions = false;
    // sub-steps per step of the default 0.01 s: keeps ω h under symplectic Euler's limit of 2
    // (Gershgorin: ω² ≤ 2 Σk / m ≈ 5.9e6 s⁻², so h = 5e-4 s gives ω h ≤ 1.2)
    int substeps = 20;
};
SceneDesc makeCloth(const ClothOptions &options);

// a chain of `links` springs hanging from a pinned first particle, laid out along +x at height y
struct ChainOptions {
    int links = 10;
    double linkLength = 0.1;  // m
    double height = 1.0;      // m
    double mass = 0.1;        // kg per particle
    double radius = 0.02;     // m
    double stiffness = 1e3;   // N/m
    double damping = 0.1;     // N·s/m
    bool pinFirst = true;     // hang it from its first particle
};
SceneDesc makeChain(const ChainOptions &options);

// a rope: a chain whose particles touch (radius = half a link), so that it reads as one cord and
// nothing passes between its links; laid out along +x at height y, its substeps set by its springs
struct RopeOptions {
    double length = 1.0;      // m, first particle to last
    int segments = 40;        // springs along it (segments + 1 particles)
    double height = 1.0;      // m
    double mass = 0.005;      // kg per particle
    double stiffness = 2000;  // N/m, each segment
    double damping = 0.02;    // N·s/m
    bool pinFirst = true;
};
SceneDesc makeRope(const RopeOptions &options);

// granular matter: a block of nx × ny × nz loose particles (no springs) on a cubic lattice,
// centred on the y axis with its lowest layer at y = height. jitter > 0 moves each particle by up
// to jitter along each axis, drawn from seed, so that a pile does not stack perfectly; the same
// seed gives the same block
struct BlockOptions {
    int nx = 6;
    int ny = 6;
    int nz = 6;
    double spacing = 0.1;   // m, between lattice points
    double height = 0.5;    // m
    double mass = 0.05;     // kg per particle
    double radius = 0.045;  // m
    double jitter = 0.004;  // m, at most spacing / 2 - radius so that no two particles overlap
    std::uint64_t seed = 1;
};
SceneDesc makeBlock(const BlockOptions &options);

// granular matter: the points of a cubic lattice inside a sphere of radius ballRadius centred at
// (0, height, 0), as loose particles; jitter and seed as for the block
struct BallOptions {
    double ballRadius = 0.3;  // m
    double spacing = 0.1;     // m
    double height = 1.0;      // m
    double mass = 0.05;       // kg per particle
    double radius = 0.045;    // m
    double jitter = 0.004;    // m
    std::uint64_t seed = 1;
};
SceneDesc makeBall(const BallOptions &options);

// a soft ball: `points` particles spread evenly over a sphere (a Fibonacci lattice), each joined
// by springs to its neighbours on the surface (those closer than 1.5 × the mean spacing
// √(4π/points) × ballRadius), and, optionally, every one to a particle at the centre. Rest
// lengths are the distances, so it starts at rest; its substeps are set by its springs. Its
// surface, the hull of the points wound outwards, is listed as its triangles (for drawing; the
// scene's sheet collisions stay as they are).
struct SoftBallOptions {
    int points = 120;
    double ballRadius = 0.25;        // m
    double height = 1.0;             // m, of the centre
    double mass = 0.02;              // kg per particle
    double radius = 0.025;           // m
    // stiff enough that a drop of a few metres onto a floor dents it and no more (at 200 and 100
    // N/m a 2 m drop crumpled the shell into a cone that stayed one)
    double stiffness = 1000.0;       // N/m, the surface springs
    double damping = 0.05;           // N·s/m, every spring
    bool centre = true;              // add a centre particle joined to every surface particle
    double centreStiffness = 1000.0;  // N/m, the springs to the centre
};
SceneDesc makeSoftBall(const SoftBallOptions &options);
// the most points a soft ball may have: its neighbour search grows as points^1.5
constexpr int kMaxSoftBallPoints = 20000;

// what is wrong with a generator's options, as a sentence naming the option, e.g. "rows must be at
// least 2 (got 0)"; nullopt when they make a valid scene (core::findProblem finds nothing) of at
// most kMaxGeneratedParticles particles whose particles do not overlap
std::optional<std::string> checkOptions(const ClothOptions &options);
std::optional<std::string> checkOptions(const ChainOptions &options);
std::optional<std::string> checkOptions(const RopeOptions &options);
std::optional<std::string> checkOptions(const BlockOptions &options);
std::optional<std::string> checkOptions(const BallOptions &options);
std::optional<std::string> checkOptions(const SoftBallOptions &options);

// balls of one radius and mass resting on each other on the floor y = 0, touching, at rest: a
// column of `count` straight up from `foot`, or a pyramid on a base of `base` in the plane through
// `foot` parallel to z = 0, each row in the hollows of the row below (r across, √3 r up), its first
// ball at `foot`
std::vector<ParticleDesc> ballColumn(int count, double radius, double mass, const Eigen::Vector3d &foot);
std::vector<ParticleDesc> ballPyramid(int base, double radius, double mass, const Eigen::Vector3d &foot);

// a floor: the plane y = height, its normal up
PlaneDesc floorPlane(double height = 0.0);
// the walls of a closed box, normals pointing in: the floor y = 0, the ceiling y = height and the
// four sides at x, z = ±halfWidth, in that order
std::vector<PlaneDesc> boxPlanes(double halfWidth, double height);

// joins particles a and b with a spring whose rest length is their current distance
void addSpring(SceneDesc &scene, int a, int b, double stiffness, double damping);

}  // namespace core
