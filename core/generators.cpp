#include "generators.h"

namespace core {

void addSpring(SceneDesc &scene, int a, int b, double stiffness, double damping)
{
    const double rest = (scene.particles[static_cast<std::size_t>(a)].position -
                         scene.particles[static_cast<std::size_t>(b)].position)
                            .norm();
    scene.springs.push_back(SpringDesc{a, b, stiffness, damping, rest});
}

namespace {

// particles of a rows × cols grid in the plane y = height, centred on the y axis; index r * cols + c
void addGrid(SceneDesc &scene, int rows, int cols, double spacing, double height, double mass, double radius)
{
    const double x0 = -0.5 * spacing * (cols - 1);
    const double z0 = -0.5 * spacing * (rows - 1);
    for (int r = 0; r < rows; ++r)
        for (int c = 0; c < cols; ++c)
            scene.particles.push_back(ParticleDesc{
                Eigen::Vector3d(x0 + spacing * c, height, z0 + spacing * r), Eigen::Vector3d::Zero(), mass, radius,
                false});
}

// joins (r, c) to (r + dr, c + dc) for every grid point where both exist
void joinGrid(SceneDesc &scene, int rows, int cols, int dr, int dc, double stiffness, double damping)
{
    for (int r = 0; r < rows; ++r)
        for (int c = 0; c < cols; ++c) {
            const int r2 = r + dr;
            const int c2 = c + dc;
            if (r2 < 0 || r2 >= rows || c2 < 0 || c2 >= cols)
                continue;
            addSpring(scene, r * cols + c, r2 * cols + c2, stiffness, damping);
        }
}

}  // namespace

SceneDesc makeNet(const NetOptions &o)
{
    SceneDesc scene;
    scene.name = "net";
    addGrid(scene, o.rows, o.cols, o.spacing, o.height, o.mass, o.radius);
    joinGrid(scene, o.rows, o.cols, 0, 1, o.stiffness, o.damping);
    joinGrid(scene, o.rows, o.cols, 1, 0, o.stiffness, o.damping);
    if (o.pinEdges)
        for (int c = 0; c < o.cols; ++c) {
            scene.particles[static_cast<std::size_t>(c)].pinned = true;
            scene.particles[static_cast<std::size_t>((o.rows - 1) * o.cols + c)].pinned = true;
        }
    return scene;
}

SceneDesc makeCloth(const ClothOptions &o)
{
    SceneDesc scene;
    scene.name = "cloth";
    scene.settings.substeps = o.substeps;
    addGrid(scene, o.rows, o.cols, o.spacing, o.height, o.mass, o.radius);
    // structural, then shear (both diagonals), then bend (every second neighbour)
    joinGrid(scene, o.rows, o.cols, 0, 1, o.structuralStiffness, o.damping);
    joinGrid(scene, o.rows, o.cols, 1, 0, o.structuralStiffness, o.damping);
    joinGrid(scene, o.rows, o.cols, 1, 1, o.shearStiffness, o.damping);
    joinGrid(scene, o.rows, o.cols, 1, -1, o.shearStiffness, o.damping);
    joinGrid(scene, o.rows, o.cols, 0, 2, o.bendStiffness, o.damping);
    joinGrid(scene, o.rows, o.cols, 2, 0, o.bendStiffness, o.damping);
    if (o.pinCorners) {
        scene.particles.front().pinned = true;
        scene.particles[static_cast<std::size_t>(o.cols - 1)].pinned = true;
    }
    return scene;
}

SceneDesc makeChain(const ChainOptions &o)
{
    SceneDesc scene;
    scene.name = "chain";
    for (int i = 0; i <= o.links; ++i)
        scene.particles.push_back(ParticleDesc{Eigen::Vector3d(o.linkLength * i, o.height, 0.0),
                                               Eigen::Vector3d::Zero(), o.mass, o.radius, i == 0});
    for (int i = 0; i < o.links; ++i)
        addSpring(scene, i, i + 1, o.stiffness, o.damping);
    return scene;
}

}  // namespace core
