#include "core/model/generators.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>

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

// joins (r, c) to (r + dr, c + dc) for every grid point where both exist, at rest at the grid's
// distance: every spring of one kind has the same rest length to the bit (the distances of the
// particles' coordinates differ in the last bits), so that the spring pass reads one value for
// all of them (Model::SpringRun::uniform)
void joinGrid(SceneDesc &scene, int rows, int cols, double spacing, int dr, int dc, double stiffness, double damping)
{
    const double rest = spacing * std::sqrt(static_cast<double>(dr * dr + dc * dc));
    for (int r = 0; r < rows; ++r)
        for (int c = 0; c < cols; ++c) {
            const int r2 = r + dr;
            const int c2 = c + dc;
            if (r2 < 0 || r2 >= rows || c2 < 0 || c2 >= cols)
                continue;
            scene.springs.push_back(SpringDesc{r * cols + c, r2 * cols + c2, stiffness, damping, rest});
        }
}

// the grid's cells as two triangles each, split along the diagonal (r, c)-(r + 1, c + 1) (a shear
// spring), counter-clockwise seen from +y
void addGridTriangles(SceneDesc &scene, int rows, int cols)
{
    for (int r = 0; r + 1 < rows; ++r)
        for (int c = 0; c + 1 < cols; ++c) {
            const int p00 = r * cols + c, p01 = p00 + 1, p10 = p00 + cols, p11 = p10 + 1;
            scene.triangles.push_back({p00, p10, p11});
            scene.triangles.push_back({p00, p11, p01});
        }
}

// the faces of the convex hull of points 0..n-1, all on one sphere about centre and sorted by
// height (a Fibonacci lattice), wound counter-clockwise seen from outside: the surface a user
// sees. A face's vertices lie within `reach` of its first (smallest) one, and only points within
// twice that can lie outside its plane, so each point's search stays local.
std::vector<std::array<int, 3>> sphereHullFaces(const std::vector<ParticleDesc> &points, int n,
                                                const Eigen::Vector3d &centre, double reach, double heightPerIndex)
{
    std::vector<std::array<int, 3>> faces;
    const auto at = [&points](int i) -> const Eigen::Vector3d & { return points[std::size_t(i)].position; };
    std::vector<int> near, nearby;
    for (int i = 0; i < n; ++i) {
        near.clear();
        nearby.clear();
        const int span = int(2.0 * reach / heightPerIndex) + 1;
        for (int j = std::max(0, i - span); j < std::min(n, i + span + 1); ++j) {
            if (j == i)
                continue;
            const double d = (at(j) - at(i)).norm();
            if (d <= 2.0 * reach)
                nearby.push_back(j);
            if (j > i && d <= reach)
                near.push_back(j);
        }
        for (std::size_t a = 0; a < near.size(); ++a)
            for (std::size_t b = a + 1; b < near.size(); ++b) {
                int j = near[a], k = near[b];
                Eigen::Vector3d normal = (at(j) - at(i)).cross(at(k) - at(i));
                const double area2 = normal.norm();
                if (area2 <= 0.0)
                    continue;
                if (normal.dot(at(i) + at(j) + at(k) - 3.0 * centre) < 0.0) {
                    std::swap(j, k);
                    normal = -normal;
                }
                // a hull face: no point beyond its plane (points on it, four on one circle, are
                // let be: either split of their quadrilateral draws the same)
                const double tolerance = 1e-12 * area2 * reach;
                bool hull = true;
                for (int q : nearby)
                    if (q != j && q != k && normal.dot(at(q) - at(i)) > tolerance) {
                        hull = false;
                        break;
                    }
                if (hull)
                    faces.push_back({i, j, k});
            }
    }
    return faces;
}

}  // namespace

SceneDesc makeNet(const NetOptions &o)
{
    SceneDesc scene;
    scene.name = "net";
    addGrid(scene, o.rows, o.cols, o.spacing, o.height, o.mass, o.radius);
    joinGrid(scene, o.rows, o.cols, o.spacing, 0, 1, o.stiffness, o.damping);
    joinGrid(scene, o.rows, o.cols, o.spacing, 1, 0, o.stiffness, o.damping);
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
    joinGrid(scene, o.rows, o.cols, o.spacing, 0, 1, o.structuralStiffness, o.damping);
    joinGrid(scene, o.rows, o.cols, o.spacing, 1, 0, o.structuralStiffness, o.damping);
    joinGrid(scene, o.rows, o.cols, o.spacing, 1, 1, o.shearStiffness, o.damping);
    joinGrid(scene, o.rows, o.cols, o.spacing, 1, -1, o.shearStiffness, o.damping);
    joinGrid(scene, o.rows, o.cols, o.spacing, 0, 2, o.bendStiffness, o.damping);
    joinGrid(scene, o.rows, o.cols, o.spacing, 2, 0, o.bendStiffness, o.damping);
    if (o.sheetCollisions) {
        addGridTriangles(scene, o.rows, o.cols);
        scene.settings.triangleCollisions = true;
        scene.settings.thickness = o.thickness;
        scene.settings.selfCollision = o.selfCollision;
    }
    if (o.pinCorners) {
        scene.particles.front().pinned = true;
        scene.particles[static_cast<std::size_t>(o.cols - 1)].pinned = true;
    }
    return scene;
}

