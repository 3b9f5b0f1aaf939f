#pragma once
// The sheets that particles and other sheets collide with: the spring mesh's triangles
// (spring_triangles.h) grouped into sheets, each with a thickness, and the edges the edge–edge
// collisions test. Compiled once per model (compileModel); the triangle collision pass
// (triangle_collisions.cpp) reads it every sub-step. A piece of the mesh in which a spring is a
// side of more than two triangles is a volume's lattice (a block, a soft ball), not a sheet: its
// triangles are drawn but do not collide (its particles still do, as spheres).

#include "core/model/scene.h"
#include "core/springs/spring_triangles.h"

#include <vector>

namespace core {

struct ClothSurface {
    // the colliding triangles: three corners each, and the springs of their sides (-1: a side no
    // spring joins, which never breaks)
    std::vector<int> corners;
    std::vector<int> sides;
    std::vector<int> triangleSheet;  // per triangle
    // every side of a colliding triangle once: its two particles (lower index first), and the one
    // or two triangles it borders (-1 for none), so that a torn sheet's free edges go with the last
    // triangle that holds them
    std::vector<int> edgeEnds;
    std::vector<int> edgeTriangles;
    std::vector<int> edgeSheet;  // per edge
    // per particle: the sheet it is a corner of (-1: none), and its distance from a sheet's middle
    // at contact: half its sheet's thickness for a corner, its radius for any other particle
    std::vector<int> vertexSheet;
    std::vector<double> contactRadius;
    std::vector<double> sheetThickness;  // m, per sheet
    bool selfCollision = true;  // a sheet's own particles and edges collide with its triangles

    int triangleCount() const { return static_cast<int>(triangleSheet.size()); }
    int edgeCount() const { return static_cast<int>(edgeSheet.size()); }
    bool empty() const { return triangleSheet.empty(); }
};

// whether the scene's triangles are those it lists (SceneDesc::triangles, then perhaps none) rather
// than those its springs span: it lists some, or it has imported meshes, whose surfaces are drawn
// instead of their lattices' triangles
bool listsTriangles(const SceneDesc &scene);

// The scene's triangles: those it lists (SceneDesc::triangles), each side's spring looked up, or,
// when it lists none, those its springs span (findSpringTriangles): one function for the drawing
// and the collisions
SpringTriangles sceneTriangles(const SceneDesc &scene);

// the corners of sceneTriangles(scene): the list a scene gives, or the one its springs make, for an
// edit that must carry them when it adds to or takes from a scene
std::vector<std::array<int, 3>> listedTriangles(const SceneDesc &scene);

// the sheets of those triangles, with the settings' thickness (0: each sheet's own, from its
// particles' radii and its shortest side, see docs/physics.md) and self-collision switch
ClothSurface makeClothSurface(const SceneDesc &scene, const SpringTriangles &triangles);

// the thickness a sheet takes when the settings leave it to the sheet: its particles' mean
// diameter, but no more than 0.3 of its shortest side (at rest), so that a flat sheet keeps clear of
// itself (a corner is 1/√2 of a side from the nearest triangle it is not a corner of)
double automaticThickness(double meanRadius, double shortestSide);

}  // namespace core
