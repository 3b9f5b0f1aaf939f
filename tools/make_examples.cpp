// Writes the example scenes of resources/scenes/ from the scene generators and the handout's
// parameters, and those made of the models in resources/meshes/ (tools/mesh_examples.h). Run it
// after changing a generator or the import: tools/make_examples resources/scenes
#include "core/model/generators.h"
#include "tools/mesh_examples.h"
#include "tools/scene_writer.h"

#include <QDir>
#include <cstdio>

#include <cmath>
#include <vector>

namespace {

using core::ParticleDesc;
using core::PlaneDesc;
using Eigen::Vector3d;

// the tearable cloth's springs break at this strain, (l - l0) / l0; its ball's mass, kg
constexpr double kTearStrain = 0.15;
constexpr double kBallMass = 4.0;

// the handout's first scene: two particles under gravity, no contacts, a fine time step
core::SceneDesc particlesScene()
{
    core::SceneDesc scene;
    scene.name = "particles";
    scene.settings.timeStep = 5e-4;
    scene.settings.planeCollisions = false;
    scene.settings.particleCollisions = false;
    scene.particles = {ParticleDesc{Vector3d(-1.0, 1.0, 0.0), Vector3d(3.0, 0.0, 0.0), 1.0, 0.1, false},
                       ParticleDesc{Vector3d(1.0, 2.0, 0.0), Vector3d(0.0, 0.0, 0.0), 2.0, 0.15, false}};
    return scene;
}

// the handout's net: 11 × 11 particles, two opposite edges pinned
core::SceneDesc springsScene()
{
    core::SceneDesc scene = core::makeNet({});
    scene.name = "springs";
    return scene;
}

// a floor, a heavy pinned particle, one resting on the floor and one falling onto the pinned one
core::SceneDesc collisionsScene()
{
    core::SceneDesc scene;
    scene.name = "collisions";
    scene.settings.restitution = 1.0;
    scene.particles = {ParticleDesc{Vector3d(0.0, 1.0, 0.0), Vector3d::Zero(), 100.0, 0.3, true},
                       ParticleDesc{Vector3d(1.2, 0.2, 0.0), Vector3d::Zero(), 1.0, 0.2, false},
                       ParticleDesc{Vector3d(0.1, 3.0, 0.0), Vector3d::Zero(), 1.0, 0.2, false}};
    scene.planes = {core::floorPlane()};
    return scene;
}

// a pool table: the felt (μ = 0.2, its rolling resistance as given) and four frictionless
// cushions around the playing area, 2 halfLength along x by 2 halfWidth along z
std::vector<PlaneDesc> poolTable(double halfLength, double halfWidth, double feltRolling)
{
    PlaneDesc felt{Vector3d(0.0, 1.0, 0.0), 0.0};
    felt.friction = 0.2;
    if (feltRolling > 0.0)
        felt.rollingFriction = feltRolling;
    std::vector<PlaneDesc> planes{felt,
                                  PlaneDesc{Vector3d(1.0, 0.0, 0.0), -halfLength},
                                  PlaneDesc{Vector3d(-1.0, 0.0, 0.0), -halfLength},
                                  PlaneDesc{Vector3d(0.0, 0.0, 1.0), -halfWidth},
                                  PlaneDesc{Vector3d(0.0, 0.0, -1.0), -halfWidth}};
    for (std::size_t k = 1; k < planes.size(); ++k)
        planes[k].friction = 0.0;
    return planes;
}

// the handout's pool: a 10 × 10 table with four cushions and two balls; the first is steered with
// the arrow keys (two presses overcome the felt). The felt is the floor's friction, μ = 0.2: a ball
// slides to a stop within a second or two instead of coasting forever; the cushions have none
core::SceneDesc poolScene()
{
    core::SceneDesc scene;
    scene.name = "pool";
    scene.settings.restitution = 0.9;
    scene.particles = {ParticleDesc{Vector3d(-2.0, 0.5, 0.0), Vector3d::Zero(), 1.0, 0.5, false},
                       ParticleDesc{Vector3d(2.0, 0.5, 0.5), Vector3d::Zero(), 1.0, 0.5, false}};
    scene.planes = poolTable(5.0, 5.0, 0.0);
    scene.steerable = 0;
    return scene;
}

// a pool break on felt, at a real table's sizes: the playing area of a 9-foot table (2.54 × 1.27 m)
// inside four cushions, fifteen balls (57.15 mm, 170 g) racked in a triangle, the cue ball struck
// at 8 m/s from the head string. The felt's friction (μ = 0.2) turns the balls' sliding into
// rolling, its rolling resistance (μr = 0.01) stops them after metres; the balls' own friction is
// small (0.05), the cushions have none. The cue ball is steered with the arrow keys
core::SceneDesc poolBreakScene()
{
    core::SceneDesc scene;
    scene.name = "pool-break";
    scene.settings.restitution = 0.93;
    scene.settings.friction = 0.05;
    scene.settings.substeps = 4;
    const double r = 0.028575, m = 0.17, halfLength = 1.27, halfWidth = 0.635;
    scene.particles.push_back(ParticleDesc{Vector3d(-0.635, r, 0.0), Vector3d(8.0, 0.0, 0.0), m, r, false});
    // the rack: its apex on the foot spot, a hair apart so that the balls start untouched
    const double gap = 2.0 * r + 1e-4;
    for (int row = 0; row < 5; ++row)
        for (int k = 0; k <= row; ++k)
            scene.particles.push_back(ParticleDesc{
                Vector3d(0.635 + row * gap * std::sqrt(3.0) / 2.0, r, (k - 0.5 * row) * gap), Vector3d::Zero(), m, r,
                false});
    scene.planes = poolTable(halfLength, halfWidth, 0.01);
    scene.steerable = 0;
    return scene;
}

// a granular heap: 400 grains (μ = 0.5, e = 0.2) poured from a narrow column onto an open floor
// pile into a cone at their angle of repose
core::SceneDesc heapScene()
{
    core::SceneDesc scene;
    scene.name = "heap";
    // grains, not balls: they do not roll (balls that turn roll apart instead of heaping)
    scene.settings.spin = false;
    scene.settings.substeps = 2;
    scene.settings.restitution = 0.2;
    scene.settings.friction = 0.5;
    constexpr double r = 0.05;  // m
    for (int k = 0; k < 400; ++k) {
        // a 4 × 4 column, each layer turned a little so that the grains do not land on each other's tops
        const double turn = 0.7 * k / 16;
        const double u = 0.11 * (k % 4 - 1.5), w = 0.11 * ((k / 4) % 4 - 1.5);
        const Vector3d at(u * std::cos(turn) - w * std::sin(turn), 0.2 + 0.11 * (k / 16), u * std::sin(turn) + w * std::cos(turn));
        scene.particles.push_back(ParticleDesc{at, Vector3d::Zero(), 0.05, r, false});
    }
    scene.planes = {core::floorPlane()};
    return scene;
}

// stacks that stand: a column of 12 balls and a pyramid on a base of 10 in one plane, μ = 0.5; with
// settings.contactSolver "handout" both collapse
core::SceneDesc stackScene()
{
    core::SceneDesc scene;
    scene.name = "stack";
    // the stacks stand as the contacts benchmark measures them, on balls that do not turn
    scene.settings.spin = false;
    scene.settings.restitution = 0.5;
    scene.settings.friction = 0.5;
    scene.particles = core::ballColumn(12, 0.1, 1.0, Vector3d(-1.5, 0.0, 0.0));
    const std::vector<ParticleDesc> pyramid = core::ballPyramid(10, 0.1, 1.0, Vector3d(-0.3, 0.0, 0.0));
    scene.particles.insert(scene.particles.end(), pyramid.begin(), pyramid.end());
    scene.planes = {core::floorPlane()};
    return scene;
}

// a cloth laid on a table (a 1 m square rectangle at 0.8 m, μ = 0.2) with a third of it over the
// edge: the hanging part drags the rest off, and the sheet falls to the floor
core::SceneDesc clothOnTableScene()
{
    core::ClothOptions options;
    options.rows = 24;
    options.cols = 24;
    options.spacing = 0.05;
    options.height = 0.8 + options.radius;
    options.pinCorners = false;
    options.sheetCollisions = true;  // it folds onto itself as it slides off the table
    core::SceneDesc scene = core::makeCloth(options);
    scene.name = "cloth-on-table";
    scene.settings.particleCollisions = false;  // the sheet collides as a surface instead
    scene.settings.restitution = 0.0;
    PlaneDesc table{Vector3d(0.0, 1.0, 0.0), 0.8};
    table.size = Eigen::Vector2d(1.0, 1.0);
    table.centre = Vector3d(0.8, 0.8, 0.0);
    table.axis = Vector3d(1.0, 0.0, 0.0);
    table.friction = 0.2;
    scene.planes = {table, core::floorPlane()};
    return scene;
}

// a 32 × 32 cloth pinned at two corners, draping onto a floor; it collides as a surface, so a ball
// generated onto it stays on it
core::SceneDesc clothScene()
{
    core::ClothOptions options;
    options.sheetCollisions = true;
    core::SceneDesc scene = core::makeCloth(options);
    scene.settings.particleCollisions = false;  // the sheet collides as a surface instead
    scene.planes = {core::floorPlane(-0.3)};
    return scene;
}

// a 32 × 32 sheet of 1.5 cm beads held upright just off the floor, a little wavy so that it
// buckles, and let fall: it folds onto itself into a heap on the floor and never passes through
// itself (the triangle collisions with self-collision on)
core::SceneDesc clothCrumpleScene()
{
    core::ClothOptions options;
    options.radius = 0.015;
    options.pinCorners = false;
    options.sheetCollisions = true;
    core::SceneDesc scene = core::makeCloth(options);
    scene.name = "cloth-crumple";
    const double half = 0.5 * options.spacing * (options.rows - 1);
    for (ParticleDesc &p : scene.particles) {
        // the sheet's rows stood up along y, its lowest 5 cm off the floor
        const double y = 0.05 + half + p.position.z();
        p.position = Vector3d(p.position.x(), y, 0.02 * std::sin(17.0 * y) + 0.01 * std::sin(23.0 * p.position.x()));
    }
    scene.settings.particleCollisions = false;  // the sheet collides as a surface instead
    scene.settings.friction = 0.3;
    scene.planes = {core::floorPlane()};
    return scene;
}

// a 24 × 24 sheet dropped onto a post of pinned 2 cm balls, thinner than its 5 cm cells: the sheet
// drapes over the post's top instead of falling through around it
core::SceneDesc clothOverPostScene()
{
    core::ClothOptions options;
    options.rows = 24;
    options.cols = 24;
    options.radius = 0.01;
    options.height = 0.75;
    options.pinCorners = false;
    options.sheetCollisions = true;
    core::SceneDesc scene = core::makeCloth(options);
    scene.name = "cloth-over-post";
    // the post: pinned balls stacked 4 cm apart from the floor to 0.6 m, under a cell's middle
    const double offset = 0.5 * options.spacing;
    for (double y = 0.02; y <= 0.6 + 1e-9; y += 0.04)
        scene.particles.push_back(ParticleDesc{Vector3d(offset, y, offset), Vector3d::Zero(), 1.0, 0.02, true});
    scene.settings.particleCollisions = false;  // the sheet collides as a surface instead
    scene.settings.friction = 0.4;
    scene.planes = {core::floorPlane()};
    return scene;
}

// a 24 × 24 sheet held along two opposite edges, its springs breakable, and a heavy ball dropped
// onto its middle: the sheet stretches under the ball until it tears
core::SceneDesc tearableClothScene()
{
    core::ClothOptions options;
    options.rows = 24;
    options.cols = 24;
    options.pinCorners = false;
    options.sheetCollisions = true;  // the ball rests on the sheet, and the torn sheet collides as torn
    core::SceneDesc scene = core::makeCloth(options);
    scene.name = "tearable-cloth";
    for (int c = 0; c < options.cols; ++c) {
        scene.particles[static_cast<std::size_t>(c)].pinned = true;
        scene.particles[static_cast<std::size_t>((options.rows - 1) * options.cols + c)].pinned = true;
    }
    for (core::SpringDesc &spring : scene.springs)
        spring.breakStrain = kTearStrain;
    // the sheet is centred on the y axis: the ball falls onto its middle
    scene.particles.push_back(
        ParticleDesc{Vector3d(0.0, options.height + 0.6, 0.0), Vector3d::Zero(), kBallMass, 0.12, false});
    scene.planes = {core::floorPlane()};
    scene.settings.restitution = 0.3;  // the ball lands where it falls through
    return scene;
}

// a stiff cloth on projective dynamics: 32 × 32, structural springs of 1e6 N/m (a sheet that hardly
// stretches, as fabric does), pinned at two corners and draping onto a floor, at 2 sub-steps of 5
// iterations: its structural springs stay within 0.88% over 3 s at 2.6 ms a step on one core, where
// xpbd at 50 sub-steps took 3.7 ms and let them stretch 2.0% (measured side by side). Symplectic
// Euler would need sub-steps under 1e-4 s
core::SceneDesc stiffClothScene()
{
    core::ClothOptions options;
    options.rows = 32;
    options.cols = 32;
    options.spacing = 0.045;
    options.structuralStiffness = 1e6;
    options.shearStiffness = 2e5;
    options.bendStiffness = 3e4;
    options.damping = 2.0;
    options.substeps = 2;
    core::SceneDesc scene = core::makeCloth(options);
    scene.name = "stiff-cloth";
    scene.settings.integrator = core::Integrator::Projective;
    scene.settings.solverIterations = 5;
    scene.settings.particleCollisions = false;  // no self contacts: the sheet does not fold onto itself here
    scene.planes = {core::floorPlane(-0.3)};
    return scene;
}

// a chain of 1000 links of 1 cm at 1e8 N/m, released horizontally from its pinned end: it swings
// as a nearly inextensible rope in real time on xpbd at 100 sub-steps, where symplectic Euler needs
// sub-steps under 1/√(2k/m) ≈ 2e-6 s. It stays on xpbd: projective at 5 sub-steps holds its links
// within 0.06% (xpbd 1.6%) for the same cost, but gains energy where the chain strikes the floor
// (test_stiff_solvers stiffChainOnTheFloorGainsNoEnergy)
core::SceneDesc stiffChainScene()
{
    core::ChainOptions options;
    options.links = 1000;
    options.linkLength = 0.01;
    options.mass = 0.001;
    options.radius = 0.005;
    options.stiffness = 1e8;
    options.damping = 1.0;
    options.height = 1.5;
    core::SceneDesc scene = core::makeChain(options);
    scene.name = "stiff-chain";
    scene.settings.integrator = core::Integrator::Xpbd;
    scene.settings.substeps = 100;
    scene.settings.particleCollisions = false;
    scene.planes = {core::floorPlane()};
    return scene;
}

}  // namespace

int main(int argc, char **argv)
{
    std::vector<core::SceneDesc> scenes{particlesScene(),   springsScene(),      collisionsScene(),    poolScene(),
                                        clothScene(),       tearableClothScene(), heapScene(),          stackScene(),
                                        clothOnTableScene(), stiffClothScene(),  stiffChainScene(),    clothCrumpleScene(),
                                        clothOverPostScene(), poolBreakScene()};
    if (argc == 2) {
        // the models are in resources/meshes/, beside the scenes' folder
        QString error;
        const std::vector<core::SceneDesc> meshes =
            tools::meshExamples(QDir(QString::fromLocal8Bit(argv[1])).filePath(QStringLiteral("../meshes")), &error);
        if (meshes.empty()) {
            std::fprintf(stderr, "%s\n", qPrintable(error));
            return 1;
        }
        scenes.insert(scenes.end(), meshes.begin(), meshes.end());
    }
    return tools::writeScenes(argc, argv, scenes);
}