std::vector<ParticleDesc> ballColumn(int count, double radius, double mass, const Eigen::Vector3d &foot)
{
    std::vector<ParticleDesc> balls;
    for (int i = 0; i < count; ++i)
        balls.push_back(ParticleDesc{foot + Eigen::Vector3d(0.0, radius + 2.0 * radius * i, 0.0),
                                     Eigen::Vector3d::Zero(), mass, radius, false});
    return balls;
}

std::vector<ParticleDesc> ballPyramid(int base, double radius, double mass, const Eigen::Vector3d &foot)
{
    std::vector<ParticleDesc> balls;
    for (int row = 0; row < base; ++row)
        for (int i = 0; i < base - row; ++i)
            balls.push_back(ParticleDesc{
                foot + Eigen::Vector3d((2 * i + row) * radius, radius + row * std::sqrt(3.0) * radius, 0.0),
                Eigen::Vector3d::Zero(), mass, radius, false});
    return balls;
}

PlaneDesc floorPlane(double height)
{
    return PlaneDesc{Eigen::Vector3d(0.0, 1.0, 0.0), height};
}

std::vector<PlaneDesc> boxPlanes(double halfWidth, double height)
{
    return {floorPlane(0.0),
            PlaneDesc{Eigen::Vector3d(0.0, -1.0, 0.0), -height},
            PlaneDesc{Eigen::Vector3d(1.0, 0.0, 0.0), -halfWidth},
            PlaneDesc{Eigen::Vector3d(-1.0, 0.0, 0.0), -halfWidth},
            PlaneDesc{Eigen::Vector3d(0.0, 0.0, 1.0), -halfWidth},
            PlaneDesc{Eigen::Vector3d(0.0, 0.0, -1.0), -halfWidth}};
}

SceneDesc makeChain(const ChainOptions &o)
{
    SceneDesc scene;
    scene.name = "chain";
    for (int i = 0; i <= o.links; ++i)
        scene.particles.push_back(ParticleDesc{Eigen::Vector3d(o.linkLength * i, o.height, 0.0),
                                               Eigen::Vector3d::Zero(), o.mass, o.radius, o.pinFirst && i == 0});
    for (int i = 0; i < o.links; ++i)
        addSpring(scene, i, i + 1, o.stiffness, o.damping);
    return scene;
}

namespace {

// the fewest substeps of the default time step that keep ω h ≤ 1.2 under symplectic Euler's limit
// of 2, ω bounded as for the cloth: ω² ≤ the largest Σ k (1/m_i + 1/√(m_i m_j)) over the springs
// at a free particle i
int substepsForSprings(const SceneDesc &scene)
{
    std::vector<double> bound(scene.particles.size(), 0.0);
    for (const SpringDesc &s : scene.springs) {
        const ParticleDesc &a = scene.particles[static_cast<std::size_t>(s.a)];
        const ParticleDesc &b = scene.particles[static_cast<std::size_t>(s.b)];
        const double cross = s.stiffness / std::sqrt(a.mass * b.mass);
        bound[static_cast<std::size_t>(s.a)] += s.stiffness / a.mass + cross;
        bound[static_cast<std::size_t>(s.b)] += s.stiffness / b.mass + cross;
    }
    double omegaSquared = 0.0;
    for (std::size_t i = 0; i < bound.size(); ++i)
        if (!scene.particles[i].pinned)
            omegaSquared = std::max(omegaSquared, bound[i]);
    const double steps = std::ceil(Settings{}.timeStep * std::sqrt(omegaSquared) / 1.2);
    return static_cast<int>(std::clamp(steps, 1.0, 10000.0));
}

// a shift of up to `jitter` along each axis, the same for the same generator state
Eigen::Vector3d jitterFrom(std::mt19937_64 &random, double jitter)
{
    // the engine's raw output is fixed by the standard; a distribution's is not
    const auto unit = [&random] { return static_cast<double>(random() >> 11) * 0x1.0p-53; };
    const double x = unit(), y = unit(), z = unit();
    return jitter * Eigen::Vector3d(2.0 * x - 1.0, 2.0 * y - 1.0, 2.0 * z - 1.0);
}

// a loose particle (no springs, free) at position
ParticleDesc looseParticle(const Eigen::Vector3d &position, double mass, double radius)
{
    return ParticleDesc{position, Eigen::Vector3d::Zero(), mass, radius, false};
}

}  // namespace

SceneDesc makeRope(const RopeOptions &o)
{
    ChainOptions chain;
    chain.links = o.segments;
    chain.linkLength = o.length / o.segments;
    chain.height = o.height;
    chain.mass = o.mass;
    chain.radius = 0.5 * chain.linkLength;
    chain.stiffness = o.stiffness;
    chain.damping = o.damping;
    chain.pinFirst = o.pinFirst;
    SceneDesc scene = makeChain(chain);
    scene.name = "rope";
    scene.settings.substeps = substepsForSprings(scene);
    return scene;
}

SceneDesc makeBlock(const BlockOptions &o)
{
    SceneDesc scene;
    scene.name = "block";
    scene.particles.reserve(static_cast<std::size_t>(o.nx) * static_cast<std::size_t>(o.ny) *
                            static_cast<std::size_t>(o.nz));
    std::mt19937_64 random(o.seed);
    const double x0 = -0.5 * o.spacing * (o.nx - 1);
    const double z0 = -0.5 * o.spacing * (o.nz - 1);
    // layer by layer from the bottom
    for (int y = 0; y < o.ny; ++y)
        for (int z = 0; z < o.nz; ++z)
            for (int x = 0; x < o.nx; ++x) {
                const Eigen::Vector3d at(x0 + o.spacing * x, o.height + o.spacing * y, z0 + o.spacing * z);
                scene.particles.push_back(looseParticle(at + jitterFrom(random, o.jitter), o.mass, o.radius));
            }
    return scene;
}

SceneDesc makeBall(const BallOptions &o)
{
    SceneDesc scene;
    scene.name = "ball";
    std::mt19937_64 random(o.seed);
    // the lattice points i·spacing with |i·spacing| ≤ ballRadius (a hair more, for rounding)
    const int n = static_cast<int>(std::floor(o.ballRadius / o.spacing + 1e-9));
    const double reach = o.ballRadius * o.ballRadius * (1.0 + 1e-12);
    const Eigen::Vector3d centre(0.0, o.height, 0.0);
    for (int y = -n; y <= n; ++y)
        for (int z = -n; z <= n; ++z)
            for (int x = -n; x <= n; ++x) {
                const Eigen::Vector3d at = o.spacing * Eigen::Vector3d(x, y, z);
                if (at.squaredNorm() <= reach)
                    scene.particles.push_back(
                        looseParticle(centre + at + jitterFrom(random, o.jitter), o.mass, o.radius));
            }
    return scene;
}

SceneDesc makeSoftBall(const SoftBallOptions &o)
{
    SceneDesc scene;
    scene.name = "soft ball";
    const int n = o.points;
    const Eigen::Vector3d centre(0.0, o.height, 0.0);
    // a Fibonacci lattice: evenly spaced heights, each point turned by the golden angle from the last
    const double golden = std::numbers::pi * (3.0 - std::sqrt(5.0));
    for (int i = 0; i < n; ++i) {
        const double y = 1.0 - 2.0 * (i + 0.5) / n;
        const double ring = std::sqrt(std::max(0.0, 1.0 - y * y));
        const double angle = golden * i;
        const Eigen::Vector3d onSphere(ring * std::cos(angle), y, ring * std::sin(angle));
        scene.particles.push_back(looseParticle(centre + o.ballRadius * onSphere, o.mass, o.radius));
    }

    // neighbours: every pair closer than the reach; points further apart in index are further
    // apart in height (2 R / n per index), which ends the search for each point early
    const double reach = 1.5 * o.ballRadius * std::sqrt(4.0 * std::numbers::pi / n);
    const double heightPerIndex = 2.0 * o.ballRadius / n;
    for (int i = 0; i < n; ++i)
        for (int j = i + 1; j < n && (j - i) * heightPerIndex <= reach; ++j) {
            const double distance = (scene.particles[static_cast<std::size_t>(i)].position -
                                     scene.particles[static_cast<std::size_t>(j)].position)
                                        .norm();
            if (distance <= reach)
                addSpring(scene, i, j, o.stiffness, o.damping);
        }

    // its surface, drawn and (with sheet collisions on) collided with: the hull of the points,
    // wound outwards (the triangles its springs span include fans to the centre and both windings)
    const double spacing = o.ballRadius * std::sqrt(4.0 * std::numbers::pi / n);
    scene.triangles = sphereHullFaces(scene.particles, n, centre, 1.9 * spacing, heightPerIndex);

    // the centre, joined to every surface point
    if (o.centre) {
        scene.particles.push_back(looseParticle(centre, o.mass, o.radius));
        for (int i = 0; i < n; ++i)
            addSpring(scene, i, n, o.centreStiffness, o.damping);
    }
    scene.settings.substeps = substepsForSprings(scene);
    return scene;
}

}  // namespace core
